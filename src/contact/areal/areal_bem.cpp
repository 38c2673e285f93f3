#include "contact/areal/areal_bem.hpp"

#include "core/fftw_planner.hpp"
#include "core/keyed_error.hpp"
#include "core/log_antiderivative.hpp"

#include <fmt/format.h>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/bessel.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace geartrib::contact::areal {

namespace {

constexpr double kPi = std::numbers::pi;
thread_local long executed_transforms = 0;

// Points of a transform's axis: the window's (periodic) or twice it (open: zero-padded).
int padded(int n, bool periodic) { return periodic ? n : 2 * n; }
// The signed wave index of FFT bin k of m.
int signed_index(int k, int m) { return k <= m / 2 ? k : k - m; }

// x asinh(y/|x|) + y asinh(x/|y|): Love's (1929) integral of 1/r over the quadrant to (x, y), less
// its functions of x or of y alone (which cancel between an element's corners). Stable where
// x ln(y + r) + y ln(x + r) loses digits (y < 0, |y| ~ r).
double love_corner(double x, double y) {
  double f = 0.0;
  if (x != 0.0) f += x * std::asinh(y / std::abs(x));
  if (y != 0.0) f += y * std::asinh(x / std::abs(y));
  return f;
}

// One open direction's influence under the other direction's Fourier mode q [1/m]: the pressure
// p(x) e^{i q y} piecewise constant over elements of width h displaces the surface by
// (2/(pi E*)) integral K_0(|q| |x - xi|) p(xi) dxi (the Fourier transform along y of 1/(pi E* r)).
// For q = 0 the line load's -(2/(pi E*)) ln|x| (its constant is a rigid shift: the approach of a
// window periodic in one direction alone is not defined). Offsets 0..n-1 [m/Pa].
std::vector<double> open_influence_under_mode(int n, double h, double q, double e_star) {
  std::vector<double> k(static_cast<std::size_t>(n), 0.0);
  if (q == 0.0) {
    for (int m = 0; m < n; ++m)
      k[static_cast<std::size_t>(m)] =
          -2.0 / (kPi * e_star) * (core::log_antiderivative((m + 0.5) * h) - core::log_antiderivative((m - 0.5) * h));
    return k;
  }
  // J(X) = integral_0^X K_0(t) dt, odd; J(inf) = pi/2. Increments by Gauss-Legendre on pieces of
  // at most 0.5 (K_0 is smooth away from 0), the first piece by tanh-sinh (K_0's log at 0).
  auto k0 = [](double t) { return boost::math::cyl_bessel_k(0, t); };
  const double x0 = q * 0.5 * h;
  boost::math::quadrature::tanh_sinh<double> tanh_sinh;
  double j_prev = x0 > 40.0 ? kPi / 2.0 : tanh_sinh.integrate(k0, 0.0, x0);
  const double scale = 2.0 / (kPi * e_star * q);
  k[0] = scale * 2.0 * j_prev;
  double x_prev = x0;
  for (int m = 1; m < n; ++m) {
    const double x = q * (m + 0.5) * h;
    if (x_prev > 40.0) break;  // K_0(40) ~ 1e-18: the rest adds nothing
    const int pieces = std::max(1, static_cast<int>(std::ceil((x - x_prev) / 0.5)));
    double inc = 0.0;
    for (int s = 0; s < pieces; ++s) {
      const double a = x_prev + (x - x_prev) * s / pieces, b = x_prev + (x - x_prev) * (s + 1) / pieces;
      inc += boost::math::quadrature::gauss<double, 10>::integrate(k0, a, b);
    }
    k[static_cast<std::size_t>(m)] = scale * inc;
    x_prev = x;
  }
  return k;
}

// Even sequences k[|m|] (m from -(n-1) to n-1) on a cyclic axis of 2n points, transformed: the
// (real) DFT at every bin 0..2n-1. One plan for every sequence of the axis.
class EvenSpectrum {
 public:
  explicit EvenSpectrum(int n)
      : n_(n),
        real_(fftw_real_array(2 * static_cast<std::size_t>(n))),
        spectrum_(fftw_complex_array(static_cast<std::size_t>(n) + 1)),
        plan_([&] { return fftw_plan_dft_r2c_1d(2 * n, real_.get(), spectrum_.get(), FFTW_ESTIMATE); }) {}
  std::vector<double> operator()(const std::vector<double>& k) const {
    const int m = 2 * n_;
    real_[0] = k[0];
    real_[static_cast<std::size_t>(n_)] = 0.0;
    for (int j = 1; j < n_; ++j)
      real_[static_cast<std::size_t>(j)] = real_[static_cast<std::size_t>(m - j)] = k[static_cast<std::size_t>(j)];
    fftw_execute(plan_.get());
    std::vector<double> out(static_cast<std::size_t>(m));
    for (int b = 0; b <= n_; ++b) out[static_cast<std::size_t>(b)] = spectrum_[b][0];
    for (int b = n_ + 1; b < m; ++b) out[static_cast<std::size_t>(b)] = out[static_cast<std::size_t>(m - b)];
    return out;
  }

 private:
  int n_;
  std::unique_ptr<double[], FftwFree> real_;
  std::unique_ptr<fftw_complex[], FftwFree> spectrum_;
  FftwPlan plan_;
};

}  // namespace

void ArealGrid::validate() const {
  if (nx < 1 || ny < 1)
    throw core::KeyedError("points", fmt::format("the grid needs points in both directions ({} x {})", nx, ny));
  if (!(dx > 0.0) || !(dy > 0.0) || !std::isfinite(dx) || !std::isfinite(dy))
    throw core::KeyedError("spacing", fmt::format("the spacing must be positive and finite ({} x {} m)", dx, dy));
}

double areal_solve_bytes(const ArealGrid& g) {
  const double padded_points = static_cast<double>(padded(g.nx, g.periodic_x)) * padded(g.ny, g.periodic_y);
  // The padded real array and its spectrum, the kernel's spectrum and its inverse's (and, open both
  // ways, Love's corner values while it is built); the solve's seven fields; the subsurface stress's
  // padded array, two spectra and six components on the window.
  const double kernel = 8.0 * padded_points + 16.0 * 0.5 * padded_points + 2.0 * 8.0 * 0.5 * padded_points +
                        (!g.periodic_x && !g.periodic_y ? 8.0 * padded_points : 0.0);
  const double stress = 8.0 * padded_points + 2.0 * 16.0 * 0.5 * padded_points + 6.0 * 8.0 * g.size();
  return kernel + 7.0 * 8.0 * g.size() + stress;
}

