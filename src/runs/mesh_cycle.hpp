// The mesh cycle of a case as the case asks for it: what `geartrib run`, `geartrib sweep` and
// the Python module run. The runs/ folder holds what the command line and the Python module
// both run on a case (no files, no command line).
#pragma once

#include "case/case.hpp"
#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"

#include <functional>

namespace geartrib::runs {

// KINSOL when coupled, the case's integrator when it asks for dynamics. Throws io::InputError
// located at the case (an overload at the torque, naming the flanks' roughness; a value the
// physics refused at the case file) and std::runtime_error when any output (a series, a summary
// value, a named point, a profile) is not finite, naming its dataset and position: nothing non-finite
// is ever returned. Thread-safe.
// The last check before a run's outputs are written or returned (the command, a sweep row, the
// Python module): every number finite. A NaN or inf is a model that left its range where nothing
// caught it: throws std::runtime_error naming the dataset (as /group/name in the HDF5 file) and
// the position. The running-in history's row 0 (the new flanks) holds NaN by design.
void check_finite_outputs(const contact::MeshContactResult& r);

contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress = {});

// The mesh cycle of a case on `mesh`, its inputs translated from the case (contact::MeshCycleInputs),
// without run_mesh_cycle's located errors and checks. solver: for a fidelity that needs one;
// positions <= 0: the case's number; dynamics: the integrator, when the case asks for dynamics
// (mesh.dynamics = cvode | odeint); flanks: the flanks' profiles, for a fidelity that rolls them.
contact::MeshContactResult run_mesh_contact(const Case& c, const gear::GearMesh& mesh, const NonlinearSolver* solver,
                                            const std::function<void(int, int)>& progress = {}, int positions = 0,
                                            const OdeIntegrator* dynamics = nullptr,
                                            const contact::FlankSource& flanks = {});

// The finest boundary elements a deterministic case's flanks allow [m]: the coarser of its two flank
// profiles' spacings (generated, measured or synthesised: the elements average a profile, finer ones
// would resolve only the interpolation between its points); 0 when neither flank has a profile.
double finest_element_size(const Case& c);
// The coarsest grid a mixed-EHL case's flanks allow [m]: the finer of its two flank profiles'
// spacings (the nodes sample a profile, coarser ones would skip its points); 0 when neither has one.
double coarsest_grid_spacing(const Case& c);

}  // namespace geartrib::runs
