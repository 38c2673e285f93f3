// The areal fidelity of the main job (contact.fidelity = "areal"): at every position of the path,
// the Hertz strip's window of both flanks' height maps in contact through areal FFT boundary
// elements (contact/areal/areal_bem.hpp): open (zero-padded) along the involute over the
// deterministic fidelity's strip, periodic across the face over areal.window. Each flank's map is
// read where it has rolled to, sliding past the other as the profile fidelity rolls its profiles;
// the pressure capped at the softer flank's hardness; the statistical model on the same flanks
// beside it. Running-in as the profile fidelity does it: each mesh lowers the maps by the plastic
// interpenetration where the pressure is capped (the softer flank takes it; equal hardness, half each),
// until shakedown.
#pragma once

#include "contact/areal/areal_bem.hpp"
#include "contact/deterministic/mesh_deterministic.hpp"
#include "contact/fidelity.hpp"

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace geartrib::contact::areal {

// Each flank's generated maps for the span, one per tooth (seed + tooth), at the elements' spacing
// along the involute (read between its points by linear interpolation, which lowers its Rq by
// (e/lambda)^2/6: 0.04 % on the shipped case):
//  - isotropic, directional: a Gaussian random surface with the flank's generated ground profile's Rq
//    and correlation length along the involute, and across the face that length (isotropic) or
//    areal.lay_ratio times it (directional);
//  - extruded: the profile's element means repeated across the face (made only for running-in, which
//    lowers them differently row by row; without it the strip reads the profiles).
// Throws core::KeyedError ("areal.lay", "areal.window", "areal.points") when a flank cannot give the
// lay or the window is too narrow. (The patch lay's maps come with the flanks: RollingFlanks.)
std::array<std::vector<FlankMap>, 2> flank_maps(const FidelityInputs& in, const FlankSpan& span,
                                                const RollingFlanks& flanks);

// The bytes an areal run holds at its peak: the flanks' maps (teeth[g] of gear g; none for an
// extruded lay without running-in) and the window's solve.
double areal_run_bytes(const FlankSpan& span, const ArealMeshOptions& o, const int teeth[2]);

// One position's answer, per unit face width where it says so.
struct ArealStrip {
  double real_area_ratio = 0.0;         // real area over the Hertz band 2b x window
  double real_area_per_width = 0.0;     // real area over the window's width [m]
  int contact_spots = 0;                // in the window
  double peak_pressure = 0.0;           // [Pa]
  double mean_real_pressure = 0.0;      // load over real area [Pa]
  double plastic_area_fraction = 0.0;   // capped over contact
  double plastic_area_per_width = 0.0;  // [m]
  double max_von_mises = 0.0;           // on the planes below the window [Pa]
  double max_von_mises_depth = 0.0;     // [m]
  double mean_gap = 0.0;                // over the Hertz band [m]
  bool edge_loaded = false;             // pressure at the window's ends along the involute
  bool converged = true;
  int iterations = 0;
  std::vector<double> pressure;  // across the strip, the mean across the face [Pa] (kept positions)
};

// The planes of the subsurface stress at a position: k element sizes (k = 1, 2, 4, 8, 16, 32: the
// asperities' scale) and 0.786 b (the smooth line contact's maximum, Johnson 1985 section 4.2) [m].
std::vector<double> stress_depths(double element_size, double hertz_half_width);

inline constexpr std::array<std::string_view, 15> kKeys = {
    "contact.positions",         "contact.outputs",  "contact.element_size", "contact.strip_halfwidths",
    "contact.pressure_profiles", "areal.window",     "areal.points",         "areal.lay",
    "areal.lay_ratio",           "areal.patch",      "areal.tolerance",      "running_in.meshes",
    "running_in.tolerance",      "running_in.teeth", "asperity.model"};
// (Not the positions: the ladder's finest, hundreds of positions, is minutes of the areal solver.)
// "ladder": GW, Persson, the profile fidelity and this one on the same flanks (geartrib tradeoff).
inline constexpr std::array<TradeKnob, 4> kKnobs = {TradeKnob{"element_size", "contact.element_size"},
                                                    {"points", "areal.points"},
                                                    {"tolerance", "areal.tolerance"},
                                                    {"ladder", ""}};
inline constexpr std::array<OutputGroup, 4> kGroups = {
    OutputGroup{"/contact",
                "both flanks' height maps in contact by areal boundary elements, a window periodic "
                "across the face"},
    OutputGroup{"/contact/pressure", "the pressure across the strip (its mean across the face) at the positions kept"},
    OutputGroup{"/statistical",
                "the statistical model (uncoupled) on the same flanks: their spectral moments from the profiles"},
    OutputGroup{"/running_in", "the flanks' plastic deformation carried from mesh to mesh, on their height maps"}};

struct Areal {
  static constexpr std::string_view name = "areal";
  static constexpr std::string_view description =
      "both flanks' height maps in contact through areal boundary elements (periodic across the face), sliding "
      "past each other along the path";
  static constexpr FidelityTraits traits{kKeys, kKnobs, {false, true}, "areal", "", "max_von_mises_Pa", kGroups, true};

  struct State {
    FlankSpan span;
    DeterministicOptions options;  // the strip, the cap, the Poisson ratio and the plastic share
    HalfPlaneGrid grid;            // the strip's elements along the involute
    std::array<std::vector<double>, 2> sigma;
    int teeth[2] = {1, 1};  // each gear's flanks held (the hunting order: every tooth's)
    bool hunting = false;
    RollingFlanks flanks;
    std::array<std::vector<FlankMap>, 2> maps;  // each tooth's; empty: the extruded lay reads the profiles
    // Persson's full gradient over the profiles' slope variance along the involute (1 extruded, 2
    // isotropic, 1 + 1/ratio^2 directional, the maps' own for a patch).
    double gradient_factor = 1.0;
    std::optional<SurfaceModel> model;
    const SurfaceModel* surface() const { return model ? &*model : nullptr; }
  };
  struct Solution {
    std::optional<StatisticalSolution> statistical;
    std::vector<double> share;       // the asperities' share of each position's load
    std::vector<ArealStrip> strips;  // the first mesh's
    std::vector<deterministic::HistoryRow> history;
    std::optional<RunningInResult> running_in;
  };
  static State prepare(const FidelityInputs& in, StageClock& clock);
  static Solution solve(const FidelityInputs& in, State& state, const std::vector<double>& share, StageClock& clock);
  static void write(const FidelityInputs& in, State& state, Solution& s, MeshContactResult& r);
};

}  // namespace geartrib::contact::areal
