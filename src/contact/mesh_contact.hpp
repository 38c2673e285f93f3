// The main job: rough-surface contact at every position of one tooth pair's path A -> E,
// evaluating only what the case asks for, with the time each stage took. The cycle's stages, each
// from typed inputs to typed results: the path (contact/mesh_path.hpp), the contact fidelity's
// preparation and solve (contact/fidelity.hpp; the registered ones in contact/fidelities.hpp), the
// lubrication around it (contact/mesh_lubrication.hpp), and the output series built once at the end.
#pragma once

#include "contact/contact_options.hpp"
#include "contact/surface_model.hpp"
#include "core/nonlinear_solver.hpp"
#include "core/ode_integrator.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"
#include "lubrication/lubrication_settings.hpp"
#include "rating/load_capacity.hpp"
#include "surface/flank_spec.hpp"
#include "surface/rough_surface.hpp"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace geartrib::contact {

// One quantity over the positions, with its unit.
struct Series {
  std::string name;
  std::string unit;
  std::vector<double> values;
};

// The mean of a series along A -> E: trapezoidal rule over the evenly spaced positions.
double path_mean(const std::vector<double>& values);

struct StageTiming {
  std::string name;
  double seconds = 0.0;
};

// The lubricated cycle's findings along the path (a case with [lubricant]).
struct LubricationSummary {
  std::string lubricant;  // its name
  std::string film_formula, inlet_heating, film_gap, asperity_pressure, traction, bulk_friction_law;
  double bearing_area_weight = 0.0;  // of the asperity pressure (contact/asperity_pressure.hpp)
  double oil_temperature = 0.0;      // [K]
  double bulk_temperature = 0.0;     // [K]
  bool bulk_estimated = false;       // from the ISO/TS 6336-20 estimate
  double dynamic_viscosity = 0.0;    // eta at the bulk temperature [Pa s]
  double pressure_viscosity = 0.0;   // alpha at the bulk temperature [1/Pa]
  double composite_rq = 0.0;         // sqrt(Rq1^2 + Rq2^2) of the flanks' heights [m]
  double mean_ra = 0.0;              // (Ra1 + Ra2)/2 [m]
  std::string roughness_source;      // where Rq and Ra came from
  double summit_model_sigma = 0.0;   // the equivalent surface's composite sigma [m]
  // Persson's closure (empty otherwise): its spectrum's source (contact::FlankSpectrum::sources(): measured,
  // generated, fitted, or the pinion's/the wheel's), and that spectrum's rq and full rms gradient h'_rms.
  std::string persson_spectrum;
  double persson_rms_height = 0.0;    // [m]
  double persson_rms_gradient = 0.0;  // [1]
  struct LawValue {
    std::string law;
    double coefficient = 0.0;
  };
  std::vector<LawValue> mean_friction;  // the gear-mean laws at C (iso, iso-flash, schlenk, fernandes)
  double mesh_mean_friction = 0.0;      // the model's: mesh power loss / (input power x H_V,path)
  double mesh_power_loss = 0.0;         // over one mesh cycle, all pairs [W]
  double input_power = 0.0;             // T1 omega1 [W]
  double efficiency = 1.0;              // 1 - mesh power loss / input power (tooth friction only)
  double loss_factor_path = 0.0;        // H_V from the computed path: (1/p_b) int (w/w_t)(|v_s|/v_b) ds
  double loss_factor_ohlendorf = 0.0;   // Ohlendorf's closed form pi (u + 1)/(z1 u)(1 - eps + eps1^2 + eps2^2)
  double max_contact_temperature = 0.0, max_iso_contact_temperature = 0.0;  // [K]
  double min_iso_lambda = 0.0, min_lambda_film = 0.0;
  double max_share_spread = 0.0;        // the asperity share's largest range over the film gaps
  int closure_dependent_positions = 0;  // positions where that range exceeds 0.1
  int oil_clamped_positions = 0;        // positions whose oil is taken at its law range's hot end
  double iso_effective_relief = 0.0;    // C_eff = F_t/(b cos alpha_t c_gamma), ISO/TR 13989-1 B.1 [m]
  double iso_scuffing_safety = 0.0;     // ISO/TS 6336-20 flash-temperature method; 0: no scuffing temperature
  double scuffing_safety = 0.0;         // the same with the model's local friction (Blok)
  struct NamedPoint {
    std::string name;  // A, AB, B, C, D, DE, E
    double s = 0.0, line_load = 0.0, film = 0.0, lambda_film = 0.0, mean_gap = 0.0, lambda_gap = 0.0, iso_film = 0.0,
           iso_lambda = 0.0, asperity_share = 0.0, share_spread = 0.0, friction = 0.0, flash = 0.0, iso_flash = 0.0,
           contact_temperature = 0.0, iso_contact_temperature = 0.0;
  };
  std::vector<NamedPoint> points;  // ISO/TS 6336-22's points, each evaluated where it stands
};

