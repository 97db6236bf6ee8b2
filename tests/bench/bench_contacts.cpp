// The explicit solver on a jointed model: what the contacts cost. Results go to
// tests/bench/RESULTS.md.
//
// B4: the seed's Case 3 region (tests/scenes.hpp: 200 m x 180 m, Case 3 joints, the glued
//     warhead "cavern") zoned to about 50k zones, built through the Model as a script would:
//     elastic rock and joints of the physically consistent prototype (Set P of
//     stdlib/edem/seed.lua, as tests/verification/seed_region_joints.lua), jassigned to every
//     joint, in-situ stress with the cavern roof 158 m deep (K0 = 0.6), roller sides and base,
//     the top loaded by the in-situ stress, gravity, static mode. The in-situ state is in
//     balance, so nothing moves much and contacts are found once: this is the steady cost of the
//     contact forces. After a warm-up of kWarmUp cycles (prepare, first contact detection),
//     kBatches batches of kBatch cycles are timed, on 1 and 2 threads: the same cycles every
//     run, since the motion after the in-situ start (and with it how often contacts are found
//     again) changes as the model settles.
//   * BM_B4_JointedRegion: the jointed model; zone-cycles/s include the contact passes (forces,
//     gather) and every re-detection the motion asks for.
//   * BM_B4_JointedRegionLoaded: the same, with the top load raised by a fifth after the
//     warm-up: blocks move and slip, and the timed cycles include the re-detections the motion
//     asks for (the sudden-load robustness test's situation).
//   * BM_B4_SameZonesNoJoints: the same region and size field without the joint sets (the
//     glued cavern outline stays, so its blocks are one continuum and there are no contacts):
//     the zones' cost alone, with a zone count within a few % of the jointed one.
//
// Reading "contacts cost less than the zones": per zone-cycle, the jointed model takes
// 1 / rate_joints, the zones alone 1 / rate_no_joints; the contacts (with the extra nodes on
// either side of a joint) take the difference. The goal holds, for the same thread count, when
//   1 / rate_joints - 1 / rate_no_joints < 1 / rate_no_joints,
// i.e. rate_joints > rate_no_joints / 2. Rates are per zone, so the small difference in zone
// count cancels.
//
// Counters: zones, contacts (as last found, after the warm-up), zone_cycles_per_s,
// bytes_per_zone (see model_rss_bytes) and first_cycle_ms (prepare + first contact detection;
// the jointed value minus the unjointed one estimates the contact boundary and detection).
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <exception>
#include <fstream>
#include <string>
#include <utility>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "scenes.hpp"

namespace {

using namespace edem;

// Zone sizes [m] near the cavern and far from it (growth 0.2 m/m, the default): about 50k zones
// in either model (50,233 with joints, 50,675 without, when written).
constexpr double kEdge = 0.45;
constexpr double kFar = 3.2;
constexpr long kWarmUp = 20;  // cycles before timing
constexpr long kBatch = 200;  // cycles per timed iteration
constexpr int kBatches = 5;   // timed iterations per run

// Resident set size of this process [bytes], from /proc/self/status (0 where unreadable).
double rss_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;  // kB
  return 0.0;
}

// Hands freed heap memory back to the system, so that the RSS before a model is built does not
// already hold the pages of the one a previous run freed (glibc keeps them otherwise).
void release_free_heap() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

// The region without joints: the same outer block and glued cavern outline.
Model unjointed_cavern() {
  Model model({"cavern region without joints", 1e-9});
  model.add_block({{{-100, -90}, {100, -90}, {100, 90}, {-100, 90}}});
  model.add_region({"cavern", scenes::warhead(24, 48, 8, 16), true});
  return model;
}

BoundaryDef on_side(std::string side, std::string fix) {
  BoundaryDef def;
  def.side = std::move(side);
  def.fix = std::move(fix);
  return def;
}

