// The explicit solver's speed (issue 3). Results go to tests/bench/RESULTS.md.
//
// B1: elastic square of n x n cells (2 triangles each), bottom fixed, top moving down slowly,
//     2000 cycles: zone-cycles per second for 1 and 2 threads, plain triangles and (third
//     argument 1) the mixed discretisation.
// B3: elastic square under gravity (bottom fixed, roller sides), n_side cells a side, solved
//     to ratio 1e-5 from rest: cycles and seconds, adaptive against local damping.
#include <benchmark/benchmark.h>

#include "solver/run.hpp"
#include "solver_scenes.hpp"

namespace {

using namespace edem;

Mechanics b1_model(const Mesh& mesh, int n, int threads, bool mixed) {
  Mechanics m = scenes::mechanics_for(mesh, scenes::rock());
  m.threads = threads;
  m.settings.mixed = mixed;
  for (int node = 0; node < m.node_count; ++node) {
    const int row = node / (n + 1);
    if (row == 0) m.fix[static_cast<size_t>(node)] = 3;
    if (row == n) {
      m.fix[static_cast<size_t>(node)] = 2;
      m.v[2 * static_cast<size_t>(node) + 1] = -1e-9;  // [m per cycle]: static mode, step 1
    }
  }
  return m;
}

void BM_B1_ElasticSquare(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0)), threads = static_cast<int>(state.range(1));
  const Mesh mesh = scenes::square_mesh(n, 1.0);
  Mechanics m = b1_model(mesh, n, threads, state.range(2) != 0);
  run_solver(m, mesh, 10, 0.0);  // prepare and warm up
  constexpr long kCycles = 2000;
  for (auto _ : state) run_solver(m, mesh, kCycles, 0.0);
  state.counters["zones"] = static_cast<double>(mesh.zone_count());
  state.counters["zone_cycles_per_s"] = benchmark::Counter(
      static_cast<double>(mesh.zone_count()) * kCycles * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_B1_ElasticSquare)
    ->ArgsProduct({{50, 200, 700}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_B3_GravitySquare(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Damping damping = state.range(1) == 0 ? Damping::adaptive : Damping::local;
  const Mesh mesh = scenes::square_mesh(n, 10.0 * n);
  long cycles = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Mechanics m = scenes::mechanics_for(mesh, scenes::rock());
    m.threads = 1;
    m.settings.damping = damping;
    m.gravity = {0.0, -9.81};
    m.gravity_set = true;
    for (int node = 0; node < m.node_count; ++node) {
      const int row = node / (n + 1), column = node % (n + 1);
      if (row == 0) m.fix[static_cast<size_t>(node)] = 3;
      if (column == 0 || column == n) m.fix[static_cast<size_t>(node)] |= 1;
    }
    state.ResumeTiming();
    const SolveResult result = run_solver(m, mesh, 1000000, 1e-5);
    if (!result.converged) state.SkipWithError("did not converge");
    cycles = result.cycles;
  }
  state.counters["cycles"] = static_cast<double>(cycles);
  state.counters["cycles_per_n"] = static_cast<double>(cycles) / n;
}
BENCHMARK(BM_B3_GravitySquare)
    ->ArgsProduct({{20, 40, 80, 160}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
