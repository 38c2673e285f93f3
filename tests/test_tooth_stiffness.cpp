// Potential-energy tooth stiffness: the numerical beam integrals against Tian's (2004)
// closed-form integrands, the Hertzian term, the fillet foundation of bored and solid bodies, and
// the mesh stiffness against ISO 6336-1.
#include "config/case_prepare.hpp"
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
  // use the seed gear with the root on the base circle to isolate the involute part (the
  // foundation is a separate term).
  const SpurPair p(test::seed_case().gear_pair);
  GearBody g = p.pinion();
  g.root_radius = g.base_radius;  // involute part only
  const ToothMaterial steel{206e9, 0.3};
  for (double phi : {0.25, 0.4, 0.55}) {
    const ToothCompliance c = tooth_compliance(g, phi, steel, 0.08, false);
    const TianCompliance t = tian(phi - g.base_half_angle, g.base_half_angle, 206e9, 0.3, 0.08);
    // 30-point Gauss vs 2e4-interval Simpson of a smooth integrand: 1e-8 relative.
    EXPECT_NEAR(c.bending / t.bending, 1.0, 1e-8) << phi;
    EXPECT_NEAR(c.shear / t.shear, 1.0, 1e-8) << phi;
    EXPECT_NEAR(c.axial / t.axial, 1.0, 1e-8) << phi;
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
  const GearMesh mesh = case_mesh(test::seed_case());
  const PairStiffness k = mesh.stiffness().pair(mesh.pair().path().c);
  // Yang & Lin: k_h = pi E b/(4 (1 - nu^2)) for equal materials = pi b E_t/2.
  EXPECT_NEAR(1.0 / k.hertz_compliance, std::numbers::pi * 206e9 * 0.08 / (4.0 * 0.91), 1e-3);
  EXPECT_NEAR(1.0 / k.stiffness, k.pinion.total() + k.wheel.total() + k.hertz_compliance, 1e-24);
}

TEST(ToothStiffness, IsoSingleAndMeshStiffnessByHand) {
  // ISO 6336-1 method B for z = 30/30, x = 0: q' = 0.04723 + 0.15551/30 + 0.25791/30
  // = 0.0610107 mm um/N; c' = 0.8 x 0.975 / q' (C_M, C_B for h_fP = 1.25 m, alpha = 20 deg).
  const GearMesh mesh = case_mesh(test::seed_case());
  const IsoMeshStiffness iso = iso6336_mesh_stiffness(mesh.pair(), 150e3);
  const double q = 0.04723 + 0.15551 / 30 + 0.25791 / 30;
  EXPECT_NEAR(iso.flexibility_q, q * 1e-9, 1e-20);
  EXPECT_NEAR(iso.single, 0.8 * 0.975 / (q * 1e-9), 1e-3);
  EXPECT_NEAR(iso.mesh, iso.single * (0.75 * mesh.pair().path().contact_ratio + 0.25), 1e-3);
  // Below 100 N/mm the ISO value scales with the load's fourth root (ISO 6336-1:2006 9.3; the
  // hand calculation of validation/iso-rating does the same from its own transcription).
  EXPECT_NEAR(iso6336_mesh_stiffness(mesh.pair(), 50e3).single, std::pow(0.5, 0.25) * iso.single, 1e-3);
}

TEST(ToothStiffness, MeanMeshStiffnessWithinThirtyPercentOfIso) {
  // The methods differ (ISO is an empirical fit for typical gears); the issue expects the
  // ratio within 30%.
  const GearMesh mesh = case_mesh(test::seed_case());
  double mean = 0.0;
  const auto cycle = mesh.analysis().cycle(128);
  for (const auto& m : cycle) mean += m.mesh_stiffness / cycle.size();
  const double iso = iso6336_mesh_stiffness(mesh.pair(), 150e3).mesh * mesh.pair().spec().face_width;
  EXPECT_NEAR(mean / iso, 1.0, 0.30);
}

