#include "contact/greenwood_williamson.hpp"

#include "core/keyed_error.hpp"

#include <fmt/format.h>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace geartrib::contact {

RoughSurfaceOverload::RoughSurfaceOverload(double nominal_pressure)
    : std::invalid_argument(
          fmt::format("nominal pressure {:.6g} Pa is beyond what the rough surface can carry at any separation",
                      nominal_pressure)) {}

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
    throw core::KeyedError("height_points",
                           fmt::format("height_points must lie in [{}, {}]", kMinHeightPoints, kMaxHeightPoints));
  if (table_points_per_sigma < kMinTablePoints || table_points_per_sigma > kMaxTablePoints)
    throw core::KeyedError("table_points_per_sigma", fmt::format("table_points_per_sigma must lie in [{}, {}]",
                                                                 kMinTablePoints, kMaxTablePoints));
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
  const double target = 1.05 * max_pressure;
  if (surface_.distribution == surface::HeightDistribution::gaussian) {
    // Stride down by sigma (direct quadrature) to the depth the table must reach; within
    // kSharedDepth, build the table on nodes shared by all its separations (gaussian_table).
    double d = z_high_;
    while (at_separation(d).nominal_pressure < target && z_high_ - d <= kSharedDepth * s) d -= s;
    if (z_high_ - d <= kSharedDepth * s) {
      gaussian_table(static_cast<int>(std::ceil((z_high_ - d) / step_)) + 1);
      const auto last = std::find_if(table_.begin() + 1, table_.end(),
                                     [&](const SurfaceContact& c) { return c.nominal_pressure >= target; });
      if (last != table_.end()) table_.erase(last + 1, table_.end());
    }
  }
  // The deepest separation the table may reach, tried first: a pressure beyond it is refused at
  // once rather than after ~10^5 table rows (seconds).
  constexpr double kDeepest = -1e4;  // [sigma]
  if (!(table_.size() >= 2 && table_.back().nominal_pressure >= target) &&
      at_separation(kDeepest * s).nominal_pressure < target)
    throw RoughSurfaceOverload(max_pressure);
  // The rest (all of it for the exponential distribution) by direct quadrature per separation.
  while (!(table_.size() >= 2 && table_.back().nominal_pressure >= target)) {
    const double d = z_high_ - static_cast<double>(table_.size()) * step_;
    table_.push_back(at_separation(d));
    if (table_.size() >= 2 && table_.back().nominal_pressure >= target) break;
    if (d < kDeepest * s) throw RoughSurfaceOverload(max_pressure);
  }
  build_cells();
}

void GreenwoodWilliamson::build_cells() {
  const double top = table_.back().nominal_pressure;
  // Segments [k, k+1] with both pressures above the floor.
  std::size_t k0 = 0;
  while (k0 + 1 < table_.size() && !(table_[k0].nominal_pressure > kCellFloor * top)) ++k0;
  for (std::size_t k = k0; k < table_.size(); ++k) segment_pressure_.push_back(table_[k].nominal_pressure);
  using Q = double SurfaceContact::*;
  constexpr Q quantities[4] = {&SurfaceContact::real_area_ratio, &SurfaceContact::contact_density,
                               &SurfaceContact::plastic_area_ratio, &SurfaceContact::plastic_contact_density};
  const double log_cell = std::log(kCellRatio);
  std::vector<double> value[4], slope[4];
  for (std::size_t k = k0; k + 1 < table_.size(); ++k) {
    cell_start_.push_back(cells_.size());
    const SurfaceContact &a = table_[k], &b = table_[k + 1];
    // In the segment, t = ln(p/pa)/L, L = ln(pb/pa), and each quantity is blend(Qa, Qb, t):
    // Q = Qa (Qb/Qa)^t (both positive) or Qa + (Qb - Qa) t; dQ/dp = dQ/dt / (L p).
    const double length = std::log(b.nominal_pressure / a.nominal_pressure);
    if (!(length > 0.0)) {  // a flat segment (never chosen by the search): a constant cell
      Cell cell;
      cell.p_lo = a.nominal_pressure;
      for (int q = 0; q < 4; ++q) cell.c[q][0] = a.*quantities[q];
      cells_.push_back(cell);
      continue;
    }
    // n cells, uniform in p; the law's value and slope at their n + 1 ends (the table's own
    // values at the segment's ends).
    const int n = std::max(1, static_cast<int>(std::ceil(length / log_cell)));
    const double width = (b.nominal_pressure - a.nominal_pressure) / n;
    auto end = [&](int j) { return j == n ? b.nominal_pressure : a.nominal_pressure + j * width; };
    for (int q = 0; q < 4; ++q) {
      const double qa = a.*quantities[q], qb = b.*quantities[q];
      const bool geometric = qa > 0.0 && qb > 0.0;
      const double log_ratio = geometric ? std::log(qb / qa) : 0.0;
      value[q].resize(static_cast<std::size_t>(n) + 1);
      slope[q].resize(static_cast<std::size_t>(n) + 1);
      for (int j = 0; j <= n; ++j) {
        const double p = end(j), t = std::log(p / a.nominal_pressure) / length;
        const double v = j == 0 ? qa : j == n ? qb : geometric ? qa * std::exp(t * log_ratio) : qa + (qb - qa) * t;
        value[q][static_cast<std::size_t>(j)] = v;
        slope[q][static_cast<std::size_t>(j)] = (geometric ? v * log_ratio : qb - qa) / (length * p);
      }
    }
    for (int j = 0; j < n; ++j) {
      Cell cell;
      cell.p_lo = end(j);
      const double w = end(j + 1) - cell.p_lo;
      cell.inv_width = 1.0 / w;
      const auto i = static_cast<std::size_t>(j);
      for (int q = 0; q < 4; ++q) {
        const double v0 = value[q][i], v1 = value[q][i + 1];
        const double m0 = slope[q][i] * w, m1 = slope[q][i + 1] * w;  // cubic Hermite in tau = (p - p_lo)/w
        cell.c[q][0] = v0;
        cell.c[q][1] = m0;
        cell.c[q][2] = 3.0 * (v1 - v0) - 2.0 * m0 - m1;
        cell.c[q][3] = 2.0 * (v0 - v1) + m0 + m1;
      }
      cells_.push_back(cell);
    }
  }
  cell_start_.push_back(cells_.size());
}

