// Zoning: meshing blocks into quality triangles with a graded size field.
//
// Constrained Delaunay refinement (CGAL) with a minimum angle of 20.7 degrees, except near
// block corners sharper than that, and a target edge length that is `edge` inside and next to
// the `near` polygons and grows linearly with distance, at rate `growth`, up to `far`.
#pragma once

#include <vector>

#include "geom/block_set.hpp"
#include "geom/mesh.hpp"
#include "geom/polygon.hpp"

namespace edem {

struct SizeField {
  double edge = 1.0;            // target edge length near the `near` polygons [m]
  double far = 1.0;             // largest edge length, far from them [m]
  double growth = 0.2;          // increase of edge length per metre of distance [-]
  std::vector<Polygon> near;    // where the mesh is finest; empty: uniform `edge`
  double at(Vec2 point) const;  // target edge length at a point [m]
};

// Minimum zone angle the mesher guarantees away from sharp block corners [deg].
inline constexpr double kMinZoneAngle = 20.0;

// Most zones one block may get; beyond it zoning stops with an error instead of running out
// of memory or time.
inline constexpr int kMaxZonesPerBlock = 5'000'000;

// Mesh the given blocks (indices into `blocks`), each with its own size field, into one
// Mesh whose block numbering follows `blocks`. Blocks with no size field (nullptr) get no
// zones.
Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block);
Mesh zone_blocks(const BlockSet& blocks, const std::vector<const SizeField*>& size_of_block,
                 int max_zones_per_block);

}  // namespace edem
