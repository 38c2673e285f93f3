// Greenwood-Williamson statistics and the rough line contact across the Hertzian strip.
#include "contact/mesh_contact.hpp"
#include "contact/rough_line_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "reference_solutions.hpp"
#include "runs/mesh_cycle.hpp"
#include "solvers/kinsol_solver.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <numbers>

using namespace geartrib;
using namespace geartrib::contact;

namespace {
constexpr double kPi = std::numbers::pi;

surface::EquivalentSurface make_surface(double sigma, double beta, double esb,
                                        surface::HeightDistribution d = surface::HeightDistribution::gaussian) {
  surface::EquivalentSurface s;
  s.summit_sigma = s.surface_sigma = sigma;
  s.summit_radius = beta;
  s.summit_density = esb / (sigma * beta);
  s.distribution = d;
  return s;
}

StripOptions coupled_options() {
  StripOptions opt;
  opt.fidelity = StripFidelity::coupled;
  return opt;
}

// The seed's flanks (continuous model) under a coupled strip at the default nodes. Members are
// built in order: the surface refers to the model, the strip to the surface and the solver.
struct SeedCoupledStrip {
  std::unique_ptr<asperity::AsperityModel> model = asperity::make_asperity_model("continuous");
  GreenwoodWilliamson gw{make_surface(1.418e-6, 0.849e-6, 0.05), *model, test::seed_pair(), 2e9, {}};
  solvers::KinsolSolver kinsol;
  RoughLineContact strip{gw, 113.19e9, 0.08, coupled_options(), &kinsol};
};
}  // namespace

TEST(GreenwoodWilliamson, GaussianIntegralsMatchTables) {
  // With Hertzian asperities: p = eta 4/3 E sqrt(beta) sigma^3/2 F_3/2(h), A_r/A_n = eta pi beta
  // sigma F_1(h), n = eta F_0(h). GW's tabulated F_0(1) = 0.15866, F_1(1) = 0.08332,
  // F_3/2(1) = 0.07567: checked to half their last digit.
  const auto model = asperity::make_asperity_model("hertz");
  const asperity::ContactPair pair = test::seed_pair();
  const auto surf = make_surface(1e-6, 50e-6, 0.04);
  GreenwoodWilliamsonOptions opt;
  opt.height_points = 512;
  const GreenwoodWilliamson gw(surf, *model, pair, 1e6, opt);
  const SurfaceContact c = gw.at_separation(1e-6);  // h = d/sigma = 1
  const double eta = surf.summit_density, s = surf.summit_sigma, beta = surf.summit_radius;
  EXPECT_NEAR(c.contact_density / eta, 0.15866, 5e-6);
  EXPECT_NEAR(c.real_area_ratio / (eta * kPi * beta * s), 0.08332, 5e-6);
  EXPECT_NEAR(c.nominal_pressure / (eta * 4.0 / 3.0 * pair.modulus * std::sqrt(beta) * std::pow(s, 1.5)), 0.07567,
              5e-6);
}

TEST(GreenwoodWilliamson, ExponentialClosedForms) {
  // phi(z) = exp(-z/sigma)/sigma: int_d (z - d)^k phi dz = Gamma(k+1) sigma^k exp(-d/sigma) for d >= 0.
  const auto model = asperity::make_asperity_model("hertz");
  const asperity::ContactPair pair = test::seed_pair();
  const auto surf = make_surface(1e-6, 50e-6, 0.04, surface::HeightDistribution::exponential);
  GreenwoodWilliamsonOptions opt;
  opt.height_points = 512;
  const GreenwoodWilliamson gw(surf, *model, pair, 1e6, opt);
  const double eta = surf.summit_density, s = surf.summit_sigma, beta = surf.summit_radius;
  for (double h : {0.0, 0.5, 2.0, 5.0}) {
    const SurfaceContact c = gw.at_separation(h * s);
    const double e = std::exp(-h);
    // 512-point quadrature of a smooth integrand (u = v^2): 1e-8 relative.
    EXPECT_NEAR(c.contact_density / (eta * e), 1.0, 1e-12) << h;
    EXPECT_NEAR(c.real_area_ratio / (eta * kPi * beta * s * e), 1.0, 1e-8) << h;
    EXPECT_NEAR(c.nominal_pressure /
                    (eta * 4.0 / 3.0 * pair.modulus * std::sqrt(beta) * std::pow(s, 1.5) * std::tgamma(2.5) * e),
                1.0, 1e-8)
        << h;
  }
}

