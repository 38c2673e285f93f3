#include "contact/half_plane_bem.hpp"

#include "core/keyed_error.hpp"
#include "core/log_antiderivative.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <fmt/format.h>

namespace geartrib::contact {

namespace {
constexpr double kPi = std::numbers::pi;
using core::log_antiderivative;  // int ln|t| dt

// arctan(x) to 1 ulp without branches (Moshier's Cephes atan: the argument reduced to |t| <= 0.66
// by pi/2 - atan(1/x) or pi/4 + atan((x-1)/(x+1)), then a (4,5) rational approximation in t^2),
// inlined: about twice as fast as libm's atan2 in the stress sums, which it dominates.
inline double arctan(double x) {
  constexpr double kTan3Pi8 = 2.41421356237309504880, kMoreBits = 6.123233995736765886130e-17;
  const double ax = std::abs(x);
  const bool big = ax > kTan3Pi8, mid = ax > 0.66;
  const double t = (big ? -1.0 : mid ? ax - 1.0 : ax) / (big ? ax : mid ? ax + 1.0 : 1.0);
  const double base = big ? 0.5 * kPi : mid ? 0.25 * kPi : 0.0;
  const double extra = big ? kMoreBits : mid ? 0.5 * kMoreBits : 0.0;
  constexpr std::array<double, 5> kP{-8.750608600031904122785e-1, -1.615753718733365076637e1,
                                     -7.500855792314704667340e1, -1.228866684490136173410e2,
                                     -6.485021904942025371773e1};
  constexpr std::array<double, 5> kQ{2.485846490142306297962e1, 1.650270098316988542046e2, 4.328810604912902668951e2,
                                     4.853903996359136964868e2, 1.945506571482613964425e2};  // Q monic
  const double z = t * t;
  double p = kP[0], q = z + kQ[0];
  for (std::size_t i = 1; i < kP.size(); ++i) p = p * z + kP[i], q = q * z + kQ[i];
  return std::copysign(base + (t * (z * p / q) + t + extra), x);
}

// A solve's cost: the FFTs this thread executed during it and their time, and its wall time.
class CostMeter {
 public:
  void fill(BemSolution& s) const {
    s.transforms = ToeplitzConvolution::transforms() - transforms_;
    s.transform_seconds = ToeplitzConvolution::transform_seconds() - transform_seconds_;
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  long transforms_ = ToeplitzConvolution::transforms();
  double transform_seconds_ = ToeplitzConvolution::transform_seconds();
};
}  // namespace

void BemOptions::validate() const {
  using core::KeyedError;
  if (!(tolerance > 0.0)) throw KeyedError("tolerance", "BEM tolerance must be positive");
  if (max_iterations < 1) throw KeyedError("max_iterations", "BEM max_iterations must be positive");
  if (!(pressure_cap > 0.0)) throw KeyedError("pressure_cap", "pressure cap must be positive");
  if (!periodic && !(reference_length > 0.0)) throw KeyedError("reference_length", "reference length must be positive");
  if (coarse_elements < 0) throw KeyedError("coarse_elements", "BEM coarse_elements must be >= 0");
}

HalfPlaneBem::HalfPlaneBem(const HalfPlaneGrid& grid, double modulus, const BemOptions& options)
    : grid_(grid), modulus_(modulus), options_(options) {
  options_.validate();
  if (grid.size < 2 || !(grid.spacing > 0.0))
    throw std::invalid_argument("BEM grid needs >= 2 elements of positive width");
  if (!(modulus > 0.0)) throw std::invalid_argument("modulus must be positive");
  const int n = grid.size;
  const double h = grid.spacing, c = 2.0 / (kPi * modulus);
  double dc = 0.0;  // the kernel's row sum: its symbol at zero frequency (non-periodic)
  if (!options_.periodic) {
    // u_i = c sum_j p_j int_elem_j ln(L_ref/|x_i - s|) ds
    const double lref = options_.reference_length;
    if (lref < n * h)
      throw std::invalid_argument(
          fmt::format("reference length {:.3g} m must exceed the domain {:.3g} m", lref, n * h));
    // k(m) = c (h ln L_ref - (F((m + 1/2) h) - F((m - 1/2) h))), even in m (F is odd, exactly
    // so in floating point): computed for m >= 0.
    std::vector<double> k(static_cast<std::size_t>(2 * n - 1));
    for (int m = 0; m <= n - 1; ++m)
      k[static_cast<std::size_t>(n - 1 + m)] = k[static_cast<std::size_t>(n - 1 - m)] =
          c * (h * std::log(lref) - (log_antiderivative(m * h + 0.5 * h) - log_antiderivative(m * h - 0.5 * h)));
    // ||K|| <= the largest absolute row sum; k > 0 falls with |m| (L_ref exceeds the domain), so
    // row sums grow toward the middle row, which is the largest: sum_{m = -i}^{n-1-i} k(m) there.
    for (int m = -(n - 1) / 2; m <= n - 1 - (n - 1) / 2; ++m) kernel_norm_ += k[static_cast<std::size_t>(m + n - 1)];
    for (double x : k) dc += x;
    conv_ = std::make_unique<ToeplitzConvolution>(k, n, false);
  } else {
    // Periodic Green's function -(c) ln|2 sin(pi t/L)| (zero mean over the period L = n h):
    // ln|t| integrated exactly, the smooth rest ln|2 sin(pi t/L)/t| by Gauss-Legendre.
    const double period = n * h;
    using Gauss = boost::math::quadrature::gauss<double, 20>;
    std::vector<double> k(static_cast<std::size_t>(n));
    for (int m = 0; m < n; ++m) {
      const double centre = (m <= n / 2 ? m : m - n) * h;  // nearest image in (-L/2, L/2]
      const double singular = log_antiderivative(centre + 0.5 * h) - log_antiderivative(centre - 0.5 * h);
      const double smooth = Gauss::integrate(
          [&](double t) {
            const double a = kPi * t / period;
            return std::abs(a) < 1e-8 ? std::log(2.0 * kPi / period) : std::log(std::abs(2.0 * std::sin(a) / t));
          },
          centre - 0.5 * h, centre + 0.5 * h);
      k[static_cast<std::size_t>(m)] = -c * (singular + smooth);
    }
    conv_ = std::make_unique<ToeplitzConvolution>(k, n, true);
    for (double x : k) kernel_norm_ += std::abs(x);  // every row's absolute sum
  }
  // Preconditioner: the inverse of the symbol of the periodic log kernel on the FFT's length m
  // (period m h), -c ln|2 sin(pi t/(m h))| = c sum_j cos(2 pi j t/(m h))/j, integrated over an
  // element: lambda_l = c h (m/2) sum_{j = +-l mod m} sinc(pi j/m)/j, here its two leading
  // terms. Positive, unlike the spectrum of the zero-padded (DC-FFT) kernel, which oscillates in
  // sign at high frequency. At zero frequency: the kernel's row sum (the reference length's
  // constant), or lambda_1 when periodic (zero mean).
  const int m = conv_->fft_size();
  auto symbol = [&](int l) {  // sin(pi (m - l)/m) = sin(pi l/m)
    const double ld = l, rest = m - l;
    return c * h * 0.5 * m * std::sin(kPi * ld / m) * (m / kPi) * (1.0 / (ld * ld) + 1.0 / (rest * rest));
  };
  inverse_symbol_.resize(static_cast<std::size_t>(m / 2 + 1));
  for (int l = 1; l <= m / 2; ++l) inverse_symbol_[static_cast<std::size_t>(l)] = 1.0 / (m * symbol(l));
  inverse_symbol_[0] = 1.0 / (m * (options_.periodic || !(dc > 0.0) ? symbol(1) : dc));
}

void HalfPlaneBem::displacement(const std::vector<double>& p, std::vector<double>& u) const {
  u.resize(p.size());
  conv_->apply(p.data(), u.data());
}

BemSolution HalfPlaneBem::solve_load(const std::vector<double>& gap0, double line_load) const {
  if (!(line_load > 0.0 && std::isfinite(line_load))) throw std::invalid_argument("line load must be positive");
  const CostMeter meter;
  BemSolution s =
      std::isinf(options_.pressure_cap) ? solve(gap0, true, line_load, nullptr) : solve_load_capped(gap0, line_load);
  meter.fill(s);
  return s;
}

BemSolution HalfPlaneBem::solve_load_capped(const std::vector<double>& gap0, double line_load) const {
  // With a pressure cap the approach is found by bracketing the monotone load-approach curve,
  // each point a displacement-controlled solve warm-started from the last.
  const int n = grid_.size;
  const double g_min = *std::min_element(gap0.begin(), gap0.end());
  const double full = options_.pressure_cap * n * grid_.spacing;
  if (line_load >= full) throw std::invalid_argument("line load exceeds what the capped domain can carry");
  if (static_cast<int>(gap0.size()) != n) throw std::invalid_argument("gap has the wrong length");
  double lo = g_min, hi = g_min + line_load / modulus_;
  int coarse_iterations = 0;
  const std::vector<double> first = start(gap0, hi, coarse_iterations);
  BemSolution at_lo, at_hi = solve(gap0, false, hi, first.empty() ? nullptr : &first);
  at_lo.approach = g_min;  // the flat just touching: no load
  int total = at_hi.iterations;
  for (int doubling = 0; at_hi.line_load < line_load; ++doubling) {
    if (doubling == 200)  // the approach doubles each time: 200 doublings span any finite load
      throw std::runtime_error(
          fmt::format("boundary elements: no approach carries the line load {:.6g} N/m", line_load));
    lo = hi;
    hi = g_min + 2.0 * (hi - g_min);
    at_lo = std::move(at_hi);
    at_hi = solve(gap0, false, hi, &at_lo.pressure);
    total += at_hi.iterations;
  }
  // How exact the load can be. A displacement-controlled solve ends with its complementarity error
  // below the tolerance of the relief: it is the exact answer for gaps changed by at most
  // e = tolerance x relief [m]. A gap change of at most e changes the load by at most s e, s the
  // load's slope in the approach (the rigid flat punch's load per unit approach on the contact set,
  // the most any change of at most e can make). So approaches closer than e are not resolved (a
  // warm-started solve may not move at all: it is already within its tolerance there): the bracket
  // ends at that width, and the load is then within s (hi - lo + 2 e) of the target. s: the secant
  // over the last bracket at least 16 e wide (the two solves' noise, 2 s e, at most 1/8 of its rise).
  const double relief_m = relief(gap0, hi);
  const double resolution = options_.tolerance * relief_m;
  double slope = (at_hi.line_load - at_lo.line_load) / (hi - lo);
  // The bracket closed to the resolution, or the load met within 1e-12.
  const auto closed = [&] {
    return hi - lo <= resolution ||
           std::min(std::abs(at_hi.line_load - line_load), std::abs(at_lo.line_load - line_load)) <= 1e-12 * line_load;
  };
  bool last_high = true;  // which end the last solve moved (it starts the next)
  for (int k = 0; k < 200 && !closed(); ++k) {
    // Regula falsi on the load, bisection when it stalls.
    double mid = lo + (line_load - at_lo.line_load) / (at_hi.line_load - at_lo.line_load) * (hi - lo);
    if (!(mid > lo && mid < hi) || k % 3 == 2) mid = 0.5 * (lo + hi);
    BemSolution s = solve(gap0, false, mid, last_high ? &at_hi.pressure : &at_lo.pressure);
    total += s.iterations;
    last_high = !(s.line_load < line_load);
    if (last_high) hi = mid, at_hi = std::move(s);
    else lo = mid, at_lo = std::move(s);
    if (hi - lo >= 16.0 * resolution) slope = (at_hi.line_load - at_lo.line_load) / (hi - lo);
  }
  const bool converged = closed();
  const bool low_closer =
      at_lo.pressure.size() == gap0.size() && line_load - at_lo.line_load < at_hi.line_load - line_load;
  BemSolution best = low_closer ? std::move(at_lo) : std::move(at_hi);
  // The bracket must have closed to the resolution (or the load met within 1e-12); the load is
  // then within s (hi - lo + 2 e) <= 3 s e, accepted within twice that (the secant is not the
  // local slope), or within 1e-12 where the solves resolve more. The bound is the resolution's,
  // not the final bracket's: a bracket that never closed is a failure, never passed by its width.
  const double resolved = std::max(1e-12 * line_load, 6.0 * slope * resolution);
  if (!converged || !(std::abs(best.line_load - line_load) <= resolved))
    throw std::runtime_error(fmt::format(
        "boundary elements: capped load control reached {:.10g} N/m for {:.10g} N/m, farther than the {:.3g} N/m the "
        "solves resolve (complementarity tolerance {:.3g} of a relief of {:.4g} m; the approach's bracket {:.3g} m "
        "wide, the resolution {:.3g} m)",
        best.line_load, line_load, resolved, options_.tolerance, relief_m, hi - lo, resolution));
  best.iterations = total;
  best.coarse_iterations = coarse_iterations;
  return best;
}

double HalfPlaneBem::relief(const std::vector<double>& g0, double approach) const {
  const auto [g_min, g_max] = std::minmax_element(g0.begin(), g0.end());
  const double r = *g_max - *g_min;
  return r > 0.0 ? r : std::max(std::abs(approach - *g_min), 1e-12);
}

BemSolution HalfPlaneBem::solve_approach(const std::vector<double>& gap0, double approach) const {
  if (!std::isfinite(approach)) throw std::invalid_argument("approach must be finite");
  if (static_cast<int>(gap0.size()) != grid_.size) throw std::invalid_argument("gap has the wrong length");
  const CostMeter meter;
  int coarse_iterations = 0;
  const std::vector<double> initial = start(gap0, approach, coarse_iterations);
  BemSolution s = solve(gap0, false, approach, initial.empty() ? nullptr : &initial);
  s.coarse_iterations = coarse_iterations;
  meter.fill(s);
  return s;
}

std::vector<double> HalfPlaneBem::start(const std::vector<double>& g0, double approach, int& coarse_iterations) const {
  // The same domain on half the elements (element pairs merged, their gaps averaged), solved to
  // the same tolerance; its pressure, interpolated linearly between its element centres, starts
  // this grid.
  const int n = grid_.size, nc = n / 2;
  if (options_.coarse_elements == 0 || n % 2 != 0 || nc < options_.coarse_elements)
    return options_.overlap_start ? overlap_start(g0, approach) : std::vector<double>{};
  const HalfPlaneBem coarse(HalfPlaneGrid{grid_.start, 2.0 * grid_.spacing, nc}, modulus_, options_);
  std::vector<double> gc(static_cast<std::size_t>(nc));
  for (std::size_t i = 0; i < gc.size(); ++i) gc[i] = 0.5 * (g0[2 * i] + g0[2 * i + 1]);
  BemSolution s;
  try {
    s = coarse.solve_approach(gc, approach);
  } catch (const std::runtime_error&) {
    return {};  // the coarse grid did not converge: start this one from zero
  }
  coarse_iterations += s.iterations + s.coarse_iterations;
  const std::vector<double>& pc = s.pressure;
  std::vector<double> p(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < pc.size(); ++i) {
    const double left = pc[i == 0 ? 0 : i - 1], right = pc[std::min(i + 1, pc.size() - 1)];
    p[2 * i] = 0.75 * pc[i] + 0.25 * left;
    p[2 * i + 1] = 0.75 * pc[i] + 0.25 * right;
  }
  return p;
}

std::vector<double> HalfPlaneBem::overlap_start(const std::vector<double>& g0, double approach) const {
  // Hertz's pressure is ~sqrt of the rigid overlap of a parabola, over a narrower band than the
  // overlap (the surface around the contact sinks too). Candidates sqrt(overlap) with the
  // approach shrunk by 1, 1/2, ..., 1/16, each at its best scale (2 transforms); the one of
  // least energy 1/2 p'Kp + p'(g0 - approach) starts the iterations.
  const std::size_t un = g0.size();
  const double g_min = *std::min_element(g0.begin(), g0.end());
  if (!(approach > g_min)) return {};
  std::vector<double> s(un), ks(un), best;
  double best_energy = 0.0;
  for (double shrink = 1.0; shrink > 0.05; shrink *= 0.5) {
    const double level = g_min + shrink * (approach - g_min);
    for (std::size_t k = 0; k < un; ++k) s[k] = std::sqrt(std::max(level - g0[k], 0.0));
    displacement(s, ks);
    double sks = 0.0, sc = 0.0;
    for (std::size_t k = 0; k < un; ++k) sks += s[k] * ks[k], sc += s[k] * (g0[k] - approach);
    if (!(sks > 0.0) || !(sc < 0.0)) continue;
    const double energy = -0.5 * sc * sc / sks;
    if (energy < best_energy) {
      best_energy = energy;
      best = s;
      for (double& x : best) x = std::min(options_.pressure_cap, -sc / sks * x);
    }
  }
  return best;
}

BemSolution HalfPlaneBem::solve(const std::vector<double>& g0, bool load_control, double target,
                                const std::vector<double>* initial) const {
  if (!load_control) return solve_box(g0, target, initial);
  const int n = grid_.size;
  if (static_cast<int>(g0.size()) != n) throw std::invalid_argument("gap has the wrong length");
  const double h = grid_.spacing, cap = options_.pressure_cap;
  const double g_min = *std::min_element(g0.begin(), g0.end());
  const double g_max = *std::max_element(g0.begin(), g0.end());
  double scale = g_max - g_min;
  if (!(scale > 0.0)) scale = std::max(std::abs(target) / modulus_, 1e-12);
  // Initial pressure: uniform over the lowest gaps (load control) or where the flat overlaps.
  std::vector<double> p(static_cast<std::size_t>(n), 0.0), u, g(static_cast<std::size_t>(n)),
      t(static_cast<std::size_t>(n), 0.0), r;
  if (initial) {
    p = *initial;
  } else if (load_control) {
    std::fill(p.begin(), p.end(), std::min(cap, target / (n * h)));
  } else {
    for (int i = 0; i < n; ++i)
      if (g0[static_cast<std::size_t>(i)] < target)
        p[static_cast<std::size_t>(i)] =
            std::min(cap, 1e-3 * modulus_ * (target - g0[static_cast<std::size_t>(i)]) / (n * h));
  }
  auto is_free = [&](double pi) { return pi > 0.0 && pi < cap; };
  double g_old = 1.0, approach = load_control ? 0.0 : target, error = 0.0;
  bool conjugate = false;
  int it = 0;
  for (; it < options_.max_iterations; ++it) {
    displacement(p, u);
    int free_count = 0;
    double mean = 0.0;
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      g[k] = u[k] + g0[k];
      if (is_free(p[k])) {
        mean += g[k];
        ++free_count;
      }
    }
    if (load_control) approach = free_count > 0 ? mean / free_count : approach;
    for (double& x : g) x -= approach;
    // Complementarity error of the current iterate.
    error = 0.0;
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      if (is_free(p[k])) error = std::max(error, std::abs(g[k]));
      else if (p[k] <= 0.0) error = std::max(error, -g[k]);
      else error = std::max(error, g[k]);
    }
    error /= scale;
    if (load_control) {
      double load = 0.0;
      for (double x : p) load += x * h;
      error = std::max(error, std::abs(load - target) / target);
    }
    if (error < options_.tolerance) break;
    if (free_count == 0) {
      // Everything capped or open: move all overlapping nodes into contact and continue.
      for (int i = 0; i < n; ++i)
        if (g[static_cast<std::size_t>(i)] < 0.0 && p[static_cast<std::size_t>(i)] <= 0.0)
          p[static_cast<std::size_t>(i)] = std::min(cap, 1e-6 * cap);
      conjugate = false;
      continue;
    }
    // Conjugate direction on the free set.
    double gg = 0.0;
    for (int i = 0; i < n; ++i)
      if (is_free(p[static_cast<std::size_t>(i)]))
        gg += g[static_cast<std::size_t>(i)] * g[static_cast<std::size_t>(i)];
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      t[k] = is_free(p[k]) ? g[k] + (conjugate && g_old > 0.0 ? gg / g_old * t[k] : 0.0) : 0.0;
    }
    g_old = gg;
    displacement(t, r);
    if (load_control) {
      double rm = 0.0;
      for (int i = 0; i < n; ++i)
        if (is_free(p[static_cast<std::size_t>(i)])) rm += r[static_cast<std::size_t>(i)];
      rm /= free_count;
      for (double& x : r) x -= rm;
    }
    double gt = 0.0, rt = 0.0;
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      if (is_free(p[k])) {
        gt += g[k] * t[k];
        rt += r[k] * t[k];
      }
    }
    const double tau = rt != 0.0 ? gt / rt : 0.0;
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      const bool was_free = is_free(p[k]);
      if (was_free) {
        p[k] = std::clamp(p[k] - tau * t[k], 0.0, cap);
        if (!is_free(p[k])) changed = true;
      } else if (p[k] <= 0.0 && g[k] < 0.0) {
        p[k] = std::min(cap, -tau * g[k]);  // overlap outside the contact: enter (Polonsky-Keer)
        changed = true;
      } else if (p[k] >= cap && g[k] > 0.0) {
        p[k] = std::max(0.0, cap - tau * g[k]);  // open gap under a capped node: release
        changed = true;
      }
    }
    conjugate = !changed;
    if (load_control) {
      double capped = 0.0, free_sum = 0.0;
      for (double x : p) (x >= cap ? capped : free_sum) += x;
      const double needed = target / h - capped;
      if (free_sum > 0.0 && needed > 0.0) {
        for (double& x : p)
          if (x < cap) x = std::min(cap, x * needed / free_sum);
      }
    }
  }
  return finish(std::move(p), std::move(u), std::move(g), approach, it, error);
}

