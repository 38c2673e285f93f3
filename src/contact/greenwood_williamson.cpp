#include "contact/greenwood_williamson.hpp"

#include <fmt/format.h>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace geartrib::contact {

namespace {
constexpr int kGaussPoints = 8;  // per panel of the composite rule
using Gauss = boost::math::quadrature::gauss<double, kGaussPoints>;

// Interpolation between two positive-or-zero values: geometric where both are positive (the
// tables decay exponentially in d), linear otherwise.
double blend(double a, double b, double t) {
  if (a > 0.0 && b > 0.0) return a * std::pow(b / a, t);
  return a + (b - a) * t;
}
}  // namespace

void GreenwoodWilliamsonOptions::validate() const {
  static_assert(kMinHeightPoints >= kGaussPoints, "at least one Gauss panel");
  if (height_points < kMinHeightPoints || height_points > kMaxHeightPoints)
    throw std::invalid_argument(fmt::format("height_points must lie in [{}, {}]", kMinHeightPoints, kMaxHeightPoints));
  if (table_points_per_sigma < kMinTablePoints || table_points_per_sigma > kMaxTablePoints)
    throw std::invalid_argument(
        fmt::format("table_points_per_sigma must lie in [{}, {}]", kMinTablePoints, kMaxTablePoints));
}

GreenwoodWilliamson::GreenwoodWilliamson(const surface::EquivalentSurface& surface,
                                         const asperity::AsperityModel& model, const asperity::ContactPair& pair,
                                         double max_pressure, const GreenwoodWilliamsonOptions& options)
    : surface_(surface), model_(model), pair_(asperity::with_radius(pair, surface.summit_radius)), options_(options) {
  surface_.validate();
  options_.validate();
  if (!(max_pressure > 0.0 && std::isfinite(max_pressure)))
    throw std::invalid_argument("max_pressure must be positive");
  delta_c_ = model_.critical(pair_).interference;
  for (double b : model_.breakpoints(pair_))
    if (std::isfinite(b) && b > 0.0) breaks_.push_back(b * delta_c_);
  std::sort(breaks_.begin(), breaks_.end());
  breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
  const double s = surface_.summit_sigma;
  if (surface_.distribution == surface::HeightDistribution::gaussian) {
    z_low_ = -8.5 * s;  // phi(8.5 sigma) / phi(0) = 2e-16
    z_high_ = 8.5 * s;
  } else {
    z_low_ = 0.0;
    z_high_ = 37.0 * s;  // exp(-37) = 9e-17
  }
  step_ = s / options_.table_points_per_sigma;
  // From no contact downward until the pressure exceeds what the caller needs.
  for (int k = 0;; ++k) {
    const double d = z_high_ - k * step_;
    table_.push_back(at_separation(d));
    if (table_.back().nominal_pressure >= 1.05 * max_pressure && k > 0) break;
    if (d < -1e4 * s)
      throw std::invalid_argument("nominal pressure " + std::to_string(max_pressure) +
                                  " Pa is beyond what the rough surface can carry at any separation");
  }
}

double GreenwoodWilliamson::density(double z) const {
  const double s = surface_.summit_sigma;
  if (surface_.distribution == surface::HeightDistribution::gaussian)
    return std::exp(-0.5 * (z / s) * (z / s)) / (s * std::sqrt(2.0 * std::numbers::pi));
  return z >= 0.0 ? std::exp(-z / s) / s : 0.0;
}

SurfaceContact GreenwoodWilliamson::at_separation(double d) const {
  SurfaceContact c;
  c.separation = d;
  const double z0 = std::max(d, z_low_);
  if (z0 >= z_high_) return c;
  // Interference u = z - d from u0 to u1, with u = v^2 so that the Hertzian u^3/2 onset is smooth;
  // composite Gauss-Legendre in v with panel ends at the model's breakpoints (its jumps and kinks),
  // the panels shared among the segments by length, at least one each.
  const double v0 = std::sqrt(z0 - d), v1 = std::sqrt(z_high_ - d);
  std::vector<double> ends{v0};
  for (double b : breaks_)
    if (b > z0 - d && b < z_high_ - d) ends.push_back(std::sqrt(b));
  ends.push_back(v1);
  const int panels = options_.height_points / kGaussPoints;
  const double eta = surface_.summit_density;
  const asperity::Detail detail = asperity::Detail::load_area;  // load, area and the plastic share
  for (std::size_t seg = 0; seg + 1 < ends.size(); ++seg) {
    const double length = ends[seg + 1] - ends[seg];
    if (!(length > 0.0)) continue;
    const int n = std::max(1, static_cast<int>(std::lround(panels * length / (v1 - v0))));
    const double h = length / n;
    for (int k = 0; k < n; ++k) {
      const double a = ends[seg] + k * h;
      for (std::size_t i = 0; i < Gauss::abscissa().size(); ++i) {
        for (int sign : {-1, 1}) {
          if (i == 0 && sign == 1 && kGaussPoints % 2 == 1) continue;  // the centre point once
          const double v = a + 0.5 * h * (1.0 + sign * Gauss::abscissa()[i]);
          const double w = 0.5 * h * Gauss::weights()[i] * 2.0 * v;  // du = 2 v dv
          const double u = v * v;
          const double phi = density(d + u) * w * eta;
          const asperity::AsperityState st = model_.evaluate(pair_, u, detail);
          c.nominal_pressure += st.load * phi;
          c.real_area_ratio += st.area * phi;
          if (options_.plastic) c.plastic_area_ratio += st.area * st.plastic_fraction * phi;
        }
      }
    }
  }
  // Contact counts in closed form.
  const double s = surface_.summit_sigma;
  auto survival = [&](double z) {
    if (surface_.distribution == surface::HeightDistribution::gaussian)
      return 0.5 * std::erfc(z / (s * std::sqrt(2.0)));
    return z <= 0.0 ? 1.0 : std::exp(-z / s);
  };
  c.contact_density = eta * survival(d);
  c.plastic_contact_density = eta * survival(d + delta_c_);
  return c;
}