TEST(GreenwoodWilliamson, InversionRobustFromZeroToFullPlasticity) {
  const auto model = asperity::make_asperity_model("continuous");
  const auto surf = make_surface(1.418e-6, 0.849e-6, 0.05);  // the seed's flanks (Ra 0.8 um, eta sigma beta 0.05)
  const GreenwoodWilliamson gw(surf, *model, test::seed_pair(), 5e9, {});
  double prev_d = gw.contact_onset() + 1.0, prev_area = -1.0;
  EXPECT_EQ(gw.separation_for_pressure(0.0), gw.contact_onset());
  for (double p : test::log_space(1e-3, 5e9, 800)) {
    const double d = gw.separation_for_pressure(p);
    ASSERT_TRUE(std::isfinite(d)) << p;
    EXPECT_LT(d, prev_d) << p;                        // monotone
    EXPECT_NEAR(gw.pressure(d) / p, 1.0, 1e-9) << p;  // the inverse of the same interpolant
    const SurfaceContact c = gw.interpolate(d);
    EXPECT_GT(c.real_area_ratio, prev_area) << p;  // real area grows with load
    EXPECT_LE(c.plastic_area_ratio, c.real_area_ratio * (1.0 + 1e-12));
    prev_d = d;
    prev_area = c.real_area_ratio;
  }
  // Beyond the table (here 20 GPa) the inversion falls back to bisection on the quadrature.
  const double d = gw.separation_for_pressure(2e10);
  EXPECT_NEAR(gw.at_separation(d).nominal_pressure / 2e10, 1.0, 1e-6);
}

TEST(GreenwoodWilliamson, PlasticFractionLimits) {
  const auto model = asperity::make_asperity_model("continuous");
  const asperity::ContactPair pair = test::seed_pair();
  // Smooth and blunt: sigma 1 nm, beta 1 mm: plasticity index (E_t/H) sqrt(sigma/beta) = 0.1.
  const GreenwoodWilliamson smooth(make_surface(1e-9, 1e-3, 0.05), *model, pair, 1e9, {});
  const SurfaceContact a = smooth.interpolate(smooth.separation_for_pressure(1e6));
  EXPECT_LT(a.plastic_area_ratio / a.real_area_ratio, 1e-3);
  // Very rough and sharp: sigma 2 um, beta 0.5 um: index 193.
  const GreenwoodWilliamson rough(make_surface(2e-6, 0.5e-6, 0.05), *model, pair, 1e9, {});
  const SurfaceContact b = rough.interpolate(rough.separation_for_pressure(1e6));
  EXPECT_GT(b.plastic_area_ratio / b.real_area_ratio, 0.99);
  EXPECT_GT(b.plastic_contact_density / b.contact_density, 0.99);
}

TEST(RoughLineContact, UncoupledCarriesTheLoad) {
  const auto model = asperity::make_asperity_model("continuous");
  const GreenwoodWilliamson gw(make_surface(1.418e-6, 0.849e-6, 0.05), *model, test::seed_pair(), 2e9, {});
  const RoughLineContact strip(gw, 113.19e9, 0.08, {}, nullptr);
  const StripResult r = strip.solve(1.5e5, 0.0154);
  EXPECT_NEAR(r.line_load / 1.5e5, 1.0, 1e-6);
  EXPECT_NEAR(r.max_nominal_pressure, reference::hertz_line_peak(1.5e5, 0.0154, 113.19e9), 1.0);
  EXPECT_GT(r.real_area_ratio, 0.0);
  EXPECT_LT(r.real_area_ratio, 1.0);
  // The highest asperity: with eta 2b L = 0.05/(sigma beta) x 2b x 80 mm ~ 6.6e5 summits, the
  // Gaussian quantile 1 - 1/N lies at 4.8 sigma above the summit mean.
  const HighestAsperity h = highest_asperity(gw, r, 0.08);
  const double n = gw.surface().summit_density * 2.0 * r.hertz_half_width * 0.08;
  EXPECT_NEAR(
      0.5 *
          std::erfc(gw.highest_summit(2.0 * r.hertz_half_width * 0.08) / (gw.surface().summit_sigma * std::sqrt(2.0))) *
          n,
      1.0, 1e-9);
  EXPECT_NEAR(h.interference, gw.highest_summit(2.0 * r.hertz_half_width * 0.08) - r.min_separation, 1e-18);
  EXPECT_GT(h.peak_pressure, 0.0);
  EXPECT_GT(h.von_mises, 0.0);
}

