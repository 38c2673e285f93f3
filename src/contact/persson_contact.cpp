#include "contact/persson_contact.hpp"

#include "core/power_law_integral.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/expint.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

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

// ---- Spectra ----

SpectrumPart SpectrumPart::gaussian(double rq, double correlation_length) {
  SpectrumPart p;
  p.shape = Shape::gaussian;
  p.rq = rq;
  p.correlation_length = correlation_length;
  p.validate();
  return p;
}

SpectrumPart SpectrumPart::self_affine(double rq, double rolloff, double cutoff, double hurst, double lower) {
  SpectrumPart p;
  p.shape = Shape::self_affine;
  p.rq = rq;
  p.rolloff = rolloff;
  p.cutoff = cutoff;
  p.hurst = hurst;
  p.lower = lower;
  p.validate();
  return p;
}

SpectrumPart SpectrumPart::tabulated(std::vector<double> nodes, std::vector<double> values) {
  SpectrumPart p;
  p.shape = Shape::tabulated;
  p.nodes = std::move(nodes);
  p.values = std::move(values);
  p.validate();
  p.rq = std::sqrt(2.0 * kPi * p.moment(1, std::numeric_limits<double>::infinity()));
  return p;
}

void SpectrumPart::validate() const {
  if (shape == Shape::tabulated) {
    if (nodes.size() < 2 || values.size() != nodes.size())
      throw std::invalid_argument("spectrum: a table needs at least two nodes and one value per node");
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (!(nodes[k] > 0.0) || !std::isfinite(nodes[k]) || (k > 0 && !(nodes[k] > nodes[k - 1])))
        throw std::invalid_argument("spectrum: a table's wavenumbers must be positive, finite and increasing");
      if (!(values[k] >= 0.0) || !std::isfinite(values[k]))
        throw std::invalid_argument("spectrum: a table's C(q) must be finite and not negative");
    }
    bool power = false;  // a segment with both ends positive
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) power = power || (values[k] > 0.0 && values[k + 1] > 0.0);
    if (!power) throw std::invalid_argument("spectrum: the table carries no power (no segment with both ends above 0)");
    return;
  }
  if (!(rq > 0.0) || !std::isfinite(rq)) throw std::invalid_argument("spectrum: rq must be positive");
  if (shape == Shape::gaussian) {
    if (!(correlation_length > 0.0) || !std::isfinite(correlation_length))
      throw std::invalid_argument("spectrum: the correlation length must be positive");
    return;
  }
  if (!(hurst > 0.0 && hurst < 1.0)) throw std::invalid_argument("spectrum: the Hurst exponent must lie in (0, 1)");
  if (!(lower >= 0.0 && rolloff > lower && cutoff > rolloff) || !std::isfinite(cutoff))
    throw std::invalid_argument("spectrum: need 0 <= q_l < q_r < q_1");
}

