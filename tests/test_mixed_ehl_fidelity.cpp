// The mixed-EHL fidelity of the main job (contact/mixed_ehl/mesh_mixed_ehl.hpp): the flanks'
// heights in the rolling frame, a smooth window's steadiness, the case's keys and refusals (a dry
// case, bad values, a grid coarser than the profiles, a position that does not converge), and a
// small run on the seed's pair: finite series, load balance at every position, the thick-film
// limit, the statistical lubricated cycle beside it and the profiles through the contact kept.
#include "contact/mixed_ehl/mesh_mixed_ehl.hpp"

#include "config/case_records.hpp"
#include "config/input_error.hpp"
#include "contact/mesh_contact.hpp"
#include "flank_tracks.hpp"
#include "reference_solutions.hpp"
#include "runs/mesh_cycle.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace geartrib;
using namespace geartrib::contact;
using namespace geartrib::contact::mixed_ehl;

namespace {

// Two 45-steel bodies (E = 206 GPa, nu = 0.3): E* = 113.19 GPa, plane strain.
constexpr double kEstar = 113.19e9;
constexpr double kSigmaP = 0.02, kSigmaW = 0.03;  // the contact points' arcs [m]

using test::flat;

const std::filesystem::path& mixed_case() {
  static const std::filesystem::path p = test::source_dir() / "gears/m6z30-mixed-ehl.toml";
  return p;
}
Case load(const std::vector<io::CaseChange>& changes) { return io::prepare_case(io::load_case(mixed_case(), changes)); }

// The key an input error names, or "" when `f` throws none.
std::string refused_key(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.key();
  }
  return "";
}

const std::vector<double>& values(const MeshContactResult& r, const std::string& name) {
  const Series* s = r.find(name);
  if (!s) throw std::logic_error("no series " + name);
  return s->values;
}

// A small thick-film run: both flanks ground at Rq 10 nm (lambda ~ 40 on the film), their
// profiles and the grid at 2 um (440 nodes at the largest contact), three positions, one contact
// width's window.
const std::vector<io::CaseChange> kThickFilm = {{"pinion.flank.profile.rq", "0.01 um"},
                                                {"wheel.flank.profile.rq", "0.01 um"},
                                                {"pinion.flank.profile.spacing", "2 um"},
                                                {"wheel.flank.profile.spacing", "2 um"},
                                                {"mixed_ehl.grid_spacing", "2 um"},
                                                {"mixed_ehl.window", "1"},
                                                {"contact.positions", "3"}};

}  // namespace

TEST(MixedEhlHeights, EachFlankMovesThroughTheContactAtItsOwnSpeed) {
  // A tent bump (height A, half-width L) at arc c on a flat flank: the node's cell mean of the
  // tent, in closed form, at the node where the rolling frame puts it. The pinion's point at x is
  // sigma1c + u1 t - x: the bump at sigma1c + c1 shows at x = u1 t - c1; the wheel's point at x is
  // sigma2c - u2 t + x: the bump at sigma2c + c2 shows at x = c2 + u2 t. Both move in +x, each at
  // its surface's speed. Within 1e-15 m: the arcs (~3 cm) round at 3.5e-18 m on slopes of 0.1.
  const double a = 1e-6, half = 10e-6, c1 = 20e-6, c2 = -15e-6, u1 = 2.0, u2 = 5.0;
  const double h = 0.5e-6, lead = 300e-6;
  const std::size_t points = 1201;
  const HalfPlaneGrid grid{-100e-6, 1e-6, 200};
  const test::Tent tent{a, half};
  const FlankTrack pinion = tent.track(kSigmaP - lead, h, points, lead + c1);
  const FlankTrack wheel = tent.track(kSigmaW - lead, h, points, lead + c2);
  const FlankTrack flat_p = flat(kSigmaP - lead, h, points), flat_w = flat(kSigmaW - lead, h, points);
  const double e = grid.spacing;
  for (double t : {0.0, 4e-6, 1e-5}) {
    std::vector<double> hp, hw;
    rolled_heights(pinion, flat_w, grid, kSigmaP + u1 * t, kSigmaW - u2 * t, hp);
    rolled_heights(flat_p, wheel, grid, kSigmaP + u1 * t, kSigmaW - u2 * t, hw);
    int peak_p = 0, peak_w = 0;
    for (int j = 0; j < grid.size; ++j) {
      const auto k = static_cast<std::size_t>(j);
      const double x = grid.x(j);
      // The pinion's own coordinate u = sigma - start = lead + u1 t - x; the wheel's lead - u2 t + x.
      const double up = lead + u1 * t - x, uw = lead - u2 * t + x;
      EXPECT_NEAR(hp[k], tent.mean(up, e, lead + c1), 1e-15);
      EXPECT_NEAR(hw[k], tent.mean(uw, e, lead + c2), 1e-15);
      if (hp[k] > hp[static_cast<std::size_t>(peak_p)]) peak_p = j;
      if (hw[k] > hw[static_cast<std::size_t>(peak_w)]) peak_w = j;
    }
    EXPECT_NEAR(grid.x(peak_p), u1 * t - c1, 0.5 * e + 1e-12) << t;
    EXPECT_NEAR(grid.x(peak_w), c2 + u2 * t, 0.5 * e + 1e-12) << t;
  }
}

