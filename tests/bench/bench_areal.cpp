// Areal rough contact by FFT boundary elements (contact/areal/areal_bem.hpp): the cost of a periodic
// elastic solve on a self-affine surface at about 20 % contact (the goal: 1024^2 under 5 s
// on one core), the cost of one iteration against its transform pair (goal: within 1.5 times), and
// the open window's and the capped (elastic-plastic) solve's costs beside it.
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "contact/areal/areal_bem.hpp"
#include "runs/mesh_cycle.hpp"
#include "surface/surface_statistics.hpp"
#include "surface/synthetic_surface.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <vector>

using namespace geartrib;
using namespace geartrib::contact::areal;

namespace {
constexpr double kEstar = 115e9;  // [Pa]

// A self-affine surface (H = 0.8, no roll-off, the shortest wavelength L/100: the GFMD reference's
// spectrum, validation/areal-gfmd) of n^2 points, and its spectral rms gradient.
struct Surface {
  ArealGrid grid;
  std::vector<double> h;
  double rms_gradient = 0.0;
};
Surface make_surface(int n, bool periodic) {
  surface::SelfAffineSpec s;
  s.nx = s.ny = n;
  s.spacing = 1e-6;
  s.rq = 1e-6;
  s.hurst = 0.8;
  s.rolloff_wavelength = n * s.spacing;
  s.cutoff_wavelength = std::max(2.0, n / 100.0) * s.spacing;
  s.seed = 5;
  const surface::HeightGrid g = surface::self_affine_surface(s);
  Surface out;
  out.grid.nx = out.grid.ny = n;
  out.grid.dx = out.grid.dy = s.spacing;
  out.grid.periodic_x = out.grid.periodic_y = periodic;
  out.h = g.z;
  out.rms_gradient = surface::spectral_rms_gradient(g);
  return out;
}
}  // namespace