void ArealOptions::validate() const {
  if (!(composite_modulus > 0.0) || !std::isfinite(composite_modulus))
    throw core::KeyedError("composite_modulus", "the composite modulus must be positive and finite");
  if (!(poisson_ratio >= 0.0 && poisson_ratio < 0.5))
    throw core::KeyedError("poisson_ratio", "Poisson's ratio must lie in [0, 0.5)");
  if (!(hardness > 0.0)) throw core::KeyedError("hardness", "the hardness must be positive (inf: elastic)");
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw core::KeyedError("tolerance", "the tolerance must lie in (0, 1)");
  if (max_iterations < 1) throw core::KeyedError("max_iterations", "at least one iteration");
}

long ElasticKernel::transforms() { return executed_transforms; }

struct ElasticKernel::Transforms {
  std::unique_ptr<double[], FftwFree> real;
  std::unique_ptr<fftw_complex[], FftwFree> spectrum;
  std::unique_ptr<FftwPlan> forward, backward;
};

ElasticKernel::~ElasticKernel() = default;

ElasticKernel::ElasticKernel(const ArealGrid& grid, double e_star) : grid_(grid), e_star_(e_star) {
  grid_.validate();
  if (!(e_star > 0.0) || !std::isfinite(e_star))
    throw core::KeyedError("composite_modulus", "the composite modulus must be positive and finite");
  mx_ = padded(grid_.nx, grid_.periodic_x);
  my_ = padded(grid_.ny, grid_.periodic_y);
  const int hx = mx_ / 2 + 1;
  const std::size_t spectral = static_cast<std::size_t>(my_) * static_cast<std::size_t>(hx);
  fft_ = std::make_unique<Transforms>();
  fft_->real = fftw_real_array(static_cast<std::size_t>(mx_) * static_cast<std::size_t>(my_));
  fft_->spectrum = fftw_complex_array(spectral);
  double* real = fft_->real.get();
  fftw_complex* spectrum = fft_->spectrum.get();
  fft_->forward =
      std::make_unique<FftwPlan>([&] { return fftw_plan_dft_r2c_2d(my_, mx_, real, spectrum, FFTW_ESTIMATE); });
  fft_->backward =
      std::make_unique<FftwPlan>([&] { return fftw_plan_dft_c2r_2d(my_, mx_, spectrum, real, FFTW_ESTIMATE); });
  kernel_hat_.assign(spectral, 0.0);
  const double lx = mx_ * grid_.dx, ly = my_ * grid_.dy;
  const double norm = 1.0 / (static_cast<double>(mx_) * my_);
  auto at = [&](int ky, int kx) -> double& { return kernel_hat_[static_cast<std::size_t>(ky) * hx + kx]; };
  if (grid_.periodic_x && grid_.periodic_y) {
    // 2/(E* |q|) (Stanley & Kato 1997); q = 0, the rigid mode, set aside.
    for (int ky = 0; ky < my_; ++ky)
      for (int kx = 0; kx < hx; ++kx) {
        const double qx = 2.0 * kPi * kx / lx, qy = 2.0 * kPi * signed_index(ky, my_) / ly;
        const double q = std::hypot(qx, qy);
        at(ky, kx) = q > 0.0 ? 2.0 / (e_star * q) * norm : 0.0;
      }
  } else if (!grid_.periodic_x && !grid_.periodic_y) {
    // Love's element influence on the cyclic padded grid, offsets -(n-1)..n-1, from the corners'
    // values (x_a = (a - n + 1/2) dx, a = 0..2n-1; as y): one asinh pair a corner.
    std::fill(real, real + static_cast<std::size_t>(mx_) * my_, 0.0);
    const int cx = 2 * grid_.nx, cy = 2 * grid_.ny;
    std::vector<double> corner(static_cast<std::size_t>(cx) * cy);
    for (int b = 0; b < cy; ++b)
      for (int a = 0; a < cx; ++a)
        corner[static_cast<std::size_t>(b) * cx + a] =
            love_corner((a - grid_.nx + 0.5) * grid_.dx, (b - grid_.ny + 0.5) * grid_.dy) / (kPi * e_star);
    auto c = [&](int a, int b) { return corner[static_cast<std::size_t>(b) * cx + a]; };
    for (int j = -(grid_.ny - 1); j < grid_.ny; ++j)
      for (int i = -(grid_.nx - 1); i < grid_.nx; ++i) {
        const int a = i + grid_.nx - 1, b = j + grid_.ny - 1;  // the element's lower corner
        real[static_cast<std::size_t>(j >= 0 ? j : my_ + j) * mx_ + (i >= 0 ? i : mx_ + i)] =
            c(a + 1, b + 1) - c(a + 1, b) - c(a, b + 1) + c(a, b);
      }
    fftw_execute(fft_->forward->get());
    for (std::size_t s = 0; s < spectral; ++s) kernel_hat_[s] = spectrum[s][0] * norm;  // even: real
  } else {
    // One direction periodic (its modes exact), the other open (its elements' influence per mode).
    const bool open_x = !grid_.periodic_x;
    const int n_open = open_x ? grid_.nx : grid_.ny;
    const double h_open = open_x ? grid_.dx : grid_.dy;
    const int m_per = open_x ? my_ : mx_;
    const double l_per = open_x ? ly : lx;
    const int modes = open_x ? my_ : hx;  // the periodic axis' bins held
    const EvenSpectrum even_spectrum(n_open);
    for (int b = 0; b < modes; ++b) {
      const int sb = open_x ? signed_index(b, m_per) : b;
      if (open_x && sb < 0) continue;  // |q| repeats: filled from its positive twin below
      const double q = 2.0 * kPi * std::abs(sb) / l_per;
      const std::vector<double> spec = even_spectrum(open_influence_under_mode(n_open, h_open, q, e_star));
      if (open_x) {
        for (int kx = 0; kx < hx; ++kx) {
          at(b, kx) = spec[static_cast<std::size_t>(kx)] * norm;
          if (b > 0 && b < my_ - b) at(my_ - b, kx) = at(b, kx);
        }
      } else {
        for (int ky = 0; ky < my_; ++ky) at(ky, b) = spec[static_cast<std::size_t>(ky)] * norm;
      }
    }
  }
  // The inverse's multiplier: apply's is K_k/N (N the padded points; the inverse transform is
  // unnormalised), so M_k/N = 1/(N^2 kernel_hat); the rigid mode (0) and any bin the padded kernel's
  // transform leaves not positive set aside.
  inverse_hat_.assign(spectral, 0.0);
  const double kernel_max = *std::max_element(kernel_hat_.begin(), kernel_hat_.end());
  for (std::size_t k = 0; k < spectral; ++k)
    if (kernel_hat_[k] > 1e-14 * kernel_max) inverse_hat_[k] = norm * norm / kernel_hat_[k];
  // The self-influence: the displacement of element 0 under a unit pressure on it.
  std::vector<double> unit(grid_.size(), 0.0), u(grid_.size());
  unit[0] = 1.0;
  apply(unit, u);
  self_ = u[0];
}