ContactAtPressure GreenwoodWilliamson::at_pressure(double p, std::size_t& segment) const {
  if (segment_pressure_.size() < 2 || !(p >= segment_pressure_.front()) || !(p < segment_pressure_.back())) {
    const SurfaceContact c = interpolate(separation_for_pressure(p));
    return {c.real_area_ratio, c.contact_density, c.plastic_area_ratio, c.plastic_contact_density};
  }
  // The segment k with P_k <= p < P_k+1 (from the caller's last, else by bisection), then its
  // cell (uniform in p within the segment).
  std::size_t k = segment;
  if (k + 1 >= segment_pressure_.size() || p < segment_pressure_[k]) k = 0;
  for (int step = 0; step < 4 && p >= segment_pressure_[k + 1]; ++step) ++k;
  if (p >= segment_pressure_[k + 1])
    k = static_cast<std::size_t>(
        std::upper_bound(segment_pressure_.begin() + static_cast<std::ptrdiff_t>(k), segment_pressure_.end(), p) -
        segment_pressure_.begin() - 1);
  segment = k;
  const std::size_t first = cell_start_[k], count = cell_start_[k + 1] - first;
  const double pa = segment_pressure_[k], pb = segment_pressure_[k + 1];
  const std::size_t j =
      std::min(count - 1, static_cast<std::size_t>((p - pa) / (pb - pa) * static_cast<double>(count)));
  const Cell& cell = cells_[first + j];
  const double tau = (p - cell.p_lo) * cell.inv_width;
  double out[4];
  for (int q = 0; q < 4; ++q) out[q] = cell.c[q][0] + tau * (cell.c[q][1] + tau * (cell.c[q][2] + tau * cell.c[q][3]));
  return {out[0], out[1], out[2], out[3]};
}