TEST(MixedEhlWindow, SmoothFlanksStaySteadyThroughTheWindow) {
  // Flat flanks: every instant of the window is the steady problem again, so the time means equal
  // the extremes (to 1e-6: each instant converges to 1e-8 of p_H, and the squeeze term sees only
  // the film's Newton residue) and the load is carried at every step. No asperity touches; the
  // sliding's heat gives the same flash temperature at every instant. Started from the steady
  // contact (lead_in 0) or after a lead-in (its 4 b/u in steps of the window's), the same window.
  WindowSetup w;
  w.fluid.viscosity = 0.05;
  w.fluid.pressure_viscosity = 2e-8;
  w.composite_modulus = kEstar;
  w.solver.nodes = 300;
  w.solver.tolerance = 1e-8;
  w.instant = {1e5, 0.0137, 2.0, 4.0};
  w.sigma_pinion = kSigmaP, w.sigma_wheel = kSigmaW;
  w.window = 1.0, w.time_step = 2.0;
  w.thermal_coefficient[0] = w.thermal_coefficient[1] = 1.2e4;
  w.subsurface = true;
  w.keep_profile = true;
  const FlankTrack pinion = flat(kSigmaP - 2e-3, 1e-6, 4001), wheel = flat(kSigmaW - 2e-3, 1e-6, 4001);
  w.lead_in = 0.0;
  const WindowResult steady = solve_window(pinion, wheel, w);
  EXPECT_EQ(steady.lead_in_steps, 0);
  w.lead_in = 4.0;
  const WindowResult r = solve_window(pinion, wheel, w);
  const double b = reference::hertz_line_half_width(w.instant.line_load, w.instant.radius, kEstar);
  EXPECT_EQ(r.lead_in_steps, static_cast<int>(std::ceil(4.0 * b / (3.0 * r.dt))));  // u = 3 m/s
  EXPECT_NEAR(steady.central_film_mean, r.central_film_mean, 1e-6 * r.central_film_mean);
  EXPECT_NEAR(steady.min_film_mean, r.min_film_mean, 1e-6 * r.min_film_mean);
  EXPECT_NEAR(steady.flash_mean, r.flash_mean, 1e-6 * r.flash_mean);
  EXPECT_NEAR(r.half_width, b, 1e-12 * b);
  EXPECT_NEAR(r.duration, 2.0 * b / 2.0, 1e-12 * r.duration);  // one contact width at the slower speed
  EXPECT_GE(r.steps, static_cast<int>(r.duration * 4.0 / (2.0 * r.spacing)));
  EXPECT_LT(r.load_error_max, 1e-7);
  EXPECT_NEAR(r.min_film_mean, r.min_film_min, 1e-6 * r.min_film_min);
  EXPECT_NEAR(r.central_film_mean, r.central_film_min, 1e-6 * r.central_film_min);
  EXPECT_NEAR(r.peak_pressure_mean, r.peak_pressure_max, 1e-6 * r.peak_pressure_max);
  EXPECT_NEAR(r.flash_mean, r.flash_max, 1e-6 * r.flash_max);
  EXPECT_GT(r.flash_max, 0.0);
  EXPECT_EQ(r.asperity_share_max, 0.0);
  EXPECT_EQ(r.real_area_ratio_max, 0.0);
  EXPECT_GT(r.min_film_min, 0.0);
  EXPECT_GT(r.stress.von_mises, 0.0);
  ASSERT_TRUE(r.profile.has_value());
  EXPECT_EQ(r.profile->x.size(), static_cast<std::size_t>(r.nodes));
  EXPECT_EQ(r.profile->peak.pressure.size(), static_cast<std::size_t>(r.nodes));
  EXPECT_EQ(r.profile->middle.film.size(), static_cast<std::size_t>(r.nodes));
}

