// The mixed-EHL fidelity of the main job (contact.fidelity = "mixed_ehl"): the flanks' profiles, as
// the deterministic fidelity rolls them, moving through a lubricated line contact at their own
// speeds at every position of the path, solved transiently over a window by the line solver
// (contact/mixed_ehl/line_ehl.hpp), with the statistical lubricated cycle on the same flanks
// beside it (the film, the load sharing, friction and flash temperature of /lubrication).
//
// Frame (contact/deterministic_contact.hpp): with the contact points at the arcs sigma1c, sigma2c
// the pinion's point at x is sigma1c - x and the wheel's sigma2c + x; the contact points move
// along the flanks at the surfaces' speeds, sigma1c + u1 t and sigma2c - u2 t, so the heights
// towards each other at node x and time t are z1(sigma1c + u1 t - x) + z2(sigma2c - u2 t + x),
// each the flank's mean over the node's cell (track_mean), as the deterministic gap takes them.
#pragma once

#include "contact/deterministic/mesh_deterministic.hpp"
#include "contact/fidelity.hpp"
#include "contact/mixed_ehl/line_ehl.hpp"
#include "contact/mixed_ehl/mixed_ehl_options.hpp"
#include "contact/statistical/strip_fidelities.hpp"

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::contact::mixed_ehl {

// The heights of both flanks towards each other at the grid's nodes (a positive height closes the
// gap) with the contact points at sigma_pinion and sigma_wheel: each flank's mean over the node's
// cell, the pinion's at sigma_pinion - x, the wheel's at sigma_wheel + x [m].
void rolled_heights(const FlankTrack& pinion, const FlankTrack& wheel, const HalfPlaneGrid& grid, double sigma_pinion,
                    double sigma_wheel, std::vector<double>& heights);

// One position's transient window, as the mesh cycle sets it up.
struct WindowSetup {
  Fluid fluid;
  double composite_modulus = 0.0;  // E* [Pa]
  EhlOptions solver;               // its nodes for this position's domain
  ContactInstant instant;
  double sigma_pinion = 0.0, sigma_wheel = 0.0;  // the contact points' arcs at the window's start [m]
  double window = 2.0;                           // contact widths 2b travelled by the slower surface
  double time_step = 1.0;                        // Courant number: dt = time_step dx / max(u1, u2)
  double lead_in = 4.0;                          // b travelled at the entrainment speed before it (0: steady start)
  double thermal_coefficient[2] = {0.0, 0.0};    // B = sqrt(k rho c) of the pinion and the wheel
  double poisson_ratio = 0.3;                    // of the softer flank, whose subsurface stress is computed
  bool pinion_softer = true;
  bool subsurface = true;  // the von Mises maximum at the instant of the highest peak pressure
  bool keep_profile = false;
};

// A window that did not converge: where in it.
class WindowFailure : public std::runtime_error {
 public:
  WindowFailure(const std::string& what, bool steady, int step, int steps, double time, double duration)
      : std::runtime_error(what), steady(steady), step(step), steps(steps), time(time), duration(duration) {}
  bool steady;  // the steady start (t = 0), not a time step
  int step, steps;
  double time, duration;  // [s]
};

// One position's window: time means (trapezoidal over the instants, contact/mesh_contact.hpp's
// path_mean) and extremes.
struct WindowResult {
  int nodes = 0;
  double spacing = 0.0;     // of the nodes [m]
  double half_width = 0.0;  // the instant's Hertz b [m]
  int steps = 0;
  double duration = 0.0, dt = 0.0;  // [s]
  int lead_in_steps = 0;            // the lead-in's time steps before t = 0 (0: the steady rough start)
  double central_film_mean = 0.0, central_film_min = 0.0, min_film_mean = 0.0, min_film_min = 0.0;  // [m]
  double contact_fraction_mean = 0.0, contact_fraction_max = 0.0;  // the solver's, nodes within |x| <= b
  double asperity_share_mean = 0.0, asperity_share_max = 0.0;
  double peak_pressure_mean = 0.0, peak_pressure_max = 0.0;  // [Pa]
  double friction_mean = 0.0, friction_max = 0.0;
  double film_friction_mean = 0.0, boundary_friction_mean = 0.0;  // [N/m]
  double heat_flux_mean = 0.0, heat_flux_max = 0.0;               // peak over x of |tau| |u1 - u2| [W/m^2]
  double flash_mean = 0.0, flash_max = 0.0;                       // peak over x of the flash temperature [K]
  double real_area_ratio_mean = 0.0, real_area_ratio_max = 0.0;   // contact nodes' length over 2b
  double plastic_fraction_mean = 0.0;  // contact nodes above the softer flank's hardness over the contact nodes
  double yield_fraction_max = 0.0;  // the solver's: nodes within |x| <= b where the flanks yield, the largest instant
  StressMaximum stress;             // at the instant of the highest peak pressure
  double load_error_max = 0.0;      // |integral of p - w|/w, the largest over the instants
  double iterations_mean = 0.0;     // Newton iterations per instant
  double linear_iterations_mean = 0.0;  // GMRES iterations per instant
  double transforms_mean = 0.0;         // FFTs per instant
  double transform_seconds = 0.0;       // their time [s]
  double edge_pressure_max = 0.0;       // the largest pressure at the domain's first or last node over p_H
  double seconds = 0.0;                 // wall time
  std::optional<EhlProfile> profile;    // x and the two instants (position, point and s: the caller's)
};

WindowResult solve_window(const FlankTrack& pinion, const FlankTrack& wheel, const WindowSetup& w);

// The whole path A -> E solved transiently, reported per position of the path: the means over the
// steps nearest each position (within half a position's interval), the peak pressure's maximum.
struct WholePath {
  std::vector<double> central_film, min_film, asperity_share, peak_pressure, friction;  // per position
  int steps = 0, nodes = 0;
  double seconds = 0.0;
  double load_error_max = 0.0;
};

inline constexpr std::array<std::string_view, 18> kKeys = {
    "contact.positions",      "contact.outputs",         "contact.pressure_profiles",
    "contact.threads",        "mixed_ehl.grid_spacing",  "mixed_ehl.inlet",
    "mixed_ehl.outlet",       "mixed_ehl.window",        "mixed_ehl.time_step",
    "mixed_ehl.tolerance",    "mixed_ehl.viscosity_law", "mixed_ehl.flow",
    "mixed_ehl.compressible", "mixed_ehl.film_floor",    "mixed_ehl.boundary_friction",
    "mixed_ehl.whole_path",   "mixed_ehl.lead_in",       "asperity.model"};
inline constexpr std::array<TradeKnob, 6> kKnobs = {TradeKnob{"positions", "contact.positions"},
                                                    {"grid_spacing", "mixed_ehl.grid_spacing"},
                                                    {"window", "mixed_ehl.window"},
                                                    {"lead_in", "mixed_ehl.lead_in"},
                                                    {"time_step", "mixed_ehl.time_step"},
                                                    {"tolerance", "mixed_ehl.tolerance"}};
inline constexpr std::array<OutputGroup, 5> kGroups = {
    OutputGroup{"/contact",
                "the asperity contact within the mixed-EHL film (contact nodes), time means over each window"},
    OutputGroup{"/mixed_ehl",
                "transient mixed EHL of the flanks' profiles at every position: time means and extremes over each "
                "window (film, shares, pressure, friction, heat, flash temperature)"},
    OutputGroup{"/mixed_ehl/profiles",
                "pressure, film, shear and node state through the contact at the positions kept, at the window's "
                "instant of highest peak pressure and at its middle"},
    OutputGroup{"/statistical",
                "the statistical model (uncoupled) on the same flanks: their spectral moments from the profiles"},
    OutputGroup{"/contact/validity", "where the mixed-EHL answer holds"}};

// The flanks' profiles through a lubricated line contact, solved transiently at every position.
struct MixedEhl {
  static constexpr std::string_view name = "mixed_ehl";
  static constexpr std::string_view description =
      "the flanks' profiles through a lubricated line contact: transient mixed EHL (Reynolds with squeeze, elastic "
      "film, asperity contact by the unified approach) over a window at every position";
  static constexpr FidelityTraits traits{kKeys,   kKnobs, {false, true, true}, "mixed_ehl", "", "max_von_mises_Pa",
                                         kGroups, true};

  struct State {
    FlankSpan span;
    std::array<std::vector<double>, 2> sigma;  // the contact point's arc coordinate on each flank [m]
    RollingFlanks flanks;
    double grid_spacing = 0.0;          // as run [m]
    int nodes_max = 0;                  // at the largest contact
    std::optional<SurfaceModel> model;  // the statistical model of the flanks' profiles
    const SurfaceModel* surface() const { return model ? &*model : nullptr; }
  };
  struct Solution {
    std::optional<StatisticalSolution> statistical;
    std::vector<WindowResult> windows;
    std::optional<WholePath> whole_path;
    Fluid fluid;
    double hardness = 0.0;  // the softer flank's [Pa]
  };
  static State prepare(const FidelityInputs& in, StageClock& clock);
  static Solution solve(const FidelityInputs& in, State& state, const std::vector<double>& share, StageClock& clock);
  static void write(const FidelityInputs& in, State& state, Solution& s, MeshContactResult& r);
};

}  // namespace geartrib::contact::mixed_ehl
