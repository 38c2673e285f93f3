#include "lubrication/mixed_lubrication.hpp"

#include "core/named_choices.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
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

namespace {
constexpr NamedChoice<FilmTraction> kTractionNames[] = {{FilmTraction::thermal_eyring, "thermal-eyring"},
                                                        {FilmTraction::isothermal_eyring, "isothermal-eyring"},
                                                        {FilmTraction::curve, "curve"}};

// ln sinh(t), t > 0, without overflow or loss of digits at either end.
double log_sinh(double t) {
  if (t < 1e-8) return std::log(t);
  if (t > 20.0) return t - std::numbers::ln2 + std::log1p(-std::exp(-2.0 * t));
  return std::log(std::sinh(t));
}
// ln cosh(x), x >= 0.
double log_cosh(double x) { return x + std::log1p(std::exp(-2.0 * x)) - std::numbers::ln2; }
// asinh(e^L) for any L (the Eyring argument can exceed the double range: eta at 1 GPa by Barus).
double asinh_exp(double l) { return l > 20.0 ? l + std::numbers::ln2 : std::asinh(std::exp(l)); }
// Isothermal Eyring from ln_drive = ln(eta |v_s|/h): tau0 asinh(eta |v_s|/(h tau0)).
double eyring_log(double ln_drive, double tau0) { return tau0 * asinh_exp(ln_drive - std::log(tau0)); }
}  // namespace

std::span<const NamedChoice<FilmTraction>> film_traction_choices() { return kTractionNames; }
const char* film_traction_name(FilmTraction t) { return choice_name(film_traction_choices(), t); }

double eyring_shear_stress(double eta, double tau0, double vs, double h) {
  if (!(h > 0.0) || vs == 0.0 || !(eta > 0.0)) return 0.0;
  return eyring_log(std::log(eta) + std::log(std::abs(vs)) - std::log(h), tau0);
}

namespace {
// The thermal Eyring law in logarithms (the Barus viscosity at a gear contact's pressure reaches
// e^50 and beyond): ln_drive = ln(eta_s |v_s|/h). Unknown X in F(X) = ln(tau0 sinh(tau/tau0))
// - ln_drive - ln g(X) = 0 with tau = X tanh X / c, c = beta h |v_s|/(8 k_f),
// g(X) = X/(sinh X cosh X); F increases with X (tau rises, g falls).
FilmShear thermal_eyring_log(double ln_drive, double tau0, double beta, double k_f, double vs, double h) {
  FilmShear out;
  const double v = std::abs(vs);
  const double tau_iso = eyring_log(ln_drive, tau0);
  const double c = beta * h * v / (8.0 * k_f);
  const double y_max = c * tau_iso;  // X tanh X at the isothermal stress: the heating's largest measure
  // Below 1e-12 the correction 1 - g(X) ~ (2/3) X^2 ~ y is below the double's resolution of tau.
  if (!(c > 0.0) || y_max < 1e-12) {
    out.shear_stress = tau_iso;
    return out;
  }
  const auto log_g = [](double x) {
    if (x < 1e-4) return -2.0 * x * x / 3.0;  // 2X/sinh 2X = 1 - (2X)^2/6 + ...
    return std::log(x) - log_sinh(x) - log_cosh(x);
  };
  const auto tau_of = [c](double x) { return x * std::tanh(x) / c; };
  const auto f = [&](double x) { return std::log(tau0) + log_sinh(tau_of(x) / tau0) - ln_drive - log_g(x); };
  // X tanh X = y has X <= max(2y, 2 sqrt y): the bracket's top gives tau >= tau_iso, F >= 0.
  const double hi = std::max(2.0 * y_max, 2.0 * std::sqrt(y_max));
  double lo = 1e-9 * hi;
  if (f(lo) >= 0.0) {  // heating negligible at the root
    out.shear_stress = tau_iso;
    return out;
  }
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      f, lo, hi, [](double l, double r) { return std::abs(r - l) <= 1e-14 * std::max(1.0, std::abs(l)); }, iterations);
  const double x = 0.5 * (a + b);
  out.shear_stress = std::min(tau_of(x), tau_iso);
  out.midfilm_rise = 2.0 / beta * log_cosh(x);
  return out;
}
}  // namespace

FilmShear thermal_eyring_shear_stress(double eta_s, double tau0, double beta, double k_f, double vs, double h) {
  if (!(h > 0.0) || vs == 0.0 || !(eta_s > 0.0)) return {};
  return thermal_eyring_log(std::log(eta_s) + std::log(std::abs(vs)) - std::log(h), tau0, beta, k_f, vs, h);
}

FilmShear film_shear_stress(FilmTraction model, const OilState& oil, double p, double vs, double h) {
  FilmShear out;
  if (!(h > 0.0) || vs == 0.0 || !(p > 0.0) || !(oil.dynamic_viscosity > 0.0)) return out;
  const double ln_eta = std::log(oil.dynamic_viscosity) + oil.pressure_viscosity * p;  // Barus at p_f
  const double ln_drive = ln_eta + std::log(std::abs(vs)) - std::log(h);
  const double tau0 = oil.eyring_stress;
  if (model == FilmTraction::thermal_eyring)
    out = thermal_eyring_log(ln_drive, tau0, oil.temperature_viscosity, oil.thermal_conductivity, vs, h);
  else out.shear_stress = eyring_log(ln_drive, tau0);
  const double limit = oil.limiting_shear_coefficient * p;
  if (out.shear_stress > limit) {
    out.shear_stress = limit;
    out.limited = true;
    if (model == FilmTraction::thermal_eyring && oil.temperature_viscosity > 0.0) {
      // The mid-film rise of the film shearing at the limit: X tanh X = beta tau_L v h/(8 k).
      const double y = oil.temperature_viscosity * h * std::abs(vs) * limit / (8.0 * oil.thermal_conductivity);
      std::uintmax_t iterations = 100;
      const auto g = [y](double x) { return x * std::tanh(x) - y; };
      const double hi = std::max(2.0 * y, 2.0 * std::sqrt(y)) + 1e-300;
      const auto [a, b] = boost::math::tools::toms748_solve(
          g, 0.0, hi, [](double l, double r) { return std::abs(r - l) <= 1e-14 * std::max(1.0, l); }, iterations);
      out.midfilm_rise = 2.0 / oil.temperature_viscosity * log_cosh(0.5 * (a + b));
    }
  }
  return out;
}

}  // namespace geartrib::lubrication