double* ElasticKernel::window_row(int j) const { return fft_->real.get() + static_cast<std::size_t>(j) * mx_; }

double ElasticKernel::apply_in_place() const { return transform_in_place(kernel_hat_); }
double ElasticKernel::precondition_in_place() const { return transform_in_place(inverse_hat_); }

double ElasticKernel::transform_in_place(const std::vector<double>& multiplier) const {
  const int nx = grid_.nx, ny = grid_.ny, hx = mx_ / 2 + 1;
  double* r = fft_->real.get();
  // The padding (an open direction's second half) zeroed: the last transform left u's images there.
  if (mx_ > nx)
    for (int j = 0; j < ny; ++j)
      std::fill(r + static_cast<std::size_t>(j) * mx_ + nx, r + static_cast<std::size_t>(j + 1) * mx_, 0.0);
  if (my_ > ny) std::fill(r + static_cast<std::size_t>(ny) * mx_, r + static_cast<std::size_t>(my_) * mx_, 0.0);
  fftw_execute(fft_->forward->get());
  // The kernel's multiplier, and p.K p = sum_k K_k |p_k|^2 over the whole spectrum (Parseval; the
  // multiplier holds the transform's 1/N): the half spectrum's columns 0 < kx < mx/2 twice.
  fftw_complex* s = fft_->spectrum.get();
  double pkp = 0.0;
  auto power = [&](std::size_t k) { return multiplier[k] * (s[k][0] * s[k][0] + s[k][1] * s[k][1]); };
  for (int ky = 0; ky < my_; ++ky) {
    const std::size_t row = static_cast<std::size_t>(ky) * hx;
    // (kx = 0, and kx = mx/2 for an even mx, appear once in the whole spectrum.)
    const double edges = power(row) + (mx_ % 2 == 0 && hx > 1 ? power(row + static_cast<std::size_t>(hx - 1)) : 0.0);
    double sum_row = 0.0;
    for (int kx = 0; kx < hx; ++kx) {
      const std::size_t k = row + static_cast<std::size_t>(kx);
      const double kh = multiplier[k], re = s[k][0], im = s[k][1];
      sum_row += kh * (re * re + im * im);
      s[k][0] = re * kh;
      s[k][1] = im * kh;
    }
    pkp += 2.0 * sum_row - edges;
  }
  fftw_execute(fft_->backward->get());
  executed_transforms += 2;
  return pkp;
}

double ElasticKernel::transform(std::span<const double> in, std::span<double> out,
                                const std::vector<double>& multiplier) const {
  const int nx = grid_.nx, ny = grid_.ny;
  for (int j = 0; j < ny; ++j) std::copy_n(in.begin() + static_cast<std::ptrdiff_t>(j) * nx, nx, window_row(j));
  const double product = transform_in_place(multiplier);
  for (int j = 0; j < ny; ++j) std::copy_n(window_row(j), nx, out.begin() + static_cast<std::ptrdiff_t>(j) * nx);
  return product;
}

void ElasticKernel::apply(std::span<const double> p, std::span<double> u) const { transform(p, u, kernel_hat_); }
double ElasticKernel::precondition(std::span<const double> g, std::span<double> z) const {
  return transform(g, z, inverse_hat_);
}

namespace {

// The factor that brings the pressures' sum to the target (Polonsky & Keer's load balance, uncapped).
double load_scale(std::span<const double> p, double target) {
  const double sum = std::accumulate(p.begin(), p.end(), 0.0);
  return sum > 0.0 ? target / sum : 1.0;
}

// The shift mu with sum_i clamp(x_i + mu, 0, H) = target, 0 < target < n H: the Euclidean projection
// of x on {0 <= p <= H, sum p = target} is clamp(x + mu, 0, H) (the continuous quadratic knapsack:
// Kiwiel 2008, Math. Program. 112:473). The sum is continuous, piecewise linear and nondecreasing in mu, its slope the
// count of elements strictly between 0 and H: Newton's steps on it, kept inside a bracket that each evaluation narrows
// (bisection where a step would leave it), end on the linear piece that holds the root, exactly (to rounding). One pass
// over x an evaluation; a few when x nearly balances already.
double capped_shift(std::span<const double> x, double cap, double target) {
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  double mu = 0.0;
  for (int it = 0; it < 400; ++it) {
    double sum = 0.0;
    std::size_t slope = 0;
    for (double v : x) {
      const double y = v + mu;
      sum += y <= 0.0 ? 0.0 : y >= cap ? cap : y;
      slope += y > 0.0 && y < cap;
    }
    const double miss = target - sum;
    if (std::abs(miss) <= 1e-15 * target) return mu;
    (miss > 0.0 ? lo : hi) = mu;
    double next = slope > 0 ? mu + miss / static_cast<double>(slope) : mu + (miss > 0.0 ? cap : -cap);
    if (std::isfinite(lo) && std::isfinite(hi)) {
      // (Every fourth step a bisection: Newton's steps may narrow the bracket a breakpoint at a time.)
      if (!(next > lo && next < hi) || it % 4 == 3) next = 0.5 * (lo + hi);
      if (hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi)))
        return miss > 0.0 ? hi : lo;
    }
    mu = next;
  }
  return mu;
}

}  // namespace

namespace {

// The residual's scale [m]: the heights' rms; for a flat or nearly flat surface a thousandth of the
// displacement the load makes over the window (the flat punch) or of the approach.
double residual_scale(const ElasticKernel& kernel, std::span<const double> h, bool load, double value) {
  const auto n = static_cast<double>(h.size());
  const double h_mean = std::accumulate(h.begin(), h.end(), 0.0) / n;
  double h_var = 0.0;
  for (double v : h) h_var += (v - h_mean) * (v - h_mean);
  const double h_rms = std::sqrt(h_var / n);
  const double reach = load ? value * std::sqrt(kernel.grid().area()) / kernel.modulus() : value;
  return std::max({h_rms, 1e-3 * reach, 1e-15});
}

// The outputs from the last fields (u is K p: the iterations stop only on a fresh one): the flat's
// height from the free elements under load control (kept as the iteration had it when none is
// free), the gap clipped to the contact conditions' signs, the fractions and the peak.
void finish_solution(ArealSolution& s, std::span<const double> h, bool load, double cap, double h_max, double flat) {
  const std::vector<double>& p = s.pressure;
  const std::vector<double>& u = s.displacement;
  std::vector<double>& gap = s.gap;
  const std::size_t n = p.size();
  if (load) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (p[i] > 0.0 && p[i] < cap) sum += h[i] - u[i], ++count;
    if (count > 0) flat = sum / static_cast<double>(count);
  }
  std::size_t contact = 0, plastic = 0;
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    gap[i] = u[i] - h[i] + flat;
    if (p[i] > 0.0) ++contact, gap[i] = std::min(gap[i], 0.0);
    else gap[i] = std::max(gap[i], 0.0);
    if (p[i] < cap) gap[i] = std::max(gap[i], 0.0);
    if (p[i] >= cap) ++plastic;
    total += p[i];
    s.peak_pressure = std::max(s.peak_pressure, p[i]);
  }
  s.mean_pressure = total / static_cast<double>(n);
  s.approach = h_max - flat;
  s.contact_fraction = static_cast<double>(contact) / static_cast<double>(n);
  s.plastic_fraction = static_cast<double>(plastic) / static_cast<double>(n);
}