TEST(MixedEhlCase, KeysParseIntoTheOptions) {
  const Case c = load({{"mixed_ehl.grid_spacing", "0.5 um"},
                       {"mixed_ehl.inlet", "5"},
                       {"mixed_ehl.outlet", "2"},
                       {"mixed_ehl.window", "3"},
                       {"mixed_ehl.time_step", "0.5"},
                       {"mixed_ehl.tolerance", "1e-5"},
                       {"mixed_ehl.viscosity_law", "barus"},
                       {"mixed_ehl.flow", "eyring"},
                       {"mixed_ehl.compressible", "false"},
                       {"mixed_ehl.film_floor", "3 nm"},
                       {"mixed_ehl.boundary_friction", "0.12"},
                       {"mixed_ehl.whole_path", "true"},
                       {"mixed_ehl.lead_in", "6"}});
  const MixedEhlOptions& o = c.contact.mixed_ehl;
  EXPECT_EQ(c.contact.fidelity, ContactFidelity::mixed_ehl);
  EXPECT_DOUBLE_EQ(o.grid_spacing, 0.5e-6);
  EXPECT_DOUBLE_EQ(o.solver.inlet, 5.0);
  EXPECT_DOUBLE_EQ(o.solver.outlet, 2.0);
  EXPECT_DOUBLE_EQ(o.window, 3.0);
  EXPECT_DOUBLE_EQ(o.time_step, 0.5);
  EXPECT_DOUBLE_EQ(o.solver.tolerance, 1e-5);
  EXPECT_EQ(o.viscosity_law, ViscosityLaw::barus);
  EXPECT_EQ(o.flow, FlowModel::eyring);
  EXPECT_FALSE(o.compressible);
  EXPECT_DOUBLE_EQ(o.solver.film_floor, 3e-9);
  EXPECT_DOUBLE_EQ(o.solver.boundary_friction, 0.12);
  EXPECT_TRUE(o.whole_path);
  EXPECT_DOUBLE_EQ(o.lead_in, 6.0);
  // The defaults as the case file states them.
  const MixedEhlOptions& d = load({}).contact.mixed_ehl;
  EXPECT_EQ(d.grid_spacing, 0.0);
  EXPECT_EQ(d.window, 2.0);
  EXPECT_EQ(d.time_step, 1.0);
  EXPECT_EQ(d.lead_in, 4.0);
  EXPECT_EQ(d.viscosity_law, ViscosityLaw::roelands);
  EXPECT_FALSE(d.whole_path);
}

