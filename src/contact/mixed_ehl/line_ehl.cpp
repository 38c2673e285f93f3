#include "contact/mixed_ehl/line_ehl.hpp"

#include "contact/toeplitz_convolution.hpp"
#include "core/keyed_error.hpp"
#include "core/log_antiderivative.hpp"
#include "lubrication/lubricant.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Dense>

namespace geartrib::contact::mixed_ehl {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr NamedChoice<ViscosityLaw> kViscosityLaws[] = {{ViscosityLaw::roelands, "roelands"},
                                                        {ViscosityLaw::barus, "barus"}};
constexpr NamedChoice<FlowModel> kFlowModels[] = {{FlowModel::newtonian, "newtonian"}, {FlowModel::eyring, "eyring"}};
// Dowson & Higginson's density: rho/rho_0 = 1 + a p/(1 + b p) [p in Pa].
constexpr double kDensityA = 0.6e-9, kDensityB = 1.7e-9;
// exp() of at most this (eta/eta_0 ~ 1e304): beyond it the film carries no Poiseuille flow anyway.
constexpr double kMaxViscosityExponent = 700.0;
using core::log_antiderivative;  // int ln|t| dt

using Block = std::array<double, 4>;  // 2x2, row major: (P, H) equations x (P, H) unknowns
using Pair = std::array<double, 2>;
Block multiply(const Block& a, const Block& b) {
  return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}
Pair multiply(const Block& a, const Pair& v) { return {a[0] * v[0] + a[1] * v[1], a[2] * v[0] + a[3] * v[1]}; }
Block inverse(const Block& a) {
  const double det = a[0] * a[3] - a[1] * a[2];
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) throw std::runtime_error("mixed EHL: singular Newton block");
  return {a[3] / det, -a[1] / det, -a[2] / det, a[0] / det};
}

// The block-tridiagonal system's factors (block Thomas): dinv_k = (D_k - L_k C_{k-1})^-1,
// C_k = dinv_k U_k, G_k = dinv_k L_k (so that the forward sweep's chain is one 2 x 2 product a node).
void factor(const std::vector<Block>& lower, const std::vector<Block>& diag, const std::vector<Block>& upper,
            std::vector<Block>& dinv, std::vector<Block>& cprime, std::vector<Block>& gain) {
  for (std::size_t k = 0; k < diag.size(); ++k) {
    Block dk = diag[k];
    if (k > 0) {
      const Block lc = multiply(lower[k], cprime[k - 1]);
      for (std::size_t e = 0; e < 4; ++e) dk[e] -= lc[e];
    }
    dinv[k] = inverse(dk);
    cprime[k] = multiply(dinv[k], upper[k]);
    gain[k] = multiply(dinv[k], lower[k]);
  }
}
// y_k = dinv_k rhs_k - G_k y_{k-1} forward, y_k -= C_k y_{k+1} backward.
void solve_tridiagonal(const std::vector<Block>& dinv, const std::vector<Block>& gain, const std::vector<Block>& cprime,
                       const std::vector<Pair>& rhs, std::vector<Pair>& y) {
  const std::size_t m = rhs.size();
  for (std::size_t k = 0; k < m; ++k) y[k] = multiply(dinv[k], rhs[k]);
  for (std::size_t k = 1; k < m; ++k) {
    const Pair a = multiply(gain[k], y[k - 1]);
    y[k] = {y[k][0] - a[0], y[k][1] - a[1]};
  }
  for (std::size_t k = m - 1; k-- > 0;) {
    const Pair a = multiply(cprime[k], y[k + 1]);
    y[k] = {y[k][0] - a[0], y[k][1] - a[1]};
  }
}

// GMRES's vectors, kept between solves (a 2 x 2048-node system's 2 x 61 vectors are 4 MB).
constexpr int kRestart = 60;
struct GmresWork {
  Eigen::MatrixXd v, zs;  // the Krylov basis V (restart + 1 columns) and the preconditioned Z
  Eigen::MatrixXd h;      // Hessenberg, (restart + 1) x restart
  Eigen::VectorXd cs, sn, g, w, ax, hj, y;
  void size(Eigen::Index n) {
    if (v.rows() == n) return;
    v.resize(n, kRestart + 1);
    zs.resize(n, kRestart);
    h.setZero(kRestart + 1, kRestart);
    cs.setZero(kRestart), sn.setZero(kRestart), g.setZero(kRestart + 1), w.setZero(n), ax.setZero(n);
  }
};

// GMRES(restart) with right preconditioning (Saad, Iterative Methods for Sparse Linear Systems,
// 2003, alg. 9.5): x from zero until ||b - A x|| <= tolerance ||b||; returns the iterations. The
// new direction is orthogonalised by classical Gram-Schmidt applied twice (Giraud, Langou &
// Rozloznik, Comput. Math. Appl. 50, 2005: as stable as modified Gram-Schmidt, and two
// matrix-vector products instead of 2 j scalar loops). apply(in, out), precondition(in, out) on
// spans of the system's size.
template <class Apply, class Precondition>
int gmres(GmresWork& work, const Apply& apply, const Precondition& precondition, const std::vector<double>& b_in,
          std::vector<double>& x_out, double tolerance, int max_iterations) {
  const auto n = static_cast<Eigen::Index>(b_in.size());
  const Eigen::Map<const Eigen::VectorXd> b(b_in.data(), n);
  x_out.assign(b_in.size(), 0.0);
  Eigen::Map<Eigen::VectorXd> x(x_out.data(), n);
  const double bnorm = b.norm();
  if (!(bnorm > 0.0)) return 0;
  work.size(n);
  auto& [v, zs, h, cs, sn, g, w, ax, hj, y] = work;
  auto span_of = [n](auto&& col) { return std::span(col.data(), static_cast<std::size_t>(n)); };
  int total = 0;
  while (total < max_iterations) {
    apply(span_of(std::as_const(x)), span_of(ax));
    v.col(0) = b - ax;
    const double beta = v.col(0).norm();
    if (beta <= tolerance * bnorm) return total;
    v.col(0) /= beta;
    g.setZero();
    g[0] = beta;
    int j = 0;
    for (; j < kRestart && total < max_iterations; ++j, ++total) {
      precondition(span_of(std::as_const(v).col(j)), span_of(zs.col(j)));
      apply(span_of(std::as_const(zs).col(j)), span_of(w));
      const auto basis = v.leftCols(j + 1);
      hj.noalias() = basis.transpose() * w;
      w.noalias() -= basis * hj;
      y.noalias() = basis.transpose() * w;  // the second pass
      w.noalias() -= basis * y;
      hj += y;
      const double hn = w.norm();
      h.col(j).head(j + 1) = hj;
      h(j + 1, j) = hn;
      if (hn > 0.0) v.col(j + 1) = w / hn;
      for (int i = 0; i < j; ++i) {  // the earlier Givens rotations
        const double a = h(i, j), c = h(i + 1, j);
        h(i, j) = cs[i] * a + sn[i] * c;
        h(i + 1, j) = -sn[i] * a + cs[i] * c;
      }
      const double a = h(j, j), c = h(j + 1, j);
      const double rr = std::hypot(a, c);
      cs[j] = rr > 0.0 ? a / rr : 1.0;
      sn[j] = rr > 0.0 ? c / rr : 0.0;
      h(j, j) = rr;
      g[j + 1] = -sn[j] * g[j];
      g[j] *= cs[j];
      if (std::abs(g[j + 1]) <= tolerance * bnorm || hn == 0.0) {
        ++j;
        ++total;
        break;
      }
    }
    // x += Z y, y from the triangular system.
    y = h.topLeftCorner(j, j).triangularView<Eigen::Upper>().solve(g.head(j));
    x.noalias() += zs.leftCols(j) * y;
    if (j > 0 && std::abs(g[j]) <= tolerance * bnorm) return total;
  }
  return total;
}
// The coarse space of the Newton systems' two-level preconditioner (LineEhlSolver::Impl::
// build_coarse_operator): nc coarse nodes spread evenly over the m interior nodes, Q and H each
// interpolated linearly between them, H0 passed through (unknowns 2 k + {0, 1} and 2 m; coarse
// 2 J + {0, 1} and 2 nc).
struct CoarseSpace {
  std::size_t m = 0, nc = 0;
  std::vector<std::size_t> node;   // coarse node J's fine index
  std::vector<std::size_t> owner;  // fine node k's interval [node[owner], node[owner + 1]]
  std::vector<double> weight;      // fine node k's weight on node owner + 1 (1 - weight on owner)
  CoarseSpace() = default;
  CoarseSpace(std::size_t fine, std::size_t coarse) : m(fine), nc(coarse), node(coarse), owner(fine), weight(fine) {
    for (std::size_t J = 0; J < nc; ++J)
      node[J] = static_cast<std::size_t>(
          std::lround(static_cast<double>(J) * static_cast<double>(m - 1) / static_cast<double>(nc - 1)));
    std::size_t J = 0;
    for (std::size_t k = 0; k < m; ++k) {
      while (J + 2 < nc && node[J + 1] <= k) ++J;
      owner[k] = J;
      weight[k] = static_cast<double>(k - node[J]) / static_cast<double>(node[J + 1] - node[J]);
    }
  }
  double hat(std::size_t J, std::size_t k) const {
    return J == owner[k] ? 1.0 - weight[k] : J == owner[k] + 1 ? weight[k] : 0.0;
  }
  // R (= P^T) of a value at fine row k, part p (0: Q's row, 1: H's), added into a coarse vector.
  template <class Coarse>
  void restrict_add(std::size_t k, std::size_t p, double value, Coarse&& c) const {
    const auto I = static_cast<Eigen::Index>(2 * owner[k] + p);
    c[I] += (1.0 - weight[k]) * value;
    c[I + 2] += weight[k] * value;
  }
  void prolong(const Eigen::VectorXd& c, std::span<double> fine) const {
    for (std::size_t k = 0; k < m; ++k) {
      const auto I = static_cast<Eigen::Index>(2 * owner[k]);
      const double w = weight[k];
      fine[2 * k] = (1.0 - w) * c[I] + w * c[I + 2];
      fine[2 * k + 1] = (1.0 - w) * c[I + 1] + w * c[I + 3];
    }
    fine[2 * m] = c[static_cast<Eigen::Index>(2 * nc)];
  }
  void restrict_to(std::span<const double> fine, Eigen::VectorXd& c) const {
    c.setZero(static_cast<Eigen::Index>(2 * nc + 1));
    for (std::size_t k = 0; k < m; ++k) restrict_add(k, 0, fine[2 * k], c), restrict_add(k, 1, fine[2 * k + 1], c);
    c[static_cast<Eigen::Index>(2 * nc)] = fine[2 * m];
  }
};
// The coarse space: at most kCoarseNodes nodes, at least kCoarseSpacing fine intervals apart (64
// took 12 GMRES iterations a time step at 1024 nodes, 32 took 21); none below kCoarseLeast. A
// fixed 64 lets the iterations grow beyond 2048 nodes (a Newton step's 4-6 at 1024-2048 nodes,
// 6-16 at 4096, 14-28 at 8192); 128 at 4096 nodes took fewer in time steps (4) but not in a
// steady solve (15), at eight times the coarse LU.
constexpr std::size_t kCoarseNodes = 64, kCoarseSpacing = 8, kCoarseLeast = 4;
constexpr int kCoarseRefresh = 8;

