// Mixed elastohydrodynamic lubrication of a rough line contact (plane strain, isothermal):
// the Reynolds equation for two surfaces moving at their own speeds, with its wedge and squeeze
// terms, coupled to the elastic deformation of the half-plane and to asperity contact where the
// film vanishes, under load control at every instant. It knows nothing of gears: the mesh cycle's
// fidelity (contact/mixed_ehl/mesh_mixed_ehl.hpp) gives it each instant's load, curvature, speeds
// and the two surfaces' heights at its nodes.
//
// Frame: x along the common tangent in the direction the surfaces roll (u1, u2 >= 0, the
// entrainment u = (u1 + u2)/2 > 0), the inlet at x < 0; the film
//   h(x, t) = h0(t) + x^2/(2 R) + v(x) - r(x, t),
// v the elastic displacement of both bodies (the plane-strain half-plane under the pressure,
// constant-pressure elements with exact influence coefficients, convolved by DC-FFT, Liu, Wang &
// Liu 2000), r the two surfaces' heights towards each other at x at time t.
//
// Equations (Hertzian units: X = x/b, P = p/p_H, H = h R/b^2, T = t u_ref/b):
//   d/dX(eps dP/dX) - (u/u_ref) d(rho H)/dX - d(rho H)/dT = 0,   eps = rho H^3 phi/(eta lambda),
//   lambda = 12 eta_0 u_ref R^2/(b^3 p_H);
// finite volumes, the Poiseuille flux centred (the coefficient at a face the mean mobility
// rho/(eta lambda) times the conductance 2 h_i^2 h_j^2/(h_i + h_j) of a film varying linearly
// between the nodes), the Couette flux upwinded to second order and the squeeze term by the
// variable-step BDF2 (Venner & Lubrecht, Multilevel Methods in Lubrication, 2000), both first
// order (upwind, backward Euler: monotone) within 20 film floors of contact. The elastic film is written in
// differential form (Evans & Hughes, Proc. IMechE C 214, 2000; Holmes, Evans & Snidle, J. Tribol. 125, 2003):
//   (H_{i+1} - 2 H_i + H_{i-1})/dX^2 = R_ref/R + sum_j D_ij P_j - d2r_i,
// D the second difference of the displacement's influence coefficients, which fall as 1/k^2.
// Newton's method on (Q_i, H_i) and h0 (Q the pressure's parameter, P without a hardness) with the exact Jacobian,
// solved by GMRES preconditioned with its block-tridiagonal part (D's three central diagonals) bordered by the load
// row; the rest of D applied by FFT; the film at the two ends from the integral form (docs/theory/mixed-ehl.md).
//
// Cavitation: Reynolds' condition (p = 0 and dp/dx = 0 at the film's rupture) by the penalty
// method (Wu, Quart. Appl. Math. 44, 1986): where p < 0 the residual gains -kappa p, kappa large,
// so the cavitated zone's pressure is ~0 and the rupture moves freely with each Newton step.
// Newton steps are limited to 1 p_H per node (the exponential viscosity) and to halving an open
// film or doubling one near contact.
// Asperity contact by the unified approach (Hu & Zhu, J. Tribol. 122, 2000, 1-9; for spur gears Li
// & Kahraman, J. Tribol. 132, 2010, 011501): one pressure and one Reynolds equation everywhere.
// Where the film thins to nanometres its Poiseuille term vanishes (h^3, and the viscosity's rise),
// the equation reduces to d(rho h)/dx + d(rho h)/dt = 0, which carries the film's thickness
// through the contact spot, while the pressure there is what the elastic film equation needs:
// the dry contact's. A node whose film is below film_floor counts as in asperity contact; the load
// those nodes carry is the asperity share. The Poiseuille coefficient is floored at
// u dX h_floor (Hertzian units) so that a pressure stays defined where the film vanishes, a flux
// ~dX/1000 of the Couette flux through a film at the floor.
// Surfaces elastic-perfectly-plastic when a hardness is given (EhlOptions::hardness; the mesh
// fidelity gives the softer flank's, as the dry boundary elements cap their pressure at it): the
// pressure is held at the hardness where the surfaces yield, and their plastic flattening opens
// the film like the elastic displacement (Almqvist et al., Wear 262, 2007); the corner of that
// pressure-flattening graph is rounded over 0.1 % of the hardness (line_ehl.cpp).
// Lubricant: viscosity by Roelands (1966) (p0 = 1.96e8 Pa, Z = alpha p0/(ln eta_0 + 9.67)) or
// Barus, density by Dowson & Higginson (1966): rho/rho_0 = 1 + 0.6e-9 p/(1 + 1.7e-9 p) [p in Pa];
// the flow Newtonian, or Ree-Eyring with the Poiseuille flow factor
// phi = cosh(tau_m/tau_0) = sqrt(1 + (eta |u1 - u2|/(tau_0 h))^2) of the mid-film shear stress
// (Conry, Wang & Cusano, J. Tribol. 109, 1987, 648-658).
#pragma once

