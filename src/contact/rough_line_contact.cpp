#include "contact/rough_line_contact.hpp"

#include "core/keyed_error.hpp"
#include "core/log_antiderivative.hpp"

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
  void add(double p, const ContactAtPressure& c, double w) {
    load += p * w;
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
using core::log_antiderivative;  // int ln|t| dt

// Coupled strip, started from the previous position's solution: how many iterations a factorised
// Jacobian may serve (KINSOL refreshes it sooner when it stops reducing the residual), and the
// iterations allowed before the start is abandoned for the cold one.
constexpr int kWarmJacobianAge = 7;
constexpr int kWarmIterations = 50;
}  // namespace

void StripOptions::validate() const {
  if (strip_points < kMinStripPoints || strip_points > kMaxStripPoints)
    throw core::KeyedError("strip_points",
                           fmt::format("strip_points must lie in [{}, {}]", kMinStripPoints, kMaxStripPoints));
  if (coupled_nodes < kMinCoupledNodes || coupled_nodes > kMaxCoupledNodes)
    throw core::KeyedError("coupled_nodes",
                           fmt::format("coupled_nodes must lie in [{}, {}]", kMinCoupledNodes, kMaxCoupledNodes));
}

RoughLineContact::RoughLineContact(const GreenwoodWilliamson& gw, double composite_modulus, double face_width,
                                   const StripOptions& options, const NonlinearSolver* solver)
    : gw_(gw), modulus_(composite_modulus), face_width_(face_width), options_(options), solver_(solver) {
  options_.validate();
  if (options_.fidelity == StripFidelity::coupled && !solver_)  // the caller's state, no option field: unkeyed
    throw std::invalid_argument("the coupled fidelity needs a nonlinear solver");
  // x = b sin(theta): the Hertz pressure p0 cos(theta) and dx = b cos(theta) d(theta) are smooth;
  // composite 8-point Gauss-Legendre over theta in (-pi/2, pi/2), symmetric about 0 (an even
  // number of nodes, none at 0): the nodes of the left half, each weighted for both.
  using Gauss = boost::math::quadrature::gauss<double, 8>;
  const int panels = std::max(1, options_.strip_points / 8);
  const double h = kPi / panels;
  std::vector<double> thetas, weights;
  for (int k = 0; k < panels; ++k) {
    const double a = -0.5 * kPi + k * h;
    for (std::size_t i = 0; i < Gauss::abscissa().size(); ++i)
      for (int sign : {-1, 1}) {
        const double theta = a + 0.5 * h * (1.0 + sign * Gauss::abscissa()[i]);
        if (!(theta < 0.0)) continue;
        thetas.push_back(theta);
        weights.push_back(0.5 * h * Gauss::weights()[i]);
      }
  }
  // In ascending pressure (theta from -pi/2 to 0), so that consecutive look-ups are neighbours.
  std::vector<std::size_t> order(thetas.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return thetas[x] < thetas[y]; });
  for (std::size_t i : order) {
    node_cos_.push_back(std::cos(thetas[i]));
    node_weight_.push_back(2.0 * weights[i] * std::cos(thetas[i]));
  }
}

StripResult RoughLineContact::solve(double w, double radius, double share, CoupledStripState* state) const {
  if (!(w >= 0.0 && std::isfinite(w))) throw std::invalid_argument("line load must be finite and >= 0");
  if (!(radius > 0.0)) throw std::invalid_argument("equivalent radius must be positive");
  if (!(share >= 0.0 && share <= 1.0)) throw std::invalid_argument("asperity share must lie in [0, 1]");
  if (options_.fidelity == StripFidelity::uncoupled || w == 0.0 || share == 0.0) return uncoupled(w, radius, share);
  if (state) {
    if (!state->data_) state->data_ = std::make_unique<CoupledStripState::Data>();  // moved from: anew
    return coupled(share * w, radius, *state->data_);
  }
  CoupledStripState single;  // a single call: cold, its buffers and solver workspace its own
  return coupled(share * w, radius, *single.data_);
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
  StripSums sums;
  std::size_t segment = 0;  // at_pressure's search starts where the last point's ended (p ascends)
  for (std::size_t i = 0; i < node_cos_.size(); ++i) {
    const double p = p0 * node_cos_[i];
    const double weight = b * node_weight_[i];  // both halves
    if (options_.lookup == StripLookup::cubic) sums.add(p, gw_.at_pressure(p, segment), weight);
    else sums.add(gw_.interpolate(gw_.separation_for_pressure(p)), weight);
  }
  store(r, sums);
  // The table's inversion reproduces p exactly at every node, so the load is the quadrature of
  // the Hertz pressure: W to ~1e-15 for 8 or more points.
  return r;
}

