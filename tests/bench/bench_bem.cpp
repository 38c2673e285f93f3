// The plane-strain boundary-element solver on the seed's HLH study (h_m = 2 delta_pc,
// spacing 0.5 um, approach 6 delta_pc at delta_pc = 0.5797 nm) for 2^12 to 2^18 elements:
// time per solve and iterations to a complementarity error of 1e-10, and the error each grid
// costs: per-asperity loads and contact widths against the finest grid (2^18), the smooth
// cylinder's peak pressure and half-width against Hertz.
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
  state.counters["error_load"] = load_error;    // largest per-asperity load error vs 2^18
  state.counters["error_width"] = width_error;  // largest contact-width error vs 2^18
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
  state.counters["error_peak"] = std::abs(peak / p0 - 1.0);             // against Hertz p0 = 2w/(pi b)
  state.counters["error_half_width"] = std::abs(half_width / b - 1.0);  // outermost loaded element's edge
}
BENCHMARK(hertz_line_contact)
    ->RangeMultiplier(4)
    ->Range(1 << 12, 1 << 18)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