// The Newton step's linear solve: to this relative residual, in at most this many iterations.
constexpr double kLinearTolerance = 1e-6;  // the least forcing term
constexpr double kMaxForcing = 1e-3;
constexpr double kPenaltyFactor = 1e5;  // kappa dX^2: large against the Poiseuille coefficients where the film ruptures
constexpr int kLinearIterations = 200;
constexpr double kMaxPressureStep = 1.0;
constexpr double kSecondOrderFilms = 20.0;  // films above this many floors: the Couette term to second order
constexpr double kEpsilonFloor = 1e-3;      // eps gains this x u dX H_floor
constexpr int kLineSearchHalvings = 10;
// The yield's corner (Impl::derive_pressure): rounded over this share of the hardness (1e-2 took
// 1.7 times as long on gears/m6z30-mixed-ehl.toml with the same shares and films to 3 digits).
constexpr double kYieldCorner = 1e-3;
constexpr double kElasticCorner = -40.0;  // (Q - P_y)/d below which e^t < 5e-18: P = Q, U = 0
constexpr double kMeritGrowth = 1e8;
constexpr int kMaxStepHalvings = 6;                // a failed time step retried as up to 64 substeps
constexpr double kMinHomotopyStride = 1.0 / 64.0;  // the roughness's smallest step in a steady solve's homotopy
}  // namespace

std::span<const NamedChoice<ViscosityLaw>> viscosity_law_choices() { return kViscosityLaws; }
std::span<const NamedChoice<FlowModel>> flow_model_choices() { return kFlowModels; }

void Fluid::set_oil_state(const lubrication::OilState& oil) {
  viscosity = oil.dynamic_viscosity;
  pressure_viscosity = oil.pressure_viscosity;
  eyring_stress = oil.eyring_stress;
  limiting_shear_coefficient = oil.limiting_shear_coefficient;
}

ViscosityExponent Fluid::viscosity_exponent(double p) const {
  const double q = std::max(p, 0.0);
  double exponent = 0.0, slope = 0.0;
  if (viscosity_law == ViscosityLaw::barus) {
    exponent = pressure_viscosity * q;
    slope = pressure_viscosity;
  } else {
    // Roelands (1966): ln(eta/eta_0) = (ln eta_0 + 9.67)((1 + p/p0)^Z - 1), Z = alpha p0/(ln eta_0 + 9.67).
    const double lnr = std::log(viscosity / kRoelandsViscosity);
    const double z = pressure_viscosity * kRoelandsPressure / lnr;
    const double base = 1.0 + q / kRoelandsPressure, power = std::pow(base, z);
    exponent = lnr * (power - 1.0);
    slope = lnr * z / kRoelandsPressure * power / base;
  }
  if (!(p > 0.0) || !(exponent < kMaxViscosityExponent)) slope = 0.0;  // at the exponent's cap: none
  return {std::min(exponent, kMaxViscosityExponent), slope};
}

double Fluid::viscosity_at(double p) const { return viscosity * std::exp(viscosity_exponent(p).value); }

double Fluid::density_ratio(double p) const {
  if (!compressible) return 1.0;
  const double q = std::max(p, 0.0);
  return 1.0 + kDensityA * q / (1.0 + kDensityB * q);
}

void Fluid::validate() const {
  using core::KeyedError;
  if (!(viscosity > 0.0) || !std::isfinite(viscosity)) throw KeyedError("viscosity", "viscosity must be positive");
  if (viscosity_law == ViscosityLaw::roelands && !(viscosity > kRoelandsViscosity))
    throw KeyedError("viscosity", fmt::format("Roelands' law needs a viscosity above {} Pa s", kRoelandsViscosity));
  if (!(pressure_viscosity >= 0.0) || !std::isfinite(pressure_viscosity))
    throw KeyedError("pressure_viscosity", "pressure-viscosity coefficient must be >= 0");
  if (!(eyring_stress > 0.0) || !std::isfinite(eyring_stress))
    throw KeyedError("eyring_stress", "Eyring stress must be positive");
  if (!(limiting_shear_coefficient >= 0.0 && limiting_shear_coefficient <= 1.0))
    throw KeyedError("limiting_shear_coefficient", "limiting shear coefficient must lie in [0, 1]");
}

void EhlOptions::validate() const {
  using core::KeyedError;
  if (!(inlet >= 1.5 && inlet <= 100.0)) throw KeyedError("inlet", "the inlet must lie 1.5 to 100 half-widths ahead");
  if (!(outlet >= 1.05 && outlet <= 100.0))
    throw KeyedError("outlet", "the outlet must lie 1.05 to 100 half-widths behind");
  if (nodes < 16 || nodes > (1 << 20)) throw KeyedError("nodes", "nodes must lie in [16, 2^20]");
  if (!(tolerance > 0.0 && tolerance < 0.1)) throw KeyedError("tolerance", "tolerance must lie in (0, 0.1)");
  if (max_iterations < 1) throw KeyedError("max_iterations", "max_iterations must be positive");
  if (!(film_floor > 0.0) || !std::isfinite(film_floor)) throw KeyedError("film_floor", "film floor must be positive");
  if (!(hardness > 0.0)) throw KeyedError("hardness", "hardness must be positive");
  if (!(boundary_friction >= 0.0 && boundary_friction <= 1.0))
    throw KeyedError("boundary_friction", "boundary friction must lie in [0, 1]");
}

