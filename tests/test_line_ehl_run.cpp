// One line contact as `geartrib ehl` runs it (contact/mixed_ehl/line_ehl_run.hpp): the moving
// roughness, the transient's bookkeeping, the dry reference's gap, Moes's groups and the result
// file (output/line_ehl_results.hpp).
#include "contact/mixed_ehl/line_ehl_run.hpp"
#include "core/keyed_error.hpp"
#include "lubrication/ehl_film.hpp"
#include "output/hdf5_handles.hpp"
#include "output/line_ehl_results.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

namespace {
using namespace geartrib::contact::mixed_ehl;
using geartrib::contact::HalfPlaneGrid;
constexpr double kPi = std::numbers::pi;

LineEhlSpec smooth_spec() {
  LineEhlSpec s;
  s.fluid.viscosity = 0.05;
  s.fluid.pressure_viscosity = 2e-8;
  s.modulus = 1.13e11;
  s.instant = {1e6, 0.0154, 5.0, 4.0};
  return s;
}
}  // namespace

// Moes's groups against the reference table's independent computation
// (validation/mixed-ehl/smooth_line_reference.csv, point S2: W = 1.3e-4, U = 1e-11, G = 5000 give
// M = 29.0688837075, L = 10.5737126344), and back: (M, L) at that W give U and G again.
TEST(MoesGroups, AgreeWithTheReferenceTableAndInvert) {
  const geartrib::lubrication::EhlGroups g{1e-11, 5000.0, 1.3e-4};
  const auto m = geartrib::lubrication::moes_groups(g);
  EXPECT_NEAR(m.load, 29.0688837075, 1e-9);
  EXPECT_NEAR(m.material, 10.5737126344, 1e-9);
  const auto back = geartrib::lubrication::groups_from_moes(m, g.load);
  EXPECT_NEAR(back.speed / g.speed, 1.0, 1e-13);
  EXPECT_NEAR(back.material / g.material, 1.0, 1e-13);
  EXPECT_EQ(back.load, g.load);
}

// The waviness enters at the inlet as the surface carries it: nothing ahead of the front
// x_s + u t, A sin(2 pi s/lambda) behind it (s the distance behind the front); in place (steady) a
// crest at x = 0. On both surfaces the heights add, each moving at its own speed.
TEST(LineRoughness, WavinessEntersAtTheInletAndMovesWithItsSurface) {
  const HalfPlaneGrid grid{-1e-3, 1e-6, 1500};
  LineRoughness r;
  r.shape = RoughnessShape::waviness;
  r.amplitude = 0.1e-6;
  r.length = 40e-6;
  const double u1 = 2.0, u2 = 3.0, t = 2e-4;  // the front of surface 1 at -1e-3 + 4e-4 m
  const auto h = roughness_heights(r, grid, t, u1, u2, true);
  for (int i = 0; i < grid.size; ++i) {
    const double s = grid.start + u1 * t - grid.x(i);
    const double expected = s >= 0.0 ? r.amplitude * std::sin(2.0 * kPi * s / r.length) : 0.0;
    EXPECT_NEAR(h[static_cast<std::size_t>(i)], expected, 1e-18) << grid.x(i);
  }
  r.on = RoughSurfaces::both;
  const auto both = roughness_heights(r, grid, t, u1, u2, true);
  r.on = RoughSurfaces::second;
  const auto second = roughness_heights(r, grid, t, u1, u2, true);
  for (std::size_t i = 0; i < h.size(); ++i) EXPECT_NEAR(both[i], h[i] + second[i], 1e-18);
  const auto steady = roughness_heights(r, grid, 0.0, u1, u2, false);
  const int centre = static_cast<int>(std::lround(-grid.start / grid.spacing - 0.5));
  EXPECT_NEAR(steady[static_cast<std::size_t>(centre)], r.amplitude * std::cos(2.0 * kPi * grid.x(centre) / r.length),
              1e-18);
}

