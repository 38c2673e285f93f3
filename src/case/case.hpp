// A case (scene): the composition of the physics' option structs (the gear pair, the bodies'
// materials and flanks, the mesh, its dynamics, the lubrication, the asperity model and the contact
// run), all SI, with the operating point and the load-time records (title, source, the parameters
// as resolved, warnings). Read from gears/*.toml by io::load_case through the declared parameter
// table (config/case_parameters.hpp: each key's default, range and meaning). case/ sits above the
// physics: the physics never includes this header; case/*_setup.hpp translate a Case into the
// physics' inputs, one translator per component.
#pragma once

#include "asperity/asperity_settings.hpp"
#include "case/origin.hpp"
#include "contact/contact_options.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"
#include "gear/spur_pair.hpp"
#include "lubrication/lubrication_settings.hpp"
#include "material/material.hpp"
#include "rating/load_capacity.hpp"
#include "surface/flank_spec.hpp"

#include <string>
#include <vector>

namespace geartrib {

// One gear's body: its material and its flank (its geometry is in GearPairSpec).
struct GearSpec {
  std::string material_file;  // as written in the case file
  Material material;
  surface::FlankSpec flank;
};

// Where the mesh runs: the load and speed (gear::GearMesh) and the oil and bulk temperatures
// (the lubricated cycle), the torque given or from the FZG load-stage table.
struct OperatingPoint {
  double pinion_torque = 0.0;     // [N m]; given, or the FZG table's at fzg_load_stage
  int fzg_load_stage = 0;         // FZG load stage 1..14 naming the torque (config/fzg_load_stages.hpp); 0: none
  std::string fzg_test;           // the FZG test whose lever arm the stage hangs on; empty: none
  double pinion_speed = 0.0;      // [rad/s]
  double oil_temperature = 0.0;   // theta_oil, the inlet (sump or spray) oil [K]; lubricated runs only
  double bulk_temperature = 0.0;  // theta_M of the flanks [K]; 0: the ISO/TS 6336-20 estimate
};

// What a declared key resolved to at load: its value with the SI unit, where it came from, and the
// value as the file or the --set wrote it (TOML text; empty for a default), which located
// messages quote. /parameters and `geartrib case` show the Case's values as it runs with these
// origins (config/case_records.hpp).
struct ResolvedParameter {
  std::string key;
  std::string value;
  Origin origin;
  std::string written;
};

// The ratings a run computes ([rating] methods) and how (rating/load_capacity.hpp, rating/scuffing.hpp).
struct RatingRequest {
  bool pitting = false, bending = false, scuffing = false, micropitting = false;
  bool any() const { return pitting || bending || scuffing || micropitting; }
  rating::RatingSettings settings;
};

struct Case {
  std::string title;
  std::string source;
  gear::GearPairSpec gear_pair;
  GearSpec pinion;
  GearSpec wheel;
  OperatingPoint operating;
  double friction_coefficient = 0.0;  // mu [-] of the asperity side contact; the boundary coefficient when lubricated
  lubrication::LubricationSettings lubrication;
  gear::MeshSettings mesh;
  gear::DynamicsSettings dynamics;  // density: the pinion material's (case/gear_setup.hpp)
  surface::RoughnessSettings roughness;
  ContactSettings contact;
  RunningInSettings running_in;
  RatingRequest rating;
  asperity::AsperitySettings asperity;
  std::string directory;                      // the folder the case's relative file names are taken from
  std::string source_text;                    // the case file as read, with the --set changes (stored with the results)
  std::vector<ResolvedParameter> parameters;  // every key as it ran
  std::vector<std::string> warnings;          // non-fatal findings of the loader (e.g. undercut), located
};

}  // namespace geartrib
