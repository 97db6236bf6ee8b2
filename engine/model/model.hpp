// The Model: owns every input and every derived store of one EDEM model.
//
// Geometry commands append inputs; the blocks (arrangement of all cuts) and the zones are
// derived from them lazily, so a geometry command after zone{} simply invalidates the mesh,
// which is rebuilt with the same zoning requests before it is next used. Every mutating call
// validates first and changes nothing when it throws.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geom/block_set.hpp"
#include "geom/mesh.hpp"
#include "geom/zoning.hpp"
#include "model/defs.hpp"

namespace edem {

class Model {
 public:
  explicit Model(ModelDef def = {});

  const std::string& title() const { return def_.title; }

  // Geometry inputs.
  void add_block(const BlockDef& def);
  int add_joint_set(const JointSetDef& def);  // returns the set's index (0-based)
  void add_crack(const CrackDef& def);
  void add_region(const RegionDef& def);
  void zone(const ZoneDef& def);

  // Derived stores, rebuilt on demand.
  const BlockSet& blocks();
  const Mesh& mesh();
  ModelInfo info();

  // Named regions.
  const std::vector<RegionDef>& regions() const { return regions_; }
  int region_index(std::string_view name) const;  // throws, with a did-you-mean hint
  Polygon resolve(const RegionRef& ref) const;     // the polygon of a name or polygon

  int joint_set_count() const { return static_cast<int>(joint_sets_.size()); }
  double tolerance() const;  // absolute geometric tolerance [m]

 private:
  struct ZoneRequest {
    SizeField size;
    std::optional<Polygon> region;  // only blocks inside it
  };

  void invalidate();
  void rebuild_blocks();
  void rebuild_mesh();

  ModelDef def_;
  std::vector<BlockDef> bases_;
  std::vector<JointSetDef> joint_sets_;
  std::vector<CrackDef> cracks_;
  std::vector<RegionDef> regions_;
  std::vector<ZoneRequest> zone_requests_;

  std::optional<BlockSet> blocks_;  // empty when inputs changed
  std::optional<Mesh> mesh_;
};

}  // namespace edem