SurfaceContact GreenwoodWilliamson::interpolate(double d) const {
  if (d >= z_high_) return SurfaceContact{d, 0, 0, 0, 0, 0};
  const double x = (z_high_ - d) / step_;
  const std::size_t k = static_cast<std::size_t>(std::floor(x));
  if (k + 1 >= table_.size()) {
    // Below the table: the caller asked for more than max_pressure; compute directly.
    return at_separation(d);
  }
  const double t = x - static_cast<double>(k);
  const SurfaceContact& a = table_[k];
  const SurfaceContact& b = table_[k + 1];
  SurfaceContact c;
  c.separation = d;
  c.nominal_pressure = blend(a.nominal_pressure, b.nominal_pressure, t);
  c.real_area_ratio = blend(a.real_area_ratio, b.real_area_ratio, t);
  c.contact_density = blend(a.contact_density, b.contact_density, t);
  c.plastic_area_ratio = blend(a.plastic_area_ratio, b.plastic_area_ratio, t);
  c.plastic_contact_density = blend(a.plastic_contact_density, b.plastic_contact_density, t);
  return c;
}

double GreenwoodWilliamson::pressure(double d) const { return interpolate(d).nominal_pressure; }

double GreenwoodWilliamson::pressure_slope(double d) const {
  if (d >= z_high_) return 0.0;
  const double x = (z_high_ - d) / step_;
  std::size_t k = static_cast<std::size_t>(std::floor(x));
  if (k + 1 >= table_.size()) k = table_.size() - 2;
  const double pa = table_[k].nominal_pressure, pb = table_[k + 1].nominal_pressure;
  if (pa > 0.0 && pb > 0.0) return -pressure(d) * std::log(pb / pa) / step_;  // d(p)/d(d) of p = pa (pb/pa)^t
  return -(pb - pa) / step_;
}

double GreenwoodWilliamson::separation_for_pressure(double p) const {
  if (!(p >= 0.0) || !std::isfinite(p)) throw std::invalid_argument("nominal pressure must be finite and >= 0");
  if (p == 0.0) return z_high_;
  // Bracket in the monotone table (pressure increases with k), then invert the segment.
  auto it = std::lower_bound(table_.begin(), table_.end(), p,
                             [](const SurfaceContact& c, double value) { return c.nominal_pressure < value; });
  if (it == table_.end()) {
    // Beyond the table: bisection on the direct quadrature, from the table's end downward.
    double hi = table_.back().separation, lo = hi - step_;
    while (at_separation(lo).nominal_pressure < p) {
      hi = lo;
      lo -= 2.0 * (table_.front().separation - lo);
    }
    for (int i = 0; i < 200 && hi - lo > 1e-12 * surface_.summit_sigma; ++i) {
      const double mid = 0.5 * (lo + hi);
      (at_separation(mid).nominal_pressure < p ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  }
  if (it == table_.begin()) return z_high_;
  const SurfaceContact& b = *it;
  const SurfaceContact& a = *(it - 1);
  double t;
  if (a.nominal_pressure > 0.0)
    t = std::log(p / a.nominal_pressure) / std::log(b.nominal_pressure / a.nominal_pressure);
  else t = (p - a.nominal_pressure) / (b.nominal_pressure - a.nominal_pressure);
  return a.separation - std::clamp(t, 0.0, 1.0) * step_;
}

double GreenwoodWilliamson::highest_summit(double nominal_area) const {
  const double n = surface_.summit_density * nominal_area;
  if (!(n > 1.0)) return 0.0;
  const double s = surface_.summit_sigma;
  if (surface_.distribution == surface::HeightDistribution::gaussian)
    return s * boost::math::quantile(boost::math::complement(boost::math::normal(), 1.0 / n));
  return s * std::log(n);
}

}  // namespace geartrib::contact
