// The plane-strain boundary-element solver on the seed's HLH study (h_m = 2 delta_pc,
// spacing 0.5 um, approach 6 delta_pc at delta_pc = 0.5797 nm) for 2^12 to 2^18 elements:
// time per solve and iterations to a complementarity error of 1e-10, and the error each grid
// costs: per-asperity loads and contact widths against the finest grid (2^18), the smooth
// cylinder's peak pressure and half-width against Hertz. Beside the time, the solve's FFTs:
// their count, one transform's mean time and the product (fft_ms), the solve's own time
// (solve_ms, the rest being loads and stresses) and solve_ms/fft_ms. multi_asperity_solver:
// the solver's options one by one on the same study.
#include "contact/multi_asperity.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

using namespace geartrib::contact;

static MultiAsperitySpec hlh_study(int elements) {
  MultiAsperitySpec s;
  s.layout = "HLH";
  s.height_step = 2.0 * 0.5797e-9;
  s.spacing = 0.5e-6;
  s.approach = 6.0 * 0.5797e-9;
  s.modulus = 206e9 / 0.91;
  s.pressure_cap = 1.1704e9;
  s.elements = elements;
  return s;
}

// The cost counters of a boundary-element solve.
template <class Result>
static void count_cost(benchmark::State& state, const Result& r, double solve_seconds) {
  const double one = r.transforms > 0 ? r.transform_seconds / static_cast<double>(r.transforms) : 0.0;
  state.counters["transforms"] = static_cast<double>(r.transforms);
  state.counters["transform_us"] = one * 1e6;                                               // one FFT's mean time
  state.counters["fft_ms"] = one * static_cast<double>(r.transforms) * 1e3;                 // count x one transform
  state.counters["solve_ms"] = solve_seconds * 1e3;                                         // the whole solve
  state.counters["solve_per_fft"] = solve_seconds / std::max(r.transform_seconds, 1e-300);  // target <= ~2
}

static void multi_asperity(benchmark::State& state) {
  const MultiAsperitySpec s = hlh_study(static_cast<int>(state.range(0)));
  MultiAsperityResult r;
  for (auto _ : state) {
    r = solve_multi_asperity(s);
    benchmark::DoNotOptimize(r.line_load);
  }
  static const MultiAsperityResult reference = solve_multi_asperity(hlh_study(1 << 18));
  double load_error = 0.0, width_error = 0.0;
  for (std::size_t i = 0; i < r.asperities.size(); ++i) {
    const auto& a = r.asperities[i];
    const auto& ref = reference.asperities[i];
    load_error = std::max(load_error, std::abs(a.load / ref.load - 1.0));
    width_error = std::max(width_error, std::abs(a.contact_width / ref.contact_width - 1.0));
  }
  state.counters["iterations"] = r.iterations;
  state.counters["coarse_iterations"] = r.coarse_iterations;
  state.counters["error_load"] = load_error;    // largest per-asperity load error vs 2^18
  state.counters["error_width"] = width_error;  // largest contact-width error vs 2^18
  count_cost(state, r, r.solve_seconds);
}
BENCHMARK(multi_asperity)->RangeMultiplier(4)->Range(1 << 12, 1 << 18)->Unit(benchmark::kMillisecond)->Iterations(1);

static void multi_asperity_solver(benchmark::State& state) {
  // Second argument, the solver's options: 0 none (zero start, plain conjugate gradients),
  // 1 preconditioner only, 2 coarse-grid start only, 3 overlap start only, 4 all (the default).
  MultiAsperitySpec s = hlh_study(static_cast<int>(state.range(0)));
  const int variant = static_cast<int>(state.range(1));
  s.precondition = variant == 1 || variant == 4;
  s.coarse_elements = variant == 2 || variant == 4 ? MultiAsperitySpec{}.coarse_elements : 0;
  s.overlap_start = variant == 3 || variant == 4;
  MultiAsperityResult r;
  for (auto _ : state) {
    r = solve_multi_asperity(s);
    benchmark::DoNotOptimize(r.line_load);
  }
  state.counters["iterations"] = r.iterations;
  state.counters["coarse_iterations"] = r.coarse_iterations;
  count_cost(state, r, r.solve_seconds);
}
BENCHMARK(multi_asperity_solver)
    ->ArgsProduct({{1 << 12, 1 << 14, 1 << 16}, {0, 1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

static void hertz_line_contact(benchmark::State& state) {
  // Load control without a cap (Polonsky-Keer) on a smooth cylinder.
  const int n = static_cast<int>(state.range(0));
  const double r = 6.6e-6, w = 200.0, e = 206e9 / 0.91;
  const double b = std::sqrt(4.0 * w * r / (3.141592653589793 * e));
  const HalfPlaneGrid grid{-2.0 * b, 4.0 * b / n, n};
  std::vector<double> gap;
  for (int i = 0; i < n; ++i) gap.push_back(grid.x(i) * grid.x(i) / (2.0 * r));
  const HalfPlaneBem bem(grid, e, {});
  BemSolution sol;
  for (auto _ : state) {
    sol = bem.solve_load(gap, w);
    benchmark::DoNotOptimize(sol.approach);
  }
  const double p0 = 2.0 * w / (3.141592653589793 * b);
  double peak = 0.0, half_width = 0.0;
  for (int i = 0; i < n; ++i) {
    peak = std::max(peak, sol.pressure[static_cast<std::size_t>(i)]);
    if (sol.pressure[static_cast<std::size_t>(i)] > 0.0)
      half_width = std::max(half_width, std::abs(grid.x(i)) + 0.5 * grid.spacing);
  }
  state.counters["iterations"] = sol.iterations;
  count_cost(state, sol, sol.seconds);
  state.counters["error_peak"] = std::abs(peak / p0 - 1.0);             // against Hertz p0 = 2w/(pi b)
  state.counters["error_half_width"] = std::abs(half_width / b - 1.0);  // outermost loaded element's edge
}
BENCHMARK(hertz_line_contact)
    ->RangeMultiplier(4)
    ->Range(1 << 12, 1 << 18)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
