// The main job: rough-surface contact at every position of one tooth pair's path A -> E,
// evaluating only what the case asks for, with the time each stage took.
#pragma once

#include "case/case.hpp"
#include "core/nonlinear_solver.hpp"
#include "core/ode_integrator.hpp"
#include "gear/gear_mesh.hpp"
#include "surface/rough_surface.hpp"

#include <functional>
#include <string>
#include <vector>

namespace geartrib::contact {

// One quantity over the positions, with its unit.
struct Series {
  std::string name;
  std::string unit;
  std::vector<double> values;
};

// The equivalent rough surface of a case's two flanks (seed section 4) with its roughness settings.
surface::EquivalentSurface case_equivalent_surface(const Case& c);

// The mean of a series along A -> E: trapezoidal rule over the evenly spaced positions.
double path_mean(const std::vector<double>& values);

struct StageTiming {
  std::string name;
  double seconds = 0.0;
};

struct MeshContactResult {
  std::vector<Series> mesh;      // kinematics and loading: s_m, load_share, hertz_p0_Pa, ...
  std::vector<Series> contact;   // rough contact: real_area_ratio, plastic_area_fraction, ...
  std::vector<Series> validity;  // where the models hold: separation_over_sigma, flags, ... (validity.hpp)
  std::string regime;            // "elastic", "elastic-plastic" or "fully plastic"
  std::string verdict;           // one paragraph: the regime and every validity rule broken, and where
  struct FlagCount {
    std::string name;
    int positions = 0;
  };
  std::vector<FlagCount> flag_counts;  // positions where each validity flag is set
  std::vector<StageTiming> stages;
  surface::EquivalentSurface surface;
  double plasticity_index = 0.0;
  gear::PathOfContact path;
  std::string asperity_model;
  std::string fidelity;
  // Findings that make a result doubtful (e.g. a real area larger than the nominal one).
  std::vector<std::string> warnings;
  const Series* find(const std::string& name) const;  // in mesh, contact, then validity; nullptr if absent
};

// progress(done, total) is called after each position. positions <= 0: the case's number.
// dynamics: when the case asks for dynamics (mesh.dynamics = cvode | odeint), the integrator that
// computes the steady mesh cycle; each pair then carries its dynamic load instead of the static share.
MeshContactResult run_mesh_contact(const Case& c, const gear::GearMesh& mesh, const NonlinearSolver* solver,
                                   const std::function<void(int, int)>& progress = {}, int positions = 0,
                                   const OdeIntegrator* dynamics = nullptr);

}  // namespace geartrib::contact