TEST(RoughLineContact, CoupledCarriesTheLoadAndSpreadsIt) {
  const SeedCoupledStrip seed;
  const StripResult r = seed.strip.solve(1.5e5, 0.0154);
  EXPECT_NEAR(r.line_load / 1.5e5, 1.0, 1e-6);
  const double p0 = reference::hertz_line_peak(1.5e5, 0.0154, 113.19e9);
  EXPECT_LT(r.max_nominal_pressure, p0);                // roughness lowers the peak ...
  EXPECT_GT(r.contact_half_width, r.hertz_half_width);  // ... and widens the contact (Greenwood-Tripp)
}

TEST(RoughLineContact, CoupledTendsToHertzAsRoughnessVanishes) {
  const auto model = asperity::make_asperity_model("continuous");
  const solvers::KinsolSolver kinsol;
  StripOptions opt = coupled_options();
  opt.coupled_nodes = 256;
  const double w = 1.5e5, r = 0.0154, e = 113.19e9;
  const double p0 = reference::hertz_line_peak(w, r, e), b = reference::hertz_line_half_width(w, r, e);
  double prev_error = 1.0;
  for (double sigma : {1e-7, 1e-8, 1e-9}) {
    const GreenwoodWilliamson gw(make_surface(sigma, 50e-6, 0.05), *model, test::seed_pair(), 2e9, {});
    const StripResult s = RoughLineContact(gw, e, 0.08, opt, &kinsol).solve(w, r);
    EXPECT_NEAR(s.line_load / w, 1.0, 1e-6);
    const double error = std::abs(s.max_nominal_pressure / p0 - 1.0);
    EXPECT_LT(error, prev_error) << sigma;  // converging toward Hertz
    prev_error = error;
  }
  // At sigma = 1 nm (sigma R/b^2 = 6e-7): within 2% of p0, the discretisation error of 256
  // elements over the domain at the Hertz peak.
  EXPECT_LT(prev_error, 0.02);
  (void)b;
}

// A path's positions solved in order from the previous one (warm: its separations, its factorised
// Jacobian) give the answers of solves from the Hertz pressure (cold). The loads follow a mesh
// cycle's shape: a rise, a plateau, then a drop by 40% between neighbours (a load-sharing step).
TEST(RoughLineContact, CoupledWarmStartsAgreeWithColdStarts) {
  const SeedCoupledStrip seed;
  const RoughLineContact& strip = seed.strip;
  CoupledStripState state;
  const int positions = 41;
  const double sigma = seed.gw.surface().summit_sigma;
  for (int k = 0; k < positions; ++k) {
    const double s = k / (positions - 1.0);
    const double share = s < 0.3 ? 1.0 / 3.0 + 2.0 / 3.0 * s / 0.3 : (s < 0.7 ? 1.0 : 0.6);
    const double w = 1.5e5 * share, radius = 0.012 + 0.0035 * std::sin(kPi * s);
    const StripResult cold = strip.solve(w, radius);
    const StripResult warm = strip.solve(w, radius, 1.0, &state);
    // Both stop at |F| <= 1e-10, KinsolSolver accepting up to 1e-9: separations (in sigma) and
    // the relative load each within ~1e-9 of the exact discrete solution, from either side. The
    // Jacobian's conditioning magnifies that little here (measured: 6e-11 relative in the
    // integrals, 5e-11 sigma in the separation); 1e-8 is the acceptance times 10.
    for (auto f : {&StripResult::line_load, &StripResult::real_area_per_width, &StripResult::contacts_per_width,
                   &StripResult::plastic_area_fraction, &StripResult::plastic_contact_fraction,
                   &StripResult::mean_real_pressure, &StripResult::max_nominal_pressure})
      EXPECT_NEAR(warm.*f / (cold.*f), 1.0, 1e-8) << k;
    EXPECT_NEAR(warm.min_separation, cold.min_separation, 1e-8 * sigma) << k;
    ASSERT_EQ(warm.x.size(), cold.x.size());
    for (std::size_t i = 0; i < warm.x.size(); ++i)
      EXPECT_NEAR(warm.nominal_pressure[i], cold.nominal_pressure[i], 1e-8 * cold.max_nominal_pressure) << k;
    // The contact half-width is an element edge: the 99.9% load crossing may fall on either
    // side of one within the tolerance, so one element.
    EXPECT_NEAR(warm.contact_half_width, cold.contact_half_width, 1.001 * (warm.x[1] - warm.x[0])) << k;
  }
  // The warm path did its work: every solve after the first from its predecessor, and far fewer
  // Jacobians than solves (one per position and Newton step when cold).
  EXPECT_EQ(state.cold_solves(), 1);
  EXPECT_EQ(state.warm_solves(), positions - 1);
  EXPECT_LT(state.jacobians(), positions);
}

