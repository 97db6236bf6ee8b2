// The Model: owns every input and every derived store of one EDEM model.
//
// Geometry commands append inputs; the blocks (arrangement of all cuts) and the zones are
// derived from the inputs. A geometry command after zone{} re-cuts and re-zones with the same
// zoning requests. Every mutating call validates and derives first, and changes nothing when
// it throws.
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

  // Derived stores.
  const BlockSet& blocks() const { return blocks_; }
  const Mesh& mesh() const { return mesh_; }
  bool zoned() const { return !inputs_.zone_requests.empty(); }
  ModelInfo info() const;

  // Named regions.
  const std::vector<RegionDef>& regions() const { return inputs_.regions; }
  int region_index(std::string_view name) const;  // throws, with a did-you-mean hint
  Polygon resolve(const RegionRef& ref) const;     // the polygon of a name or polygon

  int joint_set_count() const { return static_cast<int>(inputs_.joint_sets.size()); }
  double tolerance() const;  // absolute geometric tolerance [m]

 private:
  struct ZoneRequest {
    SizeField size;
    int region = -1;                 // only blocks in this named region (-1: see polygon)
    std::optional<Polygon> polygon;  // only blocks whose centroid is inside it
  };
  // Everything the geometry is derived from.
  struct Inputs {
    std::vector<BlockDef> bases;
    std::vector<JointSetDef> joint_sets;
    std::vector<CrackDef> cracks;
    std::vector<RegionDef> regions;
    std::vector<ZoneRequest> zone_requests;
  };

  // Derive blocks (and the mesh, if zoned) from `next` and only then make it current, so a
  // command that fails leaves the model as it was.
  void commit(Inputs next);
  BlockSet cut(const Inputs& inputs) const;
  Mesh zone_all(const Inputs& inputs, const BlockSet& blocks) const;
  double tolerance_of(const Inputs& inputs) const;
  Polygon resolve_in(const Inputs& inputs, const RegionRef& ref) const;

  ModelDef def_;
  Inputs inputs_;
  BlockSet blocks_;
  Mesh mesh_;
};

}  // namespace edem