struct LineEhlSolver::Impl {
  Fluid fluid;
  double modulus = 0.0;  // E*
  EhlOptions options;
  ContactInstant reference;
  double b = 0.0, ph = 0.0, w_ref = 0.0;  // Hertz half-width [m], pressure [Pa] and line load [N/m] of the reference
  double film_scale = 0.0;                // h = film_scale H [m]
  HalfPlaneGrid grid;
  int n = 0;
  double dx = 0.0;             // node spacing in b
  std::vector<double> X;       // nodes in b
  std::vector<double> kernel;  // K^(m) = int over an element of ln|X_i - S| dS, m = i - j in [-(n-1), n-1]
  std::unique_ptr<ToeplitzConvolution> deflection;  // sum_j K^(i-j) P_j
  std::vector<double> band;                         // D(0), D(1): the second difference of -K^/pi over dx^2 at 0, +-1
  // State (dimensionless).
  // The unknowns are Q and H: Q the pressure's parameter along the elastic-perfectly-plastic
  // graph (derive_pressure), P = p(Q) the pressure, U = u(Q) the surfaces' plastic flattening.
  std::vector<double> Q, P, dP, U, dU;
  std::vector<double> H, mass_old;              // mass_old: rho H at the last time
  std::vector<double> mass_older, mass_target;  // rho H a step before; the time derivative's known part
  std::vector<double> squeeze_at;               // the time derivative's coefficient at each node
  std::vector<char> second_order;               // the Couette term's order at each node (2 or 1)
  bool first_order = false;                     // a retry: the Couette term to first order everywhere
  double last_dt = 0.0;                         // the last step's [s]; 0 after a steady solve
  double H0 = 0.0;
  bool started = false;
  EhlField field;
  int newton_total = 0, linear_total = 0;  // over a public call's solves
  GmresWork gmres_work;
  ContactInstant last_instant;
  std::vector<double> last_heights;  // [m]
  // Work.
  std::vector<double> conv, mobility, dmobility_dp, dmobility_dh, rho, drho, r, work_p, work_conv;
  double eps_floor = 0.0;  // each face's eps gains this (coefficients())
  void build_grid() {
    n = options.nodes;
    const double x0 = -options.inlet * b, x1 = options.outlet * b;
    grid.spacing = (x1 - x0) / n;
    grid.start = x0;
    grid.size = n;
    dx = grid.spacing / b;
    X.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) X[static_cast<std::size_t>(i)] = grid.x(i) / b;
    kernel.assign(static_cast<std::size_t>(2 * n - 1), 0.0);
    for (int m = 0; m < n; ++m)
      kernel[static_cast<std::size_t>(n - 1 + m)] = kernel[static_cast<std::size_t>(n - 1 - m)] =
          log_antiderivative(m * dx + 0.5 * dx) - log_antiderivative(m * dx - 0.5 * dx);
    deflection = std::make_unique<ToeplitzConvolution>(kernel, n, false);
    band = {-(kernel_at(1) - 2.0 * kernel_at(0) + kernel_at(-1)) / (kPi * dx * dx),
            -(kernel_at(2) - 2.0 * kernel_at(1) + kernel_at(0)) / (kPi * dx * dx)};
    build_coarse_space();
    for (auto* v : {&Q, &P, &dP, &U, &dU}) v->assign(static_cast<std::size_t>(n), 0.0);
    std::fill(dP.begin(), dP.end(), 1.0);
    H.assign(static_cast<std::size_t>(n), 0.0);
    mass_old.assign(static_cast<std::size_t>(n), 0.0);
    mass_older.assign(static_cast<std::size_t>(n), 0.0);
    mass_target.assign(static_cast<std::size_t>(n), 0.0);
    for (auto* v : {&conv, &mobility, &dmobility_dp, &dmobility_dh, &rho, &drho, &r})
      v->assign(static_cast<std::size_t>(n), 0.0);
  }

  // The two-level preconditioner of solve()'s Newton systems: the coarse space, K times its
  // pressure hats (n x nc, fixed with the grid), the Galerkin operator R J P and its LU.
  CoarseSpace coarse;
  Eigen::MatrixXd coarse_film;  // R S2 K P_Q/pi: the coarse film rows' deflection entries (2 nc + 1 x nc)
  Eigen::MatrixXd coarse_ends;  // -(K P_Q)_end/pi at the first and last node (2 x nc)
  Eigen::MatrixXd coarse_matrix;
  Eigen::VectorXd coarse_yielded;
  Eigen::PartialPivLU<Eigen::MatrixXd> coarse_lu;
  bool coarse_on = false;  // the operator of the present Newton step is usable
  Eigen::VectorXd coarse_rhs, coarse_column;
  std::vector<double> cycle_r, cycle_y, probe_in, probe_out;
  double kernel_at(std::ptrdiff_t d) const { return kernel[static_cast<std::size_t>(n - 1 + std::abs(d))]; }

  // R of the film rows' deflection term S2 g/pi (the second difference over dX^2), g at every node.
  void restrict_film_rows(const Eigen::VectorXd& g, Eigen::VectorXd& out) const {
    out.setZero(2 * static_cast<Eigen::Index>(coarse.nc) + 1);
    const double scale = 1.0 / (dx * dx * kPi);
    for (std::size_t k = 0; k < coarse.m; ++k) {
      const auto i = static_cast<Eigen::Index>(k + 1);
      coarse.restrict_add(k, 1, (g[i + 1] - 2.0 * g[i] + g[i - 1]) * scale, out);
    }
  }

  void build_coarse_space() {
    const auto m = static_cast<std::size_t>(n - 2);
    const std::size_t nc = std::min(kCoarseNodes, (m - 1) / kCoarseSpacing + 1);
    coarse = nc >= kCoarseLeast ? CoarseSpace(m, nc) : CoarseSpace();
    if (coarse.nc == 0) return;
    coarse_film.resize(2 * static_cast<Eigen::Index>(nc) + 1, static_cast<Eigen::Index>(nc));
    coarse_ends.resize(2, static_cast<Eigen::Index>(nc));
    std::vector<double> hat(static_cast<std::size_t>(n));
    Eigen::VectorXd g(n);
    for (std::size_t J = 0; J < nc; ++J) {
      std::fill(hat.begin(), hat.end(), 0.0);
      for (std::size_t k = 0; k < m; ++k) hat[k + 1] = coarse.hat(J, k);
      deflection->apply(hat.data(), g.data());
      restrict_film_rows(g, coarse_column);
      coarse_film.col(static_cast<Eigen::Index>(J)) = coarse_column;
      coarse_ends(0, static_cast<Eigen::Index>(J)) = -g[0] / kPi;
      coarse_ends(1, static_cast<Eigen::Index>(J)) = -g[n - 1] / kPi;
    }
    for (auto* v : {&cycle_r, &cycle_y, &probe_in, &probe_out}) v->assign(2 * m + 1, 0.0);
  }

  // The Galerkin coarse operator R J P (R = P^T) of a Newton system. J's local part (everything
  // but the deflection's convolution: `product(in, out, false)`) by probing, the hats of every
  // third coarse node at once (their images, two fine nodes upstream to one downstream, do not
  // overlap); the deflection's part from coarse_film and coarse_ends, less the yielding nodes' share
  // (dP/dQ < 1); the end films' couplings through lower0, far1 and upper_last (as in product).
  template <class Product>
  void build_coarse_operator(const Product& product, const Block& lower0, double far1, const Block& upper_last) {
    coarse_on = false;
    if (coarse.nc == 0) return;
    const std::size_t m = coarse.m, nc = coarse.nc;
    const auto N = static_cast<Eigen::Index>(2 * nc + 1);
    coarse_matrix.setZero(N, N);
    auto add_row = [&](std::size_t k, std::size_t p, Eigen::Index column, double value) {
      coarse.restrict_add(k, p, value, coarse_matrix.col(column));
    };
    for (std::size_t colour = 0; colour < 3; ++colour)
      for (int q = 0; q < 2; ++q) {
        std::fill(probe_in.begin(), probe_in.end(), 0.0);
        for (std::size_t k = 0; k < m; ++k)
          for (std::size_t J : {coarse.owner[k], coarse.owner[k] + 1})
            if (J % 3 == colour) probe_in[2 * k + static_cast<std::size_t>(q)] += coarse.hat(J, k);
        product(probe_in, probe_out, false);
        for (std::size_t k = 0; k < m; ++k) {
          // The colour's coarse node whose image [node[J - 1], node[J + 1]] holds row k.
          std::size_t J = nc;
          for (std::size_t c = coarse.owner[k] > 0 ? coarse.owner[k] - 1 : 0; c <= coarse.owner[k] + 2 && c < nc; ++c)
            if (c % 3 == colour && k >= (c > 0 ? coarse.node[c - 1] : 0) && k <= (c + 1 < nc ? coarse.node[c + 1] : m))
              J = c;
          if (J == nc) continue;
          const auto column = static_cast<Eigen::Index>(2 * J) + q;
          add_row(k, 0, column, probe_out[2 * k]);
          add_row(k, 1, column, probe_out[2 * k + 1]);
        }
      }
    std::fill(probe_in.begin(), probe_in.end(), 0.0);  // H0's column
    probe_in[2 * m] = 1.0;
    product(probe_in, probe_out, false);
    coarse.restrict_to(probe_out, coarse_column);
    coarse_matrix.col(N - 1) = coarse_column;
    // The deflection's part, K diag(dP/dQ) P: with dP/dQ = 1 fixed with the grid (coarse_film,
    // coarse_ends); where the surfaces yield (dP/dQ < 1) less the yielded share of each hat.
    const auto add_ends = [&](std::size_t J, double front, double back) {  // the end films' dH
      const auto column = static_cast<Eigen::Index>(2 * J);
      add_row(0, 0, column, lower0[1] * front);
      add_row(0, 1, column, lower0[3] * front);
      if (m > 1) add_row(1, 0, column, far1 * front);
      add_row(m - 1, 0, column, upper_last[1] * back);
      add_row(m - 1, 1, column, upper_last[3] * back);
    };
    for (std::size_t J = 0; J < nc; ++J) {
      const auto column = static_cast<Eigen::Index>(2 * J);
      coarse_matrix.col(column) += coarse_film.col(static_cast<Eigen::Index>(J));
      add_ends(J, coarse_ends(0, static_cast<Eigen::Index>(J)), coarse_ends(1, static_cast<Eigen::Index>(J)));
      // The hat's yielded share: -K (1 - dP/dQ) hat_J.
      const std::size_t first = J > 0 ? coarse.node[J - 1] + 1 : 0, last = J + 1 < nc ? coarse.node[J + 1] : m;
      bool yielded = false;
      for (std::size_t k = first; k < last; ++k) {
        const double h = (1.0 - dP[k + 1]) * coarse.hat(J, k);
        if (!(h > 1e-12)) continue;
        if (!yielded) coarse_yielded.setZero(n);
        yielded = true;
        for (int i = 0; i < n; ++i) coarse_yielded[i] -= h * kernel_at(i - static_cast<std::ptrdiff_t>(k + 1));
      }
      if (yielded) {
        restrict_film_rows(coarse_yielded, coarse_column);
        coarse_matrix.col(column) += coarse_column;
        add_ends(J, -coarse_yielded[0] / kPi, -coarse_yielded[n - 1] / kPi);
      }
      // The load row: dx sum(dP/dQ dQ).
      double load = 0.0;
      for (std::size_t k = first; k < last; ++k) load += dP[k + 1] * coarse.hat(J, k);
      coarse_matrix(N - 1, column) = dx * load;
    }
    coarse_lu.compute(coarse_matrix);
    coarse_on = coarse_lu.rcond() > 1e-14;
  }

  // The film from the integral form at every node (H0, geometry, deflection, heights).
  void integral_film(double curvature, std::vector<double>& out) {
    derive_pressure();
    deflection->apply(P.data(), conv.data());
    for (int i = 0; i < n; ++i) {
      const auto s = static_cast<std::size_t>(i);
      out[s] = H0 + 0.5 * curvature * X[s] * X[s] - conv[s] / kPi - r[s] + U[s];
    }
  }

  void start_hertz(const ContactInstant& c, double curvature, double load) {
    // Hertz for the instant's load and curvature (in the reference's units), then H0 so that the
    // central film is a first guess from Dowson-Toyoda's line-contact formula (E' = 2 E*).
    const double a = std::sqrt(load / curvature);  // b/b_ref: a^2 proportional to w R
    const double e_prime = 2.0 * modulus;
    const double u = c.entrainment(), w = c.line_load, rr = c.radius;
    const double U = fluid.viscosity * u / (e_prime * rr), G = fluid.pressure_viscosity * e_prime,
                 W = w / (e_prime * rr);
    const double hc = 3.06 * std::pow(U, 0.69) * std::pow(std::max(G, 1.0), 0.56) * std::pow(W, -0.10) * rr;
    // Where the rigid-isoviscous film (Martin: w = 4.9 eta u R/h) is the thicker, the contact is
    // hydrodynamic: start from that film and a semi-ellipse of the same load over its pressure's
    // extent (about 2 sqrt(2 R h) ahead of the gap's minimum to 0.5 sqrt(2 R h) behind).
    const double martin = 4.9 * fluid.viscosity * u * rr / w;
    const bool hydrodynamic = martin > hc;
    const double spread = std::sqrt(2.0 * rr * martin) / b;  // sqrt(2 R h) in b_ref
    const double half = hydrodynamic ? std::max(a, 1.25 * spread) : a, centre = hydrodynamic ? -0.75 * spread : 0.0;
    for (int i = 0; i < n; ++i) {
      const auto s = static_cast<std::size_t>(i);
      const double t = (X[s] - centre) / half;
      Q[s] = std::abs(t) < 1.0 ? (load / half) * std::sqrt(1.0 - t * t) : 0.0;
      if (plastic_on) Q[s] = std::min(Q[s], yield_level());  // yielding surfaces: at most the hardness
    }
    Q.front() = Q.back() = 0.0;
    H0 = 0.0;
    integral_film(curvature, H);
    const auto mid = static_cast<std::size_t>(std::lower_bound(X.begin(), X.end(), 0.0) - X.begin());
    H0 = std::max(hc, std::min(martin, 100.0 * hc)) / film_scale - H[std::min(mid, H.size() - 1)];
    for (double& h : H) h += H0;
    started = true;
  }

  // The Poiseuille coefficient eps across the face between nodes i and j, and its derivatives by
  // each node's P and H: the lubricant's mobility rho phi/(eta lambda) averaged (as Venner &
  // Lubrecht average eps), times the conductance of a film varying linearly from h_i to h_j,
  // dX / int dX/h^3 = 2 h_i^2 h_j^2/(h_i + h_j) (h^3 where they are equal), plus eps's floor. The
  // mean of eps itself lets a closing film drain through its open neighbour's coefficient: on
  // rough surfaces sliding at the shipped case's point A that turned contact nodes' films
  // negative (to -0.45 um) while their pressure rose to tens of GPa.
  struct Face {
    double value, dp_this, dh_this, dp_other, dh_other;
  };
  Face face(std::size_t i, std::size_t j) const {
    const double hi = std::max(H[i], 0.0), hj = std::max(H[j], 0.0), sum = hi + hj;
    const double m = 0.5 * (mobility[i] + mobility[j]);
    double cond = 0.0, dci = 0.0, dcj = 0.0;
    if (sum > 0.0) {
      cond = 2.0 * hi * hi * hj * hj / sum;
      dci = 2.0 * hi * hj * hj * (hi + 2.0 * hj) / (sum * sum);
      dcj = 2.0 * hj * hi * hi * (hj + 2.0 * hi) / (sum * sum);
    }
    return {m * cond + eps_floor, 0.5 * dmobility_dp[i] * cond, 0.5 * dmobility_dh[i] * cond + m * dci,
            0.5 * dmobility_dp[j] * cond, 0.5 * dmobility_dh[j] * cond + m * dcj};
  }

  // Elastic-perfectly-plastic surfaces (the pressure truncated at the softer surface's hardness,
  // as the dry boundary elements do; Almqvist et al., Wear 262, 2007, 1320-1332): a node's
  // pressure P and the surfaces' plastic flattening U (which opens the film like the elastic
  // displacement) lie on the graph U = 0 for P < P_y, P = P_y for U > 0, P_y = hardness/p_H. The
  // graph is parametrised by Q (Newton's unknown), its corner rounded over d = kYieldCorner P_y:
  //   P = P_y - d softplus((P_y - Q)/d),   U = d softplus((Q - P_y)/d)   (film units per unit Q),
  // so the pressure never exceeds the hardness and both slopes stay within [0, 1] (a kinked cap
  // or a steep plastic compliance made Newton's method cycle). Q = P without a hardness. The
  // flattening follows the pressure at each instant (it is not carried with the surface).
  double yield_level() const { return options.hardness / ph; }
  void derive_pressure() {
    if (!plastic_on) {
      P = Q;
      return;
    }
    const double py = yield_level(), d = kYieldCorner * py;
    for (std::size_t i = 0; i < Q.size(); ++i) {
      const double t = (Q[i] - py) / d;
      if (t < kElasticCorner) {  // e^t below the round-off of P = Q and of dP/dQ = 1
        U[i] = dU[i] = 0.0;
        P[i] = Q[i];
        dP[i] = 1.0;
        continue;
      }
      // softplus(t) = ln(1 + e^t), its slope the logistic function, both without overflow.
      const double e = std::exp(-std::abs(t));
      const double up = std::max(t, 0.0) + std::log1p(e);
      const double sig = t > 0.0 ? 1.0 / (1.0 + e) : e / (1.0 + e);
      U[i] = d * up;
      dU[i] = sig;
      P[i] = Q[i] - U[i];  // P_y - d softplus(-t) = Q - d softplus(t)
      dP[i] = 1.0 - sig;
    }
  }
  bool plastic_on = false;  // a finite hardness

  // The mobility and its derivatives, rho and its derivative, at every node.
  void coefficients(const ContactInstant& c) {
    const double floor =
        kEpsilonFloor * (c.entrainment() / reference.entrainment()) * dx * options.film_floor / film_scale;
    const double lambda =
        12.0 * fluid.viscosity * reference.entrainment() * reference.radius * reference.radius / (b * b * b * ph);
    const double slide = std::abs(c.speed1 - c.speed2);
    for (int i = 0; i < n; ++i) {
      const auto s = static_cast<std::size_t>(i);
      const double p = P[s] * ph;
      const ViscosityExponent ln_eta = fluid.viscosity_exponent(p);
      const double eta_bar = std::exp(ln_eta.value), eta = fluid.viscosity * eta_bar;
      rho[s] = fluid.density_ratio(p);
      // d rho/dP and d ln(eta)/dP (Hertzian P).
      const double dlneta = ln_eta.slope * ph;
      drho[s] = fluid.compressible && p > 0.0 ? kDensityA * ph / std::pow(1.0 + kDensityB * p, 2) : 0.0;
      const double h = std::max(H[s], 0.0);
      double phi = 1.0, phi_share = 0.0;  // phi_share = s^2/phi^2 = d ln(phi)/d ln(s)
      if (fluid.flow == FlowModel::eyring && h > 0.0) {
        const double ratio = eta * slide / (fluid.eyring_stress * h * film_scale);
        phi = std::sqrt(1.0 + ratio * ratio);  // cosh(asinh(ratio)), Conry, Wang & Cusano 1987
        phi_share = ratio * ratio / (phi * phi);
      }
      // The mobility rho phi/(eta lambda) (eps = mobility H^3): ln of it = ln rho + ln phi - ln eta,
      // phi of s = eta |u1 - u2|/(tau_0 h).
      const double mob = rho[s] * phi / (eta_bar * lambda);
      mobility[s] = std::isfinite(mob) ? mob : 0.0;
      dmobility_dp[s] = mobility[s] * (drho[s] / rho[s] - (1.0 - phi_share) * dlneta);
      dmobility_dh[s] = h > 0.0 ? -phi_share * mobility[s] / h : 0.0;
    }
    // Where the film vanishes (contact, or a solid viscosity) the pressure would be undetermined
    // by this equation: each face's eps gains a constant (smoothly, not as a floor, whose kink
    // would stall Newton's method where eps crosses it), so the pressure stays the harmonic
    // continuation of its neighbours'. Its Poiseuille flux across a node where the pressure jumps
    // by p_H is 1e-3 of the Couette flux through a film at the floor (at 1, that flux drained the
    // contacts' oil until their films turned negative).
    eps_floor = floor;
  }

  // One solve (steady: dt = 0) at the instant; throws if not converged.
  const EhlField& solve(const ContactInstant& c, std::span<const double> heights, double dt) {
    if (static_cast<int>(heights.size()) != n)
      throw std::invalid_argument(fmt::format("mixed EHL: {} heights for {} nodes", heights.size(), n));
    if (!(c.line_load > 0.0) || !(c.radius > 0.0) || !(c.speed1 >= 0.0) || !(c.speed2 >= 0.0) ||
        !(c.entrainment() > 0.0))
      throw std::invalid_argument("mixed EHL: the instant needs a positive load, radius and entrainment");
    for (int i = 0; i < n; ++i) r[static_cast<std::size_t>(i)] = heights[static_cast<std::size_t>(i)] / film_scale;
    const double curvature = reference.radius / c.radius;  // R_ref/R
    const double load = c.line_load / w_ref;               // of the reference's
    const double target = 0.5 * kPi * load;                // int P dX
    const double speed = c.entrainment() / reference.entrainment();
    // The squeeze term d(rho H)/dT ~ squeeze (rho H - target): backward Euler on the first step
    // after a steady solve, then the variable-step second-order backward difference
    // a0 M^{n+1} + a1 M^n + a2 M^{n-1}, omega = dt/dt_last (Hairer, Norsett & Wanner, Solving
    // ODEs I, sec. III.5): a0 = (1 + 2 omega)/((1 + omega) dT), a1 = -(1 + omega)/dT,
    // a2 = omega^2/((1 + omega) dT). With the second-order upwind Couette term below this is
    // Venner & Lubrecht's discretisation (Multilevel Methods in Lubrication, 2000, ch. 9): first
    // order in both damped the roughness's film waves to a few per cent of their amplitude.
    double squeeze = 0.0;
    const double dT = dt * reference.entrainment() / b;
    if (dt > 0.0) {
      if (last_dt > 0.0 && !first_order) {
        const double omega = dt / last_dt;
        const double a0 = (1.0 + 2.0 * omega) / ((1.0 + omega) * dT), a1 = -(1.0 + omega) / dT,
                     a2 = omega * omega / ((1.0 + omega) * dT);
        squeeze = a0;
        for (std::size_t i = 0; i < mass_target.size(); ++i)
          mass_target[i] = -(a1 * mass_old[i] + a2 * mass_older[i]) / a0;
      } else {
        squeeze = 1.0 / dT;
        mass_target = mass_old;
      }
    }
    if (!started) start_hertz(c, curvature, load);
    // The second differences of the heights (they enter the film's differential form).
    const double inv_dx2 = 1.0 / (dx * dx);
    const std::size_t m = static_cast<std::size_t>(n - 2);  // interior unknowns
    std::vector<Block> lower(m), diag(m), upper(m), lumped(m);
    std::vector<Pair> far(m);
    std::vector<Pair> rhs(m), y1(m), y2(m), col(m);
    std::vector<Block> cprime(m), dinv(m), gain(m);
    std::vector<Pair> g1(m);
    std::vector<double> boundary(static_cast<std::size_t>(n)), z(2 * m + 1, 0.0);
    work_p.assign(static_cast<std::size_t>(n), 0.0);
    work_conv.assign(static_cast<std::size_t>(n), 0.0);
    const double penalty = kPenaltyFactor / (dx * dx);
    double update = 0.0, load_error = 0.0;
    int it = 0, linear_iterations = 0, last_linear = 0;
    std::vector<double> row_scale(2 * m, 1.0), Q_base, H_base, work_v;
    // The residuals at the present state (F, G per interior node, the load's), and with
    // `jacobian` the Newton blocks; returns the merit sum((row residual/row scale)^2) + load^2
    // with the row scales of the last Jacobian (fixed through a line search).
    auto assemble = [&](bool with_jacobian) {
      integral_film(curvature, boundary);  // the ends from the integral form (and conv = K (P + pc))
      H.front() = boundary.front();
      H.back() = boundary.back();
      coefficients(c);
      double merit = 0.0, h_scale = options.film_floor / film_scale;
      for (int i = 0; i < n; ++i)
        if (std::abs(X[static_cast<std::size_t>(i)]) <= 1.0)
          h_scale = std::max(h_scale, std::abs(H[static_cast<std::size_t>(i)]));
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = k + 1;
        const Face fa = face(i, i + 1), fc = face(i, i - 1);
        const double ea = fa.value * inv_dx2, ec = fc.value * inv_dx2;
        const double dpa = P[i + 1] - P[i], dpc_ = P[i] - P[i - 1];
        // The Couette term upwinded to second order, (3 M_i - 4 M_{i-1} + M_{i-2})/(2 dX) (first
        // order at the first node): c0, c1, c2 its weights.
        const bool second = i >= 2 && second_order[i];
        const double c0 = second ? 1.5 / dx : 1.0 / dx, c1 = second ? 2.0 / dx : 1.0 / dx, c2 = second ? 0.5 / dx : 0.0;
        const double mass = rho[i] * H[i], mass_prev = rho[i - 1] * H[i - 1];
        const double mass_far = second ? rho[i - 2] * H[i - 2] : 0.0;
        const double couette =
            speed * (c0 * mass - c1 * mass_prev + c2 * mass_far) + squeeze_at[i] * (mass - mass_target[i]);
        double F = ea * dpa - ec * dpc_ - couette;
        if (P[i] < 0.0) F -= penalty * P[i];
        const double d2conv = (conv[i + 1] - 2.0 * conv[i] + conv[i - 1]) * inv_dx2;
        const double G = (H[i + 1] - 2.0 * H[i] + H[i - 1]) * inv_dx2 - curvature + d2conv / kPi +
                         (r[i + 1] - 2.0 * r[i] + r[i - 1]) * inv_dx2 - (U[i + 1] - 2.0 * U[i] + U[i - 1]) * inv_dx2;
        rhs[k] = {-F, -G};
        if (with_jacobian) {
          Block d{}, l{}, u{};
          d[0] = -ea - ec + (fa.dp_this * dpa - fc.dp_this * dpc_) * inv_dx2 -
                 (speed * c0 + squeeze_at[i]) * drho[i] * H[i];
          d[1] = (fa.dh_this * dpa - fc.dh_this * dpc_) * inv_dx2 - (speed * c0 + squeeze_at[i]) * rho[i];
          l[0] = ec - fc.dp_other * dpc_ * inv_dx2 + speed * c1 * drho[i - 1] * H[i - 1];
          l[1] = -fc.dh_other * dpc_ * inv_dx2 + speed * c1 * rho[i - 1];
          // The node two upstream: outside the tridiagonal blocks, in the Jacobian's product;
          // the preconditioner lumps it onto the upstream neighbour.
          far[k] = second ? Pair{-speed * c2 * drho[i - 2] * H[i - 2], -speed * c2 * rho[i - 2]} : Pair{0.0, 0.0};
          u[0] = ea + fa.dp_other * dpa * inv_dx2;
          u[1] = fa.dh_other * dpa * inv_dx2;
          // Cavitation by the penalty method (Wu, 1986; Reynolds' condition as the penalty
          // grows): where P < 0 the residual gains -kappa P, so the cavitated zone's pressure is
          // F(0)/(kappa + |dF/dP|) ~ 0 and the film's rupture moves freely in each Newton step.
          if (P[i] < 0.0) d[0] -= penalty;
          // The film rows: d/dP_j through D's band, d/dH_j through the band and the contacts.
          d[2] = -band[0];
          d[3] = -2.0 * inv_dx2;
          l[2] = u[2] = -band[1];
          l[3] = u[3] = inv_dx2;
          // By Q: the pressure's columns times dP/dQ, the flattening's second difference by dU/dQ.
          d[0] *= dP[i], d[2] = d[2] * dP[i] + 2.0 * dU[i] * inv_dx2;
          l[0] *= dP[i - 1], l[2] = l[2] * dP[i - 1] - dU[i - 1] * inv_dx2;
          u[0] *= dP[i + 1], u[2] = u[2] * dP[i + 1] - dU[i + 1] * inv_dx2;
          if (second) far[k][0] *= dP[i - 2];
          lower[k] = l;
          diag[k] = d;
          upper[k] = u;
          col[k] = {0.0, 0.0};
          row_scale[2 * k] = std::abs(d[0]) + std::abs(d[1]) * h_scale + 1e-300;
          row_scale[2 * k + 1] = 2.0 * inv_dx2 * h_scale;
        }
        merit += std::pow(F / row_scale[2 * k], 2) + std::pow(G / row_scale[2 * k + 1], 2);
      }
      double sum_p = 0.0;
      for (std::size_t k = 0; k < m; ++k) sum_p += P[k + 1];
      load_error = (dx * sum_p - target) / target;
      return merit + load_error * load_error;
    };
    // The Couette term is upwinded to second order where the film, at the solve's start, is thick
    // over the three nodes (above kSecondOrderFilms floors), to first order elsewhere: second
    // order's undershoots at a contact's edge turn films negative and stall Newton's method there.
    // Fixed through the solve, so the Jacobian stays exact.
    second_order.assign(static_cast<std::size_t>(n), 0);
    const double thick = kSecondOrderFilms * options.film_floor / film_scale;
    for (int i = 2; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      second_order[k] = static_cast<char>(!first_order && std::min({H[k], H[k - 1], H[k - 2]}) > thick);
    }
    // Where the Couette term is first order (near a contact) so is the time derivative: backward
    // Euler, M^{n+1} = M^n - dT u dM/dX. BDF2's M^{n+1} = (4 M^n - M^{n-1})/3 + ... turns a film
    // that thins fast as an asperity closes (M^{n-1} > 4 M^n) negative; upwind with backward
    // Euler keeps the carried content positive (a monotone scheme, LeVeque, Finite Volume
    // Methods for Hyperbolic Problems, 2002, sec. 8.3).
    // (Nodes 0 and 1 have no second-order upwind stencil: their film decides.)
    squeeze_at.assign(static_cast<std::size_t>(n), squeeze);
    if (dt > 0.0)
      for (std::size_t i = 0; i < squeeze_at.size(); ++i)
        if (!second_order[i] && (i >= 2 || H[i] <= thick)) squeeze_at[i] = 1.0 / dT, mass_target[i] = mass_old[i];
    double merit = assemble(true), forcing = kMaxForcing;
    for (; it < options.max_iterations; ++it) {
      // -dRes/dH0 through H_0 and H_{n-1} (both move by dH0).
      col.front() = {-lower.front()[1], -lower.front()[3]};
      if (m > 1) col[1] = {col[1][0] - far[1][1], col[1][1]};  // the second row's node two upstream is node 0
      col.back() = {col.back()[0] - upper.back()[1], col.back()[1] - upper.back()[3]};
      for (std::size_t k = 0; k < m; ++k) {
        lumped[k] = lower[k];
        lumped[k][0] += far[k][0];
        lumped[k][1] += far[k][1];
      }
      // The Newton system J z = -(Res, load), J = T + E bordered by H0 and the load row: T the
      // block-tridiagonal part (D's three central diagonals), E the rest of D (in the film rows,
      // applied by FFT). Right-preconditioned GMRES with the bordered T as the preconditioner.
      factor(lumped, diag, upper, dinv, cprime, gain);
      solve_tridiagonal(dinv, gain, cprime, col, y2);   // T^-1 (-dRes/dH0)
      auto load_of = [&](const std::vector<Pair>& y) {  // the load row: dx sum(dP/dQ dQ)
        double sum = 0.0;
        for (std::size_t k = 0; k < m; ++k) sum += dP[k + 1] * y[k][0];
        return dx * sum;
      };
      const double load_y2 = load_of(y2);
      const double load_rhs = -load_error * target;
      auto precondition = [&](std::span<const double> v, std::span<double> out) {
        for (std::size_t k = 0; k < m; ++k) g1[k] = {v[2 * k], v[2 * k + 1]};
        solve_tridiagonal(dinv, gain, cprime, g1, y1);
        const double s = std::abs(load_y2) > 0.0 ? (v[2 * m] - load_of(y1)) / load_y2 : 0.0;
        for (std::size_t k = 0; k < m; ++k)
          out[2 * k] = y1[k][0] + s * y2[k][0], out[2 * k + 1] = y1[k][1] + s * y2[k][1];
        out[2 * m] = s;
      };
      // J zz; without `elastic` the part that goes through the deflection's convolution is left
      // out (the coarse operator adds it from coarse_film).
      auto product = [&](std::span<const double> zz, std::span<double> out, bool elastic) {
        std::fill(work_p.begin(), work_p.end(), 0.0);
        for (std::size_t k = 0; k < m; ++k) work_p[k + 1] = zz[2 * k] * dP[k + 1];  // dP = dP/dQ dQ
        if (elastic) deflection->apply(work_p.data(), work_conv.data());
        else std::fill(work_conv.begin(), work_conv.end(), 0.0);
        double load = 0.0;
        for (std::size_t k = 0; k < m; ++k) {
          Pair acc = multiply(diag[k], Pair{zz[2 * k], zz[2 * k + 1]});
          if (k > 0) {
            const Pair a = multiply(lower[k], Pair{zz[2 * k - 2], zz[2 * k - 1]});
            acc = {acc[0] + a[0], acc[1] + a[1]};
          }
          if (k + 1 < m) {
            const Pair a = multiply(upper[k], Pair{zz[2 * k + 2], zz[2 * k + 3]});
            acc = {acc[0] + a[0], acc[1] + a[1]};
          }
          if (k >= 2) acc[0] += far[k][0] * zz[2 * k - 4] + far[k][1] * zz[2 * k - 3];
          acc = {acc[0] - col[k][0] * zz[2 * m], acc[1] - col[k][1] * zz[2 * m]};
          // The end films move with the whole pressure (the integral form): dH_end = -(K dP)_end/pi.
          if (k == 0) {
            const double dh = -work_conv.front() / kPi;
            acc = {acc[0] + lower[k][1] * dh, acc[1] + lower[k][3] * dh};
          }
          if (k == 1) acc[0] += far[k][1] * (-work_conv.front() / kPi);
          if (k + 1 == m) {
            const double dh = -work_conv.back() / kPi;
            acc = {acc[0] + upper[k][1] * dh, acc[1] + upper[k][3] * dh};
          }
          // E: the film row's full deflection term less its band (already in T).
          const std::size_t i = k + 1;
          const double full = (work_conv[i + 1] - 2.0 * work_conv[i] + work_conv[i - 1]) * inv_dx2 / kPi;
          const double banded = -band[0] * work_p[i] - band[1] * (work_p[i - 1] + work_p[i + 1]);
          acc[1] += full - banded;
          out[2 * k] = acc[0];
          out[2 * k + 1] = acc[1];
          load += dx * work_p[i];
        }
        out[2 * m] = load;
      };
      auto jacobian = [&](std::span<const double> zz, std::span<double> out) { product(zz, out, true); };
      // The coarse operator at a solve's first Newton step, and again only when the last linear
      // solve took more than kCoarseRefresh iterations (a stale one still preconditions: on the
      // benchmark's window at 2048 nodes 7.0 s against 8.3 s rebuilding it every step).
      if (it == 0 || last_linear > kCoarseRefresh)
        build_coarse_operator(product, lower.front(), m > 1 ? far[1][1] : 0.0, upper.back());
      // The two-level preconditioner (a multiplicative two-grid cycle, Saad 2003 sec. 13.3, with
      // the bordered T as the smoother on either side of the coarse correction): T's block
      // tridiagonal leaves out the deflection's long-range part, whose smooth modes the coarse
      // Galerkin operator resolves (GMRES's iterations a Newton step on the benchmark's window at 2048
      // nodes: ~36 -> ~5).
      auto two_level = [&](std::span<const double> v, std::span<double> out) {
        precondition(v, out);
        if (!coarse_on) return;
        jacobian(out, cycle_r);
        for (std::size_t e = 0; e <= 2 * m; ++e) cycle_r[e] = v[e] - cycle_r[e];
        coarse.restrict_to(cycle_r, coarse_rhs);
        coarse_rhs = coarse_lu.solve(coarse_rhs);
        coarse.prolong(coarse_rhs, cycle_y);
        for (std::size_t e = 0; e <= 2 * m; ++e) out[e] += cycle_y[e];
        jacobian(out, cycle_r);
        for (std::size_t e = 0; e <= 2 * m; ++e) cycle_r[e] = v[e] - cycle_r[e];
        precondition(cycle_r, cycle_y);
        for (std::size_t e = 0; e <= 2 * m; ++e) out[e] += cycle_y[e];
      };
      std::vector<double> bvec(2 * m + 1);
      for (std::size_t k = 0; k < m; ++k) bvec[2 * k] = rhs[k][0], bvec[2 * k + 1] = rhs[k][1];
      bvec[2 * m] = load_rhs;
      // GMRES on the row-scaled system (the merit's scales; the load row by the target), so that
      // its tolerance holds for every row, not only the largest.
      auto scaled_jacobian = [&](std::span<const double> zz, std::span<double> out) {
        jacobian(zz, out);
        for (std::size_t e = 0; e < 2 * m; ++e) out[e] /= row_scale[e];
        out[2 * m] /= target;
      };
      auto scaled_precondition = [&](std::span<const double> v, std::span<double> out) {
        work_v.resize(v.size());
        for (std::size_t e = 0; e < 2 * m; ++e) work_v[e] = v[e] * row_scale[e];
        work_v[2 * m] = v[2 * m] * target;
        two_level(work_v, out);
      };
      for (std::size_t e = 0; e < 2 * m; ++e) bvec[e] /= row_scale[e];
      bvec[2 * m] /= target;
      // Inexact Newton: the linear solve's tolerance follows the residual's fall (Eisenstat &
      // Walker, SIAM J. Sci. Comput. 17, 1996, choice 2 with gamma 0.9, alpha 2).
      last_linear = gmres(gmres_work, scaled_jacobian, scaled_precondition, bvec, z, forcing, kLinearIterations);
      linear_iterations += last_linear;
      if (std::getenv("EHL_FD")) {
        std::vector<double> jz(z.size());
        jacobian(z, jz);
        std::vector<Pair> r0 = rhs;
        const double l0 = load_error;
        const std::vector<double> Qb = Q, Hb = H;
        const double H0b = H0, delta = 1e-7;
        for (std::size_t k = 0; k < m; ++k) Q[k + 1] += delta * z[2 * k], H[k + 1] += delta * z[2 * k + 1];
        H0 += delta * z[2 * m];
        assemble(false);
        double worst = 0.0;
        std::size_t wk = 0;
        int wr = 0;
        for (std::size_t k = 0; k < m; ++k)
          for (int q = 0; q < 2; ++q) {
            const double fd = -(rhs[k][q] - r0[k][q]) / delta;
            const double e = std::abs(fd - jz[2 * k + q]) / row_scale[2 * k + q];
            if (e > worst) worst = e, wk = k, wr = q;
          }
        fmt::print(
            stderr,
            "  FD worst {:.3e} node {} row {} X {:.4f} fd {:.4e} jz {:.4e} P {:.3f} | load fd {:.4e} jz {:.4e}\n",
            worst, wk + 1, wr, X[wk + 1], -(rhs[wk][wr] - r0[wk][wr]) / delta, jz[2 * wk + wr], P[wk + 1],
            (load_error - l0) * target / delta, jz[2 * m]);
        Q = Qb;
        H = Hb;
        H0 = H0b;
        assemble(true);
      }
      // The step's first length: no fluid pressure of the open film changes by more than
      // kMaxPressureStep p_H (the viscosity's exponential makes the linearisation poor far from
      // the solution), no open film more than halves, no film near contact more than doubles.
      double theta = 1.0;
      {
        const double floor = options.film_floor / film_scale;
        double step_max = 0.0;
        for (std::size_t k = 0; k < m; ++k) {
          step_max = std::max(step_max, std::abs(z[2 * k]));
          const double h = H[k + 1], dh = z[2 * k + 1];
          if (h > floor && dh < -0.5 * h) theta = std::min(theta, std::max(0.5 * h, h - floor) / -dh);
          const double ceiling = std::max(2.0 * h, h + 2.0 * floor) - h;
          if (h < 10.0 * floor && dh > ceiling) theta = std::min(theta, ceiling / dh);
        }
        if (step_max > kMaxPressureStep) theta = std::min(theta, kMaxPressureStep / step_max);
      }
      // A safeguard, not a line search: the step is halved (up to kLineSearchHalvings times) only
      // while the merit would grow more than kMeritGrowth-fold. (An Armijo search, Dennis &
      // Schnabel 1983 sec. 6.3, took 1.5-3 times the iterations: the cavitation's penalty and the
      // exponential viscosity make the merit fall non-monotonically along Newton's path.)
      Q_base = Q;
      H_base = H;
      const double H0_base = H0, merit_base = merit;
      for (int halving = 0; halving <= kLineSearchHalvings; ++halving) {
        for (std::size_t k = 0; k < m; ++k) {
          Q[k + 1] = Q_base[k + 1] + theta * z[2 * k];
          H[k + 1] = H_base[k + 1] + theta * z[2 * k + 1];
        }
        H0 = H0_base + theta * z[2 * m];
        const double trial_merit = assemble(false);
        if (std::isfinite(trial_merit) && trial_merit <= kMeritGrowth * merit_base) break;
        if (halving < kLineSearchHalvings) theta *= 0.5;
      }
      // Converged on the Newton step itself (not the step taken, which a short line search
      // would make small far from the solution).
      update = 0.0;
      double dh_max = 0.0, h_ref = options.film_floor / film_scale;
      for (std::size_t k = 0; k < m; ++k) {
        update = std::max(update, std::abs(z[2 * k]));
        dh_max = std::max(dh_max, std::abs(z[2 * k + 1]));
        if (std::abs(X[k + 1]) <= 1.0) h_ref = std::max(h_ref, std::abs(H[k + 1]));
      }
      const double dh_rel = dh_max / h_ref;
      if (!std::isfinite(update) || !std::isfinite(dh_rel))
        throw std::runtime_error("mixed EHL: the Newton iteration diverged (non-finite update)");
      if (std::getenv("EHL_TRACE") && it >= 470) {
        std::size_t kk = 0;
        for (std::size_t k = 0; k < m; ++k)
          if (std::abs(z[2 * k]) > std::abs(z[2 * kk])) kk = k;
        fmt::print(
            stderr,
            "it {} theta {:.2e} merit {:.3e} upd {:.2e} dh {:.2e} load {:.2e} forcing {:.1e} | node {} X {:.4f} P {:.4f} H {:.3e} mobility {:.2e} zp {:.2e} zh {:.2e} dt {:.3g}\n",
            it, theta, merit, update, dh_rel, load_error, forcing, kk + 1, X[kk + 1], P[kk + 1], H[kk + 1],
            mobility[kk + 1], z[2 * kk], z[2 * kk + 1], dt);
      }
      const double merit_last = merit;
      merit = assemble(true);
      forcing = std::clamp(0.9 * merit / merit_last, kLinearTolerance, kMaxForcing);
      if (update < options.tolerance && dh_rel < options.tolerance && std::abs(load_error) < options.tolerance) {
        ++it;
        break;
      }
    }
    if (it >= options.max_iterations && !(update < options.tolerance && std::abs(load_error) < options.tolerance))
      throw std::runtime_error(
          fmt::format("mixed EHL: not converged in {} iterations (last update {:.3g} p_H, load error {:.3g})",
                      options.max_iterations, update, load_error));
    // The film everywhere from the integral form (consistent with the converged differential form).
    integral_film(curvature, H);
    coefficients(c);
    mass_older = mass_old;
    for (int i = 0; i < n; ++i)
      mass_old[static_cast<std::size_t>(i)] = rho[static_cast<std::size_t>(i)] * H[static_cast<std::size_t>(i)];
    last_dt = dt;
    fill(c, it, update, load_error);
    newton_total += it;
    linear_total += linear_iterations;
    last_instant = c;
    last_heights.assign(heights.begin(), heights.end());
    return field;
  }

  // A time step; one that does not converge is retried as two half steps (the instant and the
  // heights interpolated linearly between the last and the new), at most kMaxStepHalvings deep.
  void advance(const ContactInstant& c, const std::vector<double>& heights, double dt, int depth) {
    const std::vector<double> Q_keep = Q, H_keep = H, mass_keep = mass_old, older_keep = mass_older,
                              heights_keep = last_heights;
    const double dt_keep = last_dt;
    const double H0_keep = H0;
    const ContactInstant instant_keep = last_instant;
    auto restore = [&] {
      Q = Q_keep, H = H_keep, mass_old = mass_keep, mass_older = older_keep, H0 = H0_keep, last_dt = dt_keep;
      last_heights = heights_keep;
      last_instant = instant_keep;
    };
    try {
      solve(c, heights, dt);
    } catch (const std::runtime_error&) {
      restore();
      // First the same step with the Couette term to first order everywhere (monotone: no
      // negative films at a contact's edge), then two half steps.
      if (!first_order) {
        first_order = true;
        try {
          solve(c, heights, dt);
          first_order = false;
          return;
        } catch (const std::runtime_error&) {
          first_order = false;
          restore();
        }
      }
      if (depth >= kMaxStepHalvings) throw;
      const ContactInstant mid{0.5 * (instant_keep.line_load + c.line_load), 0.5 * (instant_keep.radius + c.radius),
                               0.5 * (instant_keep.speed1 + c.speed1), 0.5 * (instant_keep.speed2 + c.speed2)};
      std::vector<double> mid_heights(heights.size());
      for (std::size_t i = 0; i < heights.size(); ++i) mid_heights[i] = 0.5 * (heights_keep[i] + heights[i]);
      advance(mid, mid_heights, 0.5 * dt, depth + 1);
      advance(c, heights, 0.5 * dt, depth + 1);
    }
  }

  void fill(const ContactInstant& c, int iterations, double update, double load_error) {
    EhlField& f = field;
    f.pressure.resize(static_cast<std::size_t>(n));
    f.film.resize(static_cast<std::size_t>(n));
    f.flattening.resize(static_cast<std::size_t>(n));
    f.yields.resize(static_cast<std::size_t>(n));
    f.shear.resize(static_cast<std::size_t>(n));
    f.state.resize(static_cast<std::size_t>(n));
    const double slide = std::abs(c.speed1 - c.speed2);
    const double bc = std::sqrt(c.line_load * c.radius / (w_ref * reference.radius)) * b;  // this instant's b
    double load = 0.0, contact_load = 0.0, film_friction = 0.0, boundary_friction = 0.0, peak = 0.0;
    double min_film = std::numeric_limits<double>::infinity();
    int in_band = 0, in_contact = 0, yielding = 0;
    for (int i = 0; i < n; ++i) {
      const auto s = static_cast<std::size_t>(i);
      const double p = std::max(P[s], 0.0) * ph, h = H[s] * film_scale, x = grid.x(i);
      f.pressure[s] = p;
      f.film[s] = h;
      f.flattening[s] = U[s] * film_scale;
      f.yields[s] = static_cast<char>(plastic_on && Q[s] > yield_level());  // past the yield's corner
      // The domain's two end nodes hold the pressure at zero: their film is the gap (the flanks'
      // heights may overlap there), neither a contact nor a film that shears.
      const bool end = i == 0 || i + 1 == n;
      const bool contact = h < options.film_floor && !end;
      f.state[s] = contact ? NodeState::contact : (P[s] > 0.0 ? NodeState::fluid : NodeState::cavitated);
      double tau = 0.0;
      if (contact) {  // the contacts' pressure and the film's between them: boundary friction
        tau = options.boundary_friction * p;
        boundary_friction += tau * grid.spacing;
        contact_load += p * grid.spacing;
      } else if (!end) {
        const double eta = fluid.viscosity_at(p);
        const double rate = eta * slide / h;  // Newtonian Couette shear stress [Pa]
        tau = fluid.flow == FlowModel::eyring ? fluid.eyring_stress * std::asinh(rate / fluid.eyring_stress) : rate;
        if (p > 0.0) tau = std::min(tau, fluid.limiting_shear_coefficient * p);
        film_friction += tau * grid.spacing;
        min_film = std::min(min_film, h);
      }
      f.shear[s] = tau;
      load += p * grid.spacing;
      peak = std::max(peak, p);
      if (std::abs(x) <= bc) {
        ++in_band;
        if (contact) ++in_contact;
        if (f.yields[s]) ++yielding;
      }
    }
    // Central film: linear interpolation at x = 0.
    const double t = -grid.start / grid.spacing - 0.5;
    const int i0 = std::clamp(static_cast<int>(std::floor(t)), 0, n - 2);
    const double frac = t - i0;
    f.central_film =
        (1.0 - frac) * f.film[static_cast<std::size_t>(i0)] + frac * f.film[static_cast<std::size_t>(i0 + 1)];
    f.line_load = load;
    f.contact_load = contact_load;
    f.min_film = std::isfinite(min_film) ? min_film : 0.0;
    f.contact_fraction = in_band > 0 ? static_cast<double>(in_contact) / in_band : 0.0;
    f.yield_fraction = in_band > 0 ? static_cast<double>(yielding) / in_band : 0.0;
    f.asperity_share = load > 0.0 ? contact_load / load : 0.0;
    f.peak_pressure = peak;
    f.film_friction = film_friction;
    f.boundary_friction = boundary_friction;
    f.friction_coefficient = load > 0.0 ? (film_friction + boundary_friction) / load : 0.0;
    f.iterations = iterations;
    f.update = update;
    f.load_error = load_error;
  }
};