#include "contact/half_plane_bem.hpp"
#include "core/named_choices.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace geartrib::lubrication {
struct OilState;
}

namespace geartrib::contact::mixed_ehl {

enum class ViscosityLaw { roelands, barus };
std::span<const NamedChoice<ViscosityLaw>> viscosity_law_choices();
enum class FlowModel { newtonian, eyring };
std::span<const NamedChoice<FlowModel>> flow_model_choices();

inline constexpr double kRoelandsPressure = 1.96e8;    // p0 [Pa]
inline constexpr double kRoelandsViscosity = 6.31e-5;  // eta_inf [Pa s] (ln eta_inf = -9.67)

// The oil in the contact at its inlet temperature.
// ln(eta/eta_0) at a pressure and its slope d ln(eta)/dp [1/Pa] (0 where the exponent is capped).
struct ViscosityExponent {
  double value = 0.0, slope = 0.0;
};

struct Fluid {
  double viscosity = 0.0;           // eta_0 [Pa s]
  double pressure_viscosity = 0.0;  // alpha [1/Pa]
  ViscosityLaw viscosity_law = ViscosityLaw::roelands;
  bool compressible = true;  // Dowson-Higginson density; false: constant density
  FlowModel flow = FlowModel::newtonian;
  double eyring_stress = 5e6;                            // tau_0 [Pa] (Ree-Eyring flow and the film's shear)
  double limiting_shear_coefficient = 0.075;             // the film's shear stress at most Lambda p [-]
  void set_oil_state(const lubrication::OilState& oil);  // eta_0, alpha, tau_0 and Lambda of an oil at its temperature
  double viscosity_at(double p) const;                   // eta(p) [Pa s]
  ViscosityExponent viscosity_exponent(double p) const;  // ln(eta(p)/eta_0) and its slope
  double density_ratio(double p) const;                  // rho(p)/rho_0
  void validate() const;                                 // throws core::KeyedError naming the field
};

// The contact at one instant.
struct ContactInstant {
  double line_load = 0.0;  // w [N/m]
  double radius = 0.0;     // reduced radius of curvature R [m]
  double speed1 = 0.0;     // surface speeds in +x [m/s], >= 0 with u1 + u2 > 0
  double speed2 = 0.0;
  double entrainment() const { return 0.5 * (speed1 + speed2); }
};

struct EhlOptions {
  // The domain [x_start, x_end] in Hertz half-widths of the reference instant (the solver's
  // constructor's), its nodes equally spaced.
  double inlet = 4.0;   // x_start = -inlet b_ref
  double outlet = 1.5;  // x_end = outlet b_ref
  int nodes = 1024;
  double tolerance = 1e-7;  // converged: the largest Newton update below tolerance p_H_ref, the load within tolerance
  int max_iterations = 500;
  double film_floor = 2e-9;  // h below which a node is in asperity contact [m]
  double hardness =
      std::numeric_limits<double>::infinity();  // the softer surface's [Pa]: the pressure held at it; infinite: elastic
  double boundary_friction = 0.1;               // friction coefficient in the asperity contacts [-]
  void validate() const;                        // throws core::KeyedError naming the field
};

enum class NodeState : std::uint8_t { fluid, cavitated, contact };

// One instant's answer on the nodes, per unit face width.
struct EhlField {
  std::vector<double> pressure;    // p [Pa]
  std::vector<double> film;        // h [m]
  std::vector<double> flattening;  // the surfaces' plastic flattening (EhlOptions::hardness) [m]
  std::vector<char> yields;        // 1 where the surfaces yield: the pressure held at the hardness
  std::vector<double> shear;       // the surface shear stress the lower speed's surface feels, in +x for u1 > u2 [Pa]
  std::vector<NodeState> state;
  double line_load = 0.0;             // integral of p [N/m]
  double contact_load = 0.0;          // carried by the contact nodes [N/m]
  double central_film = 0.0;          // at x = 0 [m]
  double min_film = 0.0;              // the least over the fluid nodes [m]
  double contact_fraction = 0.0;      // contact nodes over the nodes within |x| <= b [-]
  double asperity_share = 0.0;        // contact_load / line_load [-]
  double peak_pressure = 0.0;         // [Pa]
  double yield_fraction = 0.0;        // nodes within |x| <= b where the surfaces yield (at the hardness) [-]
  double film_friction = 0.0;         // integral of the film's shear [N/m]
  double boundary_friction = 0.0;     // integral of boundary_friction p over the contacts [N/m]
  double friction_coefficient = 0.0;  // (film + boundary friction)/line load [-]
  int iterations = 0;                 // Newton iterations (a retried time step: all its substeps')
  int linear_iterations = 0;          // GMRES iterations over them
  double update = 0.0;                // the last Newton update (largest, over p_H_ref)
  double load_error = 0.0;            // relative
  // Cost of the solve (a time step with its retries): FFTs executed (r2c or c2r of the
  // convolution's length), their time and the wall time [s].
  long transforms = 0;
  double transform_seconds = 0.0, seconds = 0.0;
};

class LineEhlSolver {
 public:
  // composite_modulus: E* with 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Johnson's; the EHL E' is
  // 2 E*); reference: the instant that fixes the Hertzian units and the domain.
  LineEhlSolver(const Fluid& fluid, double composite_modulus, const ContactInstant& reference,
                const EhlOptions& options);
  ~LineEhlSolver();
  LineEhlSolver(LineEhlSolver&&) noexcept;
  LineEhlSolver& operator=(LineEhlSolver&&) noexcept;