// A deterministic run's pressure across the strip at one position.
struct PressureProfile {
  int position = 0;                 // index along the path (0 at A)
  std::string point;                // the path's point it stands for (A, B, C, D, E) or empty
  double s = 0.0;                   // [m] from T1
  std::vector<double> x, pressure;  // across the strip [m], [Pa]
};

// A mixed-EHL run's film and pressure through the contact at one position kept, at two instants
// of its transient window: that of its highest peak pressure and the window's middle.
struct EhlProfile {
  int position = 0;       // index along the path (0 at A)
  std::string point;      // the path's point it stands for (A, B, C, D, E) or empty
  double s = 0.0;         // [m] from T1
  std::vector<double> x;  // the nodes, x along the rolling direction from the contact point [m]
  struct Instant {
    double time = 0.0;  // since the window's start [s]
    // Per node: p [Pa], h [m], the slower surface's shear stress (film, and the boundary friction
    // in contact) [Pa], and the node's state (0 fluid, 1 cavitated, 2 asperity contact).
    std::vector<double> pressure, film, shear, state;
  };
  Instant peak, middle;
};

// A mixed-EHL run's settings as run, its cost and the path's extremes (/mixed_ehl's attributes).
struct MixedEhlSummary {
  std::string viscosity_law, flow;
  double compressible = 1.0;
  double grid_spacing = 0.0;  // as run (the automatic one when not given) [m]
  double nodes_max = 0.0;     // at the largest contact
  double window = 0.0, time_step = 0.0, tolerance = 0.0, inlet = 0.0, outlet = 0.0, lead_in = 0.0;
  double film_floor = 0.0, boundary_friction = 0.0, hardness = 0.0;
  double eta = 0.0, alpha = 0.0, eyring_stress = 0.0, limiting_shear_coefficient = 0.0;  // the oil as run
  double steps = 0.0;                                                                    // time steps of all windows
  double window_seconds = 0.0;                                 // their wall time, summed over the threads' windows [s]
  double transform_seconds = 0.0;                              // of which in the solver's FFTs [s]
  double min_film = 0.0;                                       // the least film over every window [m]
  double max_asperity_share = 0.0, mean_asperity_share = 0.0;  // largest instant; path mean of the time means
  double max_peak_pressure = 0.0;                              // [Pa]
  double mean_friction = 0.0;                                  // path mean of the time means
  double max_flash_temperature = 0.0;                          // [K]
  double max_von_mises = 0.0;                                  // [Pa]
  double max_load_error = 0.0;                                 // the largest |integral of p - w|/w over every instant
  double whole_path = 0.0;                                     // 1: the path solved transiently A -> E as well
  double whole_path_steps = 0.0, whole_path_seconds = 0.0;
};

// Running-in (deterministic): the history over the meshes (one entry per mesh of the pair, or per
// pinion revolution in the hunting order) and the flanks' profiles before and after.
struct RunningInResult {
  std::string teeth;            // "pair" or "hunting"
  int meshes = 0;               // meshes run (each pinion tooth's, hunting)
  int shakedown_mesh = 0;       // the first mesh without new plastic deformation beyond the tolerance; 0: not reached
  double tolerance = 0.0;       // [m]
  std::vector<Series> history;  // mesh, new plastic deformation, Rq, Rsk, summit radius, real area, plastic fraction
  // One pinion and one wheel flank (tooth 0) over their active part, before and after [m].
  std::array<double, 2> spacing = {0.0, 0.0};
  std::array<std::vector<double>, 2> initial, final;
};

// A deterministic run's flank synthesised from a measured patch ([*.flank.topography] synthesis):
// what it came from and how (surface/profile_synthesis.hpp); and an areal run's maps made from one
// (areal.lay = "patch"; surface/areal_synthesis.hpp; method areal-synthesis or areal-tiled, the
// profile_* fields tooth 0's map, rolled_off_fraction the share of the patch's variance it leaves out).
struct FlankSynthesis {
  std::string gear;    // pinion | wheel
  std::string patch;   // the topography file, as the case names it
  std::string method;  // psd | iaaft | areal-synthesis | areal-tiled
  double seed = 0;     // tooth 0's; tooth t: seed + t
  int teeth = 0;       // profiles synthesised (1, or the teeth of the hunting order)
  double patch_lines = 0, patch_points = 0;
  double patch_spacing = 0.0;        // [m]
  double patch_rq = 0.0;             // the patch's lines' Rq [m]
  double rolled_off_fraction = 0.0;  // of the patch's variance, at wavelengths beyond the synthesis's
  double profile_length = 0.0;       // [m]
  double profile_rq = 0.0;           // tooth 0's [m]
  int iterations = 0;                // IAAFT: the most any tooth took
  double spectrum_misfit = 0.0;      // IAAFT: the largest
  double curvature_ratio = 1.0;      // IAAFT: m4 over the spectrum's, the farthest from 1
  bool converged = true;             // IAAFT: every tooth's
};

