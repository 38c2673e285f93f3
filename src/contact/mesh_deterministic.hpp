// The deterministic fidelity of the main job (contact.fidelity = "deterministic"): the flanks'
// profiles rolled through the strip at every position of the path (deterministic_contact.hpp),
// the statistical model on the same flanks beside it, and running-in over successive meshes.
#pragma once

#include "case/case.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/mesh_contact.hpp"
#include "core/ode_integrator.hpp"
#include "gear/gear_mesh.hpp"

#include <functional>
#include <vector>

namespace geartrib::contact {

// The stretch of each flank's involute the run reads (arc coordinates sigma = rho^2/(2 r_b)):
// the contact point's range on the path widened by the strip's half-length and one element.
struct FlankSpan {
  double first[2] = {0.0, 0.0};  // pinion, wheel [m]
  double last[2] = {0.0, 0.0};
  double active_first[2] = {0.0, 0.0};  // the contact point's range alone [m]
  double active_last[2] = {0.0, 0.0};
  double strip_half_length = 0.0;   // [m]
  double max_step[2] = {0.0, 0.0};  // the largest move of the contact point along each flank between positions [m]
  int positions = 0;
  bool running_in = false;
  double element_size = 0.0;  // [m]
  int elements = 0;           // the strip's boundary elements
  // Where a generated flank lies, whatever the strip, elements and load: from a module below the
  // base circle to a module beyond the tip (so that changing a knob does not change the flank).
  double generated_first[2] = {0.0, 0.0};
  double generated_last[2] = {0.0, 0.0};
  double length(int g) const { return last[g] - first[g]; }
  // A measured trace of `length` centred on the flank's active part: where its first point lies.
  double centred_start(int g, double length) const { return 0.5 * (active_first[g] + active_last[g]) - 0.5 * length; }
};

// The flanks a run rolls, supplied by the caller for the span: one track per tooth (`teeth[g]`
// of them: 1 for a pair, z for the hunting order), each covering [first, last] of its gear.
struct RollingFlanks {
  std::vector<FlankTrack> pinion, wheel;
};
using FlankSource = std::function<RollingFlanks(const FlankSpan& span, const int teeth[2])>;

// What a deterministic run will take, estimated from its sizes alone (before any flank is made or
// strip solved), from measured per-unit costs (docs/reference/performance.md#budgets).
struct DeterministicWork {
  double flank_points[2] = {0.0, 0.0};  // points of one flank profile of each gear
  int teeth[2] = {1, 1};                // flank profiles held per gear (the hunting order: every tooth's)
  int meshes = 1;                       // meshes planned (running-in may stop earlier, at shakedown)
  int kept_profiles = 0;                // pressure profiles kept
  int threads = 1;                      // solving threads (each with its own strip solver)
  int cores = 1;                        // of them, running at once
};
struct DeterministicCost {
  double flank_bytes = 0.0, profile_bytes = 0.0, solver_bytes = 0.0, position_bytes = 0.0;
  double solves = 0.0;         // strip solves, every planned mesh
  double solve_seconds = 0.0;  // one strip solve on one core [s]
  double seconds = 0.0;        // the whole run's wall time [s]
  double bytes() const { return flank_bytes + profile_bytes + solver_bytes + position_bytes; }
};
// One strip solve's time on one core [s] for `elements` boundary elements.
double strip_solve_seconds(int elements);
DeterministicCost deterministic_cost(const FlankSpan& span, const DeterministicWork& work);
// The threads a deterministic run solves its strips on: contact.threads, or the hardware's when 0,
// at least 1 and at most one a position.
int strip_threads(const ContactSettings& cs, int positions);

// Fills r's contact, validity, statistical, pressure-profile and running-in parts; r.mesh holds
// the path's kinematics and loads (run_mesh_contact's stage 1). dynamics: the integrator of a case
// that asks for dynamics (the statistical model beside runs on the same loads).
void run_deterministic(const Case& c, const gear::GearMesh& mesh, MeshContactResult& r, const FlankSource& flanks,
                       const std::function<void(int, int)>& progress, const OdeIntegrator* dynamics);

}  // namespace geartrib::contact
