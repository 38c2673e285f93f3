// Measured topography: the cost of a surface's statistics and how the resampling knob (--resample,
// [*.flank.topography] resample) trades it against accuracy. A 1024 x 1024 self-affine surface at
// 0.25 um (Rq 1 um, roll-off 20 um, shortest wavelength 2 um) is resampled at 1, 2, 4 and 8 times
// its spacing; counters give each statistic's relative error against the full-resolution grid.
#include "surface/height_grid.hpp"
#include "surface/surface_statistics.hpp"
#include "surface/synthetic_surface.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace geartrib::surface;

namespace {
const HeightGrid& reference_surface() {
  static const HeightGrid g = [] {
    SelfAffineSpec s;
    s.nx = s.ny = 1024;
    s.spacing = 0.25e-6;
    s.rq = 1e-6;
    s.rolloff_wavelength = 20e-6;
    s.cutoff_wavelength = 2e-6;
    s.seed = 4;
    return self_affine_surface(s);
  }();
  return g;
}
}  // namespace

static void surface_statistics_resampled(benchmark::State& state) {
  const HeightGrid& g = reference_surface();
  const SurfaceStatistics ref = surface_statistics(g);
  const double factor = static_cast<double>(state.range(0));
  SurfaceStatistics s;
  for (auto _ : state) {
    const HeightGrid r = factor == 1.0 ? g : resample(g, factor * g.dx);
    s = surface_statistics(r);
    benchmark::DoNotOptimize(s);
  }
  auto rel = [](double a, double b) { return std::abs(a / b - 1.0); };
  state.counters["spacing_um"] = factor * g.dx * 1e6;
  state.counters["err_rq"] = rel(s.rq, ref.rq);
  state.counters["err_m2"] = rel(s.m2_across, ref.m2_across);
  state.counters["err_m4"] = rel(s.m4_across, ref.m4_across);
  state.counters["err_summit_density"] = rel(s.summit_density, ref.summit_density);
  state.counters["err_summit_radius"] = rel(s.summit_radius, ref.summit_radius);
}
BENCHMARK(surface_statistics_resampled)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

static void self_affine_generation(benchmark::State& state) {
  SelfAffineSpec s;
  s.nx = s.ny = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(self_affine_surface(s).z.data());
  state.counters["points"] = static_cast<double>(s.nx) * s.ny;
}
BENCHMARK(self_affine_generation)->RangeMultiplier(4)->Range(256, 4096)->Unit(benchmark::kMillisecond);
