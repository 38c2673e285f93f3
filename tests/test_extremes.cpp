// Stability at the extremes (CTest label `extremes`): the rough-surface contact from zero load to
// beyond full plasticity, friction 0 to 1, roughness toward zero and very large, tooth numbers 12
// to 200, profile shifts -0.5 to 1, speeds from 1 rpm to three times resonance. Every output
// finite, monotone where physics says so, and an InputError (never a NaN) where the input is
// impossible. The single-asperity models over delta* 1e-9 to 1e6 are in test_model_ranges.cpp,
// also in this label.
#include "asperity/side_contact.hpp"
#include "case/contact_setup.hpp"
#include "config/case_prepare.hpp"
#include "config/input_error.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/rough_line_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"
#include "reference_solutions.hpp"
#include "runs/mesh_cycle.hpp"
#include "solvers/integrators.hpp"
#include "solvers/kinsol_solver.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace geartrib;

namespace {

Case changed(std::vector<io::CaseChange> changes) {
  return io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-dry.toml", changes));
}

// Every value of every series finite.
void expect_finite(const contact::MeshContactResult& r, const std::string& what) {
  for (const auto* group : {&r.mesh, &r.contact})
    for (const auto& q : *group)
      for (double v : q.values) ASSERT_TRUE(std::isfinite(v)) << what << ": " << q.name;
}

double max_of(const contact::MeshContactResult& r, const std::string& name) {
  const auto& v = r.find(name)->values;
  return *std::max_element(v.begin(), v.end());
}

double min_of(const contact::MeshContactResult& r, const std::string& name) {
  const auto& v = r.find(name)->values;
  return *std::min_element(v.begin(), v.end());
}

contact::MeshContactResult cycle(const Case& c, int positions = 21) {
  const gear::GearMesh mesh = gear::case_mesh(c);
  const solvers::KinsolSolver kinsol;
  return runs::run_mesh_contact(c, mesh, c.contact.fidelity == ContactFidelity::coupled ? &kinsol : nullptr, {},
                                positions);
}

// The seed's rough surface and pair with the table sized for `max_pressure`.
struct Strip {
  explicit Strip(const Case& c, double max_pressure)
      : surface(contact::case_equivalent_surface(c)),
        pair(asperity::contact_pair(c)),
        model(asperity::make_case_model(c, c.asperity.model)),
        gw(surface, *model, pair, max_pressure, {}),
        mesh(gear::case_mesh(c)) {}
  surface::EquivalentSurface surface;
  asperity::ContactPair pair;
  std::unique_ptr<asperity::AsperityModel> model;
  contact::GreenwoodWilliamson gw;
  gear::GearMesh mesh;
};

}  // namespace

// Line loads from zero to a Hertz pressure of ten times the hardness (every contact deep in the
// fully plastic range, delta* ~ 1e5): zero load is no contact; the real-area ratio, the contacts
// and the plastic share never decrease with load; everything finite, fractions in [0, 1].
TEST(Extremes, StripFromZeroLoadToTenTimesFullPlasticity) {
  const Case& c = test::seed_case();
  const double hardness = asperity::contact_pair(c).hardness;
  const double radius = 0.02;  // [m], the seed pair's equivalent radius near C
  const double e = gear::case_mesh(c).composite_modulus();
  // Hertz line contact: w for p0 = 10 H.
  const double w_max = reference::hertz_line_load_of_peak(10.0 * hardness, radius, e);
  const Strip s(c, 12.0 * hardness);
  const solvers::KinsolSolver kinsol;
  for (auto fidelity : {contact::StripFidelity::uncoupled, contact::StripFidelity::coupled}) {
    contact::StripOptions o;
    o.fidelity = fidelity;
    o.coupled_nodes = 64;
    const contact::RoughLineContact strip(s.gw, s.mesh.composite_modulus(), c.gear_pair.face_width, o, &kinsol);
    const contact::StripResult zero = strip.solve(0.0, radius);
    EXPECT_EQ(zero.real_area_ratio, 0.0);
    EXPECT_EQ(zero.contacts_per_width, 0.0);
    EXPECT_TRUE(std::isfinite(zero.plastic_area_fraction) && std::isfinite(zero.mean_real_pressure));
    contact::StripResult prev = zero;
    for (double w : test::log_space(1e-6 * w_max, w_max, 25)) {
      const contact::StripResult r = strip.solve(w, radius);
      for (double v : {r.real_area_ratio, r.real_area_per_width, r.contacts_per_width, r.plastic_area_fraction,
                       r.plastic_contact_fraction, r.mean_real_pressure, r.max_nominal_pressure, r.min_separation})
        ASSERT_TRUE(std::isfinite(v)) << "w = " << w;
      // Real area per width and contacts grow with load (the ratio to the growing Hertz width may not).
      EXPECT_GE(r.real_area_per_width, prev.real_area_per_width * (1.0 - 1e-9)) << w;
      EXPECT_GE(r.contacts_per_width, prev.contacts_per_width * (1.0 - 1e-9)) << w;
      EXPECT_GE(r.plastic_area_fraction, 0.0);
      EXPECT_LE(r.plastic_area_fraction, 1.0);
      // The mean real pressure of plastic contacts cannot exceed a few hardnesses (KE: 2.8 S_y ~ H,
      // continuous model's core up to its pressure cap); it must not run away.
      EXPECT_LE(r.mean_real_pressure, 3.0 * hardness) << w;
      const contact::HighestAsperity h = contact::highest_asperity(s.gw, r, c.gear_pair.face_width);
      EXPECT_TRUE(std::isfinite(h.von_mises) && std::isfinite(h.peak_pressure) && std::isfinite(h.interference));
      prev = r;
    }
  }
}