BemSolution HalfPlaneBem::solve_box(const std::vector<double>& g0, double approach,
                                    const std::vector<double>* initial) const {
  // Displacement control: min f(p) = 1/2 p'Kp + p'(g0 - approach) subject to 0 <= p <= cap,
  // whose gradient is the gap. Dostal's MPRGP (modified proportioning with reduced gradient
  // projections): conjugate gradients on the free set, expansion steps when a bound is hit,
  // proportioning steps when the chopped gradient dominates. Preconditioned in face (Dostal,
  // Optimal Quadratic Programming Algorithms, 2009, MPRGP's preconditioning): the directions
  // are conjugate gradients of z = M_F^-1 phi, M^-1 the inverse symbol of the kernel (inverse_symbol_)
  // restricted to the free set F, symmetric positive definite there. Expansion: the whole CG
  // step projected onto the bounds (Kruzik et al., Active set expansion strategies in MPRGP
  // algorithm, 2020), which moves many nodes onto their bounds at once, kept if f falls below
  // its value at the largest feasible step (or while a few rises are allowed); else Dostal's:
  // that step, then a projected step of 1/||K|| along the free gradient.
  const int n = grid_.size;
  if (static_cast<int>(g0.size()) != n) throw std::invalid_argument("gap has the wrong length");
  const double cap = options_.pressure_cap;
  const double scale = relief(g0, approach);
  const std::size_t un = static_cast<std::size_t>(n);
  std::vector<double> p(un, 0.0), g(un), d(un, 0.0), kd(un), phi(un), beta(un), z(un), p_old;
  if (initial) p = *initial;
  for (double& x : p) x = std::clamp(x, 0.0, cap);
  auto is_free = [&](std::size_t k) { return p[k] > 0.0 && p[k] < cap; };
  auto gradient = [&]() {
    displacement(p, g);
    for (std::size_t k = 0; k < un; ++k) g[k] += g0[k] - approach;
  };
  auto energy = [&]() {  // f = 1/2 p'(Kp + 2 (g0 - approach)) = 1/2 p'(g + g0 - approach)
    double f = 0.0;
    for (std::size_t k = 0; k < un; ++k) f += p[k] * (g[k] + g0[k] - approach);
    return 0.5 * f;
  };
  auto split = [&]() {  // free and chopped gradients
    double ff = 0.0, bb = 0.0, err = 0.0;
    for (std::size_t k = 0; k < un; ++k) {
      const bool low = p[k] <= 0.0, high = p[k] >= cap;
      phi[k] = (!low && !high) ? g[k] : 0.0;
      beta[k] = low ? std::min(g[k], 0.0) : high ? std::max(g[k], 0.0) : 0.0;
      ff += phi[k] * phi[k];
      bb += beta[k] * beta[k];
      err = std::max(err, std::abs(phi[k] + beta[k]));
    }
    return std::tuple<double, double, double>{ff, bb, err / scale};
  };
  const bool pre = options_.precondition;
  auto precondition = [&]() {  // z = M_F^-1 phi on the free set, zero elsewhere; returns phi'z
    if (pre) conv_->apply_spectral(phi.data(), z.data(), inverse_symbol_);
    double zphi = 0.0;
    for (std::size_t k = 0; k < un; ++k) {
      if (!pre) z[k] = phi[k];
      else if (!is_free(k)) z[k] = 0.0;
      zphi += z[k] * phi[k];
    }
    return zphi;
  };
  const double alpha_bar = 1.0 / kernel_norm_;  // expansion step length, 1/||K||
  gradient();
  auto [ff, bb, error] = split();
  double zphi = precondition();
  d = z;
  int it = 0;
  // The projected steps may raise f a little and still find the active set sooner: a few may,
  // the rest fall back to Dostal's expansion (finitely many exceptions keep MPRGP convergent).
  int rises_left = 8;
  for (;;) {
    for (; it < options_.max_iterations && error >= options_.tolerance; ++it) {
      if (bb <= ff) {
        displacement(d, kd);
        double dkd = 0.0, gd = 0.0;
        for (std::size_t k = 0; k < un; ++k) dkd += d[k] * kd[k], gd += g[k] * d[k];
        const double a_cg = dkd > 0.0 ? gd / dkd : 0.0;
        double a_f = std::numeric_limits<double>::infinity();  // largest feasible step along -d
        for (std::size_t k = 0; k < un; ++k) {
          if (d[k] > 0.0) a_f = std::min(a_f, p[k] / d[k]);
          else if (d[k] < 0.0) a_f = std::min(a_f, (p[k] - cap) / d[k]);
        }
        if (a_cg <= a_f) {
          for (std::size_t k = 0; k < un; ++k) p[k] -= a_cg * d[k], g[k] -= a_cg * kd[k];
          std::tie(ff, bb, error) = split();
          const double zphi_old = zphi;
          zphi = precondition();
          const double gamma = zphi_old > 0.0 ? zphi / zphi_old : 0.0;  // Fletcher-Reeves on the free set
          for (std::size_t k = 0; k < un; ++k) d[k] = is_free(k) ? z[k] + gamma * d[k] : 0.0;
          continue;
        }
        const double f_feasible = energy() - a_f * gd + 0.5 * a_f * a_f * dkd;  // f at the largest feasible step
        p_old = p;
        z = g;  // z is free until the next precondition()
        for (std::size_t k = 0; k < un; ++k) p[k] = std::clamp(p[k] - a_cg * d[k], 0.0, cap);
        gradient();
        if (!(energy() <= f_feasible || rises_left-- > 0)) {
          for (std::size_t k = 0; k < un; ++k)
            p[k] = std::clamp(p_old[k] - a_f * d[k], 0.0, cap), g[k] = z[k] - a_f * kd[k];
          split();
          for (std::size_t k = 0; k < un; ++k) p[k] = std::clamp(p[k] - alpha_bar * phi[k], 0.0, cap);
          gradient();
        }
      } else {
        // Proportioning: release along the chopped gradient.
        displacement(beta, kd);
        double bkb = 0.0;
        for (std::size_t k = 0; k < un; ++k) bkb += beta[k] * kd[k];
        const double a = bkb > 0.0 ? bb / bkb : 0.0;
        for (std::size_t k = 0; k < un; ++k) p[k] = std::clamp(p[k] - a * beta[k], 0.0, cap);
        gradient();
      }
      std::tie(ff, bb, error) = split();
      zphi = precondition();
      d = z;
    }
    // The gap from the pressure itself (the conjugate-gradient steps update it by recurrence):
    // converged only if it is within the tolerance too. kd holds the displacement.
    displacement(p, kd);
    for (std::size_t k = 0; k < un; ++k) g[k] = kd[k] + g0[k] - approach;
    std::tie(ff, bb, error) = split();
    if (error < options_.tolerance || it >= options_.max_iterations) break;
    zphi = precondition();
    d = z;
  }
  return finish(std::move(p), std::move(kd), std::move(g), approach, it, error);
}