void GreenwoodWilliamson::gaussian_table(int entries) {
  // The separations d_k = z_high - k h share one quadrature in the interference u over
  // [0, z_high - d_last] (u = v^2, composite Gauss-Legendre in v with panel ends at the model's
  // breakpoints, height_points in all): the model is evaluated once per node, and the Gaussian
  // density follows by recurrence in k (lengths over sigma):
  //   exp(-(d_k + u)^2/2) = m_k(u) exp(-(k h)^2/2),  m_k = exp(-(z_high + u)^2/2) r^k,
  //   r = exp(h (z_high + u)),
  // one multiply-add per node and separation. Within kSharedDepth sigma, m_k stays within
  // exp(+-600): no overflow or underflow.
  const double s = surface_.summit_sigma, h = step_ / s, z = z_high_ / s;
  const double u_end = (entries - 1) * step_;
  // Panel ends: the breakpoints, and a geometric grading towards u = 0 (sigma 4^-j, up to five
  // levels, one per three panels), where the shallow separations' integrands live (within
  // ~sigma^2/d of the onset).
  const int panels = options_.height_points / kGaussPoints;
  std::vector<double> ends{0.0};
  for (double b : breaks_)
    if (b < u_end) ends.push_back(std::sqrt(b));
  double g = s;
  for (int level = 0; level < std::min(5, panels / 3); ++level, g /= 4.0)
    if (g < u_end) ends.push_back(std::sqrt(g));
  std::sort(ends.begin(), ends.end());
  ends.push_back(std::sqrt(u_end));
  const double eta = surface_.summit_density / (s * std::sqrt(2.0 * std::numbers::pi));
  std::vector<double> load, area, plastic, m, r;
  for (std::size_t seg = 0; seg + 1 < ends.size(); ++seg) {
    const double length = ends[seg + 1] - ends[seg];
    if (!(length > 0.0)) continue;
    const int n = std::max(1, static_cast<int>(std::lround(panels * length / ends.back())));
    const double hp = length / n;
    for (int k = 0; k < n; ++k)
      for (std::size_t i = 0; i < Gauss::abscissa().size(); ++i)
        for (int sign : {-1, 1}) {
          if (i == 0 && sign == 1 && kGaussPoints % 2 == 1) continue;
          const double v = ends[seg] + k * hp + 0.5 * hp * (1.0 + sign * Gauss::abscissa()[i]);
          const double w = 0.5 * hp * Gauss::weights()[i] * 2.0 * v * eta;
          const double u = v * v;
          const asperity::AsperityState st = model_.evaluate(pair_, u, asperity::Detail::load_area);
          load.push_back(st.load * w);
          area.push_back(st.area * w);
          plastic.push_back(options_.plastic ? st.area * st.plastic_fraction * w : 0.0);
          const double x = z + u / s;
          m.push_back(std::exp(-0.5 * x * x));
          r.push_back(std::exp(h * x));
        }
  }
  const std::size_t nodes = m.size();
  table_.reserve(static_cast<std::size_t>(entries));
  for (int k = 0; k < entries; ++k) {
    double p = 0.0, a = 0.0, pa = 0.0;
    for (std::size_t j = 0; j < nodes; ++j) {
      p += load[j] * m[j];
      a += area[j] * m[j];
      pa += plastic[j] * m[j];
      m[j] *= r[j];
    }
    const double e = std::exp(-0.5 * (k * h) * (k * h));
    SurfaceContact c;
    c.separation = z_high_ - k * step_;
    c.nominal_pressure = p * e;
    c.real_area_ratio = a * e;
    c.plastic_area_ratio = pa * e;
    c.contact_density = contact_density(c.separation);
    c.plastic_contact_density = contact_density(c.separation + delta_c_);
    table_.push_back(c);
  }
}

double GreenwoodWilliamson::density(double z) const {
  const double s = surface_.summit_sigma;
  if (surface_.distribution == surface::HeightDistribution::gaussian)
    return std::exp(-0.5 * (z / s) * (z / s)) / (s * std::sqrt(2.0 * std::numbers::pi));
  return z >= 0.0 ? std::exp(-z / s) / s : 0.0;
}

SurfaceContact GreenwoodWilliamson::at_separation(double d, bool plastic) const {
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
          if (plastic) c.plastic_area_ratio += st.area * st.plastic_fraction * phi;
        }
      }
    }
  }
  c.contact_density = contact_density(d);
  c.plastic_contact_density = contact_density(d + delta_c_);
  return c;
}

double GreenwoodWilliamson::contact_density(double d) const {
  // eta times the share of summits above d, in closed form.
  const double s = surface_.summit_sigma;
  if (surface_.distribution == surface::HeightDistribution::gaussian)
    return surface_.summit_density * 0.5 * std::erfc(d / (s * std::sqrt(2.0)));
  return surface_.summit_density * (d <= 0.0 ? 1.0 : std::exp(-d / s));
}

GreenwoodWilliamson::TablePosition GreenwoodWilliamson::table_position(double d) const {
  const double x = (z_high_ - d) / step_;
  const std::size_t k = static_cast<std::size_t>(std::floor(x));
  return {k, x - static_cast<double>(k)};
}

SurfaceContact GreenwoodWilliamson::interpolate(double d) const {
  if (d >= z_high_) return SurfaceContact{d, 0, 0, 0, 0, 0};
  const auto [k, t] = table_position(d);
  if (k + 1 >= table_.size()) {
    // Below the table: the caller asked for more than max_pressure; compute directly.
    return at_separation(d);
  }
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

double GreenwoodWilliamson::pressure(double d) const {
  // interpolate(d).nominal_pressure alone.
  if (d >= z_high_) return 0.0;
  const auto [k, t] = table_position(d);
  if (k + 1 >= table_.size()) return at_separation(d).nominal_pressure;
  return blend(table_[k].nominal_pressure, table_[k + 1].nominal_pressure, t);
}

double GreenwoodWilliamson::pressure_slope(double d) const {
  if (d >= z_high_) return 0.0;
  const std::size_t k = std::min(table_position(d).k, table_.size() - 2);
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
    for (int doubling = 0; at_separation(lo).nominal_pressure < p; ++doubling) {
      if (doubling == 200)  // the depth doubles each time: far past any pressure the table allows
        throw RoughSurfaceOverload(p);
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
  if (surface_.distribution == surface::HeightDistribution::gaussian) {
    // In double precision (Boost's default promotes to long double: 10x slower, no gain at 1e-16).
    using Policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
    return s *
           boost::math::quantile(boost::math::complement(boost::math::normal_distribution<double, Policy>(), 1.0 / n));
  }
  return s * std::log(n);
}

}  // namespace geartrib::contact
