// A case (scene): the composition of the physics' option structs (the gear pair, the bodies'
// materials and flanks, the mesh, its dynamics, the lubrication, the asperity model and the contact
// run), all SI, with the operating point and the load-time records (title, source, the parameters
// as resolved, warnings). Read from gears/*.toml by io::load_case through the declared parameter
// table (io/case_parameters.hpp: each key's default, range and meaning). case/ sits above the
// physics: the physics never includes this header; case/*_setup.hpp translate a Case into the
// physics' inputs, one translator per component.
#pragma once

#include "asperity/asperity_settings.hpp"
#include "case/origin.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/rough_line_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"
#include "gear/spur_pair.hpp"
#include "lubrication/lubrication_settings.hpp"
#include "material/material.hpp"
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
  int fzg_load_stage = 0;         // FZG load stage 1..14 naming the torque (io/fzg_load_stages.hpp); 0: none
  std::string fzg_test;           // the FZG test whose lever arm the stage hangs on; empty: none
  double pinion_speed = 0.0;      // [rad/s]
  double oil_temperature = 0.0;   // theta_oil, the inlet (sump or spray) oil [K]; lubricated runs only
  double bulk_temperature = 0.0;  // theta_M of the flanks [K]; 0: the ISO/TS 6336-20 estimate
};

// How the rough contact across the strip is solved: the statistical model with the Hertz pressure
// imposed (uncoupled) or solved with the bulk (coupled, Greenwood-Tripp), or the flanks' profiles
// in contact through boundary elements (deterministic).
enum class ContactFidelity { uncoupled, coupled, deterministic };

// Which pressure profiles a deterministic run keeps: at the path's points A, B, C, D, E, at
// every position, or none.
enum class PressureProfiles { points, all, none };

// The mesh-cycle contact run: fidelity, the outputs asked for, and the resolution knobs.
struct ContactSettings {
  ContactFidelity fidelity = ContactFidelity::uncoupled;
  bool coupled() const { return fidelity == ContactFidelity::coupled; }
  bool deterministic() const { return fidelity == ContactFidelity::deterministic; }
  bool real_area = true;  // outputs asked for
  bool plastic_fraction = true;
  bool asperity_stress = true;
  bool mesh_stiffness = false;  // the tooth-pair stiffness along the path (needed anyway by stiffness load sharing)
  int positions = 201;          // along A -> E of one tooth pair
  // The resolutions' defaults are the physics options' own (stated once, there).
  int strip_points = contact::StripOptions{}.strip_points;                  // uncoupled quadrature across the strip
  int height_points = contact::GreenwoodWilliamsonOptions{}.height_points;  // GW quadrature over summit heights
  int table_points = contact::GreenwoodWilliamsonOptions{}.table_points_per_sigma;  // GW table points per summit sigma
  int coupled_nodes = contact::StripOptions{}.coupled_nodes;                        // coupled pressure elements
  bool exact_strip_lookup = false;  // "cubic" cells in the pressure (false) or "exact": the table's inversion
  int stress_table = 64;  // von Mises table intervals over sqrt(plastic share); 0: exact maximisation each time
  // Deterministic: boundary-element size, the strip's half-length in the path's largest Hertz
  // half-widths, the pressure profiles kept and the threads (0: all cores).
  double element_size = contact::DeterministicOptions{}.element_size;  // [m]
  double strip_halfwidths = contact::DeterministicOptions{}.strip_halfwidths;
  PressureProfiles pressure_profiles = PressureProfiles::points;
  int threads = 0;
};

// Running-in (deterministic fidelity): the plastic deformation of each flank point carried from
// one mesh of the same teeth to the next, until shakedown or `meshes` meshes.
struct RunningInSettings {
  int meshes = 0;  // 0: one mesh, no running-in
  // Plastic deformation below this counts as none [m]: the plastic area's threshold, and
  // shakedown: a mesh that deforms no flank point by more.
  double tolerance = contact::DeterministicOptions{}.plastic_overlap;
  std::string teeth = "pair";  // "pair": one pinion and one wheel tooth; "hunting": every tooth, in mesh order
};

// What a declared key resolved to at load: its value with the SI unit, where it came from, and the
// value as the file or the --set wrote it (TOML text; empty for a default), which located
// messages quote. /parameters and `geartrib case` show the Case's values as it runs with these
// origins (io/case_records.hpp).
struct ResolvedParameter {
  std::string key;
  std::string value;
  Origin origin;
  std::string written;
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
  asperity::AsperitySettings asperity;
  std::string directory;                      // the folder the case's relative file names are taken from
  std::string source_text;                    // the case file as read, with the --set changes (stored with the results)
  std::vector<ResolvedParameter> parameters;  // every key as it ran
  std::vector<std::string> warnings;          // non-fatal findings of the loader (e.g. undercut), located
};

}  // namespace geartrib
