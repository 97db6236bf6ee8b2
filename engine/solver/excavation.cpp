// Excavation and backfill: excavate{} turns the zones of a region null, as UDEC 7 does (the
// geometry stays, so fill{} can put material back), and can take the excavated zones' pull on
// the new surface off gradually; stage() counts the excavations.
//
// The rock left in place was in equilibrium with the excavated zones' forces on the nodes they
// shared. Removing those zones at once is a sudden load that rings; with release = n the same
// forces (stress and weight) are held as loads on those nodes and taken off linearly over the
// next n cycles, so the new surface unloads the way a face advancing past it would.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <utility>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"
#include "solver/energy.hpp"
#include "solver/excavation.hpp"
#include "solver/loads.hpp"
#include "solver/prepare.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

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
    if (zone_law(m.params[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])].model).is_void) continue;
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

// Glued edges (region outlines, intact potential cracks) between blocks with no rock left and
// blocks still in place: a new surface that other blocks must be able to touch (a wedge sliding
// out of the wall onto the bench below). Unglued on both sides; true if any was.
bool unglue_excavated(Mechanics& m, const Mesh& mesh) {
  std::vector<char> live(mesh.block_boundary.size(), 0);
  for (int z = 0; z < mesh.zone_count(); ++z)
    if (m.zone_excavated[static_cast<size_t>(z)] == 0 && m.zone_material[static_cast<size_t>(z)] >= 0 &&
        !zone_law(m.params[static_cast<size_t>(m.zone_material[static_cast<size_t>(z)])].model).is_void)
      live[static_cast<size_t>(mesh.zone_block[static_cast<size_t>(z)])] = 1;
  // Glued half-edges by their ends (shared corners are the same numbers on both sides).
  using Key = std::pair<std::pair<double, double>, std::pair<double, double>>;
  std::map<Key, std::vector<std::pair<size_t, int>>> sides;  // -> (flat edge, block)
  size_t flat = 0;
  for (size_t block = 0; block < mesh.block_boundary.size(); ++block)
    for (const BoundaryLoop& loop : mesh.block_boundary[block])
      for (size_t i = 0; i < loop.gridpoints.size(); ++i, ++flat) {
        if (!m.edge_glued[flat]) continue;
        const Vec2 a = mesh.gp_position[static_cast<size_t>(loop.gridpoints[i])];
        const Vec2 b = mesh.gp_position[static_cast<size_t>(loop.gridpoints[(i + 1) % loop.gridpoints.size()])];
        const auto pa = std::make_pair(a.x, a.y), pb = std::make_pair(b.x, b.y);
        sides[pa < pb ? Key{pa, pb} : Key{pb, pa}].push_back({flat, static_cast<int>(block)});
      }
  bool changed = false;
  for (const auto& [key, edges] : sides) {
    bool dead = false, alive = false;
    for (const auto& [edge, block] : edges) (live[static_cast<size_t>(block)] ? alive : dead) = true;
    if (!(dead && alive)) continue;
    for (const auto& [edge, block] : edges) m.edge_glued[edge] = 0;
    changed = true;
  }
  return changed;
}

// After reconnect(): the release's shares move from the old nodes to the new nodes of the rock
// in place at the same gridpoints (`old_node`: gridpoint -> node before).
void follow_release(Mechanics& m, const Mesh& mesh, const std::vector<int>& old_node) {
  std::vector<int> moved(old_node.size() > 0 ? static_cast<size_t>(m.node_count) : 0, -1);
  for (int z = 0; z < mesh.zone_count(); ++z) {
    if (m.zone_excavated[static_cast<size_t>(z)] > 0) continue;
    for (const int gp : mesh.zone_gp[static_cast<size_t>(z)])
      moved[static_cast<size_t>(old_node[static_cast<size_t>(gp)])] = m.gp_node[static_cast<size_t>(gp)];
  }
  for (int& dof : m.release.dof) {
    const int node = moved[static_cast<size_t>(dof / 2)];
    if (node >= 0) dof = 2 * node + dof % 2;
  }
}

