// A case (scene): the gear pair, the bodies' materials and flanks, the operating point and the
// contact-model choices, all SI. Read from gears/*.toml by io::load_case through the declared
// parameter table (io/case_parameters.hpp: each key's default, range and meaning); the physics
// takes the pieces it needs from here.
#pragma once

#include "contact/contact_options.hpp"
#include "lubrication/lubricant.hpp"
#include "material/material.hpp"
#include "surface/flank_profile.hpp"
#include "surface/height_grid.hpp"
#include "surface/profile_synthesis.hpp"
#include "surface/rough_surface.hpp"
#include "surface/surface_statistics.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geartrib {

// The pair's geometry: basic rack (ISO 53 by default), centre distance and both gears' teeth,
// shifts, tip and bore diameters; index 0 the pinion, 1 the wheel. gear::SpurPair builds on it.
struct GearPairSpec {
  static constexpr int kMinTeeth = 5;  // below this no involute spur gear is cut in practice
  static constexpr int kMaxTeeth = 1000;
  double module = 0.0;                    // m [m]
  double pressure_angle = 0.0;            // alpha of the basic rack [rad]
  double face_width = 0.0;                // b [m]
  double addendum_coefficient = 1.0;      // h_aP / m
  double dedendum_coefficient = 1.25;     // h_fP / m
  double root_radius_coefficient = 0.38;  // rho_fP / m
  double tip_shortening = 0.0;            // k: tip diameter reduced by 2 k m on both gears
  double center_distance = 0.0;           // a_w [m]; 0: zero-backlash distance from the shifts
  int teeth[2] = {0, 0};                  // z
  double profile_shift[2] = {0.0, 0.0};   // x [-]
  double tip_diameter[2] = {0.0, 0.0};    // d_a [m]; 0: from addendum, shift and tip shortening
  double bore_diameter[2] = {0.0, 0.0};   // gear-body bore [m], for the fillet-foundation stiffness
};

// A measured flank: the topography file and how it is read and cleaned.
struct TopographySpec {
  std::string file;       // as written in the case file (relative to it)
  double unit = 1e-6;     // length unit of a file that does not state one [m]
  double spacing = 0.0;   // grid spacing of files without one [m]; 0: from the file
  double resample = 0.0;  // regrid spacing [m]; 0: as measured
  surface::CleanupOptions clean;
  // The deterministic fidelity's profile: the grid line along x (or y) at this fraction of the
  // other axis, taken along the involute from root to tip.
  bool profile_along_x = true;
  double profile_at = 0.5;
  // Or a flank-long profile synthesised from the surface's profile spectrum along that axis (every
  // line; surface/profile_synthesis.hpp): psd or iaaft, the phases' seed (tooth t of the hunting
  // order: seed + t), the length centred on the active flank (0: a generated profile's stretch).
  surface::SynthesisMethod synthesis = surface::SynthesisMethod::none;
  std::uint64_t synthesis_seed = 1;
  double synthesis_length = 0.0;  // [m]
};

// The rough flank of one gear: its roughness in one of the forms of surface::FlankRoughness
// (Ra, Rq, summit statistics or spectral moments; roughness.summit_radius is the flank's summit
// radius, the only place it is kept).
struct FlankSpec {
  surface::FlankRoughness roughness;
  // When the flank is measured ([*.flank.topography]): where it came from, and the statistics
  // of the cleaned surface the roughness above was taken from.
  std::optional<TopographySpec> topography;
  std::optional<surface::SurfaceStatistics> measured;
  std::optional<surface::FlankProfile> measured_profile;   // the topography's line for the deterministic fidelity
  std::optional<surface::ProfileSpectrum> patch_spectrum;  // its profile spectrum, when a synthesis is asked for
  // A generated profile along the involute ([*.flank.profile]): the deterministic fidelity's flank,
  // and (its statistics) the roughness of the others.
  std::optional<surface::GeneratedProfileSpec> profile;
};

// One gear's body: its material and its flank (its geometry is in GearPairSpec).
struct GearSpec {
  std::string material_file;  // as written in the case file
  Material material;
  FlankSpec flank;
};