namespace {
// The self-affine shape's integral_{q_l}^{q} q'^n c(q') dq' with c = 1 on the plateau: the plateau's
// part and the power law's, (q_r^{n+1}) (t^e - 1)/e, t = q/q_r, e = n + 1 - 2(1 + H) (never 0 for H in (0, 1)).
double self_affine_shape_moment(const SpectrumPart& s, int n, double q) {
  if (!(q > s.lower)) return 0.0;
  const double np1 = n + 1.0;
  const double top = std::min(q, s.rolloff);
  double m = (std::pow(top, np1) - std::pow(s.lower, np1)) / np1;
  if (q > s.rolloff) {
    const double e = np1 - 2.0 * (1.0 + s.hurst);
    const double t = std::min(q, s.cutoff) / s.rolloff;
    m += std::pow(s.rolloff, np1) * std::expm1(e * std::log(t)) / e;
  }
  return m;
}
// C0 of the self-affine part: rq^2 = 2 pi C0 (shape's first moment).
double self_affine_level(const SpectrumPart& s) {
  return s.rq * s.rq / (2.0 * kPi * self_affine_shape_moment(s, 1, s.cutoff));
}
// The tabulated shape's segment k (nodes k and k + 1): its exponent s_k, or NaN where an end is 0.
double table_exponent(const SpectrumPart& s, std::size_t k) {
  const double c0 = s.values[k], c1 = s.values[k + 1];
  if (!(c0 > 0.0 && c1 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::log(c1 / c0) / std::log(s.nodes[k + 1] / s.nodes[k]);
}
double table_psd(const SpectrumPart& s, double q) {
  if (!(q >= s.nodes.front() && q <= s.nodes.back())) return 0.0;
  const auto k = static_cast<std::size_t>(std::upper_bound(s.nodes.begin(), s.nodes.end(), q) - s.nodes.begin()) - 1;
  if (q == s.nodes[k]) return s.values[k];  // a node's own value (the last node's too)
  const double e = table_exponent(s, k);
  return std::isnan(e) ? 0.0 : s.values[k] * std::pow(q / s.nodes[k], e);
}

}  // namespace

double SpectrumPart::psd(double q) const {
  if (shape == Shape::gaussian) {
    const double l = correlation_length;
    return rq * rq * l * l / (4.0 * kPi) * std::exp(-0.25 * q * q * l * l);
  }
  if (shape == Shape::tabulated) return table_psd(*this, q);
  if (q < lower || q > cutoff) return 0.0;
  const double c0 = self_affine_level(*this);
  return q < rolloff ? c0 : c0 * std::pow(q / rolloff, -2.0 * (1.0 + hurst));
}

double SpectrumPart::moment(int n, double q) const {
  if (n != 1 && n != 3 && n != 5) throw std::invalid_argument("spectrum: moments of order 1, 3 and 5 only");
  if (!(q > 0.0)) return 0.0;
  if (shape == Shape::gaussian) {
    // t = q^2 lambda^2/4: integral = rq^2 2^(n-2) lambda^(1-n)/pi Gamma(a) P(a, T), a = (n+1)/2.
    const double l = correlation_length, a = 0.5 * (n + 1);
    const double whole = rq * rq * std::pow(2.0, n - 2) * std::pow(l, 1 - n) / kPi * std::tgamma(a);
    return std::isfinite(q) ? whole * boost::math::gamma_p(a, 0.25 * q * q * l * l) : whole;
  }
  if (shape == Shape::tabulated) return core::log_log_moment(nodes, values, n, 0.0, q);
  return self_affine_level(*this) * self_affine_shape_moment(*this, n, q);
}

double RoughnessSpectrum::psd(double q) const {
  double c = 0.0;
  for (const SpectrumPart& p : parts) c += p.psd(q);
  return c;
}

double RoughnessSpectrum::moment(int n, double q) const {
  double m = 0.0;
  for (const SpectrumPart& p : parts) m += p.moment(n, q);
  return m;
}

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

double RoughnessSpectrum::rms_height() const { return std::sqrt(2.0 * kPi * moment(1, kInfinity)); }
double RoughnessSpectrum::rms_gradient() const { return std::sqrt(2.0 * kPi * moment(3, kInfinity)); }
double RoughnessSpectrum::profile_m0() const { return 2.0 * kPi * moment(1, kInfinity); }
double RoughnessSpectrum::profile_m2() const { return kPi * moment(3, kInfinity); }
double RoughnessSpectrum::profile_m4() const { return 0.75 * kPi * moment(5, kInfinity); }

SpectrumPart fit_self_affine_spectrum(double m0, double m2, double m4, double hurst) {
  if (!(m0 > 0.0 && m2 > 0.0 && m4 > 0.0) || !std::isfinite(m0 * m2 * m4))
    throw std::invalid_argument("spectrum fit: the moments must be positive");
  if (!(hurst > 0.0 && hurst < 1.0)) throw std::invalid_argument("spectrum fit: the Hurst exponent must lie in (0, 1)");
  // The shape's moments in units of q_r^(n+1) (q_r = 1) at z = q_1/q_r; alpha = m0 m4/m2^2 =
  // (2 pi)(3 pi/4)/pi^2 I1 I5/I3^2, 2 at z = 1 and growing as z^(2H).
  const auto shape = [hurst](double z, int n) {
    SpectrumPart s;
    s.shape = SpectrumPart::Shape::self_affine;
    s.rolloff = 1.0, s.cutoff = z, s.hurst = hurst;
    return self_affine_shape_moment(s, n, z);
  };
  const auto alpha = [&](double ln_z) {
    const double z = std::exp(ln_z);
    const double i3 = shape(z, 3);
    return 1.5 * shape(z, 1) * shape(z, 5) / (i3 * i3);
  };
  const double target = m0 * m4 / (m2 * m2);
  if (!(target > 2.0))
    throw std::invalid_argument(
        "spectrum fit: the moments' bandwidth m0 m4/m2^2 is at most 2, narrower than any self-affine spectrum with "
        "a roll-off (2: its plateau alone)");
  double hi = 1.0;
  while (alpha(hi) < target && hi < 700.0) hi *= 2.0;
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      [&](double x) { return alpha(x) - target; }, 0.0, hi,
      [](double l, double r) { return std::abs(r - l) <= 1e-13 * std::max(1.0, std::abs(l)); }, iterations);
  const double z = std::exp(0.5 * (a + b));
  // m2/m0 = (pi I3 q_r^4)/(2 pi I1 q_r^2).
  const double q_r = std::sqrt(2.0 * shape(z, 1) * m2 / (shape(z, 3) * m0));
  return SpectrumPart::self_affine(std::sqrt(m0), q_r, z * q_r, hurst);
}

// ---- Interfacial separation ----

namespace {
// The quadrature over q: Gauss-Legendre panels in ln q, at most kPanelWidth wide, bounded at the
// spectrum's breaks (C or its slope jumps); the first panel in ln q = a + (b - a) tau^4, which takes
// out w's (q - q_l)^(-1/2) where the spectrum starts at q_l > 0. Without a lower cut the spectrum
// starts kLowestWavenumber below its first feature: the part left out weighs that fraction of u
// (q^2 C w -> 2 sqrt(C(0)) as q -> 0).
constexpr double kPanelWidth = 0.5;
constexpr double kLowestWavenumber = 1e-8;
constexpr int kPanelPoints = 8;
using PanelGauss = boost::math::quadrature::gauss<double, kPanelPoints>;
// A Gaussian part's wavenumber beyond which its C is left out: q lambda/2 = sqrt(50), the slope
// variance beyond it (1 + T) e^-T = 1e-20 of the whole.
constexpr double kGaussianEnd = 14.15;
// The table in s = ln(p/E*): its step, its extent below the top (p falls by e^-50 over it: the
// asymptote's slope u0 reached there to far below the table's own error) and Gauss points a step.
constexpr double kTableStep = 0.1;
constexpr double kTableExtent = 50.0;
constexpr double kCompleteContact = 6.0;  // w p/E* at the table's top, every node's
using StepGauss = boost::math::quadrature::gauss<double, 4>;

std::vector<double> breaks(const RoughnessSpectrum& c) {
  std::vector<double> b;
  double first = kInfinity, last = 0.0;
  bool open = false;  // a part reaching q = 0
  for (const SpectrumPart& p : c.parts) {
    if (p.shape == SpectrumPart::Shape::gaussian) {
      first = std::min(first, 2.0 / p.correlation_length);
      last = std::max(last, kGaussianEnd * 2.0 / p.correlation_length);
      open = true;
      continue;
    }
    if (p.shape == SpectrumPart::Shape::tabulated) {      // C's slope changes at every node; it starts at
      b.insert(b.end(), p.nodes.begin(), p.nodes.end());  // its first segment with power
      std::size_t k = 0;
      while (k + 2 < p.nodes.size() && !(p.values[k] > 0.0 && p.values[k + 1] > 0.0)) ++k;
      first = std::min(first, p.nodes[k]);
      last = std::max(last, p.nodes.back());
      continue;
    }
    if (p.lower > 0.0) b.push_back(p.lower);
    open = open || p.lower == 0.0;
    first = std::min(first, p.lower > 0.0 ? p.lower : p.rolloff);
    b.push_back(p.rolloff);
    b.push_back(p.cutoff);
    last = std::max(last, p.cutoff);
  }
  const double start = open ? kLowestWavenumber * first : first;
  b.push_back(start);
  b.push_back(last);
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  b.erase(std::remove_if(b.begin(), b.end(), [&](double q) { return q < start || q > last; }), b.end());
  return b;
}
}  // namespace

PerssonSeparation::PerssonSeparation(const RoughnessSpectrum& c, double e_star, double gamma)
    : e_star_(e_star), gamma_(gamma) {
  if (c.parts.empty()) throw std::invalid_argument("Persson: the spectrum has no part");
  for (const SpectrumPart& p : c.parts) p.validate();
  if (!(e_star > 0.0) || !std::isfinite(e_star)) throw std::invalid_argument("Persson: the modulus must be positive");
  if (!(gamma > 0.0 && gamma <= 1.0)) throw std::invalid_argument("Persson: gamma must lie in (0, 1]");
  rms_gradient_ = c.rms_gradient();
  rms_height_ = c.rms_height();
  // The nodes over q.
  const std::vector<double> b = breaks(c);
  bool first = true;
  for (std::size_t j = 0; j + 1 < b.size(); ++j) {
    const double t0 = std::log(b[j]), t1 = std::log(b[j + 1]);
    const int panels = std::max(1, static_cast<int>(std::ceil((t1 - t0) / kPanelWidth)));
    for (int k = 0; k < panels; ++k) {
      const double a = t0 + (t1 - t0) * k / panels, len = (t1 - t0) / panels;
      const auto& x = PanelGauss::abscissa();
      const auto& wt = PanelGauss::weights();
      for (std::size_t i = 0; i < x.size(); ++i)
        for (double sign : {-1.0, 1.0}) {
          if (x[i] == 0.0 && sign > 0.0) continue;
          const double xi = 0.5 * (1.0 + sign * x[i]);  // on [0, 1]
          double t = a + len * xi, jac = len * 0.5 * wt[i];
          if (first) t = a + len * std::pow(xi, 4), jac *= 4.0 * std::pow(xi, 3);  // ln q = a + len tau^4
          const double q = std::exp(t);
          const double m3 = c.moment(3, q);
          if (!(m3 > 0.0)) continue;  // below the spectrum's start
          const double w = 1.0 / std::sqrt(kPi * m3);
          w_.push_back(w);
          weight_.push_back(jac * q * std::sqrt(kPi) * q * q * c.psd(q) * w);  // dq = q d(ln q)
        }
      first = false;
    }
  }
  double sum = 0.0;
  for (double v : weight_) sum += v;
  u0_ = gamma_ * sum;
  // The table: from the top (every wavelength near complete contact) down, u(s_k) = u(s_{k-1}) +
  // integral of the slope over the step.
  const double w_min = *std::min_element(w_.begin(), w_.end());
  top_ = std::log(kCompleteContact / w_min);
  step_ = kTableStep;
  const int n = static_cast<int>(std::lround(kTableExtent / step_));
  std::vector<double> u(static_cast<std::size_t>(n) + 1), d(u.size());
  u[0] = near_complete(top_);
  d[0] = slope(top_);
  for (int k = 1; k <= n; ++k) {
    const double hi = top_ - (k - 1) * step_, lo = hi - step_;
    const auto kk = static_cast<std::size_t>(k);
    u[kk] = u[kk - 1] + StepGauss::integrate([&](double s) { return slope(s); }, lo, hi);
    d[kk] = slope(lo);
  }
  // Interpolated as ln u (positive, and smooth where u falls as exp(-c e^{2s}) near complete contact).
  log_u_.resize(u.size());
  log_slope_.resize(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) log_u_[k] = std::log(u[k]), log_slope_[k] = -d[k] / u[k];
  // Below the table: u = u0 (ln beta - s).
  beta_ = std::exp(u.back() / u0_ + (top_ - n * step_));
}

double PerssonSeparation::slope(double s) const {
  const double e = std::exp(s);
  double d = 0.0;
  for (std::size_t i = 0; i < w_.size(); ++i) {
    const double x = w_[i] * e;
    if (x > 40.0) continue;  // exp(-1600)
    const double f = std::erf(x);
    d += weight_[i] * (gamma_ + 3.0 * (1.0 - gamma_) * f * f) * std::exp(-x * x);
  }
  return d;
}

double PerssonSeparation::near_complete(double s) const {
  const double e = std::exp(s);
  double u = 0.0;
  for (std::size_t i = 0; i < w_.size(); ++i) {
    const double x = w_[i] * e;
    if (x > 40.0) continue;
    u += weight_[i] * boost::math::expint(1, x * x);
  }
  return 0.5 * (3.0 - 2.0 * gamma_) * u;
}

double PerssonSeparation::separation(double p) const {
  if (!(p >= 0.0) || std::isnan(p)) throw std::invalid_argument("Persson: the pressure must be >= 0");
  if (p == 0.0) return kInfinity;
  const double s = std::log(p / e_star_);
  if (s >= top_) return near_complete(s);
  const double bottom = top_ - step_ * static_cast<double>(log_u_.size() - 1);
  if (s <= bottom) return std::exp(log_u_.back()) + u0_ * (bottom - s);
  // Cubic Hermite of ln u on [s_{k+1}, s_k] in t = (s - s_{k+1})/h.
  const auto k = std::min(log_u_.size() - 2, static_cast<std::size_t>((top_ - s) / step_));
  const double h = step_, t = (s - (top_ - static_cast<double>(k + 1) * h)) / h;
  const double t2 = t * t, t3 = t2 * t;
  return std::exp((2 * t3 - 3 * t2 + 1) * log_u_[k + 1] + (t3 - 2 * t2 + t) * h * log_slope_[k + 1] +
                  (3 * t2 - 2 * t3) * log_u_[k] + (t3 - t2) * h * log_slope_[k]);
}

double PerssonSeparation::pressure(double u) const {
  if (std::isnan(u)) throw std::invalid_argument("Persson: the separation is NaN");
  if (!(u > 0.0)) return kInfinity;
  if (u == kInfinity) return 0.0;
  const double bottom = top_ - step_ * static_cast<double>(log_u_.size() - 1);
  const double lu = std::log(u), u_bottom = std::exp(log_u_.back());
  if (u >= u_bottom) return e_star_ * std::exp(bottom - (u - u_bottom) / u0_);
  std::uintmax_t iterations = 200;
  const auto tol = [](double l, double r) { return std::abs(r - l) <= 1e-14 * std::max(1.0, std::abs(l)); };
  const auto f = [&](double s) { return std::log(separation(e_star_ * std::exp(s))) - lu; };
  if (lu <= log_u_.front()) {  // near complete contact: beyond the table's top
    double hi = top_ + 0.25;
    while (f(hi) > 0.0 && hi < top_ + 8.0) hi += 0.25;
    if (!(f(hi) <= 0.0)) return e_star_ * std::exp(hi);  // u below what the double resolves there
    const auto [a, b] = boost::math::tools::toms748_solve(f, top_, hi, tol, iterations);
    return e_star_ * std::exp(0.5 * (a + b));
  }
  // ln u rises with k: the step whose ends bracket it.
  const auto it = std::upper_bound(log_u_.begin(), log_u_.end(), lu);
  const auto k = static_cast<double>(it - log_u_.begin());  // log_u_[k-1] < lu <= log_u_[k]
  const double hi = top_ - (k - 1.0) * step_, lo = top_ - k * step_;
  if (f(lo) <= 0.0) return e_star_ * std::exp(lo);
  if (f(hi) >= 0.0) return e_star_ * std::exp(hi);
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, tol, iterations);
  return e_star_ * std::exp(0.5 * (a + b));
}

}  // namespace geartrib::contact
