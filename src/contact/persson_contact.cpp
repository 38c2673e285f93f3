#include "contact/persson_contact.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace geartrib::contact {

namespace {
constexpr double kPi = std::numbers::pi;

void check(double pbar, double e_star, double rms_gradient) {
  if (!(pbar >= 0.0) || !std::isfinite(pbar)) throw std::invalid_argument("Persson: the mean pressure must be >= 0");
  if (!(e_star > 0.0)) throw std::invalid_argument("Persson: the modulus must be positive");
  if (!(rms_gradient >= 0.0) || !std::isfinite(rms_gradient))
    throw std::invalid_argument("Persson: the rms gradient must be >= 0");
}
}  // namespace

double persson_elastic_area(double pbar, double e_star, double rms_gradient) {
  check(pbar, e_star, rms_gradient);
  if (rms_gradient == 0.0) return pbar > 0.0 ? 1.0 : 0.0;
  return std::erf(std::sqrt(2.0) * pbar / (e_star * rms_gradient));
}

double persson_corrected_area(double pbar, double e_star, double rms_gradient, double gamma) {
  check(pbar, e_star, rms_gradient);
  if (!(gamma > 0.0 && gamma <= 1.0)) throw std::invalid_argument("Persson: gamma must lie in (0, 1]");
  if (rms_gradient == 0.0 || pbar == 0.0) return persson_elastic_area(pbar, e_star, rms_gradient);
  // A - erf(c/sqrt(gamma + (1 - gamma) A)) grows monotonically in A: bisection on [0, 1].
  const double c = std::sqrt(2.0) * pbar / (e_star * rms_gradient);
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 100 && hi - lo > 1e-15; ++it) {
    const double a = 0.5 * (lo + hi);
    (a - std::erf(c / std::sqrt(gamma + (1.0 - gamma) * a)) < 0.0 ? lo : hi) = a;
  }
  return 0.5 * (lo + hi);
}

double PerssonAreas::elastic_mean_pressure(double pbar, double hardness) const {
  if (!(elastic > 0.0)) return 0.0;
  const double carried = std::isfinite(hardness) ? pbar - hardness * plastic : pbar;
  return std::max(0.0, carried) / elastic;
}

// With x = pi r and k_n = n pi: P(s) = 2 sum sin(n x) sin(n pi s) e^{-n^2 pi^2 g_y} on (0, 1) in units
// of H; A_el = integral P, A_pl = r - integral s P (the load balance).
PerssonAreas persson_elastic_plastic_series(double r, double g_y, int n_terms) {
  PerssonAreas a;
  double pl = 0.0;
  for (int n = 1; n <= n_terms; ++n) {
    const double t = std::sin(n * kPi * r) * std::exp(-n * n * kPi * kPi * g_y) / n;
    if (n % 2 == 1) a.elastic += 4.0 / kPi * t;
    pl += (n % 2 == 1 ? 1.0 : -1.0) * t;
  }
  a.plastic = std::max(0.0, r - 2.0 / kPi * pl);
  a.elastic = std::max(0.0, a.elastic);
  return a;
}

// P = sum_k [phi(s - (r + 2k)) - phi(s - (2k - r))], phi the Gaussian of variance 2 g_y (units of H).
PerssonAreas persson_elastic_plastic_images(double r, double g_y, int n_images) {
  const double w = std::sqrt(4.0 * g_y);  // phi(x) = exp(-x^2/w^2)/(w sqrt pi)
  auto mass = [&](double c) { return 0.5 * (std::erf((1.0 - c) / w) - std::erf(-c / w)); };
  auto moment = [&](double c) {
    return c * mass(c) +
           w / (2.0 * std::sqrt(kPi)) * (std::exp(-c * c / (w * w)) - std::exp(-(1.0 - c) * (1.0 - c) / (w * w)));
  };
  double area = 0.0, first = 0.0;
  for (int k = -n_images; k <= n_images; ++k) {
    area += mass(r + 2.0 * k) - mass(2.0 * k - r);
    first += moment(r + 2.0 * k) - moment(2.0 * k - r);
  }
  return {std::max(0.0, area), std::max(0.0, r - first)};
}

PerssonAreas persson_elastic_plastic(double pbar, double e_star, double rms_gradient, double hardness) {
  check(pbar, e_star, rms_gradient);
  if (!(hardness > 0.0)) throw std::invalid_argument("Persson: the hardness must be positive");
  if (!std::isfinite(hardness)) return {persson_elastic_area(pbar, e_star, rms_gradient), 0.0};
  if (pbar >= hardness) throw std::invalid_argument("Persson: the mean pressure must lie below the hardness");
  if (pbar == 0.0) return {};
  const double r = pbar / hardness;
  if (rms_gradient == 0.0) return {1.0, 0.0};
  const double g_y = e_star * e_star * rms_gradient * rms_gradient / 8.0 / (hardness * hardness);
  // Images three each side reach e^{-(2*3-1)^2/(4 g_y)} < 1e-50 below g_y = 0.05; the series'
  // terms fall as e^{-n^2 pi^2 g_y}: to e^{-45} at the last.
  if (g_y < 0.05) return persson_elastic_plastic_images(r, g_y, 3);
  return persson_elastic_plastic_series(r, g_y, static_cast<int>(std::ceil(std::sqrt(45.0 / (kPi * kPi * g_y)))) + 1);
}

PerssonStrip persson_hertz_strip(double p0, double e_star, double rms_gradient, double hardness) {
  PerssonStrip s;
  if (!(p0 > 0.0)) return s;
  // (1/2b) integral_{-b}^{b} A(p(x)) dx = (1/2) integral_{-pi/2}^{pi/2} A(p0 cos t) cos t dt; the pressure
  // capped just below H where the Hertz field passes it (the theory holds below H).
  auto areas = [&](double t) {
    const double p = std::min(p0 * std::cos(t), std::nextafter(hardness, 0.0));
    return persson_elastic_plastic(std::max(p, 0.0), e_star, rms_gradient, hardness);
  };
  using Gauss = boost::math::quadrature::gauss<double, 64>;
  const double half_pi = 0.5 * kPi;
  const double area =
      0.5 * Gauss::integrate([&](double t) { return areas(t).contact() * std::cos(t); }, -half_pi, half_pi);
  const double plastic =
      0.5 * Gauss::integrate([&](double t) { return areas(t).plastic * std::cos(t); }, -half_pi, half_pi);
  s.real_area_ratio = area;
  s.plastic_area_fraction = area > 0.0 ? plastic / area : 0.0;
  s.mean_real_pressure = area > 0.0 ? (kPi / 4.0) * p0 / area : 0.0;  // the mean Hertz pressure over the real area
  return s;
}

}  // namespace geartrib::contact
