// The rigid-isoviscous line contact: a rigid cylinder of radius R on a rigid plane, an
// incompressible oil of constant viscosity eta, the surfaces moving at u1 and u2 (mean u_m =
// (u1 + u2)/2), the film h(x) = h0 + x^2/(2 R) (parabolic approximation), the pressure zero at the
// inlet and Reynolds' (Swift-Stieber) condition p = dp/dx = 0 where the film ruptures. Steady
// Reynolds integrated once (the flux u_m h - h^3 p'/(12 eta) is the same at every x and equals
// u_m h_e at the rupture, where p' = 0):
//   dp/dx = 12 eta u_m (h - h_e)/h^3.
// In xi = x/sqrt(2 R h0), h = h0 (1 + xi^2), h_e = h0 (1 + xi_e^2) and the dimensionless pressure
// P = p h0^2/(12 eta u_m sqrt(2 R h0)):
//   dP/dxi = (xi^2 - xi_e^2)/(1 + xi^2)^3,  P(xi_in) = 0,  P(xi_e) = 0,
// so p = 12 eta u_m sqrt(2 R/h0)/h0 P(xi) and the load per unit width w = int p dx =
// C eta u_m R/h0 with C = 24 int P dxi; the peak lies where h = h_e, at xi = -xi_e.
// The fully flooded problem (xi_in -> -inf) is Martin's (1916) with Reynolds' exit; the issue's
// C = 4.895 and x_e = 0.4751 sqrt(2 R h0) are its constants. A finite inlet xi_in (a numerical
// domain's start, p = 0 there) is the same problem on a shorter film.
//
// Two derivations, for a solver's test to meet and for each other to check:
//  - closed_form(): with xi = tan(g), dP/dg = sin^2 g cos^2 g - xi_e^2 cos^4 g, integrated in
//    closed form; xi_e is the root of P(xi_e) = 0 (TOMS 748), the load by parts
//    int P dxi = -int xi P' dxi = [sin^4 g + xi_e^2 cos^4 g]/4 from g_e back to g_in.
//  - shooting(): the Reynolds equation integrated numerically (Boost.Odeint, Dormand-Prince 5
//    with dense output) from the inlet for a trial exit, with the load integral carried as a second
//    state; the exit shot until P(xi_e) = 0 (TOMS 748). No antiderivative is used.
// For the fully flooded contact the two give xi_e = 0.4751299201 and C = 4.894968494, and
// C (1 + xi_e^2) = 6 exactly (int P dxi = cos^2 g_e/4 there: w = 6 eta u_m R/h_e).
// Header-only, for the tests and the validation runner; not part of the library.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace geartrib::reference::rigid_isoviscous {

inline constexpr double kFullyFlooded = -std::numeric_limits<double>::infinity();

// The dimensionless solution for an inlet at xi_in (kFullyFlooded: at infinity).
struct Solution {
  double inlet = kFullyFlooded;  // xi_in = x_in/sqrt(2 R h0)
  double exit = 0.0;             // xi_e: the film ruptures at x_e = xi_e sqrt(2 R h0)
  double load = 0.0;             // C: w = C eta u_m R/h0 (u_m the mean speed)
  double peak = 0.0;             // c_p: p_max = c_p eta u_m sqrt(R/h0)/h0, at xi = -xi_e
};

