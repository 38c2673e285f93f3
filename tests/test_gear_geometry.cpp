// Involute spur pair geometry and kinematics: identities and closed forms.
#include "gear/gear_mesh.hpp"
#include "gear/involute.hpp"
#include "reference_solutions.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace geartrib;
using namespace geartrib::gear;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

GearPairSpec seed_spec() { return test::seed_case().gear_pair; }
}  // namespace

TEST(Involute, InverseRoundTrip) {
  for (double a : {1e-6, 0.005, 0.0999, 0.1001, 20 * kDeg, 0.6, 1.2, 1.5})
    EXPECT_NEAR(inverse_involute(involute(a)) / a, 1.0, 1e-12) << a;
  // Series and tan(a) - a agree where they meet (0.1 rad): continuity of the switch, to the
  // cancellation error of tan(a) - a there (3 eps/a^2 ~ 7e-14).
  EXPECT_NEAR(involute(0.1 - 1e-16) / (std::tan(0.1) - 0.1), 1.0, 1e-12);
  EXPECT_NEAR(involute(20 * kDeg), 0.014904383867336446, 1e-15);  // inv 20 deg, tabulated 0.0149044
}

TEST(SpurPair, SeedPairClosedForms) {
  const SpurPair p(seed_spec());
  const double m = 6e-3, alpha = 20 * kDeg;
  EXPECT_NEAR(p.center_distance(), 0.180, 1e-15);  // standard, no shift
  EXPECT_NEAR(p.operating_pressure_angle(), alpha, 1e-12);
  EXPECT_NEAR(p.pinion().base_radius, 0.090 * std::cos(alpha), 1e-15);
  EXPECT_NEAR(p.pinion().tip_radius, 0.096, 1e-15);
  EXPECT_NEAR(p.pinion().root_radius, 0.0825, 1e-15);
  // Contact ratio in closed form (ISO 21771): [sqrt(ra1^2 - rb1^2) + sqrt(ra2^2 - rb2^2) - a_w sin a_w] / (pi m cos a).
  const double rb = 0.090 * std::cos(alpha);
  const double eps = (2.0 * std::sqrt(0.096 * 0.096 - rb * rb) - 0.180 * std::sin(alpha)) / (kPi * m * std::cos(alpha));
  EXPECT_NEAR(p.path().contact_ratio, eps, 1e-12);
  EXPECT_NEAR(p.path().contact_ratio, 1.6535, 5e-5);                     // 30/30 standard pair, 4 decimals
  EXPECT_NEAR(p.path().b - p.path().a, p.path().e - p.path().d, 1e-15);  // both equal g_alpha - p_b
}

TEST(SpurPair, IdentitiesAlongThePath) {
  const SpurPair p(seed_spec());
  const double omega = 104.72;
  for (double t = 0.0; t <= 1.0; t += 0.05) {
    const double s = p.path().a + t * p.path().length;
    const FlankGeometry f = p.flank(s);
    // rho1 + rho2 = a_w sin(alpha_w) everywhere.
    EXPECT_NEAR(f.radius_pinion + f.radius_wheel, p.center_distance() * std::sin(p.operating_pressure_angle()), 1e-15);
    const FlankKinematics k = p.kinematics(s, omega);
    EXPECT_NEAR(k.sliding, k.rolling_pinion - k.rolling_wheel, 1e-15);
    EXPECT_NEAR(k.slide_to_roll, k.sliding / (0.5 * (k.rolling_pinion + k.rolling_wheel)), 1e-15);
  }
  // Sliding vanishes at the pitch point, where gamma = 0; the 1:1 pair mirrors about C.
  const FlankKinematics kc = p.kinematics(p.path().c, omega);
  EXPECT_NEAR(kc.sliding, 0.0, 1e-12);
  EXPECT_NEAR(p.flank(p.path().c).roll_parameter, 0.0, 1e-15);
  const FlankKinematics ka = p.kinematics(p.path().a, omega), ke = p.kinematics(p.path().e, omega);
  EXPECT_NEAR(ka.sliding, -ke.sliding, 1e-12);
  EXPECT_NEAR(ka.specific_sliding_pinion, ke.specific_sliding_wheel, 1e-12);
  EXPECT_NEAR(p.path().c - p.path().a, p.path().e - p.path().c, 1e-15);
}