struct MeshContactResult {
  std::vector<Series> mesh;         // kinematics and loading: s_m, load_share, hertz_p0_Pa, ...
  std::vector<Series> contact;      // rough contact: real_area_ratio, plastic_area_fraction, ...
  std::vector<Series> validity;     // where the models hold: separation_over_sigma, flags, ... (validity.hpp)
  std::vector<Series> lubrication;  // lubricated runs: film, lambda, shares, friction, temperatures, wear
  std::optional<LubricationSummary> lubrication_summary;
  // Deterministic runs: the statistical model on the same flanks (names prefixed statistical_),
  // the pressure profiles kept and the running-in.
  std::vector<Series> statistical;
  std::vector<PressureProfile> pressure_profiles;
  std::optional<RunningInResult> running_in;
  std::vector<FlankSynthesis> synthesis;  // flanks synthesised from a measured patch
  // Mixed-EHL runs: its per-position series (/mixed_ehl), the film and pressure profiles kept and
  // its summary.
  std::vector<Series> mixed_ehl;
  std::vector<EhlProfile> ehl_profiles;
  std::optional<MixedEhlSummary> mixed_ehl_summary;
  std::string regime;   // "elastic", "elastic-plastic" or "fully plastic"
  std::string verdict;  // one paragraph: the regime and every validity rule broken, and where
  struct FlagCount {
    std::string name;
    int positions = 0;
  };
  std::vector<FlagCount> flag_counts;  // positions where each validity flag is set
  std::vector<StageTiming> stages;
  surface::EquivalentSurface surface;
  double plasticity_index = 0.0;
  gear::PathOfContact path;
  std::array<gear::GearBody, 2> gears;  // the pinion's and the wheel's circles (for the diameters of A..E)
  std::optional<gear::TransmissionErrorStats> tooth_contact;  // compatibility sharing: over one base pitch
  std::optional<rating::RatingResult> rating;                 // the case's [rating] methods (runs/case_rating.hpp)
  std::string asperity_model;
  std::string fidelity;
  // Findings that make a result doubtful (e.g. a real area larger than the nominal one).
  std::vector<std::string> warnings;
  const Series* find(const std::string& name) const;  // in every group of groups(); nullptr if absent
  // Every per-position group, in the order of the CSV columns and of find().
  std::array<const std::vector<Series>*, 6> groups() const {
    return {&mesh, &contact, &validity, &lubrication, &statistical, &mixed_ehl};
  }
};

struct RollingFlanks;
struct FlankSpan;
// The flanks a fidelity that rolls their profiles reads: one track per tooth (teeth[g] of gear g)
// over the span it reads (contact/deterministic/mesh_deterministic.hpp).
using FlankSource = std::function<RollingFlanks(const FlankSpan& span, const int teeth[2])>;

// The operating point as the lubricated stage takes it.
struct LubricatedOperatingPoint {
  double oil_temperature = 0.0;   // theta_oil, the inlet oil [K]
  double bulk_temperature = 0.0;  // theta_M of the flanks [K]; 0: the ISO/TS 6336-20 estimate
  double pinion_torque = 0.0;     // [N m]
};

// The mesh cycle's typed inputs.
struct MeshCycleInputs {
  const gear::GearMesh& mesh;
  ContactSettings contact;  // contact.positions: the positions along A -> E
  RunningInSettings running_in;
  StatisticalFlanks flanks;
  // Lubricated: the oil and its models, and the operating point's temperatures; nullptr: dry.
  const lubrication::LubricationSettings* lubrication = nullptr;
  LubricatedOperatingPoint operating;
  // Dynamics: the integrator of the steady mesh cycle and the model's settings; each pair then
  // carries its dynamic load instead of the static share. nullptr: static load sharing.
  const OdeIntegrator* dynamics = nullptr;
  gear::DynamicsSettings dynamics_settings;
  const NonlinearSolver* solver = nullptr;  // for a fidelity that needs one (coupled)
  FlankSource flank_source;                 // for a fidelity that rolls the flanks' profiles
  std::function<void(int, int)> progress;   // (done, total) after each position
  std::array<const surface::FlankSpec*, 2> flank_specs = {nullptr, nullptr};  // the case's flanks (areal)
};

// The stages in order: path, the fidelity's preparation, the film (lubricated), its solve,
// friction/temperatures/wear, the outputs.
MeshContactResult run_mesh_contact(const MeshCycleInputs& in);

}  // namespace geartrib::contact