LineEhlSolver::LineEhlSolver(const Fluid& fluid, double composite_modulus, const ContactInstant& reference,
                             const EhlOptions& options)
    : impl_(std::make_unique<Impl>()) {
  fluid.validate();
  options.validate();
  if (!(composite_modulus > 0.0)) throw std::invalid_argument("mixed EHL: the modulus must be positive");
  if (!(reference.line_load > 0.0) || !(reference.radius > 0.0) || !(reference.entrainment() > 0.0))
    throw std::invalid_argument("mixed EHL: the reference instant needs a positive load, radius and entrainment");
  Impl& s = *impl_;
  s.fluid = fluid;
  s.modulus = composite_modulus;
  s.options = options;
  s.reference = reference;
  s.w_ref = reference.line_load;
  // Hertz (Johnson 4.43): b^2 = 4 w R/(pi E*), p_H = 2 w/(pi b) = E* b/(2 R).
  s.b = std::sqrt(4.0 * reference.line_load * reference.radius / (kPi * composite_modulus));
  s.ph = 2.0 * reference.line_load / (kPi * s.b);
  s.film_scale = s.b * s.b / reference.radius;
  s.plastic_on = std::isfinite(options.hardness);
  s.build_grid();
}
LineEhlSolver::~LineEhlSolver() = default;
LineEhlSolver::LineEhlSolver(LineEhlSolver&&) noexcept = default;
LineEhlSolver& LineEhlSolver::operator=(LineEhlSolver&&) noexcept = default;

