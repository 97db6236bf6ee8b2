// Excavation and backfill: excavate{} turns the zones of a region null, as UDEC 7 does (the
// geometry stays, so fill{} can put material back), and can take what the excavated rock bore on
// the rock in place off gradually; stage() counts the excavations.
//
// The rock left in place was in equilibrium with what is dug out: the excavated zones' forces
// (stress and weight) on the nodes they shared, and the contacts on the dug blocks' faces, which
// pressed on the rock around and on the corners it shares with them. Removing those at once is a
// sudden load that rings; with release = n whatever the excavation takes off a node that stays is
// held on it as a load and taken off linearly over the next n cycles, so the new surface unloads
// the way a face advancing past it would.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <utility>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"
#include "contact/detect.hpp"
#include "solver/cycle.hpp"
#include "solver/energy.hpp"
#include "solver/excavation.hpp"
#include "solver/loads.hpp"
#include "solver/prepare.hpp"
#include "state/mechanics.hpp"

namespace edem {
namespace {

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

// The forces on the nodes now [N/m, by dof]: the zones' stresses, the contacts, the weight and the
// loads (a running release's share among them).
std::vector<double> forces_held(const Mechanics& m) {
  std::vector<double> f = standing_forces(m);
  for (size_t dof = 0; dof < f.size(); ++dof) f[dof] += m.weight[dof] + m.load[dof];
  return f;
}

// forces_held() with the contacts found as a detection now would find them, the model left as it
// was: a model not yet cycled keeps its first detection (joints as built, the in-situ stresses
// given) for the rock that stays.
std::vector<double> forces_held_found_now(Mechanics& m) {
  const ContactSet contacts = m.contacts;
  const EnergyLedger energy = m.energy;
  const bool fresh_cracks = m.fresh_cracks;
  refresh_contacts(m, 0.0);
  std::vector<double> f = forces_held(m);
  m.contacts = contacts;
  m.energy = energy;
  m.fresh_cracks = fresh_cracks;
  return f;
}

// The release once the zones are dug and the contacts found again: on each node rock still holds,
// the forces it had before (`before`, on the nodes as they were numbered then, `old_node`:
// gridpoint -> node then) less those it has now, loads included, so that the first cycle finds
// each node as it was. A node split by the excavation (rock glued only through what was dug) gives
// what it had to its first part, and its other parts hold what they have now.
void hold_release(Mechanics& m, const std::vector<double>& before, const std::vector<int>& old_node,
                  long cycles) {
  const std::vector<double> now = forces_held(m);
  std::vector<int> origin(static_cast<size_t>(m.node_count), -1);
  for (size_t gp = 0; gp < m.gp_node.size(); ++gp)
    origin[static_cast<size_t>(m.gp_node[gp])] = old_node[gp];
  std::vector<char> rock(static_cast<size_t>(m.node_count), 0);
  for (const int z : m.active)
    for (const int n : m.geometry[static_cast<size_t>(z)].node) rock[static_cast<size_t>(n)] = 1;
  std::vector<char> given(before.size() / 2, 0);
  ReleaseLoad& r = m.release;
  r = ReleaseLoad{};
  for (size_t n = 0; n < rock.size(); ++n) {
    if (!rock[n]) continue;
    const size_t o = static_cast<size_t>(origin[n]);
    const bool first = !given[o];
    given[o] = 1;
    for (size_t c = 0; c < 2; ++c) {
      const double f = (first ? before[2 * o + c] : 0.0) - now[2 * n + c];
      if (f == 0.0) continue;
      r.dof.push_back(static_cast<int>(2 * n + c));
      r.force.push_back(f);
    }
  }
  r.cycles = cycles;
  r.factor = r.dof.empty() ? 0.0 : 1.0;
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
  std::vector<double> held;
  const std::vector<int> old_node = m.gp_node;
  if (release > 0) {
    prepare(m, mesh);  // the zone geometry and the active list of now
    held = forces_held_found_now(m);
    m.release = ReleaseLoad{};  // its share is in `held`, and goes on in the new release
    lump_boundary_loads(m);
  }
  const StoredEnergy before = stored_energy(m);
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
    m.zone_plastic_work[static_cast<size_t>(z)] = 0.0;
  }
  if (unglue_excavated(m, mesh)) {
    reconnect(m, mesh);
    m.keep_fits = false;  // the zones changed, not only the nodes: sections are fitted again
    if (release == 0) follow_release(m, mesh, old_node);
  }
  if (release == 0) drop_release_on_dug_nodes(m, mesh);
  m.dirty = true;
  // What a detection books itself (prestress given, energy taken away with dug rock) moves the
  // ledger's last point with it: not booked again below.
  const StoredEnergy last = m.energy.last;
  if (release > 0) {
    // The contacts the rock has now, as the next solve finds them: those of the dug blocks go,
    // and where a node split, its part in place may press where the whole did.
    prepare(m, mesh);
    refresh_contacts(m, 0.0);
    update_masses(m);  // with the contacts' stiffness, as the next solve has them
    hold_release(m, held, old_node, release);
    m.dirty = true;
  }
  lump_boundary_loads(m);  // with the release's share
  book_excavation(m, before, m.energy.last - last);  // the rock's energy goes with it
}

void fill_zones(Mechanics& m, const std::vector<int>& zones, int material) {
  for (const int z : zones) {
    m.zone_excavated[static_cast<size_t>(z)] = 0;
    m.zone_material[static_cast<size_t>(z)] = material;
    m.stress[static_cast<size_t>(z)] = Stress{};
    m.mean_stress_ref[static_cast<size_t>(z)] = 0.0;
    m.zone_state[static_cast<size_t>(z)] = 0;
    m.zone_history[static_cast<size_t>(z)] = 0.0;
    m.zone_plastic_work[static_cast<size_t>(z)] = 0.0;
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
