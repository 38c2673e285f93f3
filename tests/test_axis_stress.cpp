// On-axis elastic stresses: closed forms against the Boussinesq kernel, the Hertz first-yield
// point against published values, and the two-zone pressure profile against brute force.
#include "asperity/axis_stress.hpp"
#include "asperity/critical.hpp"
#include "asperity/pressure_profile.hpp"
#include "asperity/von_mises_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace geartrib::asperity;

namespace {
constexpr double kPi = std::numbers::pi;

// Brute-force superposition of the Boussinesq kernel over an axisymmetric pressure p(r) on
// [0, a], composite Simpson in r = a sin t (smooth integrand), n intervals.
template <class P>
AxisStress integrate_kernel(P p, double a, double z, double nu, int n = 20000) {
  AxisStress s{};
  const double h = 0.5 * kPi / n;
  for (int i = 0; i <= n; ++i) {
    const double t = i * h;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double r = a * std::sin(t);
    const AxisStress k = boussinesq_axis_kernel(r, z, nu);
    const double f = p(r) * 2.0 * kPi * r * a * std::cos(t) * w * h / 3.0;
    s.radial += f * k.radial;
    s.axial += f * k.axial;
  }
  return s;
}
}  // namespace

TEST(AxisStress, HertzSurfaceValues) {
  // Exact at z = 0: sigma_z = -p0, sigma_r = -(1 + 2 nu)/2 p0 (Johnson eq. 3.45).
  const AxisStress s = hertz_axis_stress(0.0, 0.3);
  EXPECT_DOUBLE_EQ(s.axial, -1.0);
  EXPECT_DOUBLE_EQ(s.radial, -0.8);
}

TEST(AxisStress, ClosedFormsEqualTheKernelIntegral) {
  const double nu = 0.3, a = 1.0;
  for (double z : {0.05, 0.3, 0.48, 1.0, 2.5}) {
    const AxisStress h = hertz_axis_stress(z, nu);
    const AxisStress hn = integrate_kernel([&](double r) { return std::sqrt(std::max(0.0, 1.0 - r * r)); }, a, z, nu);
    // Simpson with 2e4 intervals on a smooth integrand: error far below 1e-7 of p0.
    EXPECT_NEAR(h.axial, hn.axial, 1e-7) << z;
    EXPECT_NEAR(h.radial, hn.radial, 1e-7) << z;
    const AxisStress u = uniform_disc_axis_stress(z, nu);
    const AxisStress un = integrate_kernel([](double) { return 1.0; }, a, z, nu);
    EXPECT_NEAR(u.axial, un.axial, 1e-7) << z;
    EXPECT_NEAR(u.radial, un.radial, 1e-7) << z;
  }
}

TEST(AxisStress, HertzFirstYieldPointMatchesJohnson) {
  // Johnson (Contact Mechanics, sec. 4.2): for nu = 0.3 the largest von Mises (and Tresca)
  // stress lies on the axis at 0.48 a, equal to 0.62 p0. Published to two digits: +-0.005.
  const HertzYieldPoint y = hertz_yield_point(0.3);
  EXPECT_NEAR(y.depth_over_radius, 0.48, 0.005);
  EXPECT_NEAR(y.von_mises_over_peak, 0.62, 0.005);
}

TEST(AxisStress, YieldFactorFitsReproduceTheExactHertzValue) {
  // C(nu) = p0/S_y at first yield = 1/(sigma_vm/p0)max. Jackson-Green's fit 1.295 exp(0.736 nu)
  // is stated as a curve fit over 0 <= nu <= 0.5; its deviation from the exact value stays
  // below 0.5% there (0.3% at the ends).
  for (double nu : {0.0001, 0.1, 0.2, 0.3, 0.4, 0.49}) {
    const double exact = 1.0 / hertz_yield_point(nu).von_mises_over_peak;
    EXPECT_NEAR(jackson_green_yield_factor(nu) / exact, 1.0, 5e-3) << nu;
  }
  // CEB's k H = (0.454 + 0.41 nu) 2.8 S_y is the same yield peak to 0.2% at nu = 0.3.
  EXPECT_NEAR(ceb_pressure_factor(0.3) * 2.8 / (1.0 / hertz_yield_point(0.3).von_mises_over_peak), 1.0, 2e-3);
}