namespace detail {
inline double angle(double xi) { return std::isinf(xi) ? std::copysign(std::numbers::pi / 2.0, xi) : std::atan(xi); }
// The antiderivative of dP/dg = sin^2 g cos^2 g - e2 cos^4 g (e2 = xi_e^2):
// sin^2 cos^2 = (1 - cos 4g)/8, cos^4 = (3 + 4 cos 2g + cos 4g)/8.
inline double antiderivative(double g, double e2) {
  return g / 8.0 - std::sin(4.0 * g) / 32.0 - e2 * (3.0 * g / 8.0 + std::sin(2.0 * g) / 4.0 + std::sin(4.0 * g) / 32.0);
}
// int P dxi from the inlet to the exit, by parts (P vanishes at both ends): -[sin^4 g + e2 cos^4 g]/4.
inline double load_integral(double g_in, double g_e, double e2) {
  const auto f = [e2](double g) { return (std::pow(std::sin(g), 4) + e2 * std::pow(std::cos(g), 4)) / 4.0; };
  return f(g_in) - f(g_e);
}
inline double root(auto&& residual, double lo, double hi) {
  std::uintmax_t iterations = 200;
  const auto [a, b] =
      boost::math::tools::toms748_solve(residual, lo, hi, boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (a + b);
}
inline void check_inlet(double xi_in) {
  if (!(xi_in < 0.0)) throw std::invalid_argument("rigid_isoviscous: the inlet must lie before the gap's minimum");
}
}  // namespace detail

// P(xi) for an exit xi_e and inlet xi_in, in closed form; zero outside [xi_in, xi_e].
inline double pressure(double xi, double xi_e, double xi_in = kFullyFlooded) {
  if (xi <= xi_in || xi >= xi_e) return 0.0;
  const double e2 = xi_e * xi_e;
  return detail::antiderivative(std::atan(xi), e2) - detail::antiderivative(detail::angle(xi_in), e2);
}

// The first derivation: closed-form integrals, the exit by root finding.
inline Solution closed_form(double xi_in = kFullyFlooded) {
  detail::check_inlet(xi_in);
  const double g_in = detail::angle(xi_in);
  // P(xi_e) > 0 as xi_e -> 0 (the film converges all the way) and < 0 at xi_e = 1 for every inlet.
  const double xi_e = detail::root(
      [g_in](double e) { return detail::antiderivative(std::atan(e), e * e) - detail::antiderivative(g_in, e * e); },
      0.0, 1.0);
  const double e2 = xi_e * xi_e;
  const double load = 24.0 * detail::load_integral(g_in, std::atan(xi_e), e2);
  const double peak_xi = std::max(-xi_e, xi_in);  // an inlet past -xi_e cuts the rising flank off
  const double peak = 12.0 * std::numbers::sqrt2 * pressure(peak_xi, xi_e, xi_in);
  return {xi_in, xi_e, load, peak};
}

// The second derivation: the Reynolds equation integrated numerically, shooting on the exit.
// The independent variable is g = atan(xi) so that a fully flooded inlet (g = -pi/2) is a finite
// start: dP/dg = dP/dxi (1 + xi^2), d(int P dxi)/dg = P (1 + xi^2), with xi = tan g.
struct Shot {
  double pressure = 0.0;  // P at the end
  double integral = 0.0;  // int P dxi from the inlet to the end
};
// From the inlet xi_in to xi_end (xi_end <= xi_e) for a trial exit xi_e (the film h_e where p' = 0).
inline Shot shoot(double xi_e, double xi_in, double xi_end, double tolerance = 1e-13) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, 2>;
  const double e2 = xi_e * xi_e;
  auto rhs = [e2](const State& s, State& ds, double g) {
    const double xi = std::tan(g), q = 1.0 + xi * xi;  // q = h/h0
    ds[0] = (xi * xi - e2) / (q * q * q) * q;          // dP/dxi = (h - h_e)/h^3 in units of h0, times dxi/dg
    ds[1] = s[0] * q;
  };
  State s{0.0, 0.0};
  const double g0 = detail::angle(xi_in), g1 = std::atan(xi_end);
  auto stepper = odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  odeint::integrate_adaptive(stepper, rhs, s, g0, g1, (g1 - g0) * 1e-3);
  return {s[0], s[1]};
}
inline Solution shooting(double xi_in = kFullyFlooded) {
  detail::check_inlet(xi_in);
  const double xi_e = detail::root([&](double e) { return shoot(e, xi_in, e).pressure; }, 1e-6, 1.0);
  const double peak_xi = std::max(-xi_e, xi_in);
  const double peak = peak_xi > xi_in ? shoot(xi_e, xi_in, peak_xi).pressure : 0.0;
  return {xi_in, xi_e, 24.0 * shoot(xi_e, xi_in, xi_e).integral, 12.0 * std::numbers::sqrt2 * peak};
}

// The dimensional contact: R [m], eta [Pa s], u_m [m/s], h0 [m], the inlet at x_in [m] (-inf: flooded).
struct Contact {
  double radius = 0.0;
  double viscosity = 0.0;
  double entrainment = 0.0;
  double film = 0.0;  // h0, the least gap
  double inlet = kFullyFlooded;
  double length() const { return std::sqrt(2.0 * radius * film); }  // sqrt(2 R h0) [m]
  Solution solution() const { return closed_form(inlet / length()); }
  double exit() const { return solution().exit * length(); }                                           // x_e [m]
  double load() const { return solution().load * viscosity * entrainment * radius / film; }            // w [N/m]
  double pressure_scale() const { return 12.0 * viscosity * entrainment * length() / (film * film); }  // [Pa]
  double pressure_at(double x, const Solution& s) const {                                              // p(x) [Pa]
    return pressure_scale() * pressure(x / length(), s.exit, s.inlet);
  }
  double pressure_at(double x) const { return pressure_at(x, solution()); }
};

// The least film h0 [m] at which the contact carries the line load w [N/m] (load control), the inlet
// at a fixed x_in [m]: w h0 = C(x_in/sqrt(2 R h0)) eta u_m R, C rising as the inlet recedes.
inline double film_for_load(double line_load, double radius, double viscosity, double entrainment,
                            double inlet = kFullyFlooded) {
  const double flooded = closed_form().load * viscosity * entrainment * radius / line_load;
  if (std::isinf(inlet)) return flooded;
  Contact c{radius, viscosity, entrainment, flooded, inlet};
  // A finite inlet carries less at a given h0: the film is thinner than the flooded one.
  return detail::root(
      [&](double h0) {
        c.film = h0;
        return c.load() / line_load - 1.0;
      },
      flooded * 1e-6, flooded);
}

}  // namespace geartrib::reference::rigid_isoviscous
