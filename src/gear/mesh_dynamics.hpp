// Single-degree-of-freedom torsional mesh dynamics along the line of action:
//   m_e x'' + c x' + k(t) g(x) = F,   x = r_b1 theta1 - r_b2 theta2 (mesh deflection),
// m_e = I1 I2/(I1 r_b2^2 + I2 r_b1^2), k(t) the time-varying mesh stiffness of the
// potential-energy model, c = 2 zeta sqrt(k_mean m_e), F = T1/r_b1, and g(x) = x in contact,
// 0 when the teeth separate (x <= 0), x + backlash on the back flanks (x <= -backlash). Under the
// compatibility sharing each pair is its own contact with its separation e_j (profile
// modifications, gear/tooth_contact.hpp): k(t) g(x) becomes sum_j k_j(t) (x - e_j(t))+ (Velex &
// Maatar 1996), so a relief's pair enters and leaves gradually. The stiffness jumps at B and D
// (pairs entering/leaving) are integration boundaries, not smoothed.
// Integrated cycle after cycle to a periodic steady state through an OdeIntegrator.
#pragma once

#include "core/named_choices.hpp"
#include "core/ode_integrator.hpp"
#include "gear/gear_mesh.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>

#include <span>
#include <utility>
#include <vector>

namespace geartrib::gear {

// What integrates the mesh dynamics (solvers::make_integrator builds it): none (static load
// sharing, no dynamics), SUNDIALS CVODE (BDF) or Boost.Odeint (Dormand-Prince 5(4)).
enum class DynamicsEngine { none, cvode, odeint };
std::span<const NamedChoice<DynamicsEngine>> dynamics_engine_choices();  // mesh.dynamics
const char* dynamics_engine_name(DynamicsEngine engine);

// The mesh dynamics: the engine and the model's data.
struct DynamicsSettings {
  DynamicsEngine engine = DynamicsEngine::none;  // what a mesh cycle runs the dynamics with
  double damping_ratio = 0.07;  // zeta: typical of spur meshes (0.03-0.17 reported; Kasuba & Evans 1981)
  double backlash = 0.0;        // along the line of action [m]; 0: no back-flank contact
  double pinion_inertia = 0.0;  // [kg m^2]; 0: a solid disc of the pitch radius, face width and density, less the bore
  double wheel_inertia = 0.0;
  double density = 7850.0;              // [kg/m^3] for the solid discs
  OdeTolerances tolerances{1e-8, 0.0};  // absolute 0: set from the static deflection
  double steady_tolerance = 0.0;        // cycle-to-cycle change relative to the static deflection; 0: 100 x rtol
  int max_cycles = 3000;
  int samples_per_cycle = 256;
  void validate() const;  // throws core::KeyedError naming the field
};

struct SteadyCycle {
  double pinion_speed = 0.0;              // [rad/s]
  double mesh_frequency = 0.0;            // [Hz]
  double period = 0.0;                    // one base pitch [s]
  std::vector<double> time;               // over one period [s]
  std::vector<double> position;           // s of the pair that entered at A at time 0 [m], in [A, A + p_b)
  std::vector<double> stiffness;          // mesh stiffness [N/m]
  std::vector<double> deflection;         // x [m]
  std::vector<double> static_deflection;  // the static transmission error: F/k, or under compatibility its solve [m]
  std::vector<double> force;              // dynamic mesh force k g(x) + c x' (0 when separated) [N]
  double static_force = 0.0;              // F [N]
  double dynamic_factor = 0.0;            // max force / F
  // max force over the low-speed limit of the same model's peak (quasi_static_peak): tends to 1 at
  // low speed, while dynamic_factor tends to the engagement impact of the stiffness steps.
  double dynamic_factor_quasi_static = 0.0;
  bool contact_lost = false;
  bool periodic = true;      // false: no periodic state within max_cycles (the last cycles are reported)
  double last_change = 0.0;  // cycle-to-cycle change at the end, relative to the static deflection
  int cycles = 0;            // cycles integrated to reach the steady state
  long steps = 0;            // integrator steps
};

class MeshDynamics {
 public:
  MeshDynamics(const GearMesh& mesh, const DynamicsSettings& settings);

  double equivalent_mass() const { return mass_; }
  double mean_stiffness() const { return mean_stiffness_; }
  double damping() const { return damping_; }
  // Natural frequency sqrt(k_mean/m_e)/(2 pi) [Hz]; resonance when the mesh frequency meets it.
  double natural_frequency() const;
  // Peak mesh force of this model in the limit of vanishing speed [N]: with perfect involutes the
  // stiffness steps make engagement impulsive. At D (a pair enters, k rises from k1 to k2) the
  // force jumps to F k2/k1; at B (k falls) the deflection overshoots, peak
  // F (1 + (1 - k1/k2) exp(-zeta pi/sqrt(1 - zeta^2))); the transients decay between the steps.
  // Per pair (compatibility): the entering pair adds k_A (x0 - e_A)+ to F, x0 the static deflection
  // just before; the leaving pair's static load F_E returns as F + F_E exp(...) at B. A relief
  // that takes up the deflection leaves F: no impulse.
  double quasi_static_peak() const;
  // Mesh stiffness at offset u in [0, p_b) of the cycle (pair positions A + u and A + u + p_b).
  double stiffness(double u) const;
  // The elastic mesh force at deflection x and offset u [N]: k(u) g(x), or per pair.
  double elastic_force(double x, double u) const;
  // The static transmission error at offset u [m] (the dynamics' linear pair stiffnesses).
  double static_deflection(double u) const;

  // The pinion speeds [rad/s] where the model is integrated: mesh frequency from 1e-5 to 1e3 times
  // the natural frequency. Below, the cycle is quasi-static (the dynamic factor is the
  // quasi-static one to within the transients, and the integration time grows as f_n/f_mesh:
  // hours for an explicit integrator); above, the steady state takes ~f_mesh/(zeta f_n) cycles.
  // steady_cycle refuses speeds outside (std::invalid_argument).
  std::pair<double, double> speed_range() const;
  // The periodic steady state at a pinion speed [rad/s]. When none is reached within max_cycles
  // (contact loss near resonance can make the motion aperiodic), `periodic` is false and the
  // dynamic factor is the largest over the last 100 cycles.
  SteadyCycle steady_cycle(const OdeIntegrator& integrator, double pinion_speed) const;
  // The dynamic load of the pair at path position s (A <= s <= E) in a steady cycle: its share
  // k_pair(s)/k of the mesh force [N].
  double pair_force(const SteadyCycle& cycle, double s) const;

 private:
  const GearMesh& mesh_;
  DynamicsSettings settings_;
  double mass_ = 0.0, mean_stiffness_ = 0.0, damping_ = 0.0;
  double split_ = 0.0;  // u where the second pair leaves (B - A)
  std::vector<boost::math::interpolators::cardinal_cubic_b_spline<double>> segments_;
  std::vector<double> segment_start_, segment_end_;
  // Per-pair contact (compatibility sharing): each pair's linear stiffness and separation.
  const LoadedToothContact* contact_ = nullptr;
  double backlash_ = 0.0;
  // The pairs at offset u: positions A + u + j p_b within [A, E], j = 0 the last to enter.
  std::vector<double> positions(double u) const;
  // The static solve with the dynamics' linear pairs at `positions` (a subset from `first`).
  CompatibilitySolution linear_solve(const std::vector<double>& positions, std::size_t first) const;
};

}  // namespace geartrib::gear
