// Building and zoning the seed's Case 3 region through the engine (tests/scenes.hpp): Case 3
// joints in the seed's 200 m x 180 m region around a glued warhead outline, zoned to about 50k
// zones. Results go to tests/bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "model/model_plot.hpp"
#include "scenes.hpp"

namespace {

using edem::scenes::jointed_cavern;

// Zone sizes giving about 50k zones with the example's grading.
constexpr double kEdge = 0.42;
constexpr double kFar = 3.2;

edem::Model zoned_example() {
  edem::Model model = jointed_cavern();
  edem::ZoneDef zone;
  zone.edge = kEdge;
  zone.far = kFar;
  zone.near = {{"cavern", {}}};
  model.zone(zone);
  return model;
}

void BM_CutExample(benchmark::State& state) {
  for (auto _ : state) {
    edem::Model model = jointed_cavern();
    benchmark::DoNotOptimize(model.blocks().blocks.size());
  }
}
BENCHMARK(BM_CutExample)->Unit(benchmark::kMillisecond);

void BM_CutAndZoneExample(benchmark::State& state) {
  edem::ModelInfo info;
  for (auto _ : state) {
    info = zoned_example().info();
  }
  state.counters["blocks"] = info.blocks;
  state.counters["zones"] = info.zones;
  state.counters["gridpoints"] = info.gridpoints;
}
BENCHMARK(BM_CutAndZoneExample)->Unit(benchmark::kMillisecond);

// Plotting the zoned example with every layer to PNG (1200 x 900).
void BM_PlotExample(benchmark::State& state) {
  edem::Model model = zoned_example();
  edem::PlotDef def;
  def.file = (std::filesystem::temp_directory_path() / "edem_bench_plot.png").string();
  def.show = {"regions", "zones", "blocks", "joints"};
  for (auto _ : state) edem::plot(model, def);
  state.counters["zones"] = model.info().zones;
  std::filesystem::remove(def.file);
}
BENCHMARK(BM_PlotExample)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