struct CoupledStripState::Data {
  // The last converged solution: y = (d_i/sigma, h0/sigma) on n nodes evenly spread over
  // (-half_length, half_length), and that solve's Hertz half-width.
  bool has_previous = false;
  double half_length = 0.0, hertz_half_width = 0.0;
  Eigen::VectorXd previous;
  // The buffers of a solve, sized once for n nodes: nodes, influence coefficients, pressures, the
  // unknowns; g(m) = (m + 1/2) ln|m + 1/2| - (m - 1/2) ln|m - 1/2|, the influence coefficients'
  // dependence on the node distance m (they are Toeplitz: K_ij = -2 dx/(pi E) (g(|i - j|) + ln dx - 1)).
  int nodes = 0;
  Eigen::VectorXd x, g, p, elastic, y;
  Eigen::MatrixXd k;
  std::unique_ptr<NonlinearSolverWorkspace> workspace;
  const NonlinearSolver* workspace_solver = nullptr;
  int warm = 0, cold = 0, jacobians = 0;

  void prepare(int n, const NonlinearSolver& solver) {
    if (nodes != n) {
      nodes = n;
      has_previous = false;
      x.resize(n);
      p.resize(n);
      elastic.resize(n);
      y.resize(n + 1);
      k.resize(n, n);
      g.resize(n);
      for (int m = 0; m < n; ++m) g(m) = log_antiderivative(m + 0.5) - log_antiderivative(m - 0.5) + 1.0;
      workspace.reset();
    }
    if (!workspace || workspace_solver != &solver) {
      workspace = solver.make_workspace(n + 1);
      workspace_solver = &solver;
    }
  }
};

CoupledStripState::CoupledStripState() : data_(std::make_unique<Data>()) {}
CoupledStripState::~CoupledStripState() = default;
CoupledStripState::CoupledStripState(CoupledStripState&&) noexcept = default;
CoupledStripState& CoupledStripState::operator=(CoupledStripState&&) noexcept = default;
int CoupledStripState::warm_solves() const { return data_ ? data_->warm : 0; }
int CoupledStripState::cold_solves() const { return data_ ? data_->cold : 0; }
int CoupledStripState::jacobians() const { return data_ ? data_->jacobians : 0; }