BemSolution HalfPlaneBem::finish(std::vector<double> p, std::vector<double> u, std::vector<double> g, double approach,
                                 int iterations, double error) const {
  if (!(error < options_.tolerance))
    throw std::runtime_error(
        fmt::format("boundary elements: complementarity error {:.3g} above the tolerance {:.3g} after {} "
                    "iterations",
                    error, options_.tolerance, iterations));
  BemSolution s;
  for (double x : p) {
    s.line_load += x * grid_.spacing;
    s.contact_elements += x > 0.0;
    s.capped_elements += x >= options_.pressure_cap;
  }
  s.pressure = std::move(p);
  s.displacement = std::move(u);
  s.gap = std::move(g);
  s.approach = approach;
  s.iterations = iterations;
  s.complementarity_error = error;
  return s;
}

double PlaneStrainStress::von_mises() const {
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) + 3.0 * xz * xz);
}

PlaneStrainStress uniform_strip_stress(double x, double z, double a, double p, double nu) {
  // Flamant line load integrated over s in [-a, a]; xi = x - s runs from x - a to x + a.
  auto f = [z](double xi) {
    const double r2 = xi * xi + z * z;
    const double at = std::atan2(xi, z);
    return std::array<double, 3>{at - xi * z / r2, at + xi * z / r2, z * z / r2};
  };
  const auto hi = f(x + a), lo = f(x - a);
  PlaneStrainStress s;
  s.xx = -p / kPi * (hi[0] - lo[0]);
  s.zz = -p / kPi * (hi[1] - lo[1]);
  s.xz = p / kPi * (hi[2] - lo[2]);
  s.yy = nu * (s.xx + s.zz);
  return s;
}