TEST(EquivalentSurface, FromRaAndSummitRadii) {
  // The seed's flanks: Ra 0.8 um each -> Rq = sqrt(pi/2) Ra = 1.00265 um; composite
  // sqrt(2) x 1.00265 = 1.41796 um; beta = 1.65 x 1.75/3.4 = 0.849265 um; eta = 0.05/(sigma_s beta).
  // McCool at the bandwidth the GW product implies: alpha = 768 pi x 0.05^2 + 0.8968 = 6.9287,
  // sigma_s = sqrt(1 - 0.8968/alpha) sigma = 0.93306 sigma, mean summit height
  // 4 sigma/sqrt(pi alpha) = 0.85737 sigma.
  surface::FlankRoughness a, b;
  a.ra = b.ra = 0.8e-6;
  a.summit_radius = 1.65e-6;
  b.summit_radius = 1.75e-6;
  const auto s = surface::equivalent_surface(a, b, surface::HeightDistribution::gaussian);
  EXPECT_NEAR(s.surface_sigma, std::sqrt(2.0) * std::sqrt(kPi / 2.0) * 0.8e-6, 1e-18);
  EXPECT_NEAR(s.summit_radius, 1.65e-6 * 1.75e-6 / 3.4e-6, 1e-18);
  EXPECT_NEAR(s.eta_sigma_beta(), 0.05, 1e-15);
  const double alpha = 768.0 * kPi * 0.0025 + 0.8968;
  EXPECT_NEAR(s.summit_sigma / s.surface_sigma, reference::mccool_summit_sigma_ratio(alpha), 1e-12);
  EXPECT_NEAR(s.summit_mean_height / s.surface_sigma, reference::mccool_summit_mean_height_ratio(alpha), 1e-12);
  // The same surface through the summits form gives back the same statistics (one description).
  surface::FlankRoughness c, d;
  c.form = d.form = surface::FlankRoughness::Form::summits;
  c.summit_radius = a.summit_radius, d.summit_radius = b.summit_radius;
  c.summit_density = d.summit_density = s.summit_density;
  c.summit_sigma = d.summit_sigma = s.summit_sigma / std::sqrt(2.0);
  const auto t = surface::equivalent_surface(c, d, surface::HeightDistribution::gaussian);
  EXPECT_NEAR(t.surface_sigma / s.surface_sigma, 1.0, 1e-12);  // identity up to rounding
  EXPECT_NEAR(t.summit_mean_height / s.summit_mean_height, 1.0, 1e-12);
  // Plasticity index (E_t/H) sqrt(sigma_s/beta) = 96.71 x 1.2922 x 0.93306^(1/2) = 120.71.
  EXPECT_NEAR(surface::plasticity_index(s, 113.19e9, 1.1704e9), 120.71, 0.01);
}

TEST(EquivalentSurface, McCoolRelationsFromSpectralMoments) {
  // Moments add for independent surfaces; alpha = m0 m4/m2^2; eta = m4/(6 pi sqrt3 m2),
  // beta = 0.375 sqrt(pi/m4), sigma_s^2 = (1 - 0.8968/alpha) m0 (McCool 1986).
  surface::FlankRoughness a, b;
  a.form = b.form = surface::FlankRoughness::Form::spectral;
  a.m0 = 0.5e-12, a.m2 = 2e-3, a.m4 = 1e8;
  b.m0 = 0.3e-12, b.m2 = 1e-3, b.m4 = 2e8;
  const auto s = surface::equivalent_surface(a, b, surface::HeightDistribution::gaussian);
  const double m0 = 0.8e-12, m2 = 3e-3, m4 = 3e8, alpha = m0 * m4 / (m2 * m2);
  EXPECT_NEAR(s.summit_density / reference::mccool_summit_density(m2, m4), 1.0, 1e-14);
  EXPECT_NEAR(s.summit_radius / reference::mccool_summit_radius(m4), 1.0, 1e-14);
  EXPECT_NEAR(s.summit_sigma / (reference::mccool_summit_sigma_ratio(alpha) * std::sqrt(m0)), 1.0, 1e-14);
  EXPECT_NEAR(s.surface_sigma / std::sqrt(m0), 1.0, 1e-14);
  // Too narrow a band (alpha <= 0.8968) has no summit statistics.
  a.m4 = b.m4 = 1.0;
  EXPECT_THROW(surface::equivalent_surface(a, b, surface::HeightDistribution::gaussian), std::invalid_argument);
}

