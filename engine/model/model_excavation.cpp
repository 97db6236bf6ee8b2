// The excavation commands: excavate{} and fill{} pick their zones (a named region, a polygon
// that cuts no block, a block); solver/excavation.cpp takes them out or puts them back.
#include <fmt/format.h>

#include "core/error.hpp"
#include "core/names.hpp"
#include "model/model.hpp"
#include "solver/excavation.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

// The zones of a region, which must take whole blocks: the contacts and the new surface follow
// block outlines (a named region does; a polygon must not cut through a block).
std::vector<int> region_zones(const Model& model, const RegionRef& ref) {
  const std::vector<int> zones = model.zones_in(ref);
  if (zones.empty()) {
    if (!ref.name.empty()) fail("region '{}' holds no zones", ref.name);
    fail("no zone lies inside the polygon");
  }
  if (!ref.name.empty()) return zones;
  const Mesh& mesh = model.mesh();
  std::vector<int> inside(model.blocks().blocks.size(), 0), all(inside.size(), 0);
  for (const int z : zones) ++inside[static_cast<size_t>(mesh.zone_block[static_cast<size_t>(z)])];
  for (const int b : mesh.zone_block) ++all[static_cast<size_t>(b)];
  for (size_t b = 0; b < inside.size(); ++b)
    if (inside[b] > 0 && inside[b] < all[b])
      fail("the polygon cuts through block {} (it was never cut into the model): name it with "
           "region{{ name = ..., polygon = ... }} before zone{{}} and excavate that name",
           b + 1);
  return zones;
}

std::string region_label(const RegionRef& ref) {
  return ref.name.empty() ? std::string("the polygon") : "region '" + ref.name + "'";
}

}  // namespace

void Model::excavate(const ExcavateDef& def) {
  Mechanics& m = *mechanics_;
  if (mesh_.zone_count() == 0) fail("there are no zones to excavate: zone{{...}} the blocks first");
  if (def.release < 0) fail("release must be >= 0 cycles, got {}", def.release);
  const bool by_block = def.block >= 0;
  if (by_block && def.block >= static_cast<int>(mesh_.block_boundary.size()))
    fail("there is no block {} ({} blocks)", def.block + 1, mesh_.block_boundary.size());
  const std::string label = by_block ? fmt::format("block {}", def.block + 1) : region_label(def.region);
  std::vector<int> zones;
  if (by_block) {
    for (int z = mesh_.block_first_zone[static_cast<size_t>(def.block)]; z < mesh_.block_first_zone[static_cast<size_t>(def.block) + 1]; ++z)
      zones.push_back(z);
    if (zones.empty()) fail("{} holds no zones", label);
  } else {
    zones = region_zones(*this, def.region);
  }
  for (const int z : zones) {
    const int stage = m.zone_excavated[static_cast<size_t>(z)];
    if (stage > 0) fail("{} was excavated already (stage {})", label, stage);
  }
  for (const int z : zones)
    if (m.zone_material[static_cast<size_t>(z)] < 0)
      fail("{} has zones without material: assign{{}} the rock before excavating it", label);
  excavate_zones(m, mesh_, zones, def.release, !by_block);  // mucking out a fallen block is no stage
  follow_histories_past_excavation();
}

void Model::fill(const FillDef& def) {
  Mechanics& m = *mechanics_;
  const int material = index_of_name(m.materials, def.material, "material", "material{...}");
  if (mesh_.zone_count() == 0) fail("there are no zones to fill: zone{{...}} the blocks first");
  std::vector<int> zones;
  for (const int z : region_zones(*this, def.region))
    if (m.zone_excavated[static_cast<size_t>(z)] > 0) zones.push_back(z);
  if (zones.empty()) fail("{} holds no excavated zones to fill", region_label(def.region));
  fill_zones(m, zones, material);
}

int Model::stage() const { return mechanics_->stage; }

const std::vector<long>& Model::stage_cycles() const { return mechanics_->stage_cycles; }

}  // namespace edem
