// The registered contact fidelities as data, for whatever lists or describes them: the case
// table's contact.fidelity choices, `geartrib run --fidelity`, the sweep, the trade tool's knobs,
// the HDF5 writer and the Python module. The list itself is contact/fidelities.hpp; each entry is a
// type in its own folder (contact/fidelity.hpp says what it declares).
#pragma once

#include "contact/contact_options.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::contact {

// A knob of the trade tool (`geartrib tradeoff`): its name and the case key whose ladder it runs,
// or no key: one of the trade tool's own knobs by name (fidelity, dynamics, integrator,
// asperity_model, film_formula, inlet_heating, ladder).
struct TradeKnob {
  std::string_view name, key;
};

// An output group a fidelity writes, with its meaning (the HDF5 group's description).
struct OutputGroup {
  std::string_view path, description;
};

// What a fidelity needs of the stages before it.
struct FidelityNeeds {
  bool nonlinear_solver = false;  // a nonlinear solver (KINSOL) for its strips
  bool flank_profiles = false;    // the flanks' profiles along the involute (FlankSource)
  bool lubricant = false;         // a lubricated case (its film stage, FidelityInputs::film): a dry one is refused
};

struct FidelityTraits {
  std::span<const std::string_view> keys;  // the case keys a run of it reads (beyond the path's)
  std::span<const TradeKnob> knobs;        // the trade tool's knobs for it, in its order
  FidelityNeeds needs;
  // Fidelities of one family are the settings of the trade tool's `fidelity` knob, in the list's
  // order; `setting_key`: the key whose ladder gives this one's settings there (empty: one setting).
  std::string_view family, setting_key;
  std::string_view peak_stress;         // its peak-stress series, as the trade tool compares it
  std::span<const OutputGroup> groups;  // the groups it writes beyond /mesh and /lubrication
  bool statistical_beside = false;      // a statistical model runs beside it (its notes prefixed)
};

struct FidelityEntry {
  std::string_view name, description;
  FidelityTraits traits;
  ContactFidelity id() const { return ContactFidelity(name); }
};

// Every registered fidelity, in the list's order.
const std::vector<FidelityEntry>& fidelities();
// The one of that name; throws std::invalid_argument naming the known ones.
const FidelityEntry& find_fidelity(std::string_view name);
inline const FidelityEntry& find_fidelity(ContactFidelity f) { return find_fidelity(f.name()); }
// The fidelity rolls the flanks' profiles (the deterministic one): a run of it reads their lines.
inline bool rolls_flank_profiles(ContactFidelity f) { return find_fidelity(f).traits.needs.flank_profiles; }
// The refusal of a dry case by a fidelity that needs a lubricant ("" when it needs none): the rule
// the case loader and the mesh cycle state at contact.fidelity.
std::string dry_case_rule(const FidelityEntry& f);
std::vector<std::string> fidelity_names();
// "name: description; name: description; ..." (the case table's documentation).
std::string fidelity_descriptions();
// The description of an output group the run's fidelity writes ("" if none).
std::string_view group_description(std::string_view fidelity, std::string_view path);

}  // namespace geartrib::contact