TEST(SpurPair, ShiftedPairOperatingAngle) {
  // FZG type C (z 16/24, m 4.5, x 0.1817/0.1715, a 91.5 mm; see validation/fzg-type-c):
  // zero-backlash inv(alpha_w) = inv(alpha) + 2 tan(alpha)(x1 + x2)/(z1 + z2).
  GearPairSpec s = seed_spec();
  s.module = 4.5e-3;
  s.teeth[0] = 16;
  s.teeth[1] = 24;
  s.profile_shift[0] = 0.1817;
  s.profile_shift[1] = 0.1715;
  const SpurPair zero_backlash(s);
  const double inv_w = involute(20 * kDeg) + 2.0 * std::tan(20 * kDeg) * 0.3532 / 40.0;
  EXPECT_NEAR(involute(zero_backlash.operating_pressure_angle()), inv_w, 1e-15);
  EXPECT_NEAR(zero_backlash.center_distance(), 0.0915, 1e-6);  // a = 91.5 mm to the shifts' 4 decimals
  s.center_distance = 0.0916;                                  // with backlash: cos(alpha_w) = a cos(alpha)/a_w
  const SpurPair given(s);
  EXPECT_NEAR(std::cos(given.operating_pressure_angle()), 0.090 * std::cos(20 * kDeg) / 0.0916, 1e-15);
  s.center_distance = 0.0914;
  EXPECT_THROW(SpurPair{s}, GeometryError);  // below zero backlash: teeth would jam
}

TEST(SpurPair, ImpossibleGeometriesNameTheKey) {
  auto expect_key = [](GearPairSpec s, const std::string& key) {
    try {
      SpurPair p(s);
      ADD_FAILURE() << "no error for " << key;
    } catch (const GeometryError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  };
  GearPairSpec s = seed_spec();
  s.bore_diameter[0] = s.bore_diameter[1] = 0.0;
  const GearPairSpec base = s;
  s.tip_shortening = 0.6;  // short teeth: eps_alpha < 1
  expect_key(s, "gear_pair.addendum_coefficient");
  s = base;
  s.teeth[0] = 8;  // small pinion, standard addendum on a big wheel: wheel tip below the pinion's involute
  s.teeth[1] = 80;
  expect_key(s, "wheel.teeth");
  s = base;
  s.profile_shift[0] = 1.8;  // pointed pinion teeth: tip half-angle 0.1109 - inv(37.6 deg) < 0
  expect_key(s, "gear_pair.addendum_coefficient");
  s = base;
  s.center_distance = 0.150;
  expect_key(s, "gear_pair.center_distance");
}

TEST(SpurPair, UndercutIsAWarning) {
  GearPairSpec s = seed_spec();
  s.teeth[0] = 14;  // z < 2 (h_fP - rho_fP (1 - sin a))/sin^2 a = 14.9: undercut by the rack
  s.teeth[1] = 14;
  s.tip_shortening = 0.1;
  try {
    const SpurPair p(s);
    ASSERT_FALSE(p.warnings().empty());
    EXPECT_EQ(p.warnings().front().key, "pinion.teeth");
  } catch (const GeometryError& e) {
    FAIL() << e.what();
  }
}

TEST(MeshAnalysis, HertzLineContactClosedForm) {
  const GearMesh mesh = case_mesh(test::seed_case());
  const double w = 1.5e5, s = mesh.pair().path().c;
  const PairLoad l = mesh.analysis().pair_load(s, w);
  const double r = mesh.pair().flank(s).radius_equivalent, e = mesh.composite_modulus();
  // Johnson's closed form with E* = E_t.
  EXPECT_NEAR(l.hertz_peak / reference::hertz_line_peak(w, r, e), 1.0, 1e-14);
  EXPECT_NEAR(l.hertz_half_width / reference::hertz_line_half_width(w, r, e), 1.0, 1e-14);
  // The seed pair's normal force F_bn = T1 / r_b1 = 1000 N m / 84.57 mm.
  EXPECT_NEAR(mesh.normal_force(), 1000.0 / (0.090 * std::cos(20 * kDeg)), 1e-9);
}