TEST(PressureProfile, TwoZoneStressesEqualBruteForce) {
  const double nu = 0.3, a = 2.0;
  PressureProfile p{a, 1.2, 0.9, 1.3};  // core 0.9 on r < 1.2, annulus 1.3 sqrt(1 - r^2/a^2)
  auto pr = [&](double r) {
    return r < p.core_radius ? p.core_pressure : p.annulus_peak * std::sqrt(std::max(0.0, 1.0 - r * r / (a * a)));
  };
  for (double z : {0.1, 0.6, 1.5}) {
    const AxisStress s = p.axis_stress(z, nu);
    // The brute force integrates across the pressure jump at r_p: Simpson converges only to
    // O(h) there, h = a pi/2 / 2e5 ~ 1.6e-5; 2e-4 of the unit pressure covers it.
    const AxisStress b = integrate_kernel(pr, a, z, nu, 200000);
    EXPECT_NEAR(s.axial, b.axial, 2e-4) << z;
    EXPECT_NEAR(s.radial, b.radial, 2e-4) << z;
  }
}

TEST(PressureProfile, LoadIsTheIntegralOfThePressure) {
  const PressureProfile p{2.0, 1.2, 0.9, 1.3};
  // pi r_p^2 q + (2 pi/3) p_e (a^2 - r_p^2)^(3/2)/a, by hand: exact identity.
  const double expected = kPi * 1.44 * 0.9 + 2.0 * kPi / 3.0 * 1.3 * std::pow(4.0 - 1.44, 1.5) / 2.0;
  EXPECT_NEAR(p.load(), expected, 1e-12);
  EXPECT_DOUBLE_EQ(hertz_profile(1.0, 3.0).load(), 2.0 * kPi);    // Hertz: F = 2/3 pi a^2 p0
  EXPECT_DOUBLE_EQ(uniform_profile(1.0, 3.0).load(), 3.0 * kPi);  // uniform: pi a^2 p
}

TEST(PressureProfile, TwoZoneProfileCarriesTheMeanPressureContinuously) {
  // Identity: pi a^2 p_core (2 + phi)/3 = F, and the pressure is continuous at r_p:
  // p_e sqrt(1 - phi) = p_core. Limits: phi = 0 Hertz (p0 = 3/2 p_m), phi = 1 uniform.
  for (double phi : {0.0, 1e-9, 0.1, 0.5, 0.9, 1.0 - 1e-9, 1.0}) {
    for (double pm : {0.3, 1.0, 2.5}) {
      const PressureProfile p = two_zone_profile(1.0, pm, phi);
      EXPECT_NEAR(p.load() / kPi, pm, 1e-12 * pm) << phi;
      EXPECT_NEAR(p.plastic_fraction(), phi, 1e-15) << phi;
      if (phi > 0.0 && phi < 1.0) {
        EXPECT_NEAR(p.annulus_peak * std::sqrt(1.0 - phi) / p.core_pressure, 1.0, 1e-12) << phi;
      }
      EXPECT_LE(p.max_pressure(), 1.5 * pm * (1.0 + 1e-12));  // never above the Hertz peak of the same mean
      EXPECT_GE(p.max_pressure(), pm * (1.0 - 1e-12));        // never below the uniform one
    }
  }
  EXPECT_EQ(two_zone_profile(1.0, 0.5, 0.0).core_radius, 0.0);
  EXPECT_DOUBLE_EQ(two_zone_profile(1.0, 0.5, 0.0).max_pressure(), 0.75);     // p0 = 1.5 p_m
  EXPECT_DOUBLE_EQ(two_zone_profile(1.0, 0.5, 1.0).max_pressure(), 0.5);      // uniform
  EXPECT_DOUBLE_EQ(two_zone_profile(1.0, 0.5, 2.0).plastic_fraction(), 1.0);  // share clamped to [0, 1]
}

TEST(PressureProfile, VonMisesMaximumOfHertzProfile) {
  const PressureProfile p = hertz_profile(2e-8, 1e9);
  const VonMisesMaximum m = p.von_mises_maximum(0.3);
  const HertzYieldPoint y = hertz_yield_point(0.3);
  // Same maximisation of the same closed form: agree to the optimiser's precision.
  EXPECT_NEAR(m.value, y.von_mises_over_peak * 1e9, 1e-6 * 1e9);
  EXPECT_NEAR(m.depth, y.depth_over_radius * 2e-8, 1e-6 * 2e-8);
}

