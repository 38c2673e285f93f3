// The statistical fidelities: the flanks as a Greenwood-Williamson surface (contact/surface_model.hpp)
// across the Hertz strip at every position, with the Hertz pressure imposed (uncoupled) or solved
// with the bulk (coupled, Greenwood-Tripp; contact/rough_line_contact.hpp), where the models hold
// (contact/validity.hpp) and the highest asperity's stresses.
#pragma once

#include "contact/fidelity.hpp"
#include "contact/rough_line_contact.hpp"
#include "contact/validity.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace geartrib::contact {

// A statistical solve's typed results, one entry per position.
struct StatisticalSolution {
  std::vector<StripResult> strips;
  std::vector<PositionValidity> validity;
  std::vector<HighestAsperity> highest;  // empty unless the asperity stress is asked for
  ValidityVerdict verdict;
  std::vector<std::string> warnings;
};

// The strips on `model` at every position of the path, the asperities carrying `asperity_share`
// of each position's load. progress(done, total) after each position (may be empty).
StatisticalSolution solve_statistical(const FidelityInputs& in, const SurfaceModel& model, StripFidelity fidelity,
                                      const std::vector<double>& asperity_share, StageClock* clock,
                                      const std::function<void(int, int)>& progress);
// Its /contact series (real area, plastic fraction, highest asperity: as asked for) and its
// /contact/validity series.
void add_statistical_series(const StatisticalSolution& s, const SurfaceModel& model, const ContactSettings& cs,
                            std::vector<Series>& contact, std::vector<Series>& validity);

namespace statistical {

inline constexpr std::array<std::string_view, 10> kKeys = {
    "contact.positions",      "contact.outputs",      "contact.height_points", "contact.table_points",
    "contact.strip_points",   "contact.strip_lookup", "contact.stress_table",  "contact.coupled_nodes",
    "roughness.distribution", "asperity.model"};
inline constexpr std::array<OutputGroup, 2> kGroups = {
    OutputGroup{"/contact", "the asperities' contact across the Hertz strip"},
    OutputGroup{"/contact/validity", "where the statistical model holds"}};
inline constexpr std::array<TradeKnob, 12> kUncoupledKnobs = {TradeKnob{"positions", "contact.positions"},
                                                              {"height_points", "contact.height_points"},
                                                              {"table_points", "contact.table_points"},
                                                              {"strip_points", "contact.strip_points"},
                                                              {"strip_lookup", "contact.strip_lookup"},
                                                              {"stress_table", "contact.stress_table"},
                                                              {"fidelity", ""},
                                                              {"dynamics", ""},
                                                              {"integrator", ""},
                                                              {"asperity_model", ""},
                                                              {"film_formula", ""},
                                                              {"inlet_heating", ""}};
inline constexpr std::array<TradeKnob, 11> kCoupledKnobs = {TradeKnob{"positions", "contact.positions"},
                                                            {"height_points", "contact.height_points"},
                                                            {"table_points", "contact.table_points"},
                                                            {"strip_points", "contact.strip_points"},
                                                            {"stress_table", "contact.stress_table"},
                                                            {"fidelity", ""},
                                                            {"dynamics", ""},
                                                            {"integrator", ""},
                                                            {"asperity_model", ""},
                                                            {"film_formula", ""},
                                                            {"inlet_heating", ""}};

// What both statistical fidelities share: the surface model built before the film, the outputs.
template <StripFidelity kStrip>
struct StripFidelityBase {
  struct State {
    std::optional<SurfaceModel> model;
    const SurfaceModel* surface() const { return &*model; }
  };
  using Solution = StatisticalSolution;
  static State prepare(const FidelityInputs& in, StageClock& clock);
  static StatisticalSolution solve(const FidelityInputs& in, State& state, const std::vector<double>& share,
                                   StageClock& clock) {
    return solve_statistical(in, *state.model, kStrip, share, &clock, in.progress);
  }
  static void write(const FidelityInputs& in, State& state, StatisticalSolution& s, MeshContactResult& r);
};

struct Uncoupled : StripFidelityBase<StripFidelity::uncoupled> {
  static constexpr std::string_view name = "uncoupled";
  static constexpr std::string_view description = "Hertz pressure imposed on the rough surface";
  static constexpr FidelityTraits traits{kKeys,  kUncoupledKnobs, {}, "statistical", "", "max_asperity_von_mises_Pa",
                                         kGroups};
};

struct Coupled : StripFidelityBase<StripFidelity::coupled> {
  static constexpr std::string_view name = "coupled";
  static constexpr std::string_view description = "Greenwood-Tripp, bulk and asperities solved together";
  static constexpr FidelityTraits traits{kKeys,         kCoupledKnobs,           {true, false},
                                         "statistical", "contact.coupled_nodes", "max_asperity_von_mises_Pa",
                                         kGroups};
};

}  // namespace statistical
}  // namespace geartrib::contact