PlaneStrainStress subsurface_stress(const HalfPlaneGrid& grid, const std::vector<double>& p, double x, double z,
                                    double nu) {
  PlaneStrainStress s;
  for (int j = 0; j < grid.size; ++j) {
    const double pj = p[static_cast<std::size_t>(j)];
    if (pj == 0.0) continue;
    const PlaneStrainStress e = uniform_strip_stress(x - grid.x(j), z, 0.5 * grid.spacing, pj, nu);
    s.xx += e.xx;
    s.zz += e.zz;
    s.xz += e.xz;
  }
  s.yy = nu * (s.xx + s.zz);
  return s;
}

namespace {
// The far field of a cluster of edges: F(x - e) interpolated in e at kChebyshev points of the
// first kind on the cluster's interval, used where the Bernstein ellipse through the nearest
// singularity of F (e = x -+ i z) has parameter rho >= kSeparation: interpolation error
// ~rho^-kChebyshev = 1e-16 of the cluster's sum of |jumps|, below the direct sum's rounding.
constexpr int kChebyshev = 20;
constexpr double kSeparation = 6.5;
constexpr std::size_t kLeaf = 48;  // clusters of at most this many edges are summed directly

// Adds jump F(t), t = (x - e)/z, to the three sums.
inline void add_edge(double t, double jump, double& sx, double& sz, double& sxz) {
  const double w = 1.0 / (1.0 + t * t), at = arctan(t), cross = t * w;
  sx += jump * (at - cross);
  sz += jump * (at + cross);
  sxz += jump * w;
}
}  // namespace

