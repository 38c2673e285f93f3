#include "lubrication/mixed_lubrication.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace geartrib::lubrication {

LoadShare share_load(double h_smooth, double e, const std::function<double(double)>& asperity_separation,
                     double guess) {
  if (!(e > 0.0)) throw std::invalid_argument("share_load: the film exponent must be positive");
  const auto dry = [&] { return LoadShare{1.0, 0.0, asperity_separation(1.0)}; };
  if (!(h_smooth > 0.0)) return dry();  // no film
  LoadShare s;
  if (h_smooth >= asperity_separation(0.0)) {  // the smooth film clears the highest summits
    s.film_thickness = h_smooth;
    return s;
  }
  // Unknown: x = ln(film share) in (ln_min, 0]; g(x) = h_smooth e^(-e x) - h_asperity(1 - e^x) is
  // decreasing in x, positive at ln_min (the film grows without bound as its share vanishes) and
  // negative at 0 (checked above).
  auto g = [&](double x) { return h_smooth * std::exp(-e * x) - asperity_separation(-std::expm1(x)); };
  double lo = -1.0, hi = 0.0;
  if (std::isfinite(guess) && guess < 0.0 && guess > -700.0 && g(guess - 0.02) >= 0.0 &&
      g(std::min(0.0, guess + 0.02)) <= 0.0) {
    lo = guess - 0.02;  // the neighbour's bracket holds the root
    hi = std::min(0.0, guess + 0.02);
  } else {
    while (g(lo) < 0.0 && lo > -700.0) lo *= 2.0;
    if (g(lo) < 0.0) return dry();  // film share below e^-700: the asperities carry all
  }
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      g, lo, hi, [](double l, double h) { return std::abs(h - l) <= 1e-13 * std::max(1.0, std::abs(l)); }, iterations);
  const double x = 0.5 * (a + b);
  // A film carrying less than kNegligibleFilmShare is no film: far below what the asperity side
  // resolves (its pressure-separation table interpolates to ~1e-4), and the limit the dry contact must meet.
  if (std::exp(x) <= kNegligibleFilmShare) return dry();
  s.film_share = std::exp(x);
  s.asperity_share = -std::expm1(x);
  s.film_thickness = h_smooth * std::exp(-e * x);
  return s;
}

double film_shear_stress(const OilState& oil, double p, double vs, double h) {
  if (!(h > 0.0) || vs == 0.0 || !(p > 0.0)) return 0.0;
  const double eta = oil.dynamic_viscosity * std::exp(std::min(oil.pressure_viscosity * p, 700.0));
  const double tau0 = oil.eyring_stress;
  const double tau = tau0 * std::asinh(eta * std::abs(vs) / (h * tau0));
  return std::min(tau, oil.limiting_shear_coefficient * p);
}

MixedFriction mixed_friction(const OilState& oil, const LoadShare& share, double mu_b, double w, double b, double vs) {
  MixedFriction f;
  if (share.film_share > 0.0 && w > 0.0 && b > 0.0) {
    const double p = share.film_share * w / (2.0 * b);
    f.film_coefficient = film_shear_stress(oil, p, vs, share.film_thickness) / p;
  }
  f.coefficient = share.asperity_share * mu_b + share.film_share * f.film_coefficient;
  return f;
}

}  // namespace geartrib::lubrication