TEST(MixedEhlCase, RefusalsNameTheirKey) {
  // The loader's ranges, which mirror the options' rules (the line solver's: an inlet of at least 1.5 b).
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.window", "0.5"}}); }), "mixed_ehl.window");  // shorter than the contact
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.time_step", "0"}}); }), "mixed_ehl.time_step");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.lead_in", "-1"}}); }), "mixed_ehl.lead_in");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.lead_in", "101"}}); }), "mixed_ehl.lead_in");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.tolerance", "0.5"}}); }), "mixed_ehl.tolerance");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.viscosity_law", "linear"}}); }), "mixed_ehl.viscosity_law");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.flow", "bingham"}}); }), "mixed_ehl.flow");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.inlet", "1.2"}}); }), "mixed_ehl.inlet");
  EXPECT_EQ(refused_key([] { load({{"mixed_ehl.film_floor", "0"}}); }), "mixed_ehl.film_floor");
  // A Case changed in code is refused at the same key as it runs, before any work.
  Case c = load({});
  c.contact.mixed_ehl.window = 0.5;
  EXPECT_EQ(refused_key([&] { runs::run_mesh_cycle(c); }), "mixed_ehl.window");
  c = load({});
  c.contact.mixed_ehl.solver.inlet = 1.2;  // the line solver's own rule, through its field's path
  EXPECT_EQ(refused_key([&] { runs::run_mesh_cycle(c); }), "mixed_ehl.inlet");
  // A grid coarser than the flanks' profiles (1 um) would skip their points.
  const Case coarse = load({{"mixed_ehl.grid_spacing", "2 um"}});
  try {
    runs::run_mesh_cycle(coarse);
    FAIL() << "a grid coarser than the profiles ran";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "mixed_ehl.grid_spacing");
    EXPECT_NE(e.rule().find("coarser than the 1 um spacing"), std::string::npos) << e.what();
  }
}

TEST(MixedEhlCase, ADryCaseIsRefusedAtTheFidelity) {
  // The film between the flanks needs an oil: lubricant = none leaves the case dry.
  try {
    load({{"lubricant.file", "none"}});
    FAIL() << "a dry mixed-EHL case loaded";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "contact.fidelity");
    EXPECT_NE(e.file().find("m6z30-mixed-ehl.toml"), std::string::npos);
    EXPECT_GT(e.line(), 0);
    EXPECT_NE(e.rule().find("the case is dry"), std::string::npos) << e.what();
  }
  // The dry deterministic case asked for it, and a Case made dry in code, the same.
  EXPECT_EQ(refused_key([] {
              io::load_case(test::source_dir() / "gears/m6z30-deterministic.toml", {{"contact.fidelity", "mixed_ehl"}});
            }),
            "contact.fidelity");
  Case c = load({});
  c.lubrication.lubricated = false;
  EXPECT_EQ(refused_key([&] { runs::run_mesh_cycle(c); }), "contact.fidelity");
}

TEST(MixedEhlRun, APositionThatDoesNotConvergeIsNamed) {
  // A tolerance below rounding (1e-17 p_H and of the load) cannot be met: the first position's
  // steady start fails, and the refusal names it (s and point), the key and what to change.
  std::vector<io::CaseChange> changes = kThickFilm;
  changes.push_back({"mixed_ehl.tolerance", "1e-17"});
  changes.push_back({"contact.threads", "1"});
  try {
    runs::run_mesh_cycle(load(changes));
    FAIL() << "no failure";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "mixed_ehl.tolerance");
    EXPECT_NE(e.rule().find("at position 1 of 3 (s = 16.1376 mm, point A"), std::string::npos) << e.what();
    EXPECT_NE(e.rule().find("a looser tolerance (mixed_ehl.tolerance)"), std::string::npos) << e.what();
  }
}