// Friction 0 to 1: the tilted (side-contact) highest asperity finite for every mu, and the whole
// cycle finite at mu = 0 and 1.
TEST(Extremes, FrictionZeroToOne) {
  const Case& c = test::seed_case();
  const Strip s(c, 3e9);
  const contact::RoughLineContact strip(s.gw, s.mesh.composite_modulus(), c.gear_pair.face_width, {}, nullptr);
  const contact::StripResult r = strip.solve(s.mesh.normal_force() / c.gear_pair.face_width, 0.02);
  for (double mu : {0.0, 1e-6, 0.01, 0.1, 0.3, 0.6, 1.0}) {
    const auto g = asperity::side_contact_geometry(c.pinion.flank.roughness.summit_radius,
                                                   c.wheel.flank.roughness.summit_radius, mu);
    const contact::HighestAsperity h = contact::highest_asperity(s.gw, r, c.gear_pair.face_width, &g);
    EXPECT_TRUE(std::isfinite(h.von_mises) && h.von_mises > 0.0) << mu;
    EXPECT_TRUE(std::isfinite(h.peak_pressure) && std::isfinite(h.plastic_fraction)) << mu;
  }
  for (const char* mu : {"0", "1.0"}) {
    const auto res = cycle(changed({{"mu", mu}}));
    expect_finite(res, std::string("mu = ") + mu);
  }
}

// Roughness toward zero: the coupled (Greenwood-Tripp) strip tends to smooth Hertz contact, its
// peak pressure to p0 and its contact width to the Hertz width; very large roughness spreads
// the load (lower peak, wider contact). Finite throughout.
TEST(Extremes, RoughnessTowardZeroTendsToHertzAndVeryLargeSpreadsTheLoad) {
  const solvers::KinsolSolver kinsol;
  double previous_peak_error = 1e300;
  for (const char* rq : {"2um", "0.2um", "0.02um", "0.002um"}) {
    const Case c = changed({{"rq", rq}});
    const Strip s(c, 3e9);
    contact::StripOptions o;
    o.fidelity = contact::StripFidelity::coupled;
    o.coupled_nodes = 256;
    const contact::RoughLineContact strip(s.gw, s.mesh.composite_modulus(), c.gear_pair.face_width, o, &kinsol);
    const double w = s.mesh.normal_force() / c.gear_pair.face_width, radius = 0.02;
    const contact::StripResult r = strip.solve(w, radius);
    const double p0 = reference::hertz_line_peak(w, radius, s.mesh.composite_modulus());
    const double peak_error = std::abs(r.max_nominal_pressure / p0 - 1.0);
    EXPECT_LT(peak_error, previous_peak_error * (1.0 + 1e-6)) << rq << ": peak must approach Hertz as rq falls";
    previous_peak_error = peak_error;
    if (std::string(rq) == "0.002um") {
      // 256 elements over ~1.2 b resolve the Hertz peak to ~1% (the discretisation, not roughness).
      EXPECT_LT(peak_error, 0.02);
      EXPECT_NEAR(r.contact_half_width / r.hertz_half_width, 1.0, 0.05);  // 99.9%-load width, on the element grid
    }
  }
  for (const char* rq : {"20um", "50um"}) {
    const Case c = changed({{"rq", rq}, {"fidelity", "coupled"}, {"coupled_nodes", "128"}});
    const auto r = cycle(c, 11);
    expect_finite(r, std::string("rq = ") + rq);
    EXPECT_LT(max_of(r, "max_nominal_pressure_Pa"), 0.9 * max_of(r, "hertz_p0_Pa")) << rq;
    EXPECT_GT(max_of(r, "contact_halfwidth_m"), max_of(r, "hertz_halfwidth_m")) << rq;
  }
}