// Args: points a side; 1: periodic, 0: open (zero-padded); 1: capped at H = 0.5 E* g; the tolerance's
// exponent (0: the default); 1: Polonsky & Keer's own iteration (0: preconditioned, the default).
// Counters: the iterations and the transform pairs (the preconditioned iteration's two, plus the
// displacement afresh now and then), a pair's time alone, and the solve's time per iteration over one
// pair (iteration_over_pair) and over the pairs it executed (over_transforms: the cost of all that
// is not a transform).
static void areal_solve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool periodic = state.range(1) != 0, capped = state.range(2) != 0;
  const Surface s = make_surface(n, periodic);
  ArealOptions o;
  o.composite_modulus = kEstar;
  if (capped) o.hardness = 0.5 * kEstar * s.rms_gradient;
  if (state.range(3) > 0) o.tolerance = std::pow(10.0, -static_cast<double>(state.range(3)));
  o.precondition = state.range(4) == 0;
  const double pbar = 0.1 * kEstar * s.rms_gradient;  // ~20 % contact (kappa ~ 2)
  const ElasticKernel kernel(s.grid, kEstar);
  ArealSolution sol;
  long transforms = 0;
  double solve_seconds = 0.0;
  for (auto _ : state) {
    const long before = ElasticKernel::transforms();
    const auto t0 = std::chrono::steady_clock::now();
    sol = solve_contact(kernel, s.h, Control::mean_pressure, pbar, o);
    solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    transforms = ElasticKernel::transforms() - before;
  }
  // The transform pair alone (K p), timed on the same kernel: the median of 11 (a shared machine's
  // other work lengthens some).
  std::vector<double> u(s.grid.size()), pair_times;
  for (int k = 0; k < 11; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    kernel.apply(sol.pressure, u);
    pair_times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(pair_times.begin(), pair_times.begin() + 5, pair_times.end());
  const double pair_seconds = pair_times[5];
  state.counters["contact_fraction"] = sol.contact_fraction;
  state.counters["plastic_fraction"] = sol.plastic_fraction;
  state.counters["iterations"] = sol.iterations;
  state.counters["transform_pairs"] = static_cast<double>(transforms) / 2.0;
  state.counters["pair_ms"] = pair_seconds * 1e3;
  state.counters["iteration_ms"] = sol.iterations > 0 ? solve_seconds / sol.iterations * 1e3 : 0.0;
  state.counters["iteration_over_pair"] = sol.iterations > 0 ? solve_seconds / sol.iterations / pair_seconds : 0.0;
  state.counters["over_transforms"] =
      transforms > 0 ? solve_seconds / (static_cast<double>(transforms) / 2.0 * pair_seconds) : 0.0;
  state.counters["converged"] = sol.converged;
}
BENCHMARK(areal_solve)
    ->Args({256, 1, 0, 0, 0})
    ->Args({512, 1, 0, 0, 0})
    ->Args({1024, 1, 0, 0, 0})
    ->Args({1024, 1, 0, 0, 1})
    ->Args({256, 0, 0, 0, 0})
    ->Args({512, 0, 0, 0, 0})
    ->Args({512, 0, 0, 0, 1})
    ->Args({256, 1, 1, 0, 0})
    ->Args({512, 1, 1, 0, 0})
    ->Args({512, 1, 1, 0, 1})
    ->Args({512, 1, 0, 4, 0})
    ->Args({512, 1, 0, 5, 0})
    ->Args({512, 1, 0, 6, 0})
    ->Args({512, 1, 0, 7, 0})
    ->Args({512, 1, 0, 10, 0})
    ->ArgNames({"n", "periodic", "capped", "tol", "plain"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Building the kernel: the open window's Love influences, the mixed window's Bessel integrals.
static void areal_kernel(benchmark::State& state) {
  ArealGrid g;
  g.nx = g.ny = static_cast<int>(state.range(0));
  g.dx = g.dy = 1e-6;
  g.periodic_x = state.range(1) == 2;
  g.periodic_y = state.range(1) >= 1;
  for (auto _ : state) benchmark::DoNotOptimize(ElasticKernel(g, kEstar).self_influence());
}
BENCHMARK(areal_kernel)
    ->ArgsProduct({{256, 1024}, {0, 1, 2}})
    ->ArgNames({"n", "periodic"})
    ->Unit(benchmark::kMillisecond);

// The areal fidelity's cycle (issue 35: A..E on 256 x 1024 windows in under 30 s): gears/m6z30-areal.toml,
// five positions A -> E, 256 points across the face and 0.5 um elements along the involute (its
// 1600-element strip: 1600 x 256 windows), with the isotropic flanks' maps and the statistical model.
// Argument: the points across the face.
static void cycle_areal(benchmark::State& state) {
  Case c = io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30-areal.toml"));
  c.contact.areal.points = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(runs::run_mesh_cycle(c));
}
BENCHMARK(cycle_areal)->Arg(64)->Arg(256)->ArgName("points")->Unit(benchmark::kMillisecond)->Iterations(1);

// The patch lay (issue 35 item 4): gears/m6z30-measured.toml's 96 um patches made into both flanks'
// maps (their areal spectra, random phases; argument 1: tiled instead) over the 11 mm the strip
// reads, five positions A -> E, 128 points over 64 um across the face, 0.5 um elements: the maps'
// making and the solves.
static void cycle_areal_patch(benchmark::State& state) {
  const bool tiled = state.range(0) != 0;
  const std::vector<io::CaseChange> changes = {{"contact.fidelity", "areal"},
                                               {"areal.lay", "patch"},
                                               {"areal.patch", tiled ? "tiled" : "synthesis"},
                                               {"positions", "5"},
                                               {"areal.points", "128"},
                                               {"areal.window", "64um"},
                                               {"element_size", "0.5um"}};
  const Case c = io::prepare_case(
      io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30-measured.toml", changes));
  for (auto _ : state) benchmark::DoNotOptimize(runs::run_mesh_cycle(c));
}
BENCHMARK(cycle_areal_patch)->Arg(0)->Arg(1)->ArgName("tiled")->Unit(benchmark::kMillisecond)->Iterations(1);