namespace {
// The case with both bores at r_f/h (h = 0: solid bodies).
Case with_rim_ratio(Case c, double h) {
  const SpurPair p(c.gear_pair);
  for (int i = 0; i < 2; ++i) c.gear_pair.bore_diameter[i] = h > 0.0 ? 2.0 * p.gear(i).root_radius / h : 0.0;
  return c;
}
const Case& fzg_c() {
  static const Case c =
      io::prepare_case(io::load_case(test::source_dir() / "validation/fzg-type-c/fzg-c.toml", {}, io::kGeometryPart));
  return c;
}
const Case& z20_z60() {
  static const Case c = io::prepare_case(
      io::load_case(test::source_dir() / "validation/textbook-z20-z60/z20-z60.toml", {}, io::kGeometryPart));
  return c;
}
}  // namespace

// Sainsot et al. fix the body at its bore: the foundation compliance grows with r_f/r_bore over
// the whole fitted range, with no thick-rim plateau a solid body could be the limit of. On the
// seed pinion at the pitch point it grows 2.36 times from h = 3 to 7 (measured; the rule's reason,
// docs/theory/gear-geometry.md).
TEST(ToothStiffness, FoundationComplianceGrowsWithTheRimRatio) {
  const SpurPair p(test::seed_case().gear_pair);
  const ToothMaterial steel{206e9, 0.3};
  const double phi = p.roll_angle(0, p.path().c);
  auto foundation = [&](double h) {
    GearBody g = p.pinion();
    g.bore_radius = g.root_radius / h;
    return tooth_compliance(g, phi, steel, 0.08, true).foundation;
  };
  double previous = 0.0;
  for (double h = 1.4; h <= 7.0; h += 0.2) {
    EXPECT_GT(foundation(h), previous) << h;
    previous = foundation(h);
  }
  // 3.7909e-10 and 8.9467e-10 m/N (the seed's 80 mm face): 2.360; to 4 digits of the printed values.
  EXPECT_NEAR(foundation(7.0) / foundation(3.0), 2.360, 1e-3);
}

// A solid body (bore 0) has the foundation of a shaft seat at a third of its root diameter.
TEST(ToothStiffness, SolidBodyFoundationSitsOnAShaftSeatAtAThirdOfTheRoot) {
  const SpurPair p(test::seed_case().gear_pair);
  const ToothMaterial steel{206e9, 0.3};
  GearBody solid = p.pinion(), seated = p.pinion();
  solid.bore_radius = 0.0;
  seated.bore_radius = seated.root_radius / kSolidBodyRimRatio;
  EXPECT_EQ(foundation_rim_ratio(solid), kSolidBodyRimRatio);
  EXPECT_TRUE(fillet_foundation_in_range(solid));
  for (double s = p.path().a; s <= p.path().e; s += p.path().length / 10.0) {
    const double phi = p.roll_angle(0, s);
    const double f = tooth_compliance(solid, phi, steel, 0.08, true).foundation;
    EXPECT_GT(f, 0.0);
    // r_f/(r_f/3) is 3 to an ulp: the compliances agree to rounding.
    EXPECT_NEAR(f / tooth_compliance(seated, phi, steel, 0.08, true).foundation, 1.0, 1e-12) << s;
  }
}

// The FZG type C pair with its 30 mm bores is unchanged by the solid-body rule: the mean mesh
// stiffness and its ratio to ISO as `geartrib kinematics validation/fzg-type-c/fzg-c.toml
// --summary` printed them before the rule (10 digits).
TEST(ToothStiffness, BoredFzgPairUnchanged) {
  const GearMesh mesh = case_mesh(fzg_c());
  const IsoStiffnessComparison k = mesh.iso_comparison(fzg_c().mesh.positions);
  EXPECT_NEAR(k.model.mean / 214839568.4, 1.0, 1e-9);
  EXPECT_NEAR(k.ratio, 0.9389547336, 1e-9);
  EXPECT_TRUE(iso_stiffness_warning(mesh, k).empty());
}