  const HalfPlaneGrid& grid() const;  // the nodes: grid().x(i) [m]
  double hertz_half_width() const;    // b of the reference [m]
  double hertz_pressure() const;      // p_H of the reference [Pa]

  // The steady solution at `instant` with the surfaces' heights r (per node [m], towards each
  // other: a positive r closes the gap), started from the last solution (or from Hertz). Throws
  // std::runtime_error if it does not converge.
  const EhlField& solve_steady(const ContactInstant& instant, std::span<const double> heights);
  // One time step of `dt` [s] from the last solution to `instant` with the heights at the new
  // time (the squeeze term from the change of the film). Throws std::runtime_error if it does not
  // converge.
  const EhlField& step(const ContactInstant& instant, std::span<const double> heights, double dt);
  const EhlField& field() const;

  struct Impl;  // (public for the solve's helpers in line_ehl.cpp)

 private:
  std::unique_ptr<Impl> impl_;
};

// The surface temperature rise under a heat flux q(x) moving past both surfaces at high Peclet
// number, the flux split so that both surfaces have the same temperature at every x (Jaeger's
// moving band source): theta(x) = int_{-inf}^{x} q(s) / sqrt(x - s) ds / (sqrt(pi) (B1 sqrt(u1) + B2 sqrt(u2))),
// q piecewise constant on the grid's elements (integrated exactly), B = sqrt(k rho c) [K].
std::vector<double> flash_temperature(const HalfPlaneGrid& grid, std::span<const double> heat_flux, double speed1,
                                      double speed2, double contact_coefficient1, double contact_coefficient2);

// Plane-strain stresses under a uniform tangential traction q over |x| < half_width (in +x on the
// body's surface), by integrating Johnson's tangential line load (Contact Mechanics eq. 2.19):
// compression negative.
PlaneStrainStress uniform_strip_shear_stress(double x, double z, double half_width, double traction);
// The von Mises maximum below the grid under pressure and traction (constant on each node's
// element): over `depths` depths evenly in (0, max_depth] and every node's x from the first loaded
// node to the last, each depth's stresses at all of them one Toeplitz convolution of the loads
// with the strips' stresses (DC-FFT).
struct StressMaximum {
  double von_mises = 0.0;  // [Pa]
  double depth = 0.0;      // [m]
  double x = 0.0;          // [m]
};
StressMaximum subsurface_maximum(const HalfPlaneGrid& grid, std::span<const double> pressure,
                                 std::span<const double> traction, double poisson_ratio, double max_depth, int depths);

}  // namespace geartrib::contact::mixed_ehl
