// Persson's theory (contact/persson_contact.hpp): its limits (kappa = sqrt(8/pi) at vanishing load,
// complete contact, the hardness limit A = pbar/H), the elastic-plastic solution's two derivations
// (images of the Gaussian against the sine series) against each other, the elastic theory as the
// elastic-plastic one's limit, Xu et al.'s correction's small-load kappa; and the spectral rms
// gradient of a surface whose gradient is known exactly.
#include "contact/persson_contact.hpp"
#include "surface/surface_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

using namespace geartrib;
using namespace geartrib::contact;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kEstar = 115e9;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(Persson, ElasticLimits) {
  // A/A0 -> sqrt(8/pi) pbar/(E* h'_rms) as the load vanishes (erf(x) ~ 2x/sqrt(pi)), to O(x^2).
  const double g = 0.1, p = 1e-6 * kEstar * g;
  EXPECT_NEAR(persson_elastic_area(p, kEstar, g) / (std::sqrt(8.0 / kPi) * p / (kEstar * g)), 1.0, 1e-11);
  EXPECT_NEAR(persson_elastic_area(10.0 * kEstar * g, kEstar, g), 1.0, 1e-15);  // complete contact
  EXPECT_EQ(persson_elastic_area(0.0, kEstar, g), 0.0);
  EXPECT_EQ(persson_elastic_area(1e6, kEstar, 0.0), 1.0);  // a flat surface
}

TEST(Persson, ElasticPlasticImagesAgreeWithTheSeries) {
  // Two derivations of P on (0, H) with both ends absorbing: the sum of the Gaussian's images and
  // the sine series (separation of variables). Where both converge they agree to rounding.
  for (double g_y : {0.01, 0.03, 0.05, 0.1, 0.3})
    for (double r : {0.001, 0.05, 0.3, 0.7, 0.99}) {
      const PerssonAreas a = persson_elastic_plastic_images(r, g_y, 6);
      const PerssonAreas b = persson_elastic_plastic_series(r, g_y, 400);
      EXPECT_NEAR(a.elastic, b.elastic, 1e-12) << g_y << " " << r;
      EXPECT_NEAR(a.plastic, b.plastic, 1e-12) << g_y << " " << r;
    }
}

TEST(Persson, ElasticPlasticLimits) {
  const double g = 0.1, pbar = 0.02 * kEstar * g;
  // H -> inf: the elastic theory.
  const PerssonAreas e = persson_elastic_plastic(pbar, kEstar, g, 1e6 * kEstar * g);
  EXPECT_NEAR(e.elastic, persson_elastic_area(pbar, kEstar, g), 1e-12);
  EXPECT_LT(e.plastic, 1e-15);
  EXPECT_EQ(persson_elastic_plastic(pbar, kEstar, g, kInf).plastic, 0.0);
  // H/(E* h'_rms) -> 0: the whole contact yields, A_pl = pbar/H (the bearing area), A_el -> 0.
  const double h = 1e-3 * kEstar * g, p = 0.3 * h;
  const PerssonAreas y = persson_elastic_plastic(p, kEstar, g, h);
  EXPECT_NEAR(y.plastic, 0.3, 1e-12);
  EXPECT_LT(y.elastic, 1e-12);
  // Between: the plastic share grows as H falls, the yielded area carries at most the load
  // (A_pl <= pbar/H), and the load balance leaves a mean elastic pressure below H.
  double last_plastic = 0.0;
  for (double s : {0.2, 0.5, 1.0, 2.0, 4.0}) {  // E* h'_rms/H
    const double hs = kEstar * g / s, ps = 0.05 * hs;
    const PerssonAreas a = persson_elastic_plastic(ps, kEstar, g, hs);
    EXPECT_GE(a.plastic / 0.05, last_plastic);
    last_plastic = a.plastic / 0.05;
    EXPECT_LE(a.plastic, 0.05 + 1e-15);
    EXPECT_LT(a.elastic_mean_pressure(ps, hs), hs);
  }
  EXPECT_THROW(persson_elastic_plastic(h, kEstar, g, h), std::invalid_argument);
}

