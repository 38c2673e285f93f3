#include "contact/rough_line_contact.hpp"

#include "asperity/cylinder.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace geartrib::contact {

namespace {
constexpr double kPi = std::numbers::pi;

// Accumulates the GW quantities of a point of the strip with quadrature weight w [m].
struct StripSums {
  double load = 0, area = 0, contacts = 0, plastic_area = 0, plastic_contacts = 0;
  void add(const SurfaceContact& c, double w) {
    load += c.nominal_pressure * w;
    area += c.real_area_ratio * w;
    contacts += c.contact_density * w;
    plastic_area += c.plastic_area_ratio * w;
    plastic_contacts += c.plastic_contact_density * w;
  }
};

void store(StripResult& r, const StripSums& s) {
  r.line_load = s.load;
  r.real_area_per_width = s.area;
  r.real_area_ratio = r.hertz_half_width > 0.0 ? s.area / (2.0 * r.hertz_half_width) : 0.0;
  r.contacts_per_width = s.contacts;
  r.plastic_area_fraction = s.area > 0.0 ? s.plastic_area / s.area : 0.0;
  r.plastic_contact_fraction = s.contacts > 0.0 ? s.plastic_contacts / s.contacts : 0.0;
  r.mean_real_pressure = s.area > 0.0 ? s.load / s.area : 0.0;
}

// int ln|t| dt = t ln|t| - t
double log_antiderivative(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }
}  // namespace

void StripOptions::validate() const {
  if (strip_points < kMinStripPoints || strip_points > kMaxStripPoints)
    throw std::invalid_argument(fmt::format("strip_points must lie in [{}, {}]", kMinStripPoints, kMaxStripPoints));
  if (coupled_nodes < kMinCoupledNodes || coupled_nodes > kMaxCoupledNodes)
    throw std::invalid_argument(fmt::format("coupled_nodes must lie in [{}, {}]", kMinCoupledNodes, kMaxCoupledNodes));
}

RoughLineContact::RoughLineContact(const GreenwoodWilliamson& gw, double composite_modulus, double face_width,
                                   const StripOptions& options, const NonlinearSolver* solver)
    : gw_(gw), modulus_(composite_modulus), face_width_(face_width), options_(options), solver_(solver) {
  options_.validate();
  if (options_.fidelity == StripFidelity::coupled && !solver_)
    throw std::invalid_argument("the coupled fidelity needs a nonlinear solver");
}

StripResult RoughLineContact::solve(double w, double radius, double share) const {
  if (!(w >= 0.0 && std::isfinite(w))) throw std::invalid_argument("line load must be finite and >= 0");
  if (!(radius > 0.0)) throw std::invalid_argument("equivalent radius must be positive");
  if (!(share >= 0.0 && share <= 1.0)) throw std::invalid_argument("asperity share must lie in [0, 1]");
  if (options_.fidelity == StripFidelity::uncoupled || w == 0.0 || share == 0.0) return uncoupled(w, radius, share);
  return coupled(share * w, radius);
}

StripResult RoughLineContact::uncoupled(double w, double radius, double share) const {
  StripResult r;
  const double b = asperity::hertz_half_width(w, radius, modulus_);
  const double p0 = b > 0.0 ? share * 2.0 * w / (kPi * b) : 0.0;
  r.hertz_half_width = b;
  r.max_nominal_pressure = p0;
  r.min_separation = gw_.separation_for_pressure(p0);
  r.contact_half_width = b;
  if (w == 0.0 || share == 0.0) return r;
  // x = b sin(theta): the Hertz pressure p0 cos(theta) and dx = b cos(theta) d(theta) are smooth;
  // composite 8-point Gauss-Legendre over theta in (-pi/2, pi/2).
  using Gauss = boost::math::quadrature::gauss<double, 8>;
  const int panels = std::max(1, options_.strip_points / 8);
  const double h = kPi / panels;
  StripSums sums;
  for (int k = 0; k < panels; ++k) {
    const double a = -0.5 * kPi + k * h;
    for (std::size_t i = 0; i < Gauss::abscissa().size(); ++i)
      for (int sign : {-1, 1}) {
        const double theta = a + 0.5 * h * (1.0 + sign * Gauss::abscissa()[i]);
        const double weight = 0.5 * h * Gauss::weights()[i] * b * std::cos(theta);
        const double p = p0 * std::cos(theta);
        const SurfaceContact c = gw_.interpolate(gw_.separation_for_pressure(p));
        sums.add(c, weight);
        r.x.push_back(b * std::sin(theta));
        r.nominal_pressure.push_back(p);
      }
  }
  store(r, sums);
  // The table's inversion reproduces p exactly at every node, so the load is the quadrature of
  // the Hertz pressure: W to ~1e-15 for 8 or more points.
  return r;
}