// The ridge A cos^2(pi x/w): its top A at its centre, its area A w/2 (the cos^2 mean is 1/2),
// entering with its leading edge at the inlet at t = 0.
TEST(LineRoughness, RidgeHasItsHeightAndAreaAndEntersAtTheInlet) {
  const HalfPlaneGrid grid{-1e-3, 0.1e-6, 20000};
  LineRoughness r;
  r.shape = RoughnessShape::ridge;
  r.amplitude = 0.2e-6;
  r.length = 50e-6;
  const auto start = roughness_heights(r, grid, 0.0, 1.0, 1.0, true);
  for (double v : start) EXPECT_EQ(v, 0.0);
  const double t = 5e-4;  // its top at -1e-3 - 25e-6 + 5e-4 m
  const auto h = roughness_heights(r, grid, t, 1.0, 1.0, true);
  double area = 0.0, top = 0.0, where = 0.0;
  for (int i = 0; i < grid.size; ++i) {
    area += h[static_cast<std::size_t>(i)] * grid.spacing;
    if (h[static_cast<std::size_t>(i)] > top) top = h[static_cast<std::size_t>(i)], where = grid.x(i);
  }
  EXPECT_NEAR(top, r.amplitude, 1e-4 * r.amplitude);
  EXPECT_NEAR(where, grid.start - 0.5 * r.length + t, grid.spacing);
  EXPECT_NEAR(area, 0.5 * r.amplitude * r.length, 1e-6 * r.amplitude * r.length);
}

// Without a roughness the run is the solver's steady solution; a roughness of zero height run
// transiently stays on it (nothing moves: the squeeze term vanishes), every instant recorded.
TEST(LineEhlRun, SmoothRunIsTheSteadySolutionAndAFlatTransientStaysOnIt) {
  LineEhlSpec s = smooth_spec();
  const LineEhlResult steady = run_line_ehl(s);
  LineEhlSolver solver(s.fluid, s.modulus, s.instant, s.options);
  const EhlField& direct =
      solver.solve_steady(s.instant, std::vector<double>(static_cast<std::size_t>(solver.grid().size), 0.0));
  EXPECT_EQ(steady.field.central_film, direct.central_film);
  EXPECT_EQ(steady.field.min_film, direct.min_film);
  EXPECT_TRUE(steady.series.empty());
  s.roughness.shape = RoughnessShape::waviness;
  s.roughness.amplitude = 0.0;
  s.roughness.length = 50e-6;
  s.transient.window = 0.2;
  s.transient.courant = 4.0;
  int calls = 0;
  const LineEhlResult flat = run_line_ehl(s, [&](int, int) { ++calls; });
  ASSERT_GT(flat.series.size(), 2u);
  EXPECT_EQ(calls, static_cast<int>(flat.series.size()) - 1);
  // The window: 0.2 contact widths at the slower surface (1) at dt = 4 dx/u1.
  const double duration = 0.2 * 2.0 * flat.hertz_half_width / s.instant.speed1;
  EXPECT_NEAR(flat.time_step * static_cast<double>(flat.series.size() - 1), duration, 1e-12 * duration);
  EXPECT_LE(flat.time_step, 4.0 * flat.grid.spacing / s.instant.speed1 * (1.0 + 1e-12));
  // Each step converges to the solver's tolerance (1e-7 on its Newton step, or on its scaled
  // residual): the film stays on the steady one within ten times that, relative.
  for (const LineEhlStep& step : flat.series) EXPECT_NEAR(step.central_film / direct.central_film, 1.0, 1e-5);
  EXPECT_NEAR(flat.central_film.mean / direct.central_film, 1.0, 1e-5);
}

// The Petrusevich spike is read off the profile downstream of the centre, above Hertz there; the
// film ruptures behind it.
TEST(LineEhlRun, SpikeAndRuptureAreReadDownstream) {
  LineEhlSpec s = smooth_spec();
  s.instant = {1e5, 0.0154, 5.0, 5.0};
  s.options.nodes = 2048;
  const LineEhlResult r = run_line_ehl(s);
  const double b = r.hertz_half_width;
  ASSERT_TRUE(std::isfinite(r.spike_x));
  EXPECT_GT(r.spike_x / b, 0.3);
  EXPECT_LT(r.spike_x / b, 1.1);
  const double hertz = r.hertz_pressure * std::sqrt(std::max(0.0, 1.0 - std::pow(r.spike_x / b, 2)));
  EXPECT_GT(r.spike_pressure, hertz);
  EXPECT_GT(r.rupture_x, r.spike_x);
}