const HalfPlaneGrid& LineEhlSolver::grid() const { return impl_->grid; }
double LineEhlSolver::hertz_half_width() const { return impl_->b; }
double LineEhlSolver::hertz_pressure() const { return impl_->ph; }
const EhlField& LineEhlSolver::field() const { return impl_->field; }

namespace {
// A steady solve, with the roughness's homotopy when the direct solve fails (below).
void steady_solve(LineEhlSolver::Impl& s, const ContactInstant& instant, std::span<const double> heights);

// A solve's cost: the FFTs this thread executed during it, their time and its wall time.
class SolveMeter {
 public:
  void fill(EhlField& f, int iterations, int linear) const {
    f.transforms = ToeplitzConvolution::transforms() - transforms_;
    f.transform_seconds = ToeplitzConvolution::transform_seconds() - transform_seconds_;
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    f.iterations = iterations;
    f.linear_iterations = linear;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  long transforms_ = ToeplitzConvolution::transforms();
  double transform_seconds_ = ToeplitzConvolution::transform_seconds();
};
}  // namespace

const EhlField& LineEhlSolver::solve_steady(const ContactInstant& instant, std::span<const double> heights) {
  Impl& s = *impl_;
  const SolveMeter meter;
  s.newton_total = s.linear_total = 0;
  steady_solve(s, instant, heights);
  meter.fill(s.field, s.newton_total, s.linear_total);
  return s.field;
}

const EhlField& LineEhlSolver::step(const ContactInstant& instant, std::span<const double> heights, double dt) {
  if (!(dt > 0.0)) throw std::invalid_argument("mixed EHL: the time step must be positive");
  if (!impl_->started) throw std::logic_error("mixed EHL: a time step needs a solution to start from");
  Impl& s = *impl_;
  const SolveMeter meter;
  s.newton_total = s.linear_total = 0;
  s.advance(instant, std::vector<double>(heights.begin(), heights.end()), dt, 0);
  meter.fill(s.field, s.newton_total, s.linear_total);
  return s.field;
}

namespace {
void steady_solve(LineEhlSolver::Impl& s, const ContactInstant& instant, std::span<const double> heights) {
  const std::vector<double> Q_keep = s.Q, H_keep = s.H;
  // (Read after the first solve throws: a path clang's analyzer does not follow.)
  const double H0_keep = s.H0;  // NOLINT(clang-analyzer-deadcode.DeadStores)
  try {
    s.solve(instant, heights, 0.0);
    return;
  } catch (const std::runtime_error&) {
  }
  // Again with the Couette term to first order everywhere, then by homotopy in the roughness.
  s.Q = Q_keep, s.H = H_keep, s.H0 = H0_keep;
  s.first_order = true;
  struct Reset {
    LineEhlSolver::Impl& s;
    ~Reset() { s.first_order = false; }
  } reset{s};
  try {
    s.solve(instant, heights, 0.0);
    return;
  } catch (const std::runtime_error&) {
    // Homotopy in the roughness: from the smooth contact (Hertz's start) the heights scaled by
    // lambda = 0 .. 1, each solve started from the last; a stage that fails is bisected.
    s.started = false;
    std::vector<double> scaled(heights.size());
    auto at = [&](double lambda) {
      for (std::size_t i = 0; i < heights.size(); ++i) scaled[i] = lambda * heights[i];
      s.solve(instant, scaled, 0.0);
    };
    at(0.0);
    double done = 0.0, stride = 0.25;
    while (done < 1.0) {
      const double next = std::min(1.0, done + stride);
      const std::vector<double> Q_stage = s.Q, H_stage = s.H;
      const double H0_stage = s.H0;
      try {
        at(next);
        done = next;
      } catch (const std::runtime_error&) {
        if (stride < kMinHomotopyStride) throw;
        s.Q = Q_stage, s.H = H_stage, s.H0 = H0_stage;
        stride *= 0.5;
      }
    }
  }
}
}  // namespace

std::vector<double> flash_temperature(const HalfPlaneGrid& grid, std::span<const double> heat_flux, double speed1,
                                      double speed2, double contact_coefficient1, double contact_coefficient2) {
  const std::size_t n = heat_flux.size();
  if (static_cast<int>(n) != grid.size) throw std::invalid_argument("flash_temperature: one heat flux per element");
  const double denominator = std::sqrt(kPi) * (contact_coefficient1 * std::sqrt(std::max(speed1, 0.0)) +
                                               contact_coefficient2 * std::sqrt(std::max(speed2, 0.0)));
  std::vector<double> theta(n, 0.0);
  if (!(denominator > 0.0) || n == 0) return theta;
  // theta(x_i) = sum_{j <= i} q_j int_{e_j}^{min(e_{j+1}, x_i)} (x_i - s)^(-1/2) ds / denominator: a
  // causal Toeplitz convolution, k(m) = 2 sqrt(dx) (sqrt(m + 1/2) - sqrt(max(m - 1/2, 0))) for
  // m = i - j >= 0 (the element's integral exact), 0 for m < 0; by DC-FFT.
  const int size = static_cast<int>(n);
  std::vector<double> kernel(2 * n - 1, 0.0);
  const double root = 2.0 * std::sqrt(grid.spacing);
  for (int m = 0; m < size; ++m)
    kernel[static_cast<std::size_t>(m + size - 1)] = root * (std::sqrt(m + 0.5) - std::sqrt(std::max(m - 0.5, 0.0)));
  const ToeplitzConvolution convolution(kernel, size, false);
  convolution.apply(heat_flux.data(), theta.data());
  for (double& t : theta) t /= denominator;
  return theta;
}

PlaneStrainStress uniform_strip_shear_stress(double x, double z, double half_width, double traction) {
  // Johnson's tangential line load Q at s (eq. 2.19), xi = x - s, r^2 = xi^2 + z^2:
  // sigma_x = -(2Q/pi) xi^3/r^4, sigma_z = -(2Q/pi) xi z^2/r^4, tau_xz = -(2Q/pi) xi^2 z/r^4,
  // integrated over s in [-a, a] (xi from x - a to x + a) with the antiderivatives
  // int xi^3/r^4 = ln(r^2)/2 + z^2/(2 r^2), int xi/r^4 = -1/(2 r^2), int xi^2/r^4 = atan(xi/z)/(2z) - xi/(2 r^2).
  auto f = [z](double xi) {
    const double r2 = xi * xi + z * z;
    return std::array<double, 3>{0.5 * std::log(r2) + 0.5 * z * z / r2, -0.5 / r2,
                                 0.5 * std::atan2(xi, z) / z - 0.5 * xi / r2};
  };
  const auto hi = f(x + half_width), lo = f(x - half_width);
  const double c = -2.0 * traction / kPi;
  PlaneStrainStress s;
  s.xx = c * (hi[0] - lo[0]);
  s.zz = c * z * z * (hi[1] - lo[1]);
  s.xz = c * z * (hi[2] - lo[2]);
  return s;
}

StressMaximum subsurface_maximum(const HalfPlaneGrid& grid, std::span<const double> pressure,
                                 std::span<const double> traction, double poisson_ratio, double max_depth, int depths) {
  if (static_cast<int>(pressure.size()) != grid.size || static_cast<int>(traction.size()) != grid.size)
    throw std::invalid_argument("subsurface_maximum: one pressure and traction per element");
  if (depths < 1 || !(max_depth > 0.0)) throw std::invalid_argument("subsurface_maximum: positive depths and depth");
  StressMaximum best;
  const double a = 0.5 * grid.spacing;
  // Only where the surface is loaded (the columns and the loads alike).
  int first = grid.size, last = -1;
  bool sheared = false;
  for (int j = 0; j < grid.size; ++j)
    if (pressure[static_cast<std::size_t>(j)] != 0.0 || traction[static_cast<std::size_t>(j)] != 0.0) {
      first = std::min(first, j);
      last = std::max(last, j);
      sheared = sheared || traction[static_cast<std::size_t>(j)] != 0.0;
    }
  if (last < 0) return best;
  const int m = last - first + 1;
  const auto size = static_cast<std::size_t>(m);
  const double* p = pressure.data() + first;
  const double* q = traction.data() + first;
  // Per depth: the unit strip's stresses at every offset (i - j) dx, then sigma_c(x_i) = sum_j
  // (K_c^p(i - j) p_j + K_c^q(i - j) q_j) for c = xx, zz, xz, by DC-FFT.
  std::vector<std::array<std::vector<double>, 3>> kernels(sheared ? 2 : 1);
  for (auto& k : kernels)
    for (auto& c : k) c.assign(2 * size - 1, 0.0);
  std::array<std::vector<double>, 3> sum, part;
  for (auto& c : sum) c.assign(size, 0.0);
  for (auto& c : part) c.assign(size, 0.0);
  for (int d = 1; d <= depths; ++d) {
    const double z = max_depth * d / depths;
    for (int k = -(m - 1); k <= m - 1; ++k) {
      const auto at = static_cast<std::size_t>(k + m - 1);
      const PlaneStrainStress e = uniform_strip_stress(k * grid.spacing, z, a, 1.0, poisson_ratio);
      kernels[0][0][at] = e.xx, kernels[0][1][at] = e.zz, kernels[0][2][at] = e.xz;
      if (sheared) {
        const PlaneStrainStress t = uniform_strip_shear_stress(k * grid.spacing, z, a, 1.0);
        kernels[1][0][at] = t.xx, kernels[1][1][at] = t.zz, kernels[1][2][at] = t.xz;
      }
    }
    for (std::size_t c = 0; c < 3; ++c) {
      ToeplitzConvolution(kernels[0][c], m, false).apply(p, sum[c].data());
      if (sheared) {
        ToeplitzConvolution(kernels[1][c], m, false).apply(q, part[c].data());
        for (std::size_t i = 0; i < size; ++i) sum[c][i] += part[c][i];
      }
    }
    for (std::size_t i = 0; i < size; ++i) {
      PlaneStrainStress s;
      s.xx = sum[0][i], s.zz = sum[1][i], s.xz = sum[2][i];
      s.yy = poisson_ratio * (s.xx + s.zz);
      const double vm = s.von_mises();
      if (vm > best.von_mises) best = {vm, z, grid.x(first + static_cast<int>(i))};
    }
  }
  return best;
}

}  // namespace geartrib::contact::mixed_ehl
