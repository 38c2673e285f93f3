// Potential-energy tooth stiffness: the numerical beam integrals against Tian's (2004)
// closed-form integrands, the Hertzian term, and the mesh stiffness against ISO 6336-1.
#include "gear/gear_mesh.hpp"
#include "gear/iso6336_stiffness.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace geartrib;
using namespace geartrib::gear;

namespace {
// Tian (2004) integrals of the involute part (plane stress, E), by composite Simpson in alpha
// from -alpha1 to alpha2: independent of the code's beam-section formulation.
struct TianCompliance {
  double bending, shear, axial;
};
TianCompliance tian(double a1, double a2, double e, double nu, double b, int n = 20000) {
  TianCompliance c{0, 0, 0};
  const double h = (a2 + a1) / n;
  for (int i = 0; i <= n; ++i) {
    const double a = -a1 + i * h;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double den = std::sin(a) + (a2 - a) * std::cos(a);
    const double num = 1.0 + std::cos(a1) * ((a2 - a) * std::sin(a) - std::cos(a));
    c.bending += w * h / 3.0 * 3.0 * num * num * (a2 - a) * std::cos(a) / (2.0 * e * b * den * den * den);
    c.shear += w * h / 3.0 * 1.2 * (1.0 + nu) * (a2 - a) * std::cos(a) * std::cos(a1) * std::cos(a1) / (e * b * den);
    c.axial += w * h / 3.0 * (a2 - a) * std::cos(a) * std::sin(a1) * std::sin(a1) / (2.0 * e * b * den);
  }
  return c;
}
}  // namespace

TEST(ToothStiffness, InvolutePartEqualsTianIntegrals) {
  // A gear whose root circle lies above the base circle would hide the constant-section part;
  // use the seed gear with root and bore terms switched off to isolate the involute part.
  const SpurPair p(test::seed_case().gear_pair);
  GearBody g = p.pinion();
  g.root_radius = g.base_radius;  // involute part only
  g.bore_radius = 0.0;            // no foundation term
  const ToothMaterial steel{206e9, 0.3};
  for (double phi : {0.25, 0.4, 0.55}) {
    const ToothCompliance c = tooth_compliance(g, phi, steel, 0.08, false);
    const TianCompliance t = tian(phi - g.base_half_angle, g.base_half_angle, 206e9, 0.3, 0.08);
    // 30-point Gauss vs 2e4-interval Simpson of a smooth integrand: 1e-8 relative.
    EXPECT_NEAR(c.bending / t.bending, 1.0, 1e-8) << phi;
    EXPECT_NEAR(c.shear / t.shear, 1.0, 1e-8) << phi;
    EXPECT_NEAR(c.axial / t.axial, 1.0, 1e-8) << phi;
    EXPECT_EQ(c.foundation, 0.0);
  }
}

TEST(ToothStiffness, ComplianceGrowsTowardTheTip) {
  // Bending compliance rises as the load moves up the tooth (longer lever arm).
  const SpurPair p(test::seed_case().gear_pair);
  const ToothMaterial steel{206e9, 0.3};
  double prev = 0.0;
  for (double s = p.path().a; s <= p.path().e; s += p.path().length / 20.0) {
    const ToothCompliance c = tooth_compliance(p.pinion(), p.roll_angle(0, s), steel, 0.08, true);
    EXPECT_GT(c.bending, prev);
    EXPECT_GT(c.foundation, 0.0);
    prev = c.bending;
  }
}

TEST(ToothStiffness, HertzTermAndPairSeries) {
  const GearMesh mesh(test::seed_case());
  const PairStiffness k = mesh.stiffness().pair(mesh.pair().path().c);
  // Yang & Lin: k_h = pi E b/(4 (1 - nu^2)) for equal materials = pi b E_t/2.
  EXPECT_NEAR(1.0 / k.hertz_compliance, std::numbers::pi * 206e9 * 0.08 / (4.0 * 0.91), 1e-3);
  EXPECT_NEAR(1.0 / k.stiffness, k.pinion.total() + k.wheel.total() + k.hertz_compliance, 1e-24);
}

TEST(ToothStiffness, IsoSingleAndMeshStiffnessByHand) {
  // ISO 6336-1 method B for z = 30/30, x = 0: q' = 0.04723 + 0.15551/30 + 0.25791/30
  // = 0.0610107 mm um/N; c' = 0.8 x 0.975 / q' (C_M, C_B for h_fP = 1.25 m, alpha = 20 deg).
  const GearMesh mesh(test::seed_case());
  const IsoMeshStiffness iso = iso6336_mesh_stiffness(mesh.pair(), 150e3);
  const double q = 0.04723 + 0.15551 / 30 + 0.25791 / 30;
  EXPECT_NEAR(iso.flexibility_q, q * 1e-9, 1e-20);
  EXPECT_NEAR(iso.single, 0.8 * 0.975 / (q * 1e-9), 1e-3);
  EXPECT_NEAR(iso.mesh, iso.single * (0.75 * mesh.pair().path().contact_ratio + 0.25), 1e-3);
  // Below 100 N/mm the ISO value scales with the load.
  EXPECT_NEAR(iso6336_mesh_stiffness(mesh.pair(), 50e3).single, 0.5 * iso.single, 1e-3);
}

TEST(ToothStiffness, MeanMeshStiffnessWithinThirtyPercentOfIso) {
  // The methods differ (ISO is an empirical fit for typical gears); the issue expects the
  // ratio within 30%.
  const GearMesh mesh(test::seed_case());
  double mean = 0.0;
  const auto cycle = mesh.analysis().cycle(128);
  for (const auto& m : cycle) mean += m.mesh_stiffness / cycle.size();
  const double iso = iso6336_mesh_stiffness(mesh.pair(), 150e3).mesh * mesh.pair().spec().face_width;
  EXPECT_NEAR(mean / iso, 1.0, 0.30);
}