// Solid bodies of the three shipped pairs lie within the ISO band (before the rule, with no
// foundation, they were 2.32 to 2.49 times ISO's c_gamma_alpha b).
TEST(ToothStiffness, SolidBodiesWithinTheIsoBand) {
  for (const Case* c : {&test::seed_case(), &fzg_c(), &z20_z60()}) {
    const GearMesh mesh = case_mesh(with_rim_ratio(*c, 0.0));
    const IsoStiffnessComparison k = mesh.iso_comparison(c->mesh.positions);
    EXPECT_GT(k.ratio, 1.0 / kIsoStiffnessBand) << c->title;
    EXPECT_LT(k.ratio, kIsoStiffnessBand) << c->title;
    // 0.83 to 0.90 measured: below ISO, as the pairs with their given bores (0.81 to 0.94).
    EXPECT_NEAR(k.ratio, 0.87, 0.05) << c->title;
    EXPECT_TRUE(iso_stiffness_warning(mesh, k).empty()) << c->title;
  }
}

// Bores at the fit's end (r_f/r_bore = 7) halve the stiffness (0.47 of ISO): warned, naming the
// bores' keys and their rim ratio; the band's edges are inclusive.
TEST(ToothStiffness, WarnsBeyondTheIsoBand) {
  const GearMesh mesh = case_mesh(with_rim_ratio(test::seed_case(), 7.0));
  IsoStiffnessComparison k = mesh.iso_comparison(test::seed_case().mesh.positions);
  EXPECT_NEAR(k.ratio, 0.469, 0.005);
  const std::string w = iso_stiffness_warning(mesh, k);
  EXPECT_NE(w.find("0.469 x ISO 6336-1's c_gamma_alpha"), std::string::npos) << w;
  EXPECT_NE(w.find("r_f/r_bore = 7 for pinion.bore_diameter, 7 for wheel.bore_diameter"), std::string::npos) << w;
  for (double edge : {kIsoStiffnessBand, 1.0 / kIsoStiffnessBand}) {
    k.full_load_ratio = edge;
    EXPECT_TRUE(iso_stiffness_warning(mesh, k).empty()) << edge;
    k.full_load_ratio = edge * (edge > 1.0 ? 1.001 : 0.999);
    EXPECT_FALSE(iso_stiffness_warning(mesh, k).empty()) << edge;
  }
}

// Below 100 N/mm ISO scales c' down with the load (real teeth's deviations); the model of perfect
// involutes does not: the band is checked against ISO at full load. At 10 N m (1.4 N/mm) the
// seed pair is (100/1.4)^0.25 = 2.9 times the load-scaled c_gamma_alpha b and unchanged against full load.
TEST(ToothStiffness, IsoBandAtFullLoad) {
  Case light = test::seed_case();
  light.operating.pinion_torque = 10.0;
  const GearMesh heavy_mesh = case_mesh(test::seed_case()), light_mesh = case_mesh(light);
  const IsoStiffnessComparison heavy = heavy_mesh.iso_comparison(64), k = light_mesh.iso_comparison(64);
  EXPECT_GT(heavy_mesh.tangential_line_load(), kIsoFullLineLoad);  // 139 N/mm: ISO unscaled
  EXPECT_EQ(heavy.ratio, heavy.full_load_ratio);
  // The load enters neither the model nor ISO at full load: the same ratio, to rounding.
  EXPECT_NEAR(k.full_load_ratio / heavy.full_load_ratio, 1.0, 1e-12);
  EXPECT_NEAR(k.ratio / k.full_load_ratio, std::pow(kIsoFullLineLoad / light_mesh.tangential_line_load(), 0.25), 1e-9);
  EXPECT_TRUE(iso_stiffness_warning(light_mesh, k).empty());
}
