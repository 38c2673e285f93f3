#include "lubrication/film_closure.hpp"

#include "core/named_choices.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace geartrib::lubrication {

namespace {
constexpr NamedChoice<FilmGap> kGapNames[] = {
    {FilmGap::mean_gap, "mean-gap"}, {FilmGap::mean_plane, "mean-plane"}, {FilmGap::dry_offset, "dry-offset"}};
constexpr NamedChoice<AsperityPressureModel> kAsperityPressureNames[] = {
    {AsperityPressureModel::automatic, "auto"},
    {AsperityPressureModel::asperity_model, "asperity-model"},
    {AsperityPressureModel::bearing_area, "bearing-area"},
    {AsperityPressureModel::persson, "persson"}};
constexpr NamedChoice<PerssonSpectrum> kPerssonSpectrumNames[] = {{PerssonSpectrum::flanks, "flanks"},
                                                                  {PerssonSpectrum::moments, "moments"}};
}  // namespace

std::span<const NamedChoice<FilmGap>> film_gap_choices() { return kGapNames; }
const char* film_gap_name(FilmGap g) { return choice_name(film_gap_choices(), g); }
std::span<const NamedChoice<AsperityPressureModel>> asperity_pressure_model_choices() { return kAsperityPressureNames; }
const char* asperity_pressure_model_name(AsperityPressureModel m) {
  return choice_name(asperity_pressure_model_choices(), m);
}
std::span<const NamedChoice<PerssonSpectrum>> persson_spectrum_choices() { return kPerssonSpectrumNames; }
const char* persson_spectrum_name(PerssonSpectrum s) { return choice_name(persson_spectrum_choices(), s); }

double mean_gap(const CompositeHeights& s, double h) {
  if (!(s.sigma > 0.0)) return std::max(h, 0.0);
  if (s.distribution == surface::HeightDistribution::exponential) {
    const double c = h + s.sigma;
    return c > 0.0 ? c - s.sigma * (-std::expm1(-c / s.sigma)) : 0.0;
  }
  const double t = h / s.sigma;
  const double phi = std::exp(-0.5 * t * t) / std::sqrt(2.0 * std::numbers::pi);
  // t Phi(t) + phi(t), Phi(t) = erfc(-t/sqrt 2)/2. Below the mean plane this is phi(a) - a Q(a)
  // (a = -t): the two terms agree to about 1/a^2 of their size, so the difference keeps all but
  // log10(a^2) of its digits (erfc is accurate relative to its value), until phi underflows.
  return s.sigma * (t * 0.5 * std::erfc(-t / std::numbers::sqrt2) + phi);
}

double mean_gap_height(const CompositeHeights& s, double g) {
  if (!(g > 0.0) || !std::isfinite(g)) throw std::invalid_argument("the mean gap must be positive and finite");
  if (!(s.sigma > 0.0)) return g;
  // mean_gap rises from 0 to h + O(sigma e^(-h^2/2 sigma^2)) with slope P(z < h) in (0, 1]: g - h is
  // positive, and h lies below g; downwards, the bracket doubles until the gap falls below g.
  const auto f = [&](double h) { return mean_gap(s, h) - g; };
  if (f(g) <= 0.0) return g;  // g far above the heights: the mean gap is h to the double's digits
  double lo = g - s.sigma;
  while (f(lo) >= 0.0) lo = g - 2.0 * (g - lo);
  std::uintmax_t iterations = 200;
  const double scale = s.sigma;
  const auto [a, b] = boost::math::tools::toms748_solve(
      f, lo, g, [scale](double x, double y) { return std::abs(y - x) <= 1e-14 * std::max(scale, std::abs(x)); },
      iterations);
  return 0.5 * (a + b);
}

double bearing_area_fraction(const CompositeHeights& s, double h) {
  if (!(s.sigma > 0.0)) return h < 0.0 ? 1.0 : 0.0;
  if (s.distribution == surface::HeightDistribution::exponential) {
    const double c = h + s.sigma;
    return c > 0.0 ? std::exp(-c / s.sigma) : 1.0;
  }
  return 0.5 * std::erfc(h / (s.sigma * std::numbers::sqrt2));
}

double bearing_area_height(const CompositeHeights& s, double a) {
  if (!(a > 0.0 && a < 1.0)) throw std::invalid_argument("bearing area fraction must lie in (0, 1)");
  if (s.distribution == surface::HeightDistribution::exponential) return -s.sigma * std::log(a) - s.sigma;
  return s.sigma * std::numbers::sqrt2 * boost::math::erfc_inv(2.0 * a);
}

double film_gap(FilmGap g, const CompositeHeights& s, double h, double h_dry) {
  switch (g) {
    case FilmGap::mean_gap:
      return mean_gap(s, h);
    case FilmGap::mean_plane:
      return h;
    case FilmGap::dry_offset:
      return h - std::min(0.0, h_dry);
  }
  return h;
}

}  // namespace geartrib::lubrication