// Drops the release's shares on nodes no rock zone holds any more (a block mucked out while its
// step's load comes off): those nodes are no longer cycled, and their last velocity would go on
// counting the share's work.
void drop_release_on_dug_nodes(Mechanics& m, const Mesh& mesh) {
  ReleaseLoad& r = m.release;
  if (r.dof.empty()) return;
  std::vector<char> rock(static_cast<size_t>(m.node_count), 0);
  for (int z = 0; z < mesh.zone_count(); ++z) {
    if (m.zone_excavated[static_cast<size_t>(z)] > 0) continue;
    for (const int gp : mesh.zone_gp[static_cast<size_t>(z)]) rock[static_cast<size_t>(m.gp_node[static_cast<size_t>(gp)])] = 1;
  }
  const bool with_velocities = r.v_before.size() == r.dof.size();
  size_t kept = 0;
  for (size_t i = 0; i < r.dof.size(); ++i) {
    const size_t node = static_cast<size_t>(r.dof[i] / 2);
    if (node >= rock.size() || !rock[node]) continue;
    r.dof[kept] = r.dof[i];
    r.force[kept] = r.force[i];
    if (with_velocities) r.v_before[kept] = r.v_before[i];
    ++kept;
  }
  r.dof.resize(kept);
  r.force.resize(kept);
  if (with_velocities) r.v_before.resize(kept);
}

}  // namespace

void excavate_zones(Mechanics& m, const Mesh& mesh, const std::vector<int>& zones, long release,
                    bool new_stage) {
  const StoredEnergy before = stored_energy(m);
  if (release > 0) {
    prepare(m, mesh);  // the zone geometry and the active list of now
    hold_release(m, zones, release);
  }
  if (new_stage) {
    m.stage += 1;
    m.stage_cycles.push_back(m.info.cycle);
  }
  for (const int z : zones) {
    m.zone_excavated[static_cast<size_t>(z)] = std::max(m.stage, 1);
    m.stress[static_cast<size_t>(z)] = Stress{};
    m.mean_stress_ref[static_cast<size_t>(z)] = 0.0;
    m.zone_state[static_cast<size_t>(z)] = 0;
    m.zone_history[static_cast<size_t>(z)] = 0.0;
  }
  lump_boundary_loads(m);  // with the release's share
  const std::vector<int> old_node = m.gp_node;
  if (unglue_excavated(m, mesh)) {
    reconnect(m, mesh);
    m.keep_fits = false;  // the zones changed, not only the nodes: sections are fitted again
    follow_release(m, mesh, old_node);
  }
  drop_release_on_dug_nodes(m, mesh);
  lump_boundary_loads(m);
  m.dirty = true;
  book_excavation(m, before);  // the rock's energy goes with it
}

void fill_zones(Mechanics& m, const std::vector<int>& zones, int material) {
  for (const int z : zones) {
    m.zone_excavated[static_cast<size_t>(z)] = 0;
    m.zone_material[static_cast<size_t>(z)] = material;
    m.stress[static_cast<size_t>(z)] = Stress{};
    m.mean_stress_ref[static_cast<size_t>(z)] = 0.0;
    m.zone_state[static_cast<size_t>(z)] = 0;
    m.zone_history[static_cast<size_t>(z)] = 0.0;
  }
  m.dirty = true;
}

long release_cycles_left(const Mechanics& m) {
  return m.release.dof.empty() ? 0 : std::max(0L, m.release.cycles - m.release.done);
}

void release_work(Mechanics& m) {
  ReleaseLoad& r = m.release;
  if (!r.pending) return;
  r.pending = false;
  double work = 0.0;
  for (size_t i = 0; i < r.dof.size(); ++i) {
    const size_t dof = static_cast<size_t>(r.dof[i]);
    work += r.factor * r.force[i] * 0.5 * (r.v_before[i] + m.v[dof]) * m.step;
  }
  m.energy.release += work;
}

void step_release(Mechanics& m) {
  ReleaseLoad& r = m.release;
  release_work(m);
  if (r.dof.empty() || r.done >= r.cycles) return;
  r.done += 1;
  const double next = r.done >= r.cycles ? 0.0 : 1.0 - static_cast<double>(r.done) / static_cast<double>(r.cycles);
  for (size_t i = 0; i < r.dof.size(); ++i)
    m.load[static_cast<size_t>(r.dof[i])] += (next - r.factor) * r.force[i];
  r.factor = next;
  r.v_before.resize(r.dof.size());
  for (size_t i = 0; i < r.dof.size(); ++i) r.v_before[i] = m.v[static_cast<size_t>(r.dof[i])];
  r.pending = true;
}

void end_release(Mechanics& m) {
  m.release = ReleaseLoad{};
  lump_boundary_loads(m);
  m.dirty = true;  // the applied load the ratio is measured against changed
}

}  // namespace edem
