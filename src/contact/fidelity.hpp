// What a contact fidelity of the mesh cycle is given and declares (contact/fidelities.hpp lists
// them). A fidelity is a type in its own folder with:
//   static constexpr std::string_view name, description;  // its contact.fidelity value, one line of meaning
//   static constexpr FidelityTraits traits;               // its keys, knobs, needs and output groups
//   struct State;                                          // what prepare() leaves for solve()
//   static State prepare(const FidelityInputs&, StageClock&);  // before the film: State::surface() is the
//                                                          // statistical model the film shares the load with (or null)
//   struct Solution;
//   static Solution solve(const FidelityInputs&, State&, const std::vector<double>& asperity_share, StageClock&);
//                                                          // (FidelityInputs::film: the lubricated stage, when
//                                                          lubricated)
//   static void write(const FidelityInputs&, State&, Solution&, MeshContactResult&);  // its outputs
// The mesh cycle (contact/mesh_contact.cpp) runs: the path, prepare, the film (lubricated), solve,
// friction/temperatures/wear, the outputs.
#pragma once

#include "contact/contact_options.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/mesh_path.hpp"
#include "contact/surface_model.hpp"
#include "core/nonlinear_solver.hpp"
#include "gear/gear_mesh.hpp"
#include "surface/flank_spec.hpp"

#include <array>

#include <functional>
#include <string>
#include <vector>

namespace geartrib::contact {

// The stages' timings, lap by lap (contact/stage_clock.hpp, internal).
struct StageClock;
// The lubricated stage (contact/mesh_lubrication.hpp).
class MeshLubrication;

// A fidelity's typed inputs: the path stage's state and the options that concern the contact.
struct FidelityInputs {
  const gear::GearMesh& mesh;
  const PathState& path;
  const ContactSettings& contact;
  const RunningInSettings& running_in;
  const StatisticalFlanks& flanks;  // as the case gives them
  bool lubricated = false;
  const NonlinearSolver* solver = nullptr;  // for a fidelity that needs one
  const FlankSource& flank_source;          // for a fidelity that rolls the flanks' profiles
  const std::function<void(int, int)>& progress;
  // Lubricated runs: the film stage (its oil at the flanks' bulk temperature, the flanks' thermal
  // contact coefficients), set once it is built, before solve(); nullptr when dry or in prepare().
  const MeshLubrication* film = nullptr;
  // The flanks as the case gives them (a generated profile's spec: the areal fidelity's isotropic
  // maps); null when the caller has none.
  std::array<const surface::FlankSpec*, 2> flank_specs = {nullptr, nullptr};
};

}  // namespace geartrib::contact
