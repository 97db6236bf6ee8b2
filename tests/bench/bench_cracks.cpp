// The explicit solver with potential cracks. Results go to tests/bench/RESULTS.md.
//
// B5: B1's unit square (zones of edge 1/200, about as many as B1's 200 x 200 cells) with
//     potential cracks every two zone edges in both directions (crackseed angles 0 and 90,
//     spacing 1/100: 100 x 100 blocks), built through the Model as a script would: elastic
//     rock, the sections judged every 10 cycles, bottom fixed, top moving down.
//   * BM_B5_Intact: strengths far above the stresses: the cost of judging intact sections
//     (and of nothing else: intact cracks are tied, their blocks one continuum).
//   * BM_B5_Cracking: a tensile strength the top's pull exceeds soon after the start (the top
//     moves up): sections break during the timed cycles, which include the breaking (nodes
//     split, contacts found on the new faces) and the contacts of the cracks.
//   * BM_B5_NoCracks: the same square and zone size without potential cracks.
// Timed: kBatches batches of kBatch cycles after a warm-up of kWarmUp; zone-cycles per second.
#include <benchmark/benchmark.h>

#include <string>
#include <utility>

#include "model/model.hpp"

namespace {

using namespace edem;

constexpr double kEdge = 1.0 / 200.0;
constexpr long kWarmUp = 20;
constexpr long kBatch = 100;
constexpr int kBatches = 5;

enum class Case { intact, cracking, none };

BoundaryDef on_side(std::string side, std::string fix) {
  BoundaryDef def;
  def.side = std::move(side);
  def.fix = std::move(fix);
  return def;
}

Model b5_model(Case which, int threads) {
  Model model;
  model.add_block({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  if (which != Case::none) {
    CrackSeedDef seed;
    seed.angles = {0.0, 90.0};
    seed.spacing = 2.0 * kEdge;
    seed.origin = {kEdge, kEdge};
    seed.material = "strength";
    seed.after = "crack";
    model.add_crackseed(seed);
  }
  ZoneDef zone;
  zone.edge = kEdge;
  model.zone(zone);
  MaterialDef rock;
  rock.name = "rock";
  rock.young = 10e9;
  rock.poisson = 0.25;
  rock.density = 2600;
  model.add_material(rock);
  MaterialDef strength = rock;
  strength.name = "strength";
  strength.model = MaterialModel::mohr;
  strength.cohesion = which == Case::cracking ? 1e6 : 1e12;
  strength.friction = 30;
  strength.tension = which == Case::cracking ? 1e3 : 1e12;
  model.add_material(strength);
  model.assign({"rock", {}});
  JointMaterialDef crack;
  crack.name = "crack";
  crack.kn = crack.ks = 1e12;
  crack.friction = 30;
  model.add_joint_material(crack);
  model.boundary(on_side("bottom", "xy"));
  BoundaryDef top = on_side("top", "");
  top.yvel = which == Case::cracking ? 1e-9 : -1e-9;  // [m per cycle]
  model.boundary(top);
  model.set_threads(threads);
  return model;
}

void run_case(benchmark::State& state, Case which) {
  Model model = b5_model(which, static_cast<int>(state.range(0)));
  model.cycle(kWarmUp);
  for (auto _ : state)
    for (int b = 0; b < kBatches; ++b) model.cycle(kBatch);
  const ModelInfo info = model.info();
  state.counters["zones"] = info.zones;
  state.counters["sections"] = info.sections;
  state.counters["cracks"] = info.cracks;
  state.counters["zone_cycles_per_s"] = benchmark::Counter(
      static_cast<double>(info.zones) * kBatch * kBatches * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}

void BM_B5_Intact(benchmark::State& state) { run_case(state, Case::intact); }
void BM_B5_Cracking(benchmark::State& state) { run_case(state, Case::cracking); }
void BM_B5_NoCracks(benchmark::State& state) { run_case(state, Case::none); }

BENCHMARK(BM_B5_NoCracks)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_B5_Intact)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_B5_Cracking)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
