// The tooth root's critical section (gear/tooth_root.hpp): found on the generated fillet, checked
// against ISO 6336-3:2019 method B's closed form (eqs. 8-19: the theta iteration), a different
// derivation of the same section, and against the limits the construction must reach.
#include "config/case_file.hpp"
#include "config/fzg_load_stages.hpp"
#include "gear/involute.hpp"
#include "gear/tooth_root.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace geartrib;
using namespace geartrib::gear;

namespace {
constexpr double kPi = std::numbers::pi;

// ISO 6336-3 method B for an external spur gear cut by a rack without protuberance, at d_en.
struct IsoSection {
  double s_fn, rho_f, h_fe, y_f, y_s;
};
IsoSection iso_closed_form(const GearPairSpec& s, int i, double d_en) {
  const double m = s.module, a = s.pressure_angle, h = s.dedendum_coefficient * m, rho = s.root_radius_coefficient * m;
  const double x = s.profile_shift[i];
  const int z = s.teeth[i];
  const double e = kPi * m / 4.0 - h * std::tan(a) - (1.0 - std::sin(a)) * rho / std::cos(a);  // eq. (8), s_pr = 0
  const double g = rho / m - h / m + x;                                                        // eq. (9)
  const double hh = 2.0 / z * (kPi / 2.0 - e / m) - kPi / 3.0;                                 // eq. (10)
  double theta = kPi / 6.0;
  for (int k = 0; k < 200; ++k) theta = 2.0 * g / z * std::tan(theta) - hh;  // eq. (11), fixed point
  const double s_fn = m * (z * std::sin(kPi / 3.0 - theta) + std::sqrt(3.0) * (g / std::cos(theta) - rho / m));
  const double rho_f = m * (rho / m + 2.0 * g * g / (std::cos(theta) * (z * std::pow(std::cos(theta), 2) - 2.0 * g)));
  const double d = m * z, d_b = d * std::cos(a);
  const double alpha_en = std::acos(d_b / d_en);
  const double gamma_e = (0.5 * kPi + 2.0 * x * std::tan(a)) / z + involute(a) - involute(alpha_en);
  const double alpha_fen = alpha_en - gamma_e;
  const double h_fe = 0.5 * m *
                      ((std::cos(gamma_e) - std::sin(gamma_e) * std::tan(alpha_fen)) * d_en / m -
                       z * std::cos(kPi / 3.0 - theta) - g / std::cos(theta) + rho / m);
  const double y_f = 6.0 * (h_fe / m) * std::cos(alpha_fen) / (std::pow(s_fn / m, 2) * std::cos(a));
  const double l = s_fn / h_fe, q = s_fn / (2.0 * rho_f);
  return {s_fn, rho_f, h_fe, y_f, (1.2 + 0.13 * l) * std::pow(q, 1.0 / (1.21 + 2.3 / l))};
}

GearPairSpec seed_pair() {
  GearPairSpec s;
  s.module = 6e-3;
  s.pressure_angle = 20.0 * kPi / 180.0;
  s.face_width = 80e-3;
  s.teeth[0] = s.teeth[1] = 30;
  return s;
}

void expect_closed_form(const GearPairSpec& spec) {
  const SpurPair pair(spec);
  for (int i = 0; i < 2; ++i) {
    const RootSection r = iso6336_root_section(pair, i);
    const IsoSection iso = iso_closed_form(spec, i, r.load_diameter);
    // The same section by two derivations: 1e-9 is the root finder's and the fixed point's accuracy
    // (both ~1e-15 rad) with room for the curvature's algebra.
    EXPECT_NEAR(r.chord / iso.s_fn, 1.0, 1e-9) << i;
    EXPECT_NEAR(r.fillet_radius / iso.rho_f, 1.0, 1e-9) << i;
    EXPECT_NEAR(r.moment_arm / iso.h_fe, 1.0, 1e-9) << i;
    EXPECT_NEAR(r.form_factor / iso.y_f, 1.0, 1e-9) << i;
    EXPECT_NEAR(r.stress_correction / iso.y_s, 1.0, 1e-9) << i;
    EXPECT_TRUE(r.stress_correction_in_range);
  }
}

}  // namespace

TEST(ToothRoot, SeedPairMatchesIsoClosedForm) { expect_closed_form(seed_pair()); }

TEST(ToothRoot, ShiftedFzgCMatchesIsoClosedForm) { expect_closed_form(io::fzg_c_gear_pair()); }

TEST(ToothRoot, ManyTeethApproachTheRack) {
  // As z grows the trochoid of the rounding's centre straightens and the fillet becomes the rack's
  // rounding: rho_F -> rho_fP with z (rho_F - rho_fP)/m -> 16 G^2 (theta -> pi/3 in eq. (13)),
  // G = rho_fP/m - h_fP/m + x = -0.87 here. The approach is O(1/z): a quarter at four times z.
  auto deviation = [](int z) {
    GearPairSpec s = seed_pair();
    s.teeth[0] = s.teeth[1] = z;
    const SpurPair pair(s);
    const RootSection r = iso6336_root_section(pair, 0);
    const double m = s.module, rho = 0.38 * m, g = 0.38 - 1.25;
    EXPECT_GT(r.fillet_radius, rho);
    return std::abs(z * (r.fillet_radius - rho) / m / (16.0 * g * g) - 1.0);
  };
  const double d250 = deviation(250), d1000 = deviation(1000);
  EXPECT_LT(d1000, 0.05);
  EXPECT_NEAR(d250 / d1000, 4.0, 0.4);  // O(1/z), the O(1/z^2) rest within 10 %
}

TEST(ToothRoot, FzgCPairInCodeIsTheCaseFiles) {
  // The micropitting rating's test gear (io::fzg_c_gear_pair) and gears/fzg-c.toml: one pair.
  const Case c = io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/fzg-c.toml");
  const GearPairSpec a = io::fzg_c_gear_pair(), &b = c.gear_pair;
  EXPECT_DOUBLE_EQ(a.module, b.module);  // the file converts mm once: to the last bits
  EXPECT_DOUBLE_EQ(a.pressure_angle, b.pressure_angle);
  EXPECT_DOUBLE_EQ(a.face_width, b.face_width);
  EXPECT_DOUBLE_EQ(a.center_distance, b.center_distance);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(a.teeth[i], b.teeth[i]);
    EXPECT_DOUBLE_EQ(a.profile_shift[i], b.profile_shift[i]);
    EXPECT_DOUBLE_EQ(a.tip_diameter[i], b.tip_diameter[i]);
    EXPECT_DOUBLE_EQ(a.bore_diameter[i], b.bore_diameter[i]);
  }
}

TEST(ToothRoot, FzgCMaterialInCodeIsTheMaterialFiles) {
  // The micropitting rating's test-gear material (io::fzg_c_test_material) and materials/16MnCr5.toml.
  const Material a = io::fzg_c_test_material();
  const Material b = io::load_material(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "materials/16MnCr5.toml");
  EXPECT_DOUBLE_EQ(a.youngs_modulus, b.youngs_modulus);  // the file converts its units once: to the last bits
  EXPECT_DOUBLE_EQ(a.poisson_ratio, b.poisson_ratio);
  EXPECT_DOUBLE_EQ(a.hardness, b.hardness);
  EXPECT_DOUBLE_EQ(a.yield_strength, b.yield_strength);
  EXPECT_DOUBLE_EQ(a.density, b.density);
  EXPECT_DOUBLE_EQ(a.thermal_conductivity, b.thermal_conductivity);
  EXPECT_DOUBLE_EQ(a.specific_heat, b.specific_heat);
}