// Polonsky & Keer's iteration at a mean pressure (elastic) or a flat's approach (elastic or capped).
// Under load control the load is restored after each step by scaling every pressure (Polonsky &
// Keer); the capped contact under load control is capped_load_control's.
ArealSolution polonsky_keer(const ElasticKernel& kernel, std::span<const double> h, Control control, double value,
                            const ArealOptions& o, std::span<const double> start) {
  const ArealGrid& g = kernel.grid();
  const std::size_t n = g.size();
  const bool load = control == Control::mean_pressure;
  const double cap = o.hardness;
  const double h_max = *std::max_element(h.begin(), h.end());
  const double scale = residual_scale(kernel, h, load, value);

  ArealSolution s;
  std::vector<double>& p = s.pressure;
  std::vector<double>& u = s.displacement;
  std::vector<double>& gap = s.gap;
  p.assign(n, 0.0);
  u.assign(n, 0.0);
  gap.assign(n, 0.0);
  const double self = kernel.self_influence();
  double flat = h_max - value;  // the flat's height (approach control; load control: found below)
  if (load && value == 0.0) {
    s.approach = 0.0, s.converged = true;
    for (std::size_t i = 0; i < n; ++i) gap[i] = h_max - h[i];
    return s;
  }
  const bool warm = start.size() == n && std::any_of(start.begin(), start.end(), [](double v) { return v > 0.0; });
  if (warm) {
    for (std::size_t i = 0; i < n; ++i) p[i] = std::clamp(start[i], 0.0, cap);
  } else if (load) {
    std::fill(p.begin(), p.end(), value);
  } else {
    for (std::size_t i = 0; i < n; ++i) p[i] = std::min(std::max(0.0, h[i] - flat) / self, cap);
  }
  if (load) {
    const double f = load_scale(p, value * static_cast<double>(n));
    for (double& v : p) v = std::min(v * f, cap);
  }
  kernel.apply(p, u);

  // The elements' states: 0 no pressure, 1 free (0 < p < H), 2 capped. The displacement is carried
  // from step to step by the step's own K t (one transform pair an iteration) and computed afresh
  // (a second pair) when the pressure the projection moved since the last fresh one (clipped at 0 or
  // H, entering the contact, leaving the cap: left out of the carried u) passes kClipped times the
  // residual of the load (an inexact step early, an exact one as the residual falls), every kFresh
  // iterations, and before the iteration may stop.
  constexpr double kClipped = 0.1;
  constexpr int kFresh = 32;
  std::vector<double> t(n, 0.0);
  std::vector<unsigned char> state(n);
  auto classify = [cap](double v) -> unsigned char { return v <= 0.0 ? 0 : v >= cap ? 2 : 1; };
  const bool pre = o.precondition;
  double rho_old = 0.0, tau = pre ? 1.0 : 1.0 / self;
  bool reset = true, fresh = true;
  double clipped = 0.0, scale_next = 1.0;
  // Sums over the free elements: the flat's height (load control), the last direction's mean.
  double free_h = 0.0, free_u = 0.0, t_free = 0.0;
  std::size_t free_count = 0;
  auto recount = [&] {
    free_h = free_u = t_free = 0.0, free_count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      state[i] = classify(p[i]);
      if (state[i] == 1) free_h += h[i], free_u += u[i], t_free += t[i], ++free_count;
    }
  };
  recount();
  const double target = value * static_cast<double>(n);
  for (int it = 0;; ++it) {
    // The flat's height: given, or the mean over the free elements of their deformed heights.
    const double f = scale_next;
    if (load && free_count > 0) flat = (free_h - f * free_u) / static_cast<double>(free_count);
    // (The load's scale f reaches p and u in the step below, which reads and writes them anyway.)
    // The residual's sums. (The gap f u - h + flat is formed afresh in each pass that reads it: a
    // pass over the grid fewer than storing it; the solution's is formed at the end.)
    // Preconditioned, the same pass writes the free set's gap into the transform's array (g, 0
    // elsewhere), for M g below.
    double res2 = 0.0, big_g = 0.0;
    for (int j = 0; j < g.ny; ++j) {
      double* r = kernel.window_row(j);
      const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx);
      for (int c = 0; c < g.nx; ++c) {
        const std::size_t i = row + static_cast<std::size_t>(c);
        const double gi = f * u[i] - h[i] + flat;
        const unsigned char si = state[i];
        big_g += si == 1 ? gi * gi : 0.0;
        res2 += (si == 0 && gi < 0.0) || (si == 2 && gi > 0.0) ? gi * gi : 0.0;
        if (pre) r[c] = si == 1 ? gi : 0.0;
      }
    }
    s.residual = std::sqrt((res2 + big_g) / static_cast<double>(n)) / scale;
    s.iterations = it;
    auto apply_scale = [&] {
      if (scale_next == 1.0) return;
      for (std::size_t i = 0; i < n; ++i) p[i] = std::min(p[i] * scale_next, cap), u[i] *= scale_next;
      scale_next = 1.0;
    };
    if (s.residual <= o.tolerance || it >= o.max_iterations) {
      apply_scale();
      if (fresh) {
        double sum = 0.0;
        for (double v : p) sum += v;
        s.converged = s.residual <= o.tolerance && (!load || std::abs(sum - target) <= 1e-9 * target);
        if (s.converged || it >= o.max_iterations) break;
        // The contact conditions met but not the load (a safeguard: the scaling restores the load
        // after every step of the elastic iteration): on.
      } else {
        kernel.apply(p, u);  // the carried displacement checked against a fresh one
        recount();
        fresh = true, clipped = 0.0, reset = true;
        continue;
      }
    }
    // The conjugate direction on the free set (Polonsky & Keer 1999 eq. 14), written into the
    // transform's own array as it is formed. Under load control the last direction less its mean on
    // the free set: the gap's mean there is 0 (the flat's height), so t's is, and a step along t keeps
    // the load (the free set changed since the last direction: it need not have been). Its step
    // tau = g.t/t.Kt, t.Kt by Parseval in the transform (K t is read in place, in the step below).
    // Preconditioned: z = M g on the free set (M g's mean there taken out under load control, as
    // the gap's is), rho = g.z; plain: z = g.
    const bool step_t = free_count > 0 && big_g > 0.0;
    double rho = big_g, z_mean = 0.0;
    if (pre && step_t) {
      rho = kernel.precondition_in_place();
      if (load) {
        double z_sum = 0.0;
        for (int j = 0; j < g.ny; ++j) {
          const double* r = kernel.window_row(j);
          const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx);
          for (int i = 0; i < g.nx; ++i) z_sum += state[row + static_cast<std::size_t>(i)] == 1 ? r[i] : 0.0;
        }
        z_mean = z_sum / static_cast<double>(free_count);
      }
    }
    const double beta = reset || rho_old == 0.0 ? 0.0 : rho / rho_old;
    const double t_mean = load && free_count > 0 ? t_free / static_cast<double>(free_count) : 0.0;
    rho_old = rho;
    reset = false;
    double rt = 0.0;
    for (int j = 0; j < g.ny; ++j) {
      double* r = kernel.window_row(j);
      const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx);
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t e = row + static_cast<std::size_t>(i);
        const double gi = f * u[e] - h[e] + flat;
        const double zi = pre && step_t ? r[i] - z_mean : gi;
        const double ti = state[e] == 1 ? zi + beta * (t[e] - t_mean) : 0.0;
        t[e] = ti;
        r[i] = ti;
        rt += state[e] == 1 ? gi * ti : 0.0;
      }
    }
    if (step_t) {
      const double wt = kernel.apply_in_place();
      if (wt > 0.0) tau = rt / wt;
      // (Preconditioned, a direction that does not descend, g.t <= 0, is not taken: the next
      // iteration starts the directions afresh.)
      if (pre && !(rt > 0.0)) tau = 0.0, reset = true;
    }
    // The step of the elements that enter the contact or leave the cap [Pa/m]: Polonsky & Keer's
    // tau; preconditioned (tau then a number), tau times M's Rayleigh quotient on the gap, g.M g/g.g,
    // the stiffness at the residual's own wavelengths (M's diagonal, a lone element's, overshoots
    // where a patch enters at once: a warm start at three times the load diverged on it).
    const double tau_bound = pre && step_t ? tau * rho / big_g : pre ? 1.0 / self : tau;
    // The step, projected on 0 <= p <= H; elements the flat overlaps enter, capped ones whose gap
    // opens are let go (either restarts the conjugate directions).
    bool moved = false;  // an element entered the contact or left the cap
    bool left = false;   // a free element was clipped at 0 or H
    double total = 0.0;
    free_h = free_u = t_free = 0.0, free_count = 0;
    for (int j = 0; j < g.ny; ++j) {
      const double* w = kernel.window_row(j);  // K t (0 when no step was taken along t)
      const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx);
      for (int c = 0; c < g.nx; ++c) {
        const std::size_t i = row + static_cast<std::size_t>(c);
        double pi = p[i];
        switch (state[i]) {
          case 1:
            pi = f * pi - tau * t[i];
            if (pi <= 0.0) clipped -= pi, pi = 0.0, left = true;
            else if (pi >= cap) clipped += pi - cap, pi = cap, left = true;
            break;
          case 0: {  // (p = 0: unscaled)
            const double gi = f * u[i] - h[i] + flat;
            if (gi < 0.0) pi = std::min(-tau_bound * gi, cap), clipped += pi, moved = true;
            break;
          }
          default: {
            const double gi = f * u[i] - h[i] + flat;
            if (gi > 0.0) pi = std::max(0.0, cap - tau_bound * gi), clipped += cap - pi, moved = true;
            break;
          }
        }
        p[i] = pi;
        const double ui = f * u[i] - (step_t ? tau * w[c] : 0.0);
        u[i] = ui;
        const unsigned char si = classify(pi);
        state[i] = si;
        total += pi;
        if (si == 1) free_h += h[i], free_u += ui, t_free += t[i], ++free_count;
      }
    }
    scale_next = 1.0;  // the step took it (f); load control sets a new one below
    if (load && !(total > 0.0)) {
      // Every pressure stepped to 0: the element nearest to touching takes the load.
      std::size_t next = 0;
      for (std::size_t i = 1; i < n; ++i)  // (the gap after the step, u - h + flat: u has taken it)
        if (u[i] - h[i] < u[next] - h[next]) next = i;
      p[next] = std::min(target, cap);
      state[next] = classify(p[next]);
      if (state[next] == 1) free_h += h[next], free_u += u[next], t_free += t[next], ++free_count;
      clipped += p[next];
      total = p[next];
    } else if (load) {
      scale_next = target / total;  // Polonsky & Keer's scaling of every pressure, carried to u as well
    }
    fresh = false;
    // (Preconditioned, a clipped element restarts the directions too: the preconditioner's
    // restriction changed, and M's large entries turn the residual's jump there into a direction
    // that does not descend.)
    if (moved || (pre && left)) reset = true;
    if (clipped > kClipped * s.residual * std::max(total, 1e-300) || (it + 1) % kFresh == 0) {
      for (double& v : p) v = std::min(v * scale_next, cap);
      scale_next = 1.0;
      kernel.apply(p, u);
      recount();
      if (pre && clipped > 0.0) reset = true;  // the residual jumps by the clipped pressure's displacement
      fresh = true, clipped = 0.0;
    }
  }
  finish_solution(s, h, load, cap, h_max, flat);
  return s;
}

