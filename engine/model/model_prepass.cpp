// Model::prepass: the implicit problem made from the model's present state, solved through its
// stages on copies of the stresses and displacements.
#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include "constitutive/zone_law.hpp"
#include "core/error.hpp"
#include "model/model.hpp"
#include "prepass/load_stepping.hpp"
#include "solver/prepare.hpp"

namespace edem {
namespace {

void check_settings(const NewtonSettings& s) {
  if (s.steps < 1) fail("steps must be >= 1, got {}", s.steps);
  if (!(s.tolerance > 0.0 && s.tolerance < 1.0)) fail("tolerance must be in (0, 1), got {}", s.tolerance);
  if (s.max_iterations < 1) fail("iterations must be >= 1, got {}", s.max_iterations);
  if (s.restarts < 0) fail("restarts must be >= 0, got {}", s.restarts);
}

// Each node tied to the first node at exactly its reference place: the two faces of a joint, whose
// gridpoints the zoning puts at the same points, move as one.
std::vector<int> tie_joint_faces(const Mechanics& m) {
  std::vector<int> tie(static_cast<size_t>(m.node_count));
  std::map<std::pair<double, double>, int> first;
  for (int n = 0; n < m.node_count; ++n) {
    const auto at = std::make_pair(m.position[2 * static_cast<size_t>(n)], m.position[2 * static_cast<size_t>(n) + 1]);
    tie[static_cast<size_t>(n)] = first.emplace(at, n).first->second;
  }
  return tie;
}

}  // namespace

PrepassResult Model::prepass(const PrepassDef& def) {
  const auto start = std::chrono::steady_clock::now();
  Mechanics& m = *mechanics_;
  if (m.cycling_now) fail("not from inside a callback or history while cycling");
  check_settings(def.newton);
  if (!(def.duration >= 0.0)) fail("duration must be >= 0, got {}", def.duration);
  if (!zoned()) fail("the model has no zones yet (zone{{}} first)");
  prepare(m, mesh_);
  if (def.newton.solver == PrepassSolver::ldlt) {
    for (int z : m.active) {
      const size_t material = static_cast<size_t>(m.zone_material[static_cast<size_t>(z)]);
      const MaterialParams& p = m.params[material];
      if (const ZoneLaw& law = zone_law(p.model); law.unsymmetric && law.unsymmetric(p))
        fail("solver = \"ldlt\" needs a symmetric tangent, and material '{}' flows non-associated (dilation "
             "differs from friction); use \"umfpack\", \"lu\" or \"klu\"",
             m.materials[material].name);
    }
  }

  std::vector<int> tie;
  std::vector<InterfacePair> pairs;
  std::vector<InterfaceState> pair_state;
  if (m.faces.touchable_blocks >= 2) {
    if (def.joints)
      make_interfaces(m, pairs, pair_state);
    else
      tie = tie_joint_faces(m);
  }

  // The stages' zones, checked before anything is solved.
  std::vector<std::vector<int>> stage_zones;
  std::vector<std::string> stage_names;
  std::set<int> live(m.active.begin(), m.active.end());
  std::set<int> gone;
  for (size_t i = 0; i < def.stages.size(); ++i) {
    const RegionRef& ref = def.stages[i];
    const std::string name = ref.name.empty() ? fmt::format("stage {} (a polygon)", i + 1) : ref.name;
    std::vector<int> zones;
    for (int z : zones_in(ref))
      if (live.count(z) && !gone.count(z)) zones.push_back(z);
    if (zones.empty()) fail("stage {}, {}: no rock left there to excavate", i + 1, name);
    gone.insert(zones.begin(), zones.end());
    stage_zones.push_back(std::move(zones));
    stage_names.push_back(name);
  }

  PrepassResult result;
  result.zones = m.active;
  std::sort(result.zones.begin(), result.zones.end());
  std::map<int, size_t> index;
  for (size_t k = 0; k < result.zones.size(); ++k) index[result.zones[k]] = k;
  result.state.assign(result.zones.size(), {});
  for (int z : result.zones) result.centroid.push_back(mesh_.zone_centroid(z));

  std::vector<Stress> stress = m.stress;
  std::vector<double> u = m.u;
  std::vector<int> zones = result.zones;
  const auto started = std::chrono::steady_clock::now();
  // A budget of a century or more is none (and would overflow the clock's count).
  const auto deadline = def.newton.seconds >= 3e9
                            ? std::chrono::steady_clock::time_point::max()
                            : started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                            std::chrono::duration<double>(def.newton.seconds));
  auto reported = started;
  int iterations = 0;
  for (size_t stage = 0; stage <= stage_zones.size(); ++stage) {
    const std::string name = stage == 0 ? "present state" : stage_names[stage - 1];
    if (stage > 0) {
      std::vector<char> out(stress.size(), 0);
      for (int z : stage_zones[stage - 1]) {
        stress[static_cast<size_t>(z)] = Stress{};
        out[static_cast<size_t>(z)] = 1;
      }
      std::erase_if(zones, [&](int z) { return out[static_cast<size_t>(z)] != 0; });
    }
    ImplicitProblem p = make_problem(m, zones, stress, u, tie);
    add_interfaces(m, p, pairs, pair_state);
    if (stage == 0 && def.duration > 0.0) {
      p.drive.assign(u.size(), 0.0);
      for (size_t i = 0; i < u.size(); ++i)
        if ((m.fix[i / 2] & (1u << (i % 2))) && m.v[i] != 0.0) p.drive[i] = m.v[i] * def.duration;
    }
    std::vector<std::uint8_t> yielded;
    // Progress: the stage, its load factor and the iterations so far, every progress interval.
    const int before = iterations;
    const StepDone step_done = [&](double reached, int stage_iterations) {
      if (!m.prepass_progress || !(m.progress_every > 0.0)) return;
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - reported).count() < m.progress_every) return;
      reported = now;
      m.prepass_progress({.stage = name,
                          .index = static_cast<int>(stage),
                          .count = static_cast<int>(stage_zones.size()),
                          .load = reached,
                          .iterations = before + stage_iterations,
                          .seconds = std::chrono::duration<double>(now - started).count()});
    };
    StageLog log = solve_stage(m, p, def.newton, stage == 0 ? name : fmt::format("stage {} ({})", stage, name), yielded,
                               step_done, deadline);
    iterations += log.iterations;
    for (auto& s : result.state) s.push_back(kExcavatedInPrepass);
    for (size_t k = 0; k < p.zones.size(); ++k) {
      stress[static_cast<size_t>(p.zones[k])] = p.stress0[k];
      result.state[index[p.zones[k]]].back() = yielded[k];
    }
    u = p.u0;
    for (size_t k = 0; k < p.pairs.size(); ++k) pair_state[static_cast<size_t>(p.pair_index[k])] = p.pair_state0[k];
    const bool stopped = !log.failure.empty();
    result.stages.push_back({name, std::move(log)});
    if (stopped) break;  // kept: the result ends with the stage that failed
  }
  for (int z : result.zones) result.stress.push_back(stress[static_cast<size_t>(z)]);
  result.gridpoint_u.resize(static_cast<size_t>(mesh_.gp_count()));
  for (size_t g = 0; g < result.gridpoint_u.size(); ++g) {
    const size_t n = static_cast<size_t>(m.gp_node[g]);
    result.gridpoint_u[g] = {u[2 * n] - m.u[2 * n], u[2 * n + 1] - m.u[2 * n + 1]};
  }
  prepass_yield_.assign(static_cast<size_t>(mesh_.zone_count()), 0);
  for (size_t k = 0; k < result.zones.size(); ++k)
    for (std::uint8_t bits : result.state[k])
      if (!(bits & kExcavatedInPrepass))
        prepass_yield_[static_cast<size_t>(result.zones[k])] |= static_cast<std::uint8_t>(bits & (kShearNow | kTensionNow));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  last_prepass_ = result;
  return result;
}

}  // namespace edem
