// The deterministic fidelity of the main job (contact.fidelity = "deterministic"): the flanks'
// profiles rolled through the strip at every position of the path (deterministic_contact.hpp),
// the statistical model on the same flanks beside it, and running-in over successive meshes.
#pragma once

#include "contact/contact_options.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/fidelity.hpp"
#include "contact/half_plane_bem.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/statistical/strip_fidelities.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
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
  // Who reads the flanks: the strip's boundary elements average a profile over each element
  // (element_size not finer than its spacing), or the mixed-EHL grid samples it at its nodes
  // (element_size, the nodes' spacing, not coarser than it; 0: chosen by the fidelity once the
  // profiles are made, never coarser).
  // (areal: the areal fidelity's strip and its height maps across the face.)
  enum class Reader { strip, grid, areal };
  Reader reader = Reader::strip;
  double length(int g) const { return last[g] - first[g]; }
  // A measured trace of `length` centred on the flank's active part: where its first point lies.
  double centred_start(int g, double length) const { return 0.5 * (active_first[g] + active_last[g]) - 0.5 * length; }
};

// A flank's height map over its stretch of the involute and a window across the face (the areal
// fidelity's): z(sigma, y) at sigma = start + i dx, y = j dy (periodic across the face) [m].
struct FlankMap {
  int nx = 0, ny = 0;
  double start = 0.0, dx = 0.0, dy = 0.0;  // [m]
  std::vector<double> z;                   // [m], z[j * nx + i]
  // The height at sigma on row j, linear between the map's points (sigma inside the map).
  double at(double sigma, int j) const;
};

// The flanks a run rolls, supplied by the caller for the span: one track per tooth (`teeth[g]`
// of them: 1 for a pair, z for the hunting order), each covering [first, last] of its gear. The
// areal fidelity's patch lay also takes each tooth's map from the caller (the track: its middle row).
struct RollingFlanks {
  std::vector<FlankTrack> pinion, wheel;
  std::vector<FlankMap> pinion_maps, wheel_maps;
};

// What every fidelity that rolls the flanks' profiles shares (the deterministic one, the mixed-EHL
// one): the contact point's arc coordinate on each flank at every position, sigma = rho^2/(2 r_b)
// (Litvin: the involute's arc length from the base circle) [m].
std::array<std::vector<double>, 2> contact_arcs(const gear::SpurPair& pair, const PathState& p);
// The span's ranges from the arcs: the active ranges, the largest step between positions, the
// generated stretch (a module below the base circle to a module beyond the tip) and the positions;
// each flank read from `before[g]` below its active range to `after[g]` above it [m].
void set_span_ranges(FlankSpan& span, const gear::SpurPair& pair, const std::array<std::vector<double>, 2>& sigma,
                     const double before[2], const double after[2]);
// The strip every rolling fidelity solves along the involute (the deterministic one, the areal one):
// +- contact.strip_halfwidths of the path's largest Hertz half-width in elements of
// contact.element_size, the softer flank's hardness capping the pressure, and the span of each flank
// it reads (the grid's reach and two elements more).
void plan_rolling_strip(const FidelityInputs& in, FlankSpan& span, std::array<std::vector<double>, 2>& sigma,
                        DeterministicOptions& options, HalfPlaneGrid& grid);
// The statistical model's uncoupled strips beside a rolling fidelity (none without a model: a flat
// flank), with the lap "statistical_model".
std::optional<StatisticalSolution> statistical_beside(const FidelityInputs& in,
                                                      const std::optional<SurfaceModel>& model,
                                                      const std::vector<double>& share, StageClock& clock);
// The flanks' statistical model from the rolled profiles (each flank's spectral moments over its
// active part, McCool's summits), when both are rough; none when a flank is flat, which a lubricated
// run refuses (core::KeyedError naming the flat flank: the film shares the load with the model).
// `fidelity`: the run's, for the refusal. Built into `model`, with the lap "statistical_surface_table".
void build_rolled_flanks_model(const FidelityInputs& in, const FlankSpan& span, const RollingFlanks& flanks,
                               std::string_view fidelity, StageClock& clock, std::optional<SurfaceModel>& model);
// The statistical model beside a rolling fidelity: its series (prefixed statistical_) in
// /statistical, its surface, plasticity index, asperity model and warnings ("statistical model: ").
void write_statistical_beside(const FidelityInputs& in, const SurfaceModel& model, const StatisticalSolution& s,
                              MeshContactResult& r);
// Persson's theory on the same flanks beside a rolling fidelity (contact/persson_contact.hpp): across
// each position's Hertz strip at the asperities' share of its load, on the composite surface's full
// gradient, gradient_factor times the profiles' summed slope variance m2 (1: lay-directed, the
// profiles extruded across the face; 2: isotropic), capped at the softer flank's hardness. Its series
// in /statistical: statistical_persson_real_area_ratio, _plastic_area_fraction, _mean_real_pressure_Pa;
// its time the stage "persson_beside".
void write_persson_beside(const FidelityInputs& in, const SurfaceModel& m, const std::vector<double>& share,
                          double gradient_factor, MeshContactResult& r);