// The flat's height with no free element (every element at 0 or H: the plastic limit): the deformed
// height h - u of the element after the floor(P/H) highest, which at H carry all of the load but a
// part of one element's. `up`: scratch of the heights' size.
double plastic_flat(std::span<const double> h, std::span<const double> u, double target, double cap,
                    std::span<double> up) {
  const std::size_t n = h.size();
  for (std::size_t i = 0; i < n; ++i) up[i] = h[i] - u[i];
  const auto k = static_cast<std::ptrdiff_t>(std::clamp(std::floor(target / cap), 0.0, static_cast<double>(n) - 1.0));
  std::nth_element(up.begin(), up.begin() + k, up.end(), std::greater<>());
  return up[static_cast<std::size_t>(k)];
}

// The capped contact under load control. It is the minimum of F(p) = p.Kp/2 - h.p over the set
// C = {0 <= p <= H, sum p = P}: its optimality conditions are the contact conditions, the flat's
// height the load's multiplier. Polonsky & Keer's conjugate gradients on the free elements
// (0 < p < H), the unloaded ones entering with -tau g and the capped ones leaving with H - tau g as
// in approach control, and every step projected on C (capped_shift: the load exact after every
// step). A step that changes the active set (an element entering or leaving the contact or the
// cap, or a free one clipped) is kept only if it lowers F by Armijo's rule on the projection arc
// (Bertsekas 1976, IEEE Trans. Autom. Control 21:174; the active-set method of More & Toraldo 1991,
// SIAM J. Optim. 1:93), else retried along the gradient with half the step. F decreasing, the
// active set cannot cycle: scaling or releasing the capped elements by rules of thumb instead
// stalled on heavily plastic windows (80 % of the contact at H), a 2-cycle of one element a row.
ArealSolution capped_load_control(const ElasticKernel& kernel, std::span<const double> h, double value,
                                  const ArealOptions& o, std::span<const double> start) {
  const std::size_t n = h.size();
  const double cap = o.hardness, target = value * static_cast<double>(n);
  const double h_max = *std::max_element(h.begin(), h.end());
  const double scale = residual_scale(kernel, h, true, value);
  ArealSolution s;
  std::vector<double>& p = s.pressure;
  std::vector<double>& u = s.displacement;
  std::vector<double>& gap = s.gap;
  p.assign(n, value);
  u.assign(n, 0.0);
  gap.assign(n, 0.0);
  // The start (a previous load's pressure, or uniform) scaled to the load, capped, then projected on C.
  if (start.size() == n && std::any_of(start.begin(), start.end(), [](double v) { return v > 0.0; }))
    for (std::size_t i = 0; i < n; ++i) p[i] = std::clamp(start[i], 0.0, cap);
  const double f0 = load_scale(p, target);
  for (double& v : p) v = std::min(v * f0, cap);
  const double mu0 = capped_shift(p, cap, target);
  for (double& v : p) v = std::clamp(v + mu0, 0.0, cap);
  kernel.apply(p, u);

  // States: 0 no pressure, 1 free, 2 capped. A step on an unchanged active set carries u by its own
  // K t (one transform pair) and leaves out of it the load's shift of the free elements (clipped);
  // one that changes it computes u afresh to test F (a second pair). Afresh too when the clipped
  // pressure passes kClipped times the residual of the load, every kFresh iterations, and before
  // the iteration may stop (as in polonsky_keer).
  constexpr double kClipped = 0.1;
  constexpr int kFresh = 32;
  constexpr double kArmijo = 1e-4;  // the sufficient decrease (Bertsekas 1976's sigma)
  constexpr int kHalvings = 40;     // tau / 2^40: below any step that moves a pressure
  auto classify = [cap](double v) -> unsigned char { return v <= 0.0 ? 0 : v >= cap ? 2 : 1; };
  std::vector<unsigned char> state(n);
  for (std::size_t i = 0; i < n; ++i) state[i] = classify(p[i]);
  std::vector<double> t(n, 0.0), w(n, 0.0), trial(n, 0.0);  // trial: the step's pressure (scratch between)
  const bool pre = o.precondition;
  std::vector<double> z(pre ? n : 0);
  double rho_old = 0.0, tau = pre ? 1.0 : 1.0 / kernel.self_influence(), clipped = 0.0, flat = 0.0;
  bool reset = true, fresh = true;
  for (int it = 0;; ++it) {
    // The flat's height: the mean over the free elements of their deformed heights.
    double free_h = 0.0, free_u = 0.0;
    std::size_t free_count = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (state[i] == 1) free_h += h[i], free_u += u[i], ++free_count;
    flat =
        free_count > 0 ? (free_h - free_u) / static_cast<double>(free_count) : plastic_flat(h, u, target, cap, trial);
    double res2 = 0.0, big_g = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double gi = u[i] - h[i] + flat;
      gap[i] = gi;
      const unsigned char si = state[i];
      big_g += si == 1 ? gi * gi : 0.0;
      res2 += (si == 0 && gi < 0.0) || (si == 2 && gi > 0.0) ? gi * gi : 0.0;
    }
    s.residual = std::sqrt((res2 + big_g) / static_cast<double>(n)) / scale;
    s.iterations = it;
    if (s.residual <= o.tolerance || it >= o.max_iterations) {
      if (fresh) {
        const double sum = std::accumulate(p.begin(), p.end(), 0.0);
        s.converged = s.residual <= o.tolerance && std::abs(sum - target) <= 1e-9 * target;
        break;
      }
      kernel.apply(p, u);  // the carried displacement checked against a fresh one
      fresh = true, clipped = 0.0, reset = true;
      continue;
    }
    // The conjugate direction on the free set (Polonsky & Keer 1999 eq. 14) and its step; the
    // preconditioned one's z = M g there, less its mean (as polonsky_keer's), else z = g.
    const bool step_t = free_count > 0 && big_g > 0.0;
    double rho = big_g;
    if (pre && step_t) {
      for (std::size_t i = 0; i < n; ++i) w[i] = state[i] == 1 ? gap[i] : 0.0;  // (w free until K t below)
      rho = kernel.precondition(w, z);
      double z_sum = 0.0;
      for (std::size_t i = 0; i < n; ++i) z_sum += state[i] == 1 ? z[i] : 0.0;
      const double z_mean = z_sum / static_cast<double>(free_count);
      for (std::size_t i = 0; i < n; ++i) z[i] = state[i] == 1 ? z[i] - z_mean : 0.0;
    }
    const bool use_z = pre && step_t;
    const double beta = reset || rho_old == 0.0 ? 0.0 : rho / rho_old;
    for (std::size_t i = 0; i < n; ++i) t[i] = state[i] == 1 ? (use_z ? z[i] : gap[i]) + beta * t[i] : 0.0;
    rho_old = rho;
    reset = false;
    if (step_t) {
      kernel.apply(t, w);
      double w_sum = 0.0, t_sum = 0.0, wt = 0.0, rt = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const double ti = t[i], wi = state[i] == 1 ? w[i] : 0.0;
        w_sum += wi, t_sum += ti, wt += wi * ti, rt += gap[i] * ti;
      }
      wt -= w_sum / static_cast<double>(free_count) * t_sum;  // K t less its mean on the free set
      if (wt > 0.0) tau = rt / wt;
      if (pre && !(rt > 0.0)) tau = 0.0, reset = true;  // not a descent direction: not taken (polonsky_keer)
    } else {
      std::fill(w.begin(), w.end(), 0.0);
    }
    // The step p - tau d projected on C: d = t on the free elements, g on the others (preconditioned,
    // tau times M's Rayleigh quotient on the gap there, as in polonsky_keer).
    double tau_bound = use_z ? tau * rho / big_g : pre ? 1.0 / kernel.self_influence() : tau;
    for (int halving = 0;; ++halving) {
      for (std::size_t i = 0; i < n; ++i) {
        const unsigned char si = state[i];
        trial[i] = si == 1 ? p[i] - tau * t[i] : si == 0 ? -tau_bound * gap[i] : cap - tau_bound * gap[i];
      }
      const double mu = capped_shift(trial, cap, target);
      bool changed = false;
      for (std::size_t i = 0; i < n; ++i) {
        const double v = std::clamp(trial[i] + mu, 0.0, cap);
        changed = changed || classify(v) != state[i];
        trial[i] = v;
      }
      if (!changed && halving == 0) {
        // The active set kept: u carried by K t, the load's shift of the free elements left out of it.
        for (std::size_t i = 0; i < n; ++i) {
          u[i] -= tau * w[i];
          clipped += state[i] == 1 ? std::abs(mu) : 0.0;
        }
        p.swap(trial);
        fresh = false;
        break;
      }
      if (!changed) {
        // Kept after a halving: w holds K of a rejected trial, not K t: u afresh.
        p.swap(trial);
        kernel.apply(p, u);
        fresh = true, clipped = 0.0, reset = true;
        break;
      }
      // The active set changed: F's change p -> p + D is g.D + D.K D/2 (sum D = 0, the load kept),
      // with u afresh (in w). Rounding allowance: 1e-13 of |D| (|u| + |K p'|).
      kernel.apply(trial, w);
      double slope = 0.0, curvature = 0.0, noise = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const double d = trial[i] - p[i];
        slope += gap[i] * d;
        curvature += d * (w[i] - u[i]);
        noise += std::abs(d) * (std::abs(u[i]) + std::abs(w[i]));
      }
      if (slope + 0.5 * curvature <= kArmijo * slope + 1e-13 * noise || halving >= kHalvings) {
        p.swap(trial);
        u.swap(w);
        for (std::size_t i = 0; i < n; ++i) state[i] = classify(p[i]);
        fresh = true, clipped = 0.0, reset = true;
        break;
      }
      // Rejected: along the (preconditioned) gradient (the conjugate direction need not descend on
      // the arc), half the step.
      tau *= 0.5, tau_bound *= 0.5;
      for (std::size_t i = 0; i < n; ++i) t[i] = state[i] == 1 ? (use_z ? z[i] : gap[i]) : 0.0;
    }
    if (!fresh && (clipped > kClipped * s.residual * target || (it + 1) % kFresh == 0)) {
      kernel.apply(p, u);
      if (pre && clipped > 0.0) reset = true;  // the residual jumps by the load shift's displacement
      fresh = true, clipped = 0.0;
    }
  }
  finish_solution(s, h, true, cap, h_max, flat);
  return s;
}

}  // namespace

