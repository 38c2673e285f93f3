// The rigid-isoviscous line contact (tests/reference/rigid_isoviscous.hpp), the reference the
// mixed-EHL solver's rigid limit is checked against: its two derivations against each other, its
// constants against a third (30-digit quadrature), the Reynolds conditions, and the dimensional form.
#include "reference/rigid_isoviscous.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>

namespace {

namespace ri = geartrib::reference::rigid_isoviscous;

// A third derivation, for the digits: mpmath 1.x at 30 digits, the exit by findroot on
// quad((t^2 - e^2)/(1 + t^2)^3, [-inf, e]) = 0 and the load by quad of that pressure (no
// antiderivative, no integration by parts):
//   /usr/bin/python3 validation/mixed-ehl/rigid_isoviscous_quadrature.py  (about 6 s)
// inlet: (exit xi_e, load C, peak coefficient c_p)
struct Digits {
  double inlet, exit, load, peak;
};
constexpr Digits kQuadrature[] = {
    {-std::numeric_limits<double>::infinity(), 0.4751299200930563, 4.894968493913369, 2.150941872128263},
    {-10.0, 0.4747785699765727, 4.778210553925393, 2.146516581175927},
    {-3.0, 0.464146240966184, 3.809443387504696, 2.015165327115155},
    {-1.0, 0.3578688661371307, 1.010923464625858, 0.9651998610729617},
    {-0.3, 0.1442323579374048, 0.02368815295883963, 0.06706010473139965},
};

TEST(RigidIsoviscous, TheIssuesConstantsToTheirPrintedDigits) {
  const ri::Solution s = ri::closed_form();
  // Issue 32 prints C = 4.895 and x_e = 0.4751 sqrt(2 R h0): within half their last digit.
  EXPECT_NEAR(s.load, 4.895, 5e-4);
  EXPECT_NEAR(s.exit, 0.4751, 5e-5);
}

TEST(RigidIsoviscous, ClosedFormAndShootingAgree) {
  // Two derivations (antiderivative vs Dormand-Prince at 1e-13): they meet to 2e-11 (the load at
  // xi_in = -0.3, where it is 0.024 and the Dormand-Prince tolerance is absolute); 1e-9 leaves the
  // integrator's step control room across compilers.
  for (const Digits& d : kQuadrature) {
    const ri::Solution a = ri::closed_form(d.inlet), b = ri::shooting(d.inlet);
    EXPECT_NEAR(a.exit, b.exit, 1e-9) << d.inlet;
    EXPECT_NEAR(a.load / b.load, 1.0, 1e-9) << d.inlet;
    EXPECT_NEAR(a.peak / b.peak, 1.0, 1e-9) << d.inlet;
  }
}

TEST(RigidIsoviscous, ConstantsAgainstThirtyDigitQuadrature) {
  // The closed form in double precision: 1e-12 relative covers the roots' 2^-52 and the
  // cancellation in the antiderivative's difference (terms of order 1, results down to 0.02).
  for (const Digits& d : kQuadrature) {
    const ri::Solution s = ri::closed_form(d.inlet);
    EXPECT_NEAR(s.exit / d.exit, 1.0, 1e-12) << d.inlet;
    EXPECT_NEAR(s.load / d.load, 1.0, 1e-11) << d.inlet;
    EXPECT_NEAR(s.peak / d.peak, 1.0, 1e-11) << d.inlet;
  }
}

TEST(RigidIsoviscous, FullyFloodedLoadIsSixOverExitFilm) {
  // int P dxi = cos^2(g_e)/4 when the inlet is at infinity (sin^4 + sin^2 cos^2 = sin^2):
  // w = 6 eta u_m R/h_e with h_e = h0 (1 + xi_e^2). An identity: to rounding.
  const ri::Solution s = ri::closed_form();
  EXPECT_NEAR(s.load * (1.0 + s.exit * s.exit), 6.0, 1e-13);
}

TEST(RigidIsoviscous, ReynoldsConditionsAndThePeak) {
  for (const Digits& d : kQuadrature) {
    const ri::Solution s = ri::closed_form(d.inlet);
    const auto p = [&](double xi) { return ri::pressure(xi, s.exit, s.inlet); };
    // p = 0 at the exit, and dp/dxi = 0 there: the central difference over 2e-5 vanishes to its
    // truncation (P'' at the exit ~ 2 xi_e/(1 + xi_e^2)^3 ~ 0.5, times the step, ~1e-5 of P's scale).
    EXPECT_NEAR(p(s.exit - 1e-13), 0.0, 1e-13) << d.inlet;
    const double h = 1e-5, slope = (p(s.exit - h) - p(s.exit - 3 * h)) / (2 * h);
    EXPECT_NEAR(slope, 0.0, 2e-5) << d.inlet;
    // The pressure is nowhere negative and peaks at xi = -xi_e (where h = h_e) when the inlet lies before it.
    double best = 0.0, where = 0.0;
    const double lo = std::isinf(s.inlet) ? -20.0 : s.inlet;
    for (int i = 0; i <= 200000; ++i) {
      const double xi = lo + (s.exit - lo) * i / 200000.0, v = p(xi);
      EXPECT_GE(v, -1e-15);
      if (v > best) best = v, where = xi;
    }
    if (-s.exit > s.inlet) {
      EXPECT_NEAR(where, -s.exit, 2.0 * (s.exit - lo) / 200000.0) << d.inlet;
    }
    EXPECT_NEAR(12.0 * std::numbers::sqrt2 * best / s.peak, 1.0, 1e-9) << d.inlet;
  }
}

TEST(RigidIsoviscous, LoadIsTheIntegralOfThePressure) {
  // The load by direct quadrature of the closed-form pressure (Gauss-Kronrod 61, adaptive), not by
  // the integration by parts the closed form uses.
  for (const Digits& d : kQuadrature) {
    const ri::Solution s = ri::closed_form(d.inlet);
    const auto p = [&](double xi) { return ri::pressure(xi, s.exit, s.inlet); };
    const double integral =
        boost::math::quadrature::gauss_kronrod<double, 61>::integrate(p, s.inlet, s.exit, 15, 1e-13);
    EXPECT_NEAR(24.0 * integral / s.load, 1.0, 1e-10) << d.inlet;
  }
}

TEST(RigidIsoviscous, AFiniteInletCarriesLessAndTendsToTheFloodedContact) {
  double last = 0.0;
  for (double xi_in : {-0.3, -1.0, -3.0, -10.0, -100.0, -1e4}) {
    const ri::Solution s = ri::closed_form(xi_in);
    EXPECT_GT(s.load, last);
    last = s.load;
  }
  // The load's deficit falls as 1/xi_in^2 (2.4 % at -10, 2.4e-4 at -100): 2.4e-8 at -1e4.
  EXPECT_NEAR(last / ri::closed_form().load, 1.0, 1e-7);
  EXPECT_LT(last, ri::closed_form().load);
}

TEST(RigidIsoviscous, DimensionalContactAndLoadControl) {
  // Steel-like rigid limit of the validation case (validation/mixed-ehl/README.md): R = 10 mm,
  // eta = 0.01 Pa s, u_m = 1 m/s, h0 = 10 um.
  const ri::Contact c{0.01, 0.01, 1.0, 10e-6};
  EXPECT_NEAR(c.load(), ri::closed_form().load * 0.01 * 1.0 * 0.01 / 10e-6, 1e-12);
  EXPECT_NEAR(c.exit(), ri::closed_form().exit * std::sqrt(2.0 * 0.01 * 10e-6), 1e-15);
  // The pressure integrates to the load: trapezoid on 2e5 intervals over [-400, x_e] lengths; the
  // flooded pressure's tail beyond, P ~ 1/(3 |xi|^3), carries 1/(6 400^2)/0.204 = 5e-6 of it.
  const ri::Solution s = c.solution();
  const double l = c.length(), x0 = -400.0 * l, x1 = c.exit();
  const int n = 200000;
  double w = 0.0;
  for (int i = 0; i <= n; ++i) w += (i == 0 || i == n ? 0.5 : 1.0) * c.pressure_at(x0 + (x1 - x0) * i / n, s);
  w *= (x1 - x0) / n;
  EXPECT_NEAR(w / c.load(), 1.0, 2e-5);
  // Load control round trip, flooded and with the inlet at -2 mm (xi_in ~ -4.5).
  EXPECT_NEAR(ri::film_for_load(c.load(), 0.01, 0.01, 1.0) / 10e-6, 1.0, 1e-12);
  ri::Contact cut = c;
  cut.inlet = -2e-3;
  const double h0 = ri::film_for_load(cut.load(), 0.01, 0.01, 1.0, -2e-3);
  EXPECT_NEAR(h0 / 10e-6, 1.0, 1e-10);
}

TEST(RigidIsoviscous, TheValidationCaseTableIsThisSolution) {
  // validation/mixed-ehl/rigid_isoviscous_case.csv (20-digit mpmath, a fixed point on the Hertz
  // half-width) read back: at its line load, with p = 0 at -960 b, the least film is 10 um.
  std::ifstream in(std::string(GEARTRIB_SOURCE_DIR) + "/validation/mixed-ehl/rigid_isoviscous_case.csv");
  ASSERT_TRUE(in);
  std::string line, header;
  while (std::getline(in, line) && line.starts_with("#")) {
  }
  header = line;
  ASSERT_TRUE(std::getline(in, line));
  std::map<std::string, double> v;
  std::stringstream hs(header), ls(line);
  for (std::string k, x; std::getline(hs, k, ',') && std::getline(ls, x, ',');) v[k] = std::stod(x);
  const double r = 0.01, eta = 0.01, um = 1.0, x_in = -960.0 * v["hertz_halfwidth_m"];
  // The table's b is Hertz's at its load (E* of steel, 206 GPa, 0.3).
  EXPECT_NEAR(v["hertz_halfwidth_m"] /
                  std::sqrt(4.0 * v["line_load_N_per_m"] * r / (std::numbers::pi * 206e9 / (2.0 * (1.0 - 0.09)))),
              1.0, 1e-10);
  const double h0 = ri::film_for_load(v["line_load_N_per_m"], r, eta, um, x_in);
  EXPECT_NEAR(h0 / 10e-6, 1.0, 1e-10);  // the table's 12 digits
  const ri::Contact c{r, eta, um, h0, x_in};
  EXPECT_NEAR(c.exit() / v["exit_x_m"], 1.0, 1e-10);
  EXPECT_NEAR(c.solution().load / v["load_C"], 1.0, 1e-10);
  EXPECT_NEAR(c.solution().peak * eta * um * std::sqrt(r / h0) / h0 / v["peak_pressure_Pa"], 1.0, 1e-10);
}

}  // namespace
