// The mesh cycle's first stage: the kinematics and loading of one tooth pair along its path
// A -> E, ISO/TS 6336-22's named points, and (when asked for) the steady dynamic load, as typed
// state every later stage reads.
#pragma once

#include "core/ode_integrator.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::contact {

// One position's loading and kinematics.
struct PathPoint {
  double s = 0.0, line_load = 0.0, half_width = 0.0, hertz_p0 = 0.0, radius = 0.0, v1 = 0.0, v2 = 0.0;
  double load_sharing_factor = 0.0;  // the pair's share of the normal load (ISO X_Gamma for ISO sharing)
};

// The path's loading and kinematics, one value per position (SI; the run's /mesh series), and
// ISO/TS 6336-22's named points A, AB, B, C, D, DE, E computed at their exact places (B and D on
// the single-pair side of the load's jump).
struct PathState {
  gear::PathOfContact path;
  std::vector<double> s;                     // from T1 [m]
  std::vector<double> roll_angle;            // the pinion's [rad]
  std::vector<double> gamma;                 // roll parameter
  std::vector<double> rho1, rho2, radius;    // the flanks' and the equivalent radius of curvature [m]
  std::vector<double> share;                 // the pair's share of the normal load
  std::vector<double> line_load;             // [N/m]: the static share's, or the dynamic force's
  std::vector<double> hertz_p0, half_width;  // [Pa], [m]
  std::vector<double> v1, v2, entrainment, sliding, slide_to_roll;  // [m/s], [m/s], [m/s], [m/s], 1
  std::vector<double> stiffness;  // the mesh's [N/m] (under compatibility its tangent); empty when not computed
  std::vector<double> transmission_error;  // the static transmission error [m]; compatibility sharing only
  std::vector<double> dynamic_factor;      // dynamic over static line load; empty without dynamics
  std::vector<std::pair<std::string, PathPoint>> named;  // empty unless asked for
  std::size_t size() const { return s.size(); }
  PathPoint point(std::size_t i) const {
    return {s[i], line_load[i], half_width[i], hertz_p0[i], radius[i], v1[i], v2[i], share[i]};
  }
};

struct PathOptions {
  int positions = 201;        // evenly spaced A -> E
  bool stiffness = false;     // the tooth-pair stiffness (also computed when the load sharing uses it)
  bool named_points = false;  // ISO/TS 6336-22's points (the lubricated summary's)
};

// The quasi-static path: kinematics, the load share, the Hertz strip.
PathState path_state(const gear::GearMesh& mesh, const PathOptions& o);

// The steady mesh cycle at the operating speed (integrated by `integrator`): each pair's dynamic
// load replaces its share at every position and named point; the dynamic factor is kept.
void apply_dynamics(PathState& p, const gear::GearMesh& mesh, const gear::DynamicsSettings& settings,
                    const OdeIntegrator& integrator);

}  // namespace geartrib::contact
