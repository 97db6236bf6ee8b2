// Excavation and backfill: excavate{} turns the zones of a region null, as UDEC 7 does (the
// geometry stays, so fill{} can put material back), and can take the excavated zones' pull on
// the new surface off gradually; stage() counts the excavations.
//
// The rock left in place was in equilibrium with the excavated zones' forces on the nodes they
// shared. Removing those zones at once is a sudden load that rings; with release = n the same
// forces (stress and weight) are held as loads on those nodes and taken off linearly over the
// next n cycles, so the new surface unloads the way a face advancing past it would.
#include "core/error.hpp"
#include "core/names.hpp"
#include "model/model.hpp"
#include "solver/excavation.hpp"
#include "solver/loads.hpp"
#include "solver/mechanics.hpp"
#include "solver/prepare.hpp"

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

// Forces of the zones `gone` (stress and weight) on the nodes that active zones still hold.
void hold_release(Mechanics& m, const std::vector<int>& gone, long cycles) {
  std::vector<char> going(m.zone_material.size(), 0);
  for (const int z : gone) going[static_cast<size_t>(z)] = 1;
  std::vector<char> kept(static_cast<size_t>(m.node_count), 0);
  for (const int z : m.active)
    if (!going[static_cast<size_t>(z)])
      for (const int n : m.geometry[static_cast<size_t>(z)].node) kept[static_cast<size_t>(n)] = 1;
  std::vector<double> force(2 * static_cast<size_t>(m.node_count), 0.0);
  for (const int z : gone) {
    if (m.params[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])].model == MaterialModel::null) continue;
    const ZoneGeometry& g = m.geometry[static_cast<size_t>(z)];
    const Stress& s = m.stress[static_cast<size_t>(z)];
    const double weight = m.params[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])].density *
                          g.area / 3.0;
    for (int i = 0; i < 3; ++i) {
      const size_t n = static_cast<size_t>(g.node[static_cast<size_t>(i)]);
      force[2 * n] += -g.area * (s.xx * g.b[i] + s.xy * g.c[i]) + weight * m.gravity.x;
      force[2 * n + 1] += -g.area * (s.xy * g.b[i] + s.yy * g.c[i]) + weight * m.gravity.y;
    }
  }
  ReleaseLoad& r = m.release;
  // A release still running is merged: its share left over, as it stands now.
  std::vector<double> previous(force.size(), 0.0);
  for (size_t i = 0; i < r.dof.size(); ++i)
    previous[static_cast<size_t>(r.dof[i])] = r.factor * r.force[i];
  r = ReleaseLoad{};
  for (size_t dof = 0; dof < force.size(); ++dof) {
    if (!kept[dof / 2]) continue;
    const double f = force[dof] + previous[dof];
    if (f == 0.0) continue;
    r.dof.push_back(static_cast<int>(dof));
    r.force.push_back(f);
  }
  r.cycles = cycles;
  r.factor = r.dof.empty() ? 0.0 : 1.0;
}

}  // namespace

void Model::excavate(const ExcavateDef& def) {
  Mechanics& m = *mechanics_;
  if (mesh_.zone_count() == 0) fail("there are no zones to excavate: zone{{...}} the blocks first");
  if (def.release < 0) fail("release must be >= 0 cycles, got {}", def.release);
  const std::vector<int> zones = region_zones(*this, def.region);
  for (const int z : zones) {
    const int stage = m.zone_excavated[static_cast<size_t>(z)];
    if (stage > 0) fail("{} was excavated already (stage {})", region_label(def.region), stage);
  }
  for (const int z : zones)
    if (m.zone_material[static_cast<size_t>(z)] < 0)
      fail("{} has zones without material: assign{{}} the rock before excavating it",
           region_label(def.region));
  if (def.release > 0) {
    prepare(m, mesh_);  // the zone geometry and the active list of now
    hold_release(m, zones, def.release);
  }
  m.stage += 1;
  for (const int z : zones) {
    m.zone_excavated[static_cast<size_t>(z)] = m.stage;
    m.stress[static_cast<size_t>(z)] = Stress{};
    m.mean_stress_ref[static_cast<size_t>(z)] = 0.0;
    m.zone_state[static_cast<size_t>(z)] = 0;
  }
  lump_boundary_loads(m);  // with the release's share
  m.dirty = true;
}

void Model::fill(const FillDef& def) {
  Mechanics& m = *mechanics_;
  const int material = index_of_name(m.materials, def.material, "material", "material{...}");
  if (mesh_.zone_count() == 0) fail("there are no zones to fill: zone{{...}} the blocks first");
  std::vector<int> zones;
  for (const int z : region_zones(*this, def.region))
    if (m.zone_excavated[static_cast<size_t>(z)] > 0) zones.push_back(z);
  if (zones.empty()) fail("{} holds no excavated zones to fill", region_label(def.region));
  for (const int z : zones) {
    m.zone_excavated[static_cast<size_t>(z)] = 0;
    m.zone_material[static_cast<size_t>(z)] = material;
    m.stress[static_cast<size_t>(z)] = Stress{};
    m.mean_stress_ref[static_cast<size_t>(z)] = 0.0;
    m.zone_state[static_cast<size_t>(z)] = 0;
  }
  m.dirty = true;
}

int Model::stage() const { return mechanics_->stage; }

// Takes the next cycle's step off the excavation loads; true while a release runs.
bool step_release(Mechanics& m) {
  ReleaseLoad& r = m.release;
  if (r.dof.empty()) return false;
  r.done += 1;
  const double next = r.done >= r.cycles ? 0.0 : 1.0 - static_cast<double>(r.done) / static_cast<double>(r.cycles);
  for (size_t i = 0; i < r.dof.size(); ++i)
    m.load[static_cast<size_t>(r.dof[i])] += (next - r.factor) * r.force[i];
  r.factor = next;
  if (next == 0.0) {
    r = ReleaseLoad{};
    lump_boundary_loads(m);  // exactly the boundary's own loads again
    m.dirty = true;          // the applied load the ratio is measured against changed
  }
  return true;
}

}  // namespace edem