ArealSolution solve_contact(const ElasticKernel& kernel, std::span<const double> h, Control control, double value,
                            const ArealOptions& o, std::span<const double> start) {
  o.validate();
  const ArealGrid& g = kernel.grid();
  if (h.size() != g.size()) throw std::invalid_argument("solve_contact: the heights do not match the grid");
  if (control == Control::mean_pressure) {
    if (!(value >= 0.0) || !std::isfinite(value))
      throw core::KeyedError("mean_pressure",
                             fmt::format("the mean pressure must be finite and not negative ({} Pa)", value));
    if (value >= o.hardness)
      throw core::KeyedError("mean_pressure",
                             fmt::format("a mean pressure ({:.4g} Pa) at or above the hardness ({:.4g} Pa) yields the "
                                         "whole surface: no contact carries it",
                                         value, o.hardness));
  } else {
    if (!(value >= 0.0) || !std::isfinite(value))
      throw core::KeyedError("approach", fmt::format("the approach must be finite and not negative ({} m)", value));
    if (g.periodic_x != g.periodic_y)
      throw core::KeyedError("approach",
                             "the approach of a window periodic in one direction alone is not defined (its mean "
                             "line load's displacement grows as ln of the distance): give a mean pressure");
  }
  if (std::isfinite(o.hardness) && start.empty() && value > 0.0) {
    // Capped from nothing: the elastic contact first, then capped from it (from a cold start the
    // first steps cap far more elements than the answer has, at an approach every element the flat
    // overlaps, and the iteration has them to let go again).
    ArealOptions elastic = o;
    elastic.hardness = std::numeric_limits<double>::infinity();
    ArealSolution e = polonsky_keer(kernel, h, control, value, elastic, {});
    const std::vector<double> p = std::move(e.pressure);
    const int iterations = e.iterations;
    e = ArealSolution{};  // (its other fields freed: the bytes areal_solve_bytes counts)
    ArealSolution s = control == Control::mean_pressure ? capped_load_control(kernel, h, value, o, p)
                                                        : polonsky_keer(kernel, h, control, value, o, p);
    s.iterations += iterations;
    return s;
  }
  if (control == Control::mean_pressure && std::isfinite(o.hardness) && value > 0.0)
    return capped_load_control(kernel, h, value, o, start);
  return polonsky_keer(kernel, h, control, value, o, start);
}