SubsurfaceStressField::SubsurfaceStressField(const HalfPlaneGrid& grid, const std::vector<double>& p) {
  if (static_cast<int>(p.size()) != grid.size) throw std::invalid_argument("pressure has the wrong length");
  for (int k = 0; k <= grid.size; ++k) {
    const double jump =
        (k < grid.size ? p[static_cast<std::size_t>(k)] : 0.0) - (k > 0 ? p[static_cast<std::size_t>(k - 1)] : 0.0);
    if (jump == 0.0) continue;
    edge_.push_back(grid.start + k * grid.spacing);
    jump_.push_back(jump);
  }
  // Binary tree of clusters (halves of the edge list) down to kLeaf edges; each cluster above a
  // leaf keeps its Chebyshev points' weights W_j = sum_k jump_k L_j(e_k) (barycentric Lagrange
  // basis of the first-kind points).
  std::array<double, kChebyshev> node{}, lambda{};
  for (int j = 0; j < kChebyshev; ++j) {
    const double angle = (2 * j + 1) * kPi / (2 * kChebyshev);
    node[static_cast<std::size_t>(j)] = std::cos(angle);
    lambda[static_cast<std::size_t>(j)] = (j % 2 == 0 ? 1.0 : -1.0) * std::sin(angle);
  }
  if (edge_.empty()) return;
  std::vector<std::size_t> pending{0};
  cluster_.push_back({0, edge_.size()});
  while (!pending.empty()) {
    const std::size_t c = pending.back();
    pending.pop_back();
    const std::size_t lo = cluster_[c].lo, hi = cluster_[c].hi;
    if (hi - lo <= kLeaf) continue;
    Cluster& k = cluster_[c];
    k.centre = 0.5 * (edge_[lo] + edge_[hi - 1]);
    k.half = 0.5 * (edge_[hi - 1] - edge_[lo]);
    k.weights = weight_.size();
    weight_.resize(weight_.size() + kChebyshev, 0.0);
    for (std::size_t e = lo; e < hi; ++e) {
      const double s = (edge_[e] - k.centre) / k.half;
      std::array<double, kChebyshev> b{};
      double total = 0.0;
      int exact = -1;
      for (int j = 0; j < kChebyshev && exact < 0; ++j) {
        const double d = s - node[static_cast<std::size_t>(j)];
        if (d == 0.0) exact = j;
        else total += b[static_cast<std::size_t>(j)] = lambda[static_cast<std::size_t>(j)] / d;
      }
      for (int j = 0; j < kChebyshev; ++j)
        weight_[k.weights + static_cast<std::size_t>(j)] +=
            jump_[e] * (exact >= 0 ? (j == exact ? 1.0 : 0.0) : b[static_cast<std::size_t>(j)] / total);
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    k.left = cluster_.size();
    cluster_.push_back({lo, mid});
    cluster_.push_back({mid, hi});
    pending.push_back(cluster_.size() - 2);
    pending.push_back(cluster_.size() - 1);
  }
}

PlaneStrainStress SubsurfaceStressField::at(double x, double z, double nu) const {
  // uniform_strip_stress's F(xi) = (atan2(xi, z) -+ xi z/r^2, z^2/r^2), r^2 = xi^2 + z^2; with
  // t = xi/z: (atan t -+ t/(1 + t^2), 1/(1 + t^2)). Clusters far enough from (x, z) by their
  // Chebyshev points, the others by their halves, leaves edge by edge.
  if (!(z > 0.0)) throw std::invalid_argument("stress depth must be positive");
  const double inverse_z = 1.0 / z;
  double sx = 0.0, sz = 0.0, sxz = 0.0;
  std::array<std::size_t, 128> stack{};
  std::size_t top = 0;
  if (!cluster_.empty()) stack[top++] = 0;
  while (top > 0) {
    const Cluster& c = cluster_[stack[--top]];
    if (c.left == 0) {
      for (std::size_t k = c.lo; k < c.hi; ++k) add_edge((x - edge_[k]) * inverse_z, jump_[k], sx, sz, sxz);
      continue;
    }
    // Bernstein ellipse parameter of the singularity (x + i z - centre)/half.
    const std::complex<double> w((x - c.centre) / c.half, z / c.half), root = std::sqrt(w - 1.0) * std::sqrt(w + 1.0);
    const double rho = std::max(std::abs(w + root), std::abs(w - root));
    if (rho >= kSeparation) {
      for (int j = 0; j < kChebyshev; ++j) {
        const double e = c.centre + c.half * std::cos((2 * j + 1) * kPi / (2 * kChebyshev));
        add_edge((x - e) * inverse_z, weight_[c.weights + static_cast<std::size_t>(j)], sx, sz, sxz);
      }
    } else {
      stack[top++] = c.left;
      stack[top++] = c.left + 1;
    }
  }
  PlaneStrainStress s;
  s.xx = -sx / kPi;
  s.zz = -sz / kPi;
  s.xz = sxz / kPi;
  s.yy = nu * (s.xx + s.zz);
  return s;
}

}  // namespace geartrib::contact