Model b4_model(bool joints, int threads) {
  Model model = joints ? scenes::jointed_cavern() : unjointed_cavern();
  ZoneDef zone;
  zone.edge = kEdge;
  zone.far = kFar;
  zone.near = {{"cavern", {}}};
  model.zone(zone);

  MaterialDef rock;
  rock.name = "rock";
  rock.density = 2688;  // [kg/m^3]
  rock.young = 7.421e9; // [Pa]
  rock.poisson = 0.136;
  model.add_material(rock);
  model.assign({"rock", {}});
  if (joints) {
    JointMaterialDef joint;
    joint.name = "joint";
    joint.kn = 83.9e6;      // [Pa/m]
    joint.ks = 3.60e6;      // [Pa/m]
    joint.friction = 31.2;  // [deg]
    model.add_joint_material(joint);
    JassignDef rule;
    rule.material = "joint";
    rule.kind = "joint";
    model.jassign(rule);
  }
  model.set_gravity({0.0, -9.81});
  InsituDef insitu;
  insitu.from_surface = true;
  insitu.surface = 24 + 158;  // [m]: the cavern roof (y = 24) 158 m deep
  insitu.density = 2688;
  insitu.k0 = 0.6;
  model.insitu(insitu);
  model.boundary(on_side("left", "x"));  // rollers
  model.boundary(on_side("right", "x"));
  model.boundary(on_side("bottom", "y"));
  BoundaryDef top = on_side("top", "");
  top.stress_insitu = true;
  model.boundary(top);
  model.set_solver({});  // static mode, adaptive damping
  model.set_threads(threads);
  return model;
}

// Raises the top load by a fifth at once (the sides stay on rollers): the blocks move, slip,
// and the contacts are found again as they go, as in
// tests/verification/long/seed_region_sudden_load.lua.
void load_suddenly(Model& model) {
  const double top = -(2688 * 9.81 * (24 + 158 - 90));  // in-situ syy at y = 90 [Pa]
  BoundaryDef def = on_side("top", "");
  def.stress = std::array<double, 3>{0.6 * 1.2 * top, 1.2 * top, 0.0};
  model.boundary(def);
}

void run_b4(benchmark::State& state, bool joints, bool loaded = false) {
  const int threads = static_cast<int>(state.range(0));
  release_free_heap();
  const double rss_before = rss_bytes();
  Model model;
  std::chrono::duration<double, std::milli> first{};
  try {
    model = b4_model(joints, threads);
    const auto start = std::chrono::steady_clock::now();
    model.cycle(1);
    first = std::chrono::steady_clock::now() - start;
    model.cycle(kWarmUp - 1);
    if (loaded) load_suddenly(model);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  // The growth of the RSS over building, zoning, preparing and warming up the model, once the
  // freed memory (the zoning's temporaries) is handed back: an estimate of the whole model's
  // footprint (geometry, mesh, solver arrays, contacts) with the allocator's slack and the
  // threads' stacks, not an exact count of bytes in use.
  release_free_heap();
  const double model_rss_bytes = rss_bytes() - rss_before;
  const int zones = model.info().zones;
  const int contacts = model.contact_count();

  for (auto _ : state) {
    try {
      model.cycle(kBatch);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      break;
    }
  }
  state.counters["zones"] = zones;
  state.counters["contacts"] = contacts;
  state.counters["zone_cycles_per_s"] = benchmark::Counter(
      static_cast<double>(zones) * kBatch * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["bytes_per_zone"] = model_rss_bytes / zones;
  state.counters["first_cycle_ms"] = first.count();
}

void BM_B4_JointedRegion(benchmark::State& state) {
  run_b4(state, true);
}
BENCHMARK(BM_B4_JointedRegion)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(kBatches)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_B4_JointedRegionLoaded(benchmark::State& state) {
  run_b4(state, true, true);
}
BENCHMARK(BM_B4_JointedRegionLoaded)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(kBatches)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_B4_SameZonesNoJoints(benchmark::State& state) {
  run_b4(state, false);
}
BENCHMARK(BM_B4_SameZonesNoJoints)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(kBatches)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