ContactSpots contact_spots(const ArealGrid& g, std::span<const double> pressure) {
  const int nx = g.nx, ny = g.ny;
  const std::size_t n = g.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[static_cast<std::size_t>(a)] != a) {
      parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
      a = parent[static_cast<std::size_t>(a)];
    }
    return a;
  };
  auto unite = [&](int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  };
  auto in = [&](int i, int j) { return pressure[static_cast<std::size_t>(j) * nx + i] > 0.0; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!in(i, j)) continue;
      const int a = j * nx + i;
      if (i + 1 < nx ? in(i + 1, j) : (g.periodic_x && nx > 1 && in(0, j))) unite(a, j * nx + (i + 1) % nx);
      if (j + 1 < ny ? in(i, j + 1) : (g.periodic_y && ny > 1 && in(i, 0))) unite(a, ((j + 1) % ny) * nx + i);
    }
  ContactSpots out;
  out.label.assign(n, -1);
  std::vector<int> root_label(n, -1);
  std::vector<double> area, load;
  const double cell = g.dx * g.dy;
  for (std::size_t k = 0; k < n; ++k) {
    if (!(pressure[k] > 0.0)) continue;
    const auto r = static_cast<std::size_t>(find(static_cast<int>(k)));
    if (root_label[r] < 0) {
      root_label[r] = static_cast<int>(area.size());
      area.push_back(0.0), load.push_back(0.0);
    }
    out.label[k] = root_label[r];
    area[static_cast<std::size_t>(root_label[r])] += cell;
    load[static_cast<std::size_t>(root_label[r])] += pressure[k] * cell;
  }
  // Largest first, the labels renumbered to match.
  std::vector<int> order(area.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return area[static_cast<std::size_t>(a)] > area[static_cast<std::size_t>(b)]; });
  std::vector<int> rank(area.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    rank[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
    out.area.push_back(area[static_cast<std::size_t>(order[k])]);
    out.load.push_back(load[static_cast<std::size_t>(order[k])]);
  }
  for (int& l : out.label)
    if (l >= 0) l = rank[static_cast<std::size_t>(l)];
  return out;
}