// The dry reference solves the same gap under the same load: smooth, it is Hertz's contact (the
// boundary elements' load to their tolerance, the peak p_H within 0.5 %: Hertz line contact by
// these elements, tests/test_half_plane_bem.cpp).
TEST(LineEhlRun, DryReferenceOfASmoothGapIsHertz) {
  LineEhlSpec s = smooth_spec();
  s.dry_reference = true;
  const LineEhlResult r = run_line_ehl(s);
  ASSERT_EQ(r.dry_pressure.size(), static_cast<std::size_t>(r.grid.size));
  double load = 0.0, peak = 0.0;
  for (double p : r.dry_pressure) load += p * r.grid.spacing, peak = std::max(peak, p);
  EXPECT_NEAR(load / s.instant.line_load, 1.0, 1e-6);
  EXPECT_NEAR(peak / r.hertz_pressure, 1.0, 0.005);
}

// Refusals name the field: a rough surface standing still has no transient; a window of more
// steps than allowed; a roughness without a length.
TEST(LineEhlRun, RefusalsNameTheirField) {
  LineEhlSpec s = smooth_spec();
  s.roughness.shape = RoughnessShape::ridge;
  s.roughness.amplitude = 0.1e-6;
  s.roughness.length = 20e-6;
  s.roughness.on = RoughSurfaces::second;
  s.instant.speed2 = 0.0;
  try {
    run_line_ehl(s);
    ADD_FAILURE() << "a still rough surface ran transiently";
  } catch (const geartrib::core::KeyedError& e) {
    EXPECT_EQ(e.key(), "window");
  }
  s.instant.speed2 = 4.0;
  s.transient.courant = 1e-6;
  try {
    run_line_ehl(s);
    ADD_FAILURE() << "10^9 steps ran";
  } catch (const geartrib::core::KeyedError& e) {
    EXPECT_EQ(e.key(), "courant");
  }
  s.roughness.length = 0.0;
  try {
    run_line_ehl(s);
    ADD_FAILURE() << "a ridge of no width ran";
  } catch (const geartrib::core::KeyedError& e) {
    EXPECT_EQ(e.key(), "length");
  }
}

// The result file: the profile's columns with their units, the state as text, the summary's rows
// as attributes.
TEST(LineEhlFile, WritesProfileSeriesAndSummary) {
  using geartrib::io::Column;
  geartrib::io::LineEhlFile f;
  Column x;
  x.name = "x_m";
  x.unit = "m";
  x.numbers = {-1.0, 0.0, 1.0};
  Column state;
  state.name = "state";
  state.text = true;
  state.texts = {"fluid", "contact", "cavitated"};
  f.profile.columns = {x, state};
  f.summary.add_row("central_film_m", {1.5e-7});
  f.texts = {{"flow", "newtonian"}};
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "geartrib_line_ehl_test.h5";
  geartrib::io::write_line_ehl_hdf5(path, f);
  using geartrib::io::hdf5::Handle;
  {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "file");
    Handle profile(H5Gopen2(file, "/profile", H5P_DEFAULT), H5Gclose, "/profile");
    EXPECT_EQ(geartrib::io::hdf5::read_strings(profile, "state"), state.texts);
    Handle summary(H5Gopen2(file, "/summary", H5P_DEFAULT), H5Gclose, "/summary");
    double hc = 0.0;
    EXPECT_TRUE(geartrib::io::hdf5::read_number_attribute(summary, "central_film_m", hc));
    EXPECT_EQ(hc, 1.5e-7);
    std::string flow;
    EXPECT_TRUE(geartrib::io::hdf5::read_string_attribute(summary, "flow", flow));
    EXPECT_EQ(flow, "newtonian");
    EXPECT_LT(H5Lexists(file, "/series", H5P_DEFAULT), 1);
  }
  std::filesystem::remove(path);
}