// Tooth numbers 12 to 200 on both gears (with a rigid bore: a 60 mm bore does not fit z = 12):
// undercut reported as a warning exactly below the rack's limit 2/sin^2(alpha) = 17.1; a pair
// whose tips cut into the mate's undercut root is an InputError naming the key; every cycle that
// runs is finite, and every z >= 14 runs.
TEST(Extremes, ToothNumbersTwelveToTwoHundred) {
  for (int z : {12, 13, 14, 17, 18, 25, 40, 80, 120, 200}) {
    const std::string teeth = std::to_string(z);
    try {
      const Case c = changed({{"teeth", teeth}, {"pinion.bore_diameter", "0"}, {"wheel.bore_diameter", "0"}});
      bool undercut = false;
      for (const auto& w : c.warnings) undercut = undercut || w.find("undercut") != std::string::npos;
      EXPECT_EQ(undercut, z < 17.1) << "z = " << z;
      expect_finite(cycle(c), "z = " + teeth);
    } catch (const io::InputError& e) {
      EXPECT_LT(z, 14) << e.what();
      EXPECT_NE(std::string(e.what()).find("interference"), std::string::npos) << e.what();
      EXPECT_EQ(e.key(), "wheel.teeth") << e.what();
    }
  }
}

// Profile shift -0.5 to 1 on the pinion: runs give finite outputs; a shift the geometry cannot
// take is an InputError naming the key, never a NaN. Negative shift on z = 30 undercuts (warning).
TEST(Extremes, ProfileShiftMinusHalfToOne) {
  int ran = 0;
  for (double x : {-0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0}) {
    const std::string value = std::to_string(x);
    try {
      const Case c = changed(
          {{"x1", value}, {"x2", std::to_string(-x)}, {"pinion.bore_diameter", "0"}, {"wheel.bore_diameter", "0"}});
      expect_finite(cycle(c), "x1 = " + value);
      ++ran;
    } catch (const io::InputError& e) {
      EXPECT_FALSE(e.key().empty()) << e.what();
      EXPECT_FALSE(e.rule().empty()) << e.what();
    }
  }
  EXPECT_GE(ran, 5);  // x = -0.25 .. 0.75 with x2 = -x are ordinary designs for z = 30/30
}

// Torque from almost nothing to 100 times the seed's: finite, and the largest real-area ratio and
// Hertz pressure grow with torque.
TEST(Extremes, TorqueFromTinyToHundredTimes) {
  double prev_area = -1.0, prev_p0 = -1.0;
  for (const char* torque : {"1e-3 N m", "1 N m", "100 N m", "1000 N m", "10000 N m", "100000 N m"}) {
    const auto r = cycle(changed({{"torque", torque}}));
    expect_finite(r, torque);
    EXPECT_GT(max_of(r, "real_area_ratio"), prev_area) << torque;
    EXPECT_GT(max_of(r, "hertz_p0_Pa"), prev_p0) << torque;
    prev_area = max_of(r, "real_area_ratio");
    prev_p0 = max_of(r, "hertz_p0_Pa");
  }
}

