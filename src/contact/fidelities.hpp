// The one list of contact fidelities: a new one is its folder (a type as contact/fidelity.hpp
// describes) and its line here. The mesh cycle (contact/mesh_contact.cpp) visits the list; the
// registry's data (contact/fidelity_registry.hpp) is read from it.
#pragma once

#include "contact/areal/mesh_areal.hpp"
#include "contact/deterministic/mesh_deterministic.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/mixed_ehl/mesh_mixed_ehl.hpp"
#include "contact/statistical/strip_fidelities.hpp"

#include <string>
#include <string_view>
#include <tuple>

namespace geartrib::contact {

using FidelityList = std::tuple<statistical::Uncoupled, statistical::Coupled, deterministic::BoundaryElements,
                                mixed_ehl::MixedEhl, areal::Areal>;

template <class Fidelity>
struct FidelityTag {
  using type = Fidelity;
};

// Calls f(FidelityTag<F>{}) for every fidelity F, in the list's order.
template <class F>
void for_each_fidelity(F&& f) {
  [&]<class... Fs>(std::tuple<Fs...>*) { (f(FidelityTag<Fs>{}), ...); }(static_cast<FidelityList*>(nullptr));
}

// Calls f(FidelityTag<F>{}) for the fidelity named `name`; throws std::invalid_argument (listing
// the known names) for an unknown one.
template <class F>
void visit_fidelity(std::string_view name, F&& f) {
  bool found = false;
  std::string known;
  for_each_fidelity([&]<class Fidelity>(FidelityTag<Fidelity> tag) {
    known += (known.empty() ? "" : ", ") + std::string(Fidelity::name);
    if (found || Fidelity::name != name) return;
    found = true;
    f(tag);
  });
  if (!found)
    throw std::invalid_argument("unknown contact fidelity '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace geartrib::contact
