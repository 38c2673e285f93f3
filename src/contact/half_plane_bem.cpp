#include "contact/half_plane_bem.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <fmt/format.h>

namespace geartrib::contact {

namespace {
constexpr double kPi = std::numbers::pi;
double log_antiderivative(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }  // int ln|t| dt
}  // namespace

void BemOptions::validate() const {
  if (!(tolerance > 0.0)) throw std::invalid_argument("BEM tolerance must be positive");
  if (max_iterations < 1) throw std::invalid_argument("BEM max_iterations must be positive");
  if (!(pressure_cap > 0.0)) throw std::invalid_argument("pressure cap must be positive");
  if (!periodic && !(reference_length > 0.0)) throw std::invalid_argument("reference length must be positive");
}

HalfPlaneBem::HalfPlaneBem(const HalfPlaneGrid& grid, double modulus, const BemOptions& options)
    : grid_(grid), modulus_(modulus), options_(options) {
  options_.validate();
  if (grid.size < 2 || !(grid.spacing > 0.0))
    throw std::invalid_argument("BEM grid needs >= 2 elements of positive width");
  if (!(modulus > 0.0)) throw std::invalid_argument("modulus must be positive");
  const int n = grid.size;
  const double h = grid.spacing, c = 2.0 / (kPi * modulus);
  if (!options_.periodic) {
    // u_i = c sum_j p_j int_elem_j ln(L_ref/|x_i - s|) ds
    const double lref = options_.reference_length;
    if (lref < n * h)
      throw std::invalid_argument(
          fmt::format("reference length {:.3g} m must exceed the domain {:.3g} m", lref, n * h));
    std::vector<double> k(static_cast<std::size_t>(2 * n - 1));
    for (int m = -(n - 1); m <= n - 1; ++m)
      k[static_cast<std::size_t>(m + n - 1)] =
          c * (h * std::log(lref) - (log_antiderivative(m * h + 0.5 * h) - log_antiderivative(m * h - 0.5 * h)));
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
  }
}

void HalfPlaneBem::displacement(const std::vector<double>& p, std::vector<double>& u) const {
  u.resize(p.size());
  conv_->apply(p.data(), u.data());
}

BemSolution HalfPlaneBem::solve_load(const std::vector<double>& gap0, double line_load) const {
  if (!(line_load > 0.0 && std::isfinite(line_load))) throw std::invalid_argument("line load must be positive");
  if (std::isinf(options_.pressure_cap)) return solve(gap0, true, line_load, nullptr);
  // With a pressure cap the approach is found by bracketing the monotone load-approach curve,
  // each point a displacement-controlled solve warm-started from the last.
  const int n = grid_.size;
  const double g_min = *std::min_element(gap0.begin(), gap0.end());
  const double full = options_.pressure_cap * n * grid_.spacing;
  if (line_load >= full) throw std::invalid_argument("line load exceeds what the capped domain can carry");
  double lo = g_min, hi = g_min + line_load / modulus_;
  BemSolution at_hi = solve(gap0, false, hi, nullptr);
  int total = at_hi.iterations;
  while (at_hi.line_load < line_load) {
    lo = hi;
    hi = g_min + 2.0 * (hi - g_min);
    at_hi = solve(gap0, false, hi, &at_hi.pressure);
    total += at_hi.iterations;
  }
  BemSolution best = at_hi;
  double load_lo = 0.0, load_hi = at_hi.line_load;
  for (int k = 0; k < 200 && std::abs(best.line_load - line_load) > 1e-12 * line_load; ++k) {
    // Regula falsi on the load, bisection when it stalls.
    double mid = lo + (line_load - load_lo) / (load_hi - load_lo) * (hi - lo);
    if (!(mid > lo && mid < hi) || k % 3 == 2) mid = 0.5 * (lo + hi);
    best = solve(gap0, false, mid, &best.pressure);
    total += best.iterations;
    if (best.line_load < line_load) lo = mid, load_lo = best.line_load;
    else hi = mid, load_hi = best.line_load;
    if (hi - lo <= 1e-15 * std::max(1.0, std::abs(hi))) break;
  }
  if (std::abs(best.line_load - line_load) > 1e-9 * line_load)
    throw std::runtime_error(fmt::format("boundary elements: capped load control reached {:.10g} N/m for {:.10g} N/m",
                                         best.line_load, line_load));
  best.iterations = total;
  return best;
}

BemSolution HalfPlaneBem::solve_approach(const std::vector<double>& gap0, double approach) const {
  if (!std::isfinite(approach)) throw std::invalid_argument("approach must be finite");
  return solve(gap0, false, approach, nullptr);
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
  // Displacement control: min 1/2 p'Kp + p'(g0 - approach) subject to 0 <= p <= cap, whose
  // gradient is the gap. Dostal's MPRGP (modified proportioning with reduced gradient
  // projections): conjugate gradients on the free set, expansion steps along the projected
  // free gradient when a bound is hit, proportioning steps when the chopped gradient dominates.
  const int n = grid_.size;
  if (static_cast<int>(g0.size()) != n) throw std::invalid_argument("gap has the wrong length");
  const double cap = options_.pressure_cap;
  const double g_min = *std::min_element(g0.begin(), g0.end()), g_max = *std::max_element(g0.begin(), g0.end());
  double scale = g_max - g_min;
  if (!(scale > 0.0)) scale = std::max(std::abs(approach - g_min), 1e-12);
  const std::size_t un = static_cast<std::size_t>(n);
  std::vector<double> p(un, 0.0), g(un), d(un, 0.0), kd(un), phi(un), beta(un);
  if (initial) p = *initial;
  for (double& x : p) x = std::clamp(x, 0.0, cap);
  auto gradient = [&]() {
    displacement(p, g);
    for (std::size_t k = 0; k < un; ++k) g[k] += g0[k] - approach;
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
  // Step length of the expansion steps: 1/||K||, ||K|| bounded by the kernel's absolute row sum.
  std::vector<double> ones(un, 1.0), row;
  displacement(ones, row);
  const double norm_k = *std::max_element(row.begin(), row.end());
  const double alpha_bar = 1.0 / std::max(norm_k, 1e-300);
  gradient();
  auto [ff, bb, error] = split();
  d = phi;
  int it = 0;
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
        const double ff_old = ff;
        std::tie(ff, bb, error) = split();
        const double gamma = ff_old > 0.0 ? ff / ff_old : 0.0;  // Fletcher-Reeves on the free set
        for (std::size_t k = 0; k < un; ++k) d[k] = phi[k] + gamma * d[k] * (phi[k] != 0.0 ? 1.0 : 0.0);
      } else {
        // Expansion: to the bound, then a projected step along the free gradient.
        for (std::size_t k = 0; k < un; ++k) p[k] = std::clamp(p[k] - a_f * d[k], 0.0, cap);
        gradient();
        split();
        for (std::size_t k = 0; k < un; ++k) p[k] = std::clamp(p[k] - alpha_bar * phi[k], 0.0, cap);
        gradient();
        std::tie(ff, bb, error) = split();
        d = phi;
      }
    } else {
      // Proportioning: release along the chopped gradient.
      displacement(beta, kd);
      double bkb = 0.0;
      for (std::size_t k = 0; k < un; ++k) bkb += beta[k] * kd[k];
      const double a = bkb > 0.0 ? bb / bkb : 0.0;
      for (std::size_t k = 0; k < un; ++k) p[k] = std::clamp(p[k] - a * beta[k], 0.0, cap);
      gradient();
      std::tie(ff, bb, error) = split();
      d = phi;
    }
  }
  std::vector<double> u;
  displacement(p, u);
  return finish(std::move(p), std::move(u), std::move(g), approach, it, error);
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

}  // namespace geartrib::contact