// The regime of a rolling fidelity's loaded positions (real area > 0): elastic where under 1 % of
// the real area yielded at every one, fully plastic where over 99 % did, else elastic-plastic.
struct RollingRegime {
  int loaded = 0, elastic = 0, plastic = 0;
  void add(double real_area, double plastic_area_fraction);
  std::string name() const;
};
// The path's points A, B, C, D, E at their nearest positions ("" elsewhere).
std::vector<std::string> path_point_names(const PathState& p);
// The positions whose profiles are kept (contact.pressure_profiles: the named points, all or none).
std::vector<bool> kept_profiles(const ContactSettings& cs, const PathState& p);

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
// The case's boundary elements (ContactSettings::boundary_elements) with what the flanks decide: the
// softer flank's hardness capping the pressure and taking the plastic deformation (equal hardness:
// half each), the subsurface stress when asked for.
DeterministicOptions deterministic_options(const ContactSettings& cs, const Material& pinion, const Material& wheel);
// One strip solve's time on one core [s] for `elements` boundary elements.
double strip_solve_seconds(int elements);
DeterministicCost deterministic_cost(const FlankSpan& span, const DeterministicWork& work);

namespace deterministic {

inline constexpr std::array<std::string_view, 10> kKeys = {
    "contact.positions",         "contact.outputs", "contact.element_size", "contact.strip_halfwidths",
    "contact.pressure_profiles", "contact.threads", "running_in.meshes",    "running_in.tolerance",
    "running_in.teeth",          "asperity.model"};
inline constexpr std::array<TradeKnob, 3> kKnobs = {TradeKnob{"positions", "contact.positions"},
                                                    {"element_size", "contact.element_size"},
                                                    {"strip_halfwidths", "contact.strip_halfwidths"}};
inline constexpr std::array<OutputGroup, 4> kGroups = {
    OutputGroup{"/contact", "the flanks' profiles in contact across the strip, by boundary elements"},
    OutputGroup{"/contact/pressure", "the pressure across the strip at the positions kept"},
    OutputGroup{"/statistical",
                "the statistical model (uncoupled) on the same flanks: their spectral moments from the profiles"},
    OutputGroup{"/running_in", "the flanks' plastic deformation carried from mesh to mesh"}};

// A row of the running-in history.
struct HistoryRow {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();  // row 0: before any mesh
  double mesh = 0.0, new_plastic = kNaN, real_area = kNaN, plastic_fraction = kNaN, peak_pressure = kNaN;
  surface::ProfileStatistics flank[2];
  // A mesh's passes (one per tooth pair; each with strips of real_area_ratio, plastic_area_fraction and
  // peak_pressure, and its max_new_plastic): the deepest new plastic deformation, the path's mean real
  // area and plastic share over the passes, the peak pressure.
  template <class Pass>
  void add_passes(const std::vector<const Pass*>& passes) {
    if (passes.empty()) return;
    new_plastic = real_area = plastic_fraction = peak_pressure = 0.0;
    for (const Pass* p : passes) {
      std::vector<double> area, fraction;
      for (const auto& s : p->strips) {
        area.push_back(s.real_area_ratio);
        fraction.push_back(s.plastic_area_fraction);
        peak_pressure = std::max(peak_pressure, s.peak_pressure);
      }
      new_plastic = std::max(new_plastic, p->max_new_plastic);
      real_area += path_mean(area) / static_cast<double>(passes.size());
      plastic_fraction += path_mean(fraction) / static_cast<double>(passes.size());
    }
  }
};

// The flanks' profiles rolled through the strip by boundary elements, with the statistical model
// on the same flanks beside it and running-in over successive meshes.
struct BoundaryElements {
  static constexpr std::string_view name = "deterministic";
  static constexpr std::string_view description =
      "the flanks' profiles in contact through boundary elements, sliding past each other along the path";
  static constexpr FidelityTraits traits{kKeys,   kKnobs, {false, true}, "deterministic", "", "max_von_mises_Pa",
                                         kGroups, true};

  struct State {
    FlankSpan span;
    DeterministicOptions options;
    HalfPlaneGrid grid;
    std::array<std::vector<double>, 2> sigma;  // the contact point's arc coordinate on each flank [m]
    int teeth[2] = {1, 1};
    bool hunting = false;
    RollingFlanks flanks;
    std::optional<SurfaceModel> model;  // the statistical model of the flanks' profiles (both rough)
    const SurfaceModel* surface() const { return model ? &*model : nullptr; }
  };
  struct Solution {
    std::optional<StatisticalSolution> statistical;
    std::vector<double> share;  // the asperities' share of each position's load
    MeshPass first;             // the first mesh's strips and pressure profiles
    std::vector<HistoryRow> history;
    std::optional<RunningInResult> running_in;
  };
  static State prepare(const FidelityInputs& in, StageClock& clock);
  static Solution solve(const FidelityInputs& in, State& state, const std::vector<double>& share, StageClock& clock);
  static void write(const FidelityInputs& in, State& state, Solution& s, MeshContactResult& r);
};

}  // namespace deterministic

// The running-in history's series (/running_in: mesh, new plastic deformation, the path's mean real
// area and plastic fraction, the peak pressure, each flank's Rq, peak height, Rsk and summit radius),
// shared by the rolling fidelities that run in.
void write_running_in_history(const std::vector<deterministic::HistoryRow>& history, RunningInResult& ri);

}  // namespace geartrib::contact