StripResult RoughLineContact::coupled(double w, double radius, CoupledStripState::Data& st) const {
  const double b = asperity::hertz_half_width(w, radius, modulus_);
  const double sigma = gw_.surface().summit_sigma;
  const int n = options_.coupled_nodes;
  st.prepare(n, *solver_);
  Eigen::VectorXd& x = st.x;
  Eigen::MatrixXd& k = st.k;
  double half_length = 2.0 * b + 6.0 * std::sqrt(sigma * radius);  // rough contacts spread beyond b
  for (int attempt = 0; attempt < 6; ++attempt, half_length *= 1.6) {
    const double dx = 2.0 * half_length / n;
    for (int i = 0; i < n; ++i) x(i) = -half_length + (i + 0.5) * dx;
    // Elastic influence of uniform pressure on element j on the separation at node i
    // (plane strain, both bodies: 2/(pi E_t) int ln|x - s| ds; Johnson eq. 2.25b), from g.
    const double scale = -2.0 * dx / (kPi * modulus_), shift = std::log(dx) - 1.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) k(i, j) = scale * (st.g(std::abs(i - j)) + shift);
    // Unknowns y = (d_i/sigma, h0/sigma): d_i = h0 + x_i^2/(2R) + sum_j K_ij p(d_j), sum_j dx p(d_j) = w.
    // The residual and the Jacobian write into the state's buffers: no allocation per call.
    NonlinearSystem sys;
    sys.size = n + 1;
    double load = w;
    sys.residual = [&](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
      f.resize(n + 1);
      for (int i = 0; i < n; ++i) st.p(i) = gw_.pressure(y(i) * sigma);
      st.elastic.noalias() = k * st.p;
      for (int i = 0; i < n; ++i) f(i) = y(i) - y(n) - (x(i) * x(i) / (2.0 * radius) + st.elastic(i)) / sigma;
      f(n) = (dx * st.p.sum() - load) / load;
    };
    sys.jacobian = [&](const Eigen::VectorXd& y, Eigen::MatrixXd& jac) {
      jac.resize(n + 1, n + 1);
      for (int j = 0; j < n; ++j) {
        const double slope = gw_.pressure_slope(y(j) * sigma);  // dp/dd
        jac.col(j).head(n) = -slope * k.col(j);                 // d/d(y_j) of -(K p)/sigma, times sigma
        jac(j, j) += 1.0;
        jac(n, j) = dx * slope * sigma / load;
      }
      jac.col(n).head(n).setConstant(-1.0);
      jac(n, n) = 0.0;
    };
    // Initial guess: the uncoupled (Hertz) pressure and the separations it implies.
    auto hertz_guess = [&](double wl, Eigen::VectorXd& y) {
      const double bh = asperity::hertz_half_width(wl, radius, modulus_);
      const double p0 = 2.0 * wl / (kPi * bh);
      for (int i = 0; i < n; ++i) st.p(i) = std::abs(x(i)) < bh ? p0 * std::sqrt(1.0 - x(i) * x(i) / (bh * bh)) : 0.0;
      st.elastic.noalias() = k * st.p;
      const double d0 = gw_.separation_for_pressure(p0);
      const int mid = n / 2;
      y(n) = (d0 - x(mid) * x(mid) / (2.0 * radius) - st.elastic(mid)) / sigma;
      for (int i = 0; i < n; ++i) y(i) = y(n) + (x(i) * x(i) / (2.0 * radius) + st.elastic(i)) / sigma;
    };
    // Warm guess: the previous solution's separations, its x scaled by the ratio of the Hertz
    // half-widths (linear between its nodes; beyond its domain, its edge plus the gap's parabola),
    // and its rigid approach.
    auto warm_guess = [&](Eigen::VectorXd& y) {
      const Eigen::VectorXd& prev = st.previous;
      const double ratio = st.hertz_half_width / b, prev_dx = 2.0 * st.half_length / n;
      for (int i = 0; i < n; ++i) {
        const double u = (x(i) * ratio + st.half_length) / prev_dx - 0.5;  // fractional index
        if (u <= 0.0 || u >= n - 1.0) {
          const int edge = u <= 0.0 ? 0 : n - 1;
          const double xe = (-st.half_length + (edge + 0.5) * prev_dx) / ratio;
          y(i) = prev(edge) + (x(i) * x(i) - xe * xe) / (2.0 * radius * sigma);
        } else {
          const int j = static_cast<int>(u);
          const double t = u - j;
          y(i) = (1.0 - t) * prev(j) + t * prev(j + 1);
        }
      }
      y(n) = prev(n);
    };
    NonlinearSolveOptions opt;
    opt.residual_tolerance = 1e-10;
    Eigen::VectorXd& y = st.y;
    NonlinearSolveSummary summary;
    int iterations = 0;
    if (st.has_previous) {
      // Modified Newton from the last factorised Jacobian; a start that fails is retried cold.
      NonlinearSolveOptions warm = opt;
      warm.max_jacobian_age = kWarmJacobianAge;
      warm.max_iterations = kWarmIterations;
      warm_guess(y);
      summary = solver_->solve(sys, y, warm, st.workspace.get());
      iterations += summary.iterations;
      st.jacobians += summary.jacobian_evaluations;
      if (summary.converged) ++st.warm;
    }
    if (!summary.converged) {
      ++st.cold;
      hertz_guess(w, y);
      summary = solver_->solve(sys, y, opt, st.workspace.get());
      iterations += summary.iterations;
      st.jacobians += summary.jacobian_evaluations;
      if (!summary.converged) {
        // Load continuation: ramp from a tenth of the load, each step from the last solution.
        hertz_guess(0.1 * w, y);
        for (int step = 1; step <= 10; ++step) {
          load = w * step / 10.0;
          summary = solver_->solve(sys, y, opt, st.workspace.get());
          iterations += summary.iterations;
          st.jacobians += summary.jacobian_evaluations;
          if (!summary.converged) break;
        }
        load = w;
      }
    }
    if (!summary.converged) {
      st.has_previous = false;
      throw std::runtime_error(
          fmt::format("coupled rough line contact did not converge (line load {:.6g} N/m, R {:.6g} m): "
                      "{}, residual {:.3g} after {} iterations",
                      w, radius, summary.message, summary.residual_norm, iterations));
    }
    StripResult r;
    r.hertz_half_width = b;
    r.solver_iterations = iterations;
    StripSums sums;
    double p_max = 0.0;
    r.x.reserve(static_cast<std::size_t>(n));
    r.nominal_pressure.reserve(static_cast<std::size_t>(n));
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
    if (edge <= 1e-9 * p_max) {  // the domain holds the whole contact
      st.previous = y;
      st.half_length = half_length;
      st.hertz_half_width = b;
      st.has_previous = true;
      return r;
    }
  }
  st.has_previous = false;
  throw std::runtime_error("coupled rough line contact: the pressure does not vanish within the solution domain");
}

double highest_asperity_interference(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width) {
  if (strip.line_load <= 0.0) return 0.0;
  return gw.highest_summit(2.0 * strip.hertz_half_width * face_width) - strip.min_separation;
}

HighestAsperity highest_asperity(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width,
                                 const asperity::SideContactGeometry* side, asperity::VonMisesTable* stress_table) {
  HighestAsperity h;
  const double delta = highest_asperity_interference(gw, strip, face_width);
  if (delta <= 0.0) return h;
  h.interference = delta;
  const asperity::AsperityState s =
      side ? asperity::evaluate_side_contact(gw.model(), gw.pair(), *side, delta, asperity::Detail::full, stress_table)
                 .normal
           : gw.model().evaluate(gw.pair(), delta, asperity::Detail::full, stress_table);
  h.peak_pressure = s.max_pressure;
  h.von_mises = s.max_von_mises;
  h.plastic_fraction = s.plastic_fraction;
  return h;
}

}  // namespace geartrib::contact
