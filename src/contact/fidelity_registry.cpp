#include "contact/fidelity_registry.hpp"

#include "contact/fidelities.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace geartrib::contact {

const std::vector<FidelityEntry>& fidelities() {
  static const std::vector<FidelityEntry> list = [] {
    std::vector<FidelityEntry> out;
    for_each_fidelity([&]<class F>(FidelityTag<F>) { out.push_back({F::name, F::description, F::traits}); });
    return out;
  }();
  return list;
}

const FidelityEntry& find_fidelity(std::string_view name) {
  std::string known;
  for (const FidelityEntry& e : fidelities()) {
    if (e.name == name) return e;
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  throw std::invalid_argument("unknown contact fidelity '" + std::string(name) + "' (known: " + known + ")");
}

std::string dry_case_rule(const FidelityEntry& f) {
  if (!f.traits.needs.lubricant) return "";
  return fmt::format(
      "\"{}\" solves the lubricant's film between the flanks, and the case is dry: give a [lubricant] (its file, or "
      "its data) and operating.oil_temperature, or choose a dry fidelity (deterministic, uncoupled, coupled)",
      f.name);
}

std::vector<std::string> fidelity_names() {
  std::vector<std::string> out;
  for (const FidelityEntry& e : fidelities()) out.emplace_back(e.name);
  return out;
}

std::string fidelity_descriptions() {
  std::string out;
  for (const FidelityEntry& e : fidelities())
    out += (out.empty() ? "" : "; ") + std::string(e.name) + ": " + std::string(e.description);
  return out;
}

std::string_view group_description(std::string_view fidelity, std::string_view path) {
  for (const OutputGroup& g : find_fidelity(fidelity).traits.groups)
    if (g.path == path) return g.description;
  return {};
}

}  // namespace geartrib::contact
