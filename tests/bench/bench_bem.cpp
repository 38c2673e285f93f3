// The plane-strain boundary-element solver on the seed's HLH study (h_m = 2 delta_pc,
// spacing 0.5 um, approach 6 delta_pc at delta_pc = 0.5797 nm) for 2^12 to 2^18 elements:
// time per solve and iterations to a complementarity error of 1e-10.
#include "contact/multi_asperity.hpp"

#include <benchmark/benchmark.h>

using namespace geartrib::contact;

static void multi_asperity(benchmark::State& state) {
  MultiAsperitySpec s;
  s.layout = "HLH";
  s.height_step = 2.0 * 0.5797e-9;
  s.spacing = 0.5e-6;
  s.approach = 6.0 * 0.5797e-9;
  s.modulus = 206e9 / 0.91;
  s.pressure_cap = 1.1704e9;
  s.elements = static_cast<int>(state.range(0));
  int iterations = 0;
  for (auto _ : state) {
    const MultiAsperityResult r = solve_multi_asperity(s);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.line_load);
  }
  state.counters["iterations"] = iterations;
  state.counters["elements"] = static_cast<double>(s.elements);
}
BENCHMARK(multi_asperity)->RangeMultiplier(4)->Range(1 << 12, 1 << 18)->Unit(benchmark::kMillisecond)->Iterations(1);

static void hertz_line_contact(benchmark::State& state) {
  // Load control without a cap (Polonsky-Keer) on a smooth cylinder.
  const int n = static_cast<int>(state.range(0));
  const double r = 6.6e-6, w = 200.0, e = 206e9 / 0.91;
  const double b = std::sqrt(4.0 * w * r / (3.141592653589793 * e));
  const HalfPlaneGrid grid{-2.0 * b, 4.0 * b / n, n};
  std::vector<double> gap;
  for (int i = 0; i < n; ++i) gap.push_back(grid.x(i) * grid.x(i) / (2.0 * r));
  const HalfPlaneBem bem(grid, e, {});
  int iterations = 0;
  for (auto _ : state) {
    const BemSolution sol = bem.solve_load(gap, w);
    iterations = sol.iterations;
    benchmark::DoNotOptimize(sol.approach);
  }
  state.counters["iterations"] = iterations;
}
BENCHMARK(hertz_line_contact)->RangeMultiplier(4)->Range(1 << 12, 1 << 18)->Unit(benchmark::kMillisecond)->Iterations(1);