struct OperatingPoint {
  double pinion_torque = 0.0;     // [N m]; given, or the FZG table's at fzg_load_stage
  int fzg_load_stage = 0;         // FZG load stage 1..14 naming the torque (io/fzg_load_stages.hpp); 0: none
  std::string fzg_test;           // the FZG test whose lever arm the stage hangs on; empty: none
  double pinion_speed = 0.0;      // [rad/s]
  double oil_temperature = 0.0;   // theta_oil, the inlet (sump or spray) oil [K]; lubricated runs only
  double bulk_temperature = 0.0;  // theta_M of the flanks [K]; 0: the ISO/TS 6336-20 estimate
};

// The lubricated mesh cycle: the oil (a lubricant file, or eta and alpha at the oil temperature
// given in the case) and the models along the path. A case without [lubricant] runs dry.
struct LubricationCase {
  bool lubricated = false;     // the case has a [lubricant] table
  std::string lubricant_file;  // as written in the case (relative to it); empty: the fixed form
  lubrication::Lubricant lubricant;
  std::string film_formula = "dowson-higginson";  // lubrication/ehl_film.hpp
  std::string inlet_heating = "gupta";
  std::string film_gap = "mean-gap";        // lubrication/film_closure.hpp
  std::string asperity_pressure = "auto";   // contact/asperity_pressure.hpp
  std::string traction = "thermal-eyring";  // lubrication/mixed_lubrication.hpp
  std::string mean_friction = "iso-flash";  // lubrication/flank_temperature.hpp: the bulk estimate's law
  double wear_coefficient = 1e-17;          // Archard's dimensional k [m^2/N = m^3/(N m)] (assumed order, mild wear)
  double scuffing_temperature = 0.0;        // theta_S [K]; 0: no scuffing safety
};

// Single-asperity settings: the model by name, per-model constant overrides, the measured
// side-contact offsets, and the cylinder asperity of seed section 5.
struct AsperitySettings {
  std::string model = "continuous";
  std::map<std::string, std::vector<std::pair<std::string, double>>> constants;  // model -> (name, value)
  double measured_axis_offset = 0.0;                                             // seed's d0 [m]
  double measured_tip_gap = 0.0;                                                 // seed's y0 [m]
  double cylinder_tip_radius = 0.0;       // R_m [m]; 0: not given (only the cylinder studies need it)
  double cylinder_yield_constant = 1.64;  // C of delta_pc
};

// Mesh-cycle settings: how the load is shared between simultaneous tooth pairs, how many
// positions sample one base pitch, and the beam model of the tooth stiffness.
struct MeshSettings {
  std::string load_sharing = "iso";  // "iso" (ISO/TS 6336-22 method B) or "stiffness"
  int positions = 64;                // samples of one base pitch of pinion rotation
  bool plane_strain = true;          // tooth beam in plane strain (wide face) or plane stress
};

// Rough-surface settings shared by both flanks.
struct RoughnessSettings {
  surface::HeightDistribution distribution = surface::HeightDistribution::gaussian;
  double eta_sigma_beta = surface::kTypicalEtaSigmaBeta;  // for flanks given by Ra or Rq
};

// Mesh dynamics: the engine (none: static load sharing) and the model's data.
struct DynamicsCase {
  std::string engine = "none";       // "none", "cvode" or "odeint"
  double damping_ratio = 0.07;       // zeta, a typical value for spur meshes (assumed)
  double relative_tolerance = 1e-8;  // integrator rtol
  double backlash = 0.0;             // along the line of action [m]; 0: no back-flank contact
  double pinion_inertia = 0.0;       // [kg m^2]; 0: solid disc
  double wheel_inertia = 0.0;
};

// What a declared key resolved to: its value with the SI unit and where it came from
// ("file:line", "--set" or "default"); written to /scene and printed by `geartrib case`.
struct ResolvedParameter {
  std::string key;
  std::string value;
  std::string origin;
};

struct Case {
  std::string title;
  std::string source;
  GearPairSpec gear_pair;
  GearSpec pinion;
  GearSpec wheel;
  OperatingPoint operating;
  double friction_coefficient = 0.0;  // mu [-] of the asperity side contact; the boundary coefficient when lubricated
  LubricationCase lubrication;
  MeshSettings mesh;
  DynamicsCase dynamics;
  RoughnessSettings roughness;
  ContactSettings contact;
  RunningInSettings running_in;
  AsperitySettings asperity;
  std::string source_text;                    // the case file as read, with the --set changes (stored with the results)
  std::vector<ResolvedParameter> parameters;  // every key as it ran
  std::vector<std::string> warnings;          // non-fatal findings of the loader (e.g. undercut), located
};

}  // namespace geartrib