TEST(AxisStress, HertzAnnulusEqualsTheKernelIntegral) {
  // The annulus c <= r <= a of the Hertz pressure, closed form, against Simpson over the kernel
  // on that annulus (r = a sin t, t from asin(c) to pi/2: a smooth integrand).
  const double nu = 0.3;
  for (double c : {0.0, 0.2, 0.6, 0.95}) {
    for (double z : {1e-3, 0.05, 0.48, 1.0, 2.5}) {
      const AxisStress s = hertz_annulus_axis_stress(z, c, nu);
      AxisStress b{};
      const int n = 20000;
      const double t0 = std::asin(c), h = (0.5 * kPi - t0) / n;
      for (int i = 0; i <= n; ++i) {
        const double t = t0 + i * h;
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        const AxisStress k = boussinesq_axis_kernel(std::sin(t), z, nu);
        const double f = std::cos(t) * 2.0 * kPi * std::sin(t) * std::cos(t) * w * h / 3.0;
        b.radial += f * k.radial;
        b.axial += f * k.axial;
      }
      // Simpson, 2e4 intervals on a smooth integrand: far below 1e-7 of p_e, except near the
      // surface (z = 1e-3 over a kernel of width z): 1e-5 there.
      const double tol = z < 0.01 ? 1e-5 : 1e-7;
      EXPECT_NEAR(s.axial, b.axial, tol) << c << " " << z;
      EXPECT_NEAR(s.radial, b.radial, tol) << c << " " << z;
    }
  }
  // c = 0 is the whole Hertz distribution (the same closed form rearranged: rounding only).
  for (double z : {0.0, 1e-6, 0.3, 3.0}) {
    EXPECT_NEAR(hertz_annulus_axis_stress(z, 0.0, 0.3).axial, hertz_axis_stress(z, 0.3).axial, 1e-14);
    EXPECT_NEAR(hertz_annulus_axis_stress(z, 0.0, 0.3).radial, hertz_axis_stress(z, 0.3).radial, 1e-14);
  }
  // c = a carries nothing; at the surface an annulus c > 0 leaves the axis unstressed.
  EXPECT_EQ(hertz_annulus_axis_stress(0.5, 1.0, 0.3).axial, 0.0);
  EXPECT_EQ(hertz_annulus_axis_stress(0.0, 0.5, 0.3).radial, 0.0);
}

TEST(VonMisesTable, MatchesTheExactMaximisation) {
  // Normalisation: sigma_vm,max/p_m and z/a depend on phi alone. Sampled between the nodes
  // (where the error peaks). Cubic interpolation: the error falls as h^4 (measured 3e-3, 1.4e-4,
  // 2e-5, 1.9e-6, 1.3e-7, 8e-9 of p_m at 4 to 128 intervals, largest near phi = 0 where the
  // stress departs from Hertz as c^4): 64 intervals below 2e-7, 16 below 3e-5.
  for (int intervals : {64, 16}) {
    VonMisesTable table(0.3, intervals);
    double worst = 0.0, worst_depth = 0.0;
    for (int i = 0; i <= 997; ++i) {
      const double phi = std::pow(i / 997.0, 2.0);
      const double a = 3e-6, pm = 2e9;
      const VonMisesMaximum exact = two_zone_profile(a, pm, phi).von_mises_maximum(0.3);
      const VonMisesMaximum t = table.at(a, pm, phi);
      worst = std::max(worst, std::abs(t.value - exact.value) / pm);
      worst_depth = std::max(worst_depth, std::abs(t.depth - exact.depth) / a);
    }
    EXPECT_LT(worst, intervals == 64 ? 2e-7 : 3e-5) << intervals << " " << worst;
    EXPECT_LT(worst_depth, intervals == 64 ? 2e-6 : 3e-4) << intervals << " " << worst_depth;
    EXPECT_EQ(table.nodes_computed(), intervals + 1);  // every node needed once, none twice
  }
  // Nodes are computed only where asked: one phi needs four.
  VonMisesTable lazy(0.3, 64);
  lazy.at(1.0, 1.0, 0.5);
  EXPECT_EQ(lazy.nodes_computed(), 4);
  // The ends are the exact Hertz and uniform values (nodes); the coarsest tables still work.
  for (int intervals : {1, 2, 3}) {
    VonMisesTable t(0.3, intervals);
    EXPECT_NEAR(t.at(1.0, 1.0, 0.0).value, hertz_profile(1.0, 1.5).von_mises_maximum(0.3).value, 1e-15);
    EXPECT_NEAR(t.at(1.0, 1.0, 1.0).value, uniform_profile(1.0, 1.0).von_mises_maximum(0.3).value, 1e-15);
  }
  EXPECT_THROW(VonMisesTable(0.5, 64), std::invalid_argument);
  EXPECT_THROW(VonMisesTable(0.3, 0), std::invalid_argument);
}