TEST(MixedEhlRun, ThickFilmAlongThePathBesideTheStatisticalCycle) {
  const Case c = load(kThickFilm);
  const MeshContactResult r = runs::run_mesh_cycle(c);  // refuses a non-finite output
  ASSERT_EQ(r.fidelity, "mixed_ehl");
  const std::size_t n = values(r, "s_m").size();
  ASSERT_EQ(n, 3u);
  ASSERT_FALSE(r.mixed_ehl.empty());
  for (const Series& s : r.mixed_ehl) EXPECT_EQ(s.values.size(), n) << s.name;
  const auto& w = values(r, "line_load_N_per_m");
  // Load balance at every instant of every window, the pressures' integral against the line load:
  // to the solver's load criterion (tolerance 1e-6 of the load).
  for (double e : values(r, "ehl_load_error_max")) EXPECT_LT(e, 1e-6);
  ASSERT_TRUE(r.mixed_ehl_summary.has_value());
  EXPECT_LT(r.mixed_ehl_summary->max_load_error, 1e-6);
  // The thick-film limit: lambda ~ 40, no asperity touches, the film carries everything.
  for (const char* name : {"ehl_asperity_share_max", "ehl_contact_fraction_max", "ehl_real_area_ratio_max",
                           "ehl_boundary_friction_mean_N_per_m", "real_area_ratio", "plastic_area_fraction"})
    for (double v : values(r, name)) EXPECT_EQ(v, 0.0) << name;
  EXPECT_EQ(r.regime, "full film");
  // The statistical lubricated cycle beside it, on the same flanks: its film, shares and friction
  // in /lubrication, its contact in /statistical.
  const auto& share = values(r, "asperity_load_share");
  const auto& film = values(r, "film_isothermal_m");
  const auto& h_min = values(r, "ehl_min_film_mean_m");
  const auto& h_c = values(r, "ehl_central_film_mean_m");
  const auto& p_max = values(r, "ehl_peak_pressure_max_Pa");
  const auto& p0 = values(r, "hertz_p0_Pa");
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_LT(share[k], 1e-6) << k;
    EXPECT_GT(h_min[k], 0.0);
    EXPECT_GT(h_c[k], h_min[k]);  // the outlet's constriction
    // Dowson & Higginson's minimum film (isothermal, the statistical cycle's formula) against the
    // solver's: the fit's 2.65 U^0.7 G^0.54 W^-0.13 is within ~10% of numerical solutions over its
    // range, and the grid here (2 um, ~150 nodes across the contact) resolves the outlet's
    // constriction to some 10%: within 25%.
    EXPECT_NEAR(h_min[k] / film[k], 1.0, 0.25) << k;
    // A smooth EHL pressure peaks near Hertz (its Petrusevich spike above it).
    EXPECT_GT(p_max[k], 0.8 * p0[k]) << k;
    EXPECT_LT(p_max[k], 2.0 * p0[k]) << k;
    // Heat from sliding: none at the pitch point (the middle position, pure rolling).
    const double sliding = std::abs(values(r, "sliding_m_per_s")[k]);
    if (sliding > 1e-9) EXPECT_GT(values(r, "ehl_flash_temperature_max_K")[k], 0.0) << k;
    else EXPECT_EQ(values(r, "ehl_flash_temperature_max_K")[k], 0.0) << k;
    EXPECT_GT(w[k], 0.0);
  }
  EXPECT_FALSE(r.statistical.empty());
  EXPECT_NE(r.find("statistical_real_area_ratio"), nullptr);
  EXPECT_NE(r.find("friction_coefficient"), nullptr);
  EXPECT_NE(r.find("flash_temperature_K"), nullptr);
  // The profiles through the contact at the named points' positions (A at 0, E at 2; the middle
  // one stands for B, C and D: the last named).
  ASSERT_EQ(r.ehl_profiles.size(), 3u);
  EXPECT_EQ(r.ehl_profiles.front().point, "A");
  EXPECT_EQ(r.ehl_profiles.back().point, "E");
  for (const EhlProfile& p : r.ehl_profiles) {
    const std::size_t k = static_cast<std::size_t>(p.position);
    ASSERT_EQ(p.peak.pressure.size(), p.x.size());
    double load = 0.0;
    for (double q : p.peak.pressure) load += q * (p.x[1] - p.x[0]);
    EXPECT_NEAR(load, w[k], 1e-6 * w[k]);
    EXPECT_GT(p.middle.time, 0.0);  // the window's middle instant
  }
}