TEST(EquivalentSurface, SummitStatisticsAndMixedFormsRejected) {
  surface::FlankRoughness a, b;
  a.form = b.form = surface::FlankRoughness::Form::summits;
  a.summit_density = 1e10, b.summit_density = 3e10;
  a.summit_sigma = 0.3e-6, b.summit_sigma = 0.4e-6;
  a.summit_radius = b.summit_radius = 10e-6;
  const auto s = surface::equivalent_surface(a, b, surface::HeightDistribution::exponential);
  EXPECT_NEAR(s.summit_sigma, 0.5e-6, 1e-18);
  EXPECT_NEAR(s.summit_radius, 5e-6, 1e-18);
  EXPECT_NEAR(s.summit_density, 2e10, 1e-3);
  b.form = surface::FlankRoughness::Form::ra;
  EXPECT_THROW(surface::equivalent_surface(a, b, surface::HeightDistribution::gaussian), std::invalid_argument);
}

TEST(GreenwoodWilliamson, SharedNodeTableEqualsTheDirectQuadrature) {
  // The Gaussian table is built on nodes shared by its separations (one model evaluation per
  // node, the density by recurrence); at its nodes it must equal the direct quadrature per
  // separation. The direct rule cuts the height distribution at 8.5 sigma, which shows (above
  // 1e-8) for separations beyond 5 sigma, pressures below ~1e-8 of the table's top (skipped:
  // the shared rule keeps the whole Gaussian there). Measured against a
  // 4096-point reference, the shared rule is within 7e-9 for pressure and area and 3e-8 for
  // the plastic area, the direct rule within 1e-10 and 6e-7 (the plastic share's steep onset):
  // tolerances 1e-8 and 1e-6.
  const auto surf = make_surface(1.418e-6, 0.849e-6, 0.05);
  for (const char* name : {"continuous", "kogut-etsion", "hertz"}) {
    const auto model = asperity::make_asperity_model(name);
    const GreenwoodWilliamson gw(surf, *model, test::seed_pair(), 3e9, {});
    const double step = surf.summit_sigma / GreenwoodWilliamsonOptions{}.table_points_per_sigma;
    int checked = 0;
    for (int k = 0;; k += 7) {
      const double d = gw.contact_onset() - k * step;
      const SurfaceContact t = gw.interpolate(d), q = gw.at_separation(d);
      if (q.nominal_pressure > 1.05 * 3e9) break;
      if (d > 5.0 * surf.summit_sigma) continue;
      EXPECT_NEAR(t.nominal_pressure / q.nominal_pressure, 1.0, 1e-8) << name << " " << k;
      EXPECT_NEAR(t.real_area_ratio / q.real_area_ratio, 1.0, 1e-8) << name << " " << k;
      if (q.plastic_area_ratio > 1e-12 * q.real_area_ratio) {
        EXPECT_NEAR(t.plastic_area_ratio / q.plastic_area_ratio, 1.0, 1e-6) << name << " " << k;
      }
      ++checked;
    }
    EXPECT_GT(checked, 20) << name;
  }
}