TEST(Persson, XuCorrectionSmallLoadKappa) {
  // Xu et al. 2024: A = erf(c/sqrt(gamma + (1 - gamma) A)) tends to kappa = sqrt(8/(pi gamma)) p/(E* g).
  const double g = 0.2, p = 1e-7 * kEstar * g;
  EXPECT_NEAR(persson_corrected_area(p, kEstar, g) / (std::sqrt(8.0 / (kPi * kXuGamma)) * 1e-7), 1.0, 1e-6);
  // gamma = 1 is Persson's own theory.
  EXPECT_NEAR(persson_corrected_area(0.3 * kEstar * g, kEstar, g, 1.0),
              persson_elastic_area(0.3 * kEstar * g, kEstar, g), 1e-14);
  // It always predicts more area than the original (the variance scaled by at most 1).
  for (double x : {0.01, 0.1, 0.5, 1.0})
    EXPECT_GE(persson_corrected_area(x * kEstar * g, kEstar, g), persson_elastic_area(x * kEstar * g, kEstar, g));
}

TEST(SpectralGradient, OfACosineAndACrossedCosine) {
  // z = a cos(2 pi 3 x/L) + b cos(2 pi 5 y/L): |grad z|_rms^2 = (a q1)^2/2 + (b q2)^2/2.
  surface::HeightGrid g = surface::make_grid(64, 32, 1e-6, 2e-6);
  const double a = 0.3e-6, b = 0.1e-6, q1 = 2 * kPi * 3 / 64e-6, q2 = 2 * kPi * 5 / 64e-6;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.at(i, j) = a * std::cos(q1 * i * g.dx) + b * std::cos(q2 * j * g.dy);
  EXPECT_NEAR(surface::spectral_rms_gradient(g), std::sqrt(0.5 * (a * q1) * (a * q1) + 0.5 * (b * q2) * (b * q2)),
              1e-15);
}

TEST(Persson, HertzStripLimits) {
  // Across a Hertz strip p(x) = p0 sqrt(1 - x^2/b^2): at light load A is linear in p, so the real
  // area over 2b is sqrt(8/pi) (pi/4) p0/(E* g) (the elliptic profile's mean, pi/4 p0); as
  // H/(E* g) -> 0 every contact yields: (pi/4) p0/H, all of it plastic, at the mean real pressure H.
  const double g = 0.1;
  const double light = 1e-6 * kEstar * g;
  const PerssonStrip e = persson_hertz_strip(light, kEstar, g, kInf);
  EXPECT_NEAR(e.real_area_ratio / (std::sqrt(8.0 / kPi) * 0.25 * kPi * 1e-6), 1.0, 1e-9);
  EXPECT_EQ(e.plastic_area_fraction, 0.0);
  const double h = 1e-4 * kEstar * g, p0 = 0.5 * h;
  const PerssonStrip y = persson_hertz_strip(p0, kEstar, g, h);
  EXPECT_NEAR(y.real_area_ratio / (0.25 * kPi * p0 / h), 1.0, 1e-9);
  EXPECT_NEAR(y.plastic_area_fraction, 1.0, 1e-9);
  EXPECT_NEAR(y.mean_real_pressure / h, 1.0, 1e-9);
  // A Hertz peak above H: the theory taken at just below H there; finite, the area at most the band.
  const PerssonStrip over = persson_hertz_strip(3.0 * h, kEstar, g, h);
  EXPECT_TRUE(std::isfinite(over.real_area_ratio));
  EXPECT_LE(over.real_area_ratio, 1.0);
  EXPECT_EQ(persson_hertz_strip(0.0, kEstar, g, h).real_area_ratio, 0.0);
}