std::vector<SubsurfacePlane> subsurface_von_mises(const ElasticKernel& kernel, std::span<const double> pressure,
                                                  double nu, std::span<const double> depths,
                                                  std::vector<std::vector<double>>* fields) {
  const ArealGrid& g = kernel.grid();
  const int nx = g.nx, ny = g.ny, mx = kernel.padded_nx(), my = kernel.padded_ny(), hx = mx / 2 + 1;
  if (pressure.size() != g.size())
    throw std::invalid_argument("subsurface_von_mises: the pressure does not match the grid");
  const std::size_t spectral = static_cast<std::size_t>(my) * hx, padded_size = static_cast<std::size_t>(mx) * my;
  auto real = fftw_real_array(padded_size);
  auto p_hat = fftw_complex_array(spectral);
  auto work = fftw_complex_array(spectral);
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_2d(my, mx, real.get(), p_hat.get(), FFTW_ESTIMATE); });
  const FftwPlan backward([&] { return fftw_plan_dft_c2r_2d(my, mx, work.get(), real.get(), FFTW_ESTIMATE); });
  std::fill(real.get(), real.get() + padded_size, 0.0);
  for (int j = 0; j < ny; ++j)
    std::copy_n(pressure.begin() + static_cast<std::ptrdiff_t>(j) * nx, nx,
                real.get() + static_cast<std::size_t>(j) * mx);
  fftw_execute(forward.get());
  const double norm = 1.0 / static_cast<double>(padded_size);
  const double lx = mx * g.dx, ly = my * g.dy;
  std::vector<SubsurfacePlane> out;
  std::array<std::vector<double>, 6> comp;  // xx, yy, zz, xy, xz, yz on the window [Pa]
  for (auto& c : comp) c.resize(g.size());
  for (double z : depths) {
    if (!(z > 0.0) || !std::isfinite(z))
      throw core::KeyedError("depths", fmt::format("a depth must be positive ({} m)", z));
    for (int c = 0; c < 6; ++c) {
      for (int ky = 0; ky < my; ++ky)
        for (int kx = 0; kx < hx; ++kx) {
          const std::size_t k = static_cast<std::size_t>(ky) * hx + kx;
          const double qx = 2.0 * kPi * kx / lx, qy = 2.0 * kPi * signed_index(ky, my) / ly;
          const double q = std::hypot(qx, qy);
          const std::complex<double> ph(p_hat[k][0], p_hat[k][1]);
          std::complex<double> v = 0.0;
          if (q == 0.0) {
            // The mean pressure: sigma_zz = -pbar, and along an open direction the lateral stress of
            // the padded window's images, the q -> 0 limit along it (a row of line loads: mean
            // sigma_ss = -pbar, sigma_tt = -2 nu pbar; open both ways, the mean over directions).
            // A window periodic both ways: sigma_zz alone (its lateral stress is the body's beyond).
            const double open_x = g.periodic_x ? 0.0 : 1.0, open_y = g.periodic_y ? 0.0 : 1.0;
            const double sum = open_x + open_y;
            const double wx = sum > 0.0 ? open_x / sum : 0.0, wy = sum > 0.0 ? open_y / sum : 0.0;
            const double lateral_x = sum > 0.0 ? -(wx + 2.0 * nu * wy) : 0.0;
            const double lateral_y = sum > 0.0 ? -(wy + 2.0 * nu * wx) : 0.0;
            v = c == 0 ? lateral_x * ph : c == 1 ? lateral_y * ph : c == 2 ? -ph : 0.0;
          } else {
            // Plane strain under P cos(q s) (Airy phi = (P/q^2)(1 + qz) e^{-qz} cos qs), turned to
            // the mode's direction n = q/|q| (s along n, t across it).
            const double e = std::exp(-q * z), n1 = qx / q, n2 = qy / q;
            const double ss = -(1.0 - q * z) * e, tt = -2.0 * nu * e, zz = -(1.0 + q * z) * e;
            const std::complex<double> sz(0.0, q * z * e);
            switch (c) {
              case 0:
                v = (n1 * n1 * ss + n2 * n2 * tt) * ph;
                break;
              case 1:
                v = (n2 * n2 * ss + n1 * n1 * tt) * ph;
                break;
              case 2:
                v = zz * ph;
                break;
              case 3:
                v = n1 * n2 * (ss - tt) * ph;
                break;
              case 4:
                v = n1 * sz * ph;
                break;
              default:
                v = n2 * sz * ph;
                break;
            }
          }
          work[k][0] = v.real() * norm;
          work[k][1] = v.imag() * norm;
        }
      fftw_execute(backward.get());
      for (int j = 0; j < ny; ++j)
        std::copy_n(real.get() + static_cast<std::size_t>(j) * mx, nx,
                    comp[static_cast<std::size_t>(c)].begin() + static_cast<std::ptrdiff_t>(j) * nx);
    }
    SubsurfacePlane plane;
    plane.depth = z;
    std::vector<double> vm(fields ? g.size() : 0);
    for (std::size_t k = 0; k < g.size(); ++k) {
      const double sxx = comp[0][k], syy = comp[1][k], szz = comp[2][k], sxy = comp[3][k], sxz = comp[4][k],
                   syz = comp[5][k];
      const double v =
          std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                    3.0 * (sxy * sxy + sxz * sxz + syz * syz));
      if (fields) vm[k] = v;
      if (v > plane.max_von_mises) {
        plane.max_von_mises = v;
        const std::size_t row = k / static_cast<std::size_t>(nx), column = k % static_cast<std::size_t>(nx);
        plane.x = static_cast<double>(column) * g.dx;
        plane.y = static_cast<double>(row) * g.dy;
      }
    }
    if (fields) fields->push_back(std::move(vm));
    out.push_back(plane);
  }
  return out;
}

}  // namespace geartrib::contact::areal