TEST(GreenwoodWilliamson, CubicCellsEqualTheExactLookup) {
  // at_pressure: cubic Hermite cells of at most 2% in pressure on each segment's power law.
  // Hermite error ~ (0.02)^4/384 x (a few) ~ 1e-8 of the value at most; 2e-8 allowed.
  // Below the cells' floor and beyond the table: the exact route itself (equal).
  for (const auto distribution : {surface::HeightDistribution::gaussian, surface::HeightDistribution::exponential}) {
    for (const char* name : {"continuous", "kogut-etsion", "jackson-green"}) {
      const auto model = asperity::make_asperity_model(name);
      const GreenwoodWilliamson gw(make_surface(1.418e-6, 0.849e-6, 0.05, distribution), *model, test::seed_pair(), 3e9,
                                   {});
      const double top = gw.max_pressure();
      for (double p : test::log_space(1e-9 * top, 1.2 * top, 1777)) {
        const ContactAtPressure f = gw.at_pressure(p);
        const SurfaceContact e = gw.interpolate(gw.separation_for_pressure(p));
        const bool exact_route = p < GreenwoodWilliamson::kCellFloor * top || p >= top;
        const double tol = exact_route ? 0.0 : 2e-8;
        auto near = [&](double x, double y) { return std::abs(x - y) <= tol * std::abs(y); };
        EXPECT_TRUE(near(f.real_area_ratio, e.real_area_ratio)) << name << " " << p;
        EXPECT_TRUE(near(f.contact_density, e.contact_density)) << name << " " << p;
        EXPECT_TRUE(near(f.plastic_area_ratio, e.plastic_area_ratio)) << name << " " << p;
        EXPECT_TRUE(near(f.plastic_contact_density, e.plastic_contact_density)) << name << " " << p;
      }
    }
  }
}

TEST(MeshContact, FastPathsEqualTheExactPathOnTheDefaultCase) {
  // The default case (lubricated, continuous model, asperity stresses) with the cubic strip
  // look-up and the von Mises table, against the exact look-up and the maximisation at every
  // position: every output within 1e-6 relative (measured: 1e-10).
  const Case& fast = test::lubricated_case();
  Case exact = fast;
  exact.contact.strip.lookup = contact::StripLookup::exact;
  exact.contact.stress_table = 0;
  ASSERT_FALSE(fast.contact.strip.lookup == contact::StripLookup::exact);
  ASSERT_GT(fast.contact.stress_table, 0);
  for (const double ra : {0.8e-6, 0.1e-6}) {  // fully plastic (the default flanks) and elastic-plastic
    Case f = fast, e = exact;
    for (Case* c : {&f, &e}) {
      c->pinion.flank.roughness.ra = ra;
      c->wheel.flank.roughness.ra = ra;
    }
    const gear::GearMesh mesh_f = gear::case_mesh(f), mesh_e = gear::case_mesh(e);
    const MeshContactResult rf = runs::run_mesh_contact(f, mesh_f, nullptr, {}, 201);
    const MeshContactResult re = runs::run_mesh_contact(e, mesh_e, nullptr, {}, 201);
    int compared = 0;
    for (const auto* group : re.groups())
      for (const auto& s : *group) {
        const Series* t = rf.find(s.name);
        ASSERT_NE(t, nullptr) << s.name;
        ASSERT_EQ(t->values.size(), s.values.size()) << s.name;
        for (std::size_t i = 0; i < s.values.size(); ++i)
          EXPECT_NEAR(t->values[i], s.values[i], 1e-6 * std::abs(s.values[i])) << s.name << " " << i << " " << ra;
        ++compared;
      }
    EXPECT_GT(compared, 40);
  }
}

TEST(MeshContact, ToothPairStiffnessOnlyWhenAskedOrUsed) {
  // ISO load sharing needs no tooth stiffness: the series is written only when contact.outputs
  // asks for it, and then equals the mesh analysis' sum over the pairs in contact.
  Case c = test::seed_case();
  ASSERT_FALSE(c.contact.mesh_stiffness);
  c.contact.real_area = c.contact.plastic_fraction = c.contact.asperity_stress = false;
  const gear::GearMesh mesh = gear::case_mesh(c);
  ASSERT_EQ(mesh.analysis().method(), gear::LoadSharing::iso);
  EXPECT_EQ(runs::run_mesh_contact(c, mesh, nullptr, {}, 11).find("mesh_stiffness_N_per_m"), nullptr);
  c.contact.mesh_stiffness = true;
  const MeshContactResult r = runs::run_mesh_contact(c, mesh, nullptr, {}, 11);
  const Series* k = r.find("mesh_stiffness_N_per_m");
  ASSERT_NE(k, nullptr);
  const auto& s = r.find("s_m")->values;
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_EQ(k->values[i], mesh.analysis().at(s[i]).mesh_stiffness) << i;
}
