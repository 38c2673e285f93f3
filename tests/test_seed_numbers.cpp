// The seed's derived numbers (sections 1, 2, 2.1, 5), checked in ERRATA.md. Tolerances are
// half a unit of the last digit the seed/ERRATA print.
#include "asperity/critical.hpp"
#include "asperity/cylinder.hpp"
#include "asperity/side_contact.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace geartrib;
using namespace geartrib::asperity;

TEST(SeedNumbers, EquivalentAsperity) {
  const ContactPair p = test::seed_pair();
  EXPECT_NEAR(p.modulus, 113.19e9, 0.005e9);     // E_t 113.19 GPa
  EXPECT_NEAR(p.radius, 0.8493e-6, 0.00005e-6);  // R 0.8493 um
  EXPECT_NEAR(ceb_pressure_factor(p.poisson_ratio), 0.577, 0.0005);
  EXPECT_NEAR(p.hardness, 1.1704e9, 0.00005e9);  // H 1.1704 GPa
}

TEST(SeedNumbers, CriticalValues) {
  const ContactPair p = test::seed_pair();
  const Critical c = hertz_critical(p, ceb_pressure_factor(p.poisson_ratio) * p.hardness);
  EXPECT_NEAR(c.interference, 0.0746e-9, 0.00005e-9);                              // delta_c 0.0746 nm
  EXPECT_NEAR(c.load, 0.0896e-6, 0.00005e-6);                                      // F_c 0.0896 uN
  EXPECT_NEAR(hertz_contact_radius(c.interference, p.radius), 7.96e-9, 0.005e-9);  // a_c 7.96 nm
  // Identity: the Hertz peak pressure at delta_c is k H (ERRATA: 0.675 GPa).
  const double a = hertz_contact_radius(c.interference, p.radius);
  EXPECT_NEAR(hertz_peak_pressure(a, p.radius, p.modulus), ceb_pressure_factor(0.3) * p.hardness, 1e-6);
  EXPECT_NEAR(c.peak_pressure, 0.675e9, 0.0005e9);
}

TEST(SeedNumbers, YieldDepth) {
  EXPECT_NEAR(hertz_yield_point(0.3).depth_over_radius, 0.48, 0.005);  // y1 = 0.48 r_a
}

TEST(SeedNumbers, SideContact) {
  const Case& c = test::seed_case();
  const ContactPair p = test::seed_pair();
  const auto g =
      side_contact_geometry(c.pinion.flank.roughness.summit_radius, c.wheel.flank.roughness.summit_radius, 0.1);
  EXPECT_NEAR(g.theta * 180.0 / std::numbers::pi, 5.71, 0.005);  // seed: theta = atan(0.1) = 5.71 deg
  // R0 = R/cos^3(theta) = 0.8620 um and delta_cn = (pi k H/(2 E_t))^2 R0 = 0.07572 nm: derived
  // here (the seed prints no value); checked by hand from R and theta.
  EXPECT_NEAR(g.radius_0 / (p.radius / std::pow(std::cos(std::atan(0.1)), 3)), 1.0, 1e-14);
  EXPECT_NEAR(g.radius_0, 0.8620e-6, 0.00005e-6);
  EXPECT_NEAR(hertz_critical(with_radius(p, g.radius_0), 0.577 * p.hardness).interference, 0.07572e-9, 0.000005e-9);
  // The measured d0, y0 (0.68, 0.068 um) describe touching paraboloids, y0 = d0^2/(2(R1+R2)),
  // whose normal is tilted by atan(0.2) = 11.31 deg (ERRATA departure).
  const double r12 = c.pinion.flank.roughness.summit_radius + c.wheel.flank.roughness.summit_radius;
  EXPECT_NEAR(c.asperity.measured_axis_offset * c.asperity.measured_axis_offset / (2.0 * r12),
              c.asperity.measured_tip_gap, 1e-12);
  EXPECT_NEAR(normal_tilt_from_offset(1.65e-6, 1.75e-6, 0.68e-6) * 180.0 / std::numbers::pi, 11.31, 0.005);
}

TEST(SeedNumbers, CylinderCriticalInterference) {
  const CylinderAsperity cyl = cylinder_asperity(test::seed_case());
  // ERRATA: the printed formula gives 0.423 um (the seed prints 0.38 um).
  EXPECT_NEAR(seed_critical_interference(cyl), 0.423e-6, 0.0005e-6);
}
