// The moments of a power law, in closed form: integral_a^b q^n c0 (q/q0)^s dq, and of a spectrum
// tabulated log-log linear between its nodes, segment by segment (contact::SpectrumPart's tabulated
// shape and surface::radial_spectrum, which builds its nodes).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace geartrib::core {

// integral_a^b q^n c0 (q/q0)^s dq = c0 q0^(n+1) t_a^e (exp(e ln(b/a)) - 1)/e, t_a = a/q0, e = n + 1 + s,
// and c0 q0^(n+1) t_a^e ln(b/a) where e = 0 (the integrand q^-1): expm1(x)/x taken as 1 at x = 0, so
// the two forms join without a cancellation. 0 < a <= b, q0 > 0.
inline double power_law_integral(double c0, double q0, double s, int n, double a, double b) {
  const double e = n + 1.0 + s, span = std::log(b / a);
  const double x = e * span;
  const double growth = x == 0.0 ? 1.0 : std::expm1(x) / x;
  return c0 * std::pow(q0, n + 1.0) * std::exp(e * std::log(a / q0)) * span * growth;
}

// integral_a^b q^n C(q) dq of the nodes' interpolant C, log-log linear between nodes q (increasing,
// positive) with values c (>= 0), zero outside them and over a segment with a zero end.
inline double log_log_moment(const std::vector<double>& q, const std::vector<double>& c, int n, double a, double b) {
  double m = 0.0;
  for (std::size_t k = 0; k + 1 < q.size() && q[k] < b; ++k) {
    const double lo = std::max(a, q[k]), hi = std::min(b, q[k + 1]);
    if (!(hi > lo) || !(c[k] > 0.0 && c[k + 1] > 0.0)) continue;
    m += power_law_integral(c[k], q[k], std::log(c[k + 1] / c[k]) / std::log(q[k + 1] / q[k]), n, lo, hi);
  }
  return m;
}

}  // namespace geartrib::core