StripResult RoughLineContact::coupled(double w, double radius) const {
  const double b = asperity::hertz_half_width(w, radius, modulus_);
  const double sigma = gw_.surface().summit_sigma;
  const int n = options_.coupled_nodes;
  double half_length = 2.0 * b + 6.0 * std::sqrt(sigma * radius);  // rough contacts spread beyond b
  for (int attempt = 0; attempt < 6; ++attempt, half_length *= 1.6) {
    const double dx = 2.0 * half_length / n;
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x(i) = -half_length + (i + 0.5) * dx;
    // Elastic influence of uniform pressure on element j on the separation at node i
    // (plane strain, both bodies: 2/(pi E_t) int ln|x - s| ds; Johnson eq. 2.25b).
    Eigen::MatrixXd k(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        k(i, j) = -2.0 / (kPi * modulus_) *
                  (log_antiderivative(x(j) + 0.5 * dx - x(i)) - log_antiderivative(x(j) - 0.5 * dx - x(i)));
    // Unknowns y = (d_i/sigma, h0/sigma): d_i = h0 + x_i^2/(2R) + sum_j K_ij p(d_j), sum_j dx p(d_j) = w.
    NonlinearSystem sys;
    sys.size = n + 1;
    double load = w;
    sys.residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
      f.resize(n + 1);
      Eigen::VectorXd p(n);
      for (int i = 0; i < n; ++i) p(i) = gw_.pressure(y(i) * sigma);
      const Eigen::VectorXd elastic = k * p;
      for (int i = 0; i < n; ++i) f(i) = y(i) - y(n) - (x(i) * x(i) / (2.0 * radius) + elastic(i)) / sigma;
      f(n) = (dx * p.sum() - load) / load;
    };
    sys.jacobian = [&](const Eigen::VectorXd& y, Eigen::MatrixXd& jac) {
      jac.setZero(n + 1, n + 1);
      for (int j = 0; j < n; ++j) {
        const double slope = gw_.pressure_slope(y(j) * sigma);     // dp/dd
        for (int i = 0; i < n; ++i) jac(i, j) = -k(i, j) * slope;  // d/d(y_j) of -(K p)/sigma, times sigma
        jac(j, j) += 1.0;
        jac(n, j) = dx * slope * sigma / load;
      }
      for (int i = 0; i < n; ++i) jac(i, n) = -1.0;
    };
    // Initial guess: the uncoupled (Hertz) pressure and the separations it implies.
    auto hertz_guess = [&](double wl) {
      const double bh = asperity::hertz_half_width(wl, radius, modulus_);
      const double p0 = 2.0 * wl / (kPi * bh);
      Eigen::VectorXd p(n), y(n + 1);
      for (int i = 0; i < n; ++i) p(i) = std::abs(x(i)) < bh ? p0 * std::sqrt(1.0 - x(i) * x(i) / (bh * bh)) : 0.0;
      const Eigen::VectorXd elastic = k * p;
      const double d0 = gw_.separation_for_pressure(p0);
      const int mid = n / 2;
      y(n) = (d0 - x(mid) * x(mid) / (2.0 * radius) - elastic(mid)) / sigma;
      for (int i = 0; i < n; ++i) y(i) = y(n) + (x(i) * x(i) / (2.0 * radius) + elastic(i)) / sigma;
      return y;
    };
    NonlinearSolveOptions opt;
    opt.residual_tolerance = 1e-10;
    Eigen::VectorXd y = hertz_guess(w);
    NonlinearSolveSummary summary = solver_->solve(sys, y, opt);
    int iterations = summary.iterations;
    if (!summary.converged) {
      // Load continuation: ramp from a tenth of the load, each step from the last solution.
      y = hertz_guess(0.1 * w);
      for (int step = 1; step <= 10; ++step) {
        load = w * step / 10.0;
        summary = solver_->solve(sys, y, opt);
        iterations += summary.iterations;
        if (!summary.converged) break;
      }
      load = w;
    }
    if (!summary.converged)
      throw std::runtime_error(
          fmt::format("coupled rough line contact did not converge (line load {:.6g} N/m, R {:.6g} m): "
                      "{}, residual {:.3g} after {} iterations",
                      w, radius, summary.message, summary.residual_norm, iterations));
    StripResult r;
    r.hertz_half_width = b;
    r.solver_iterations = iterations;
    StripSums sums;
    double p_max = 0.0;
    for (int i = 0; i < n; ++i) {
      const SurfaceContact c = gw_.interpolate(y(i) * sigma);
      sums.add(c, dx);
      r.x.push_back(x(i));
      r.nominal_pressure.push_back(c.nominal_pressure);
      p_max = std::max(p_max, c.nominal_pressure);
    }
    store(r, sums);
    r.max_nominal_pressure = p_max;
    r.min_separation = y.head(n).minCoeff() * sigma;
    // Extent carrying 99.9% of the load (symmetric about the centre).
    double carried = 0.0;
    for (int i = n / 2; i < n; ++i) {
      carried += 2.0 * dx * r.nominal_pressure[static_cast<std::size_t>(i)];
      if (carried >= 0.999 * r.line_load) {
        r.contact_half_width = x(i) + 0.5 * dx;
        break;
      }
    }
    const double edge = std::max(r.nominal_pressure.front(), r.nominal_pressure.back());
    if (edge <= 1e-9 * p_max) return r;  // the domain holds the whole contact
  }
  throw std::runtime_error("coupled rough line contact: the pressure does not vanish within the solution domain");
}

double highest_asperity_interference(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width) {
  if (strip.line_load <= 0.0) return 0.0;
  return gw.highest_summit(2.0 * strip.hertz_half_width * face_width) - strip.min_separation;
}

HighestAsperity highest_asperity(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width,
                                 const asperity::SideContactGeometry* side) {
  HighestAsperity h;
  const double delta = highest_asperity_interference(gw, strip, face_width);
  if (delta <= 0.0) return h;
  h.interference = delta;
  const asperity::AsperityState s = side ? asperity::evaluate_side_contact(gw.model(), gw.pair(), *side, delta).normal
                                         : gw.model().evaluate(gw.pair(), delta, asperity::Detail::full);
  h.peak_pressure = s.max_pressure;
  h.von_mises = s.max_von_mises;
  h.plastic_fraction = s.plastic_fraction;
  return h;
}

}  // namespace geartrib::contact
