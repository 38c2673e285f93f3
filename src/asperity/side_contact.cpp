#include "asperity/side_contact.hpp"

#include "core/series_radius.hpp"

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::asperity {

namespace {
constexpr double kPi = std::numbers::pi;

// (K - E)/e^2 and K for eccentricity e, with the series near e = 0 where K - E cancels.
struct EllipticTerms {
  double k;
  double k_minus_e_over_e2;
  double e;
};
EllipticTerms elliptic_terms(double e) {
  if (e < 1e-4) {
    const double e2 = e * e;
    return {0.5 * kPi * (1.0 + e2 / 4.0), 0.25 * kPi * (1.0 + 3.0 * e2 / 8.0), 0.5 * kPi * (1.0 - e2 / 4.0)};
  }
  const double k = boost::math::ellint_1(e);
  const double ee = boost::math::ellint_2(e);
  return {k, (k - ee) / (e * e), ee};
}

// R_x / R_y as a function of e (equals B/A of Johnson 4.39), increasing from 1 at e = 0.
double radius_ratio(double e) {
  const EllipticTerms t = elliptic_terms(e);
  const double e2 = e * e;
  if (e < 1e-4) return 1.0 + 0.75 * e2;  // series of [E/(1-e^2) - K]/[K - E]
  return (t.e / (1.0 - e2) - t.k) / (t.k - t.e);
}
}  // namespace

SideContactGeometry side_contact_geometry(double r1, double r2, double mu) {
  if (!(r1 > 0.0 && r2 > 0.0)) throw std::invalid_argument("side contact: tip radii must be positive");
  if (!(mu >= 0.0 && std::isfinite(mu))) throw std::invalid_argument("side contact: friction coefficient must be >= 0");
  SideContactGeometry g;
  g.theta = std::atan(mu);
  const double c = std::cos(g.theta);
  const double r = series_radius(r1, r2);
  g.axis_offset = (r1 + r2) * mu;
  g.tip_gap = g.axis_offset * g.axis_offset / (2.0 * (r1 + r2));
  g.radius_x = r / (c * c * c);
  g.radius_y = r / c;
  g.radius_0 = g.radius_x;
  g.radius_mean = std::sqrt(g.radius_x * g.radius_y);
  const EllipticHertz unit = elliptic_hertz(g.radius_x, g.radius_y, 1.0, 1.0);
  g.load_ratio = unit.load / hertz_load(1.0, g.radius_0, 1.0);
  g.area_ratio = unit.area() / (kPi * g.radius_0);
  g.aspect = std::sqrt(1.0 - unit.eccentricity * unit.eccentricity);
  return g;
}

double normal_tilt_from_offset(double r1, double r2, double d) { return std::atan(d / (r1 + r2)); }

double EllipticHertz::area() const { return kPi * semi_major * semi_minor; }

EllipticHertz elliptic_hertz(double rx, double ry, double modulus, double delta) {
  if (!(rx >= ry && ry > 0.0)) throw std::invalid_argument("elliptic Hertz: need R_x >= R_y > 0");
  const double target = rx / ry;
  double e = 0.0;
  if (target > 1.0 + 1e-15) {
    // Bracket in e: the ratio rises monotonically from 1 (e = 0) to infinity (e -> 1).
    double hi = 0.5;
    while (radius_ratio(hi) < target && hi < 1.0 - 1e-15) hi = 1.0 - 0.5 * (1.0 - hi);
    boost::uintmax_t iters = 200;
    const auto r = boost::math::tools::toms748_solve([&](double x) { return radius_ratio(x) - target; }, 0.0, hi,
                                                     boost::math::tools::eps_tolerance<double>(50), iters);
    e = 0.5 * (r.first + r.second);
  }
  const EllipticTerms t = elliptic_terms(e);
  EllipticHertz h;
  h.eccentricity = e;
  // A = 1/(2 R_x): a^2 = delta (K - E)/(A e^2 K) = 2 R_x delta (K - E)/(e^2 K).
  h.semi_major = std::sqrt(2.0 * rx * delta * t.k_minus_e_over_e2 / t.k);
  h.semi_minor = h.semi_major * std::sqrt(1.0 - e * e);
  h.peak_pressure = h.semi_minor > 0.0 ? modulus * delta / (h.semi_minor * t.k) : 0.0;
  h.load = 2.0 / 3.0 * kPi * h.semi_major * h.semi_minor * h.peak_pressure;
  return h;
}

SideContactState evaluate_side_contact(const AsperityModel& model, const ContactPair& pair,
                                       const SideContactGeometry& g, double applied_delta, Detail detail,
                                       VonMisesTable* stress_table) {
  const ContactPair pair0 = with_radius(pair, g.radius_0);
  SideContactState s;
  s.theta = g.theta;
  s.applied_delta = applied_delta;
  const double delta_n = applied_delta * std::cos(g.theta);
  s.normal = model.evaluate(pair0, delta_n, detail, stress_table);
  const double load_ratio = g.load_ratio, area_ratio = g.area_ratio, aspect = g.aspect;
  AsperityState& n = s.normal;
  n.load *= load_ratio;
  n.area *= area_ratio;
  n.mean_pressure *= load_ratio / area_ratio;
  n.max_pressure *= load_ratio / area_ratio;
  n.max_von_mises *= load_ratio / area_ratio;
  n.contact_radius = std::sqrt(n.area / kPi);  // radius of the circle of equal area
  n.plastic_radius *= std::sqrt(area_ratio);
  s.semi_major = std::sqrt(n.area / (kPi * aspect));
  s.semi_minor = s.semi_major * aspect;
  s.vertical_load = n.load * std::cos(g.theta);
  s.tangential_load = n.load * std::sin(g.theta);
  return s;
}

}  // namespace geartrib::asperity