// Speeds from 1 rpm to three times the resonance: the steady cycle finite, the dynamic factor
// positive and tending to the quasi-static response at the lowest speed.
TEST(Extremes, SpeedsFromOneRpmToThreeTimesResonance) {
  const Case& c = test::seed_case();
  const gear::GearMesh mesh = gear::case_mesh(c);
  const gear::MeshDynamics dyn(mesh, gear::dynamics_settings(c));
  const auto integrator = solvers::make_integrator(gear::DynamicsEngine::cvode);
  const double resonance =
      2.0 * std::numbers::pi * dyn.natural_frequency() / mesh.pair().pinion().teeth;  // pinion rad/s
  for (double f : {1.0 / (resonance * 60.0 / (2.0 * std::numbers::pi)), 0.01, 0.3, 0.9, 1.0, 1.1, 2.0, 3.0}) {
    const gear::SteadyCycle s = dyn.steady_cycle(*integrator, f * resonance);
    for (double v : s.force) ASSERT_TRUE(std::isfinite(v)) << f;
    EXPECT_TRUE(std::isfinite(s.dynamic_factor) && s.dynamic_factor > 0.0) << f;
    if (f < 1e-3) {
      EXPECT_NEAR(s.dynamic_factor_quasi_static, 1.0, 0.02) << "1 rpm";  // quasi-static limit
    }
  }
}

// A real area beyond the nominal one is reported, not passed silently: Jackson-Green's area law
// extrapolated to the seed surface's delta* ~ 1e4 gives real-area ratios of 1.8-3.6; the
// continuous model stays below 0.4 and raises no warning.
TEST(Extremes, EveryModelKeepsTheRealAreaBelowNominalOnTheSeed) {
  // Issue 14: on the seed's flanks (psi ~ 120, highest asperities at delta* ~ 1e4) every model
  // past its range switches to (or, continuous and ZMC, reaches) the fully plastic limit, so the
  // real area is load/H < the nominal one (p0 < H here) and the plastic area fraction is near 1;
  // Jackson-Green's area law extrapolated gave real-area ratios up to 3.6 and plastic fractions
  // of 1e-4 before. Hertz (elastic reference) and CEB (plastic pressure k H) are not limited.
  for (const char* model : {"jackson-green", "kogut-etsion", "zmc", "continuous"}) {
    const auto r = cycle(changed({{"model", model}}), 21);
    EXPECT_LE(max_of(r, "real_area_ratio"), 1.0) << model;
    EXPECT_GT(min_of(r, "plastic_area_fraction"), 0.99) << model;
    EXPECT_TRUE(r.warnings.empty()) << model;
    EXPECT_EQ(r.regime, "fully plastic") << model;
  }
}

TEST(Extremes, RealAreaAboveNominalIsWarned) {
  // 100 x the torque: p0 ~ 9 GPa > H, the real area cannot stay below the nominal one.
  const auto r = cycle(changed({{"torque", "100000 N m"}}), 5);
  EXPECT_GT(max_of(r, "real_area_ratio"), 1.0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings.front().find("real-area ratio"), std::string::npos);
}

// The fidelity knobs at their extremes: the coarsest settings the case accepts and very fine
// ones give finite cycles, and the coarsest stay near the defaults (the trade is measured by
// `geartrib tradeoff`; here only that nothing breaks: 5% is far above the 0.02% the knobs cost
// on this fully plastic case).
TEST(Extremes, FidelityKnobsAtTheirLimits) {
  const auto base = cycle(test::seed_case(), 21);
  const auto coarse = cycle(changed({{"height_points", "8"}, {"table_points", "4"}, {"strip_points", "8"}}), 21);
  const auto fine = cycle(changed({{"height_points", "2048"}, {"table_points", "1024"}, {"strip_points", "4096"}}), 21);
  const auto two = cycle(test::seed_case(), 2);  // A and E only
  const auto coupled = cycle(changed({{"fidelity", "coupled"}, {"coupled_nodes", "16"}}), 5);
  for (const auto* r : {&coarse, &fine, &two, &coupled}) expect_finite(*r, "knob limits");
  for (const char* q : {"real_area_ratio", "plastic_area_fraction", "max_asperity_von_mises_Pa"}) {
    EXPECT_NEAR(max_of(coarse, q) / max_of(base, q), 1.0, 0.05) << q;
    EXPECT_NEAR(max_of(fine, q) / max_of(base, q), 1.0, 0.05) << q;
  }
}
