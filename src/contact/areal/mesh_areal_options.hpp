// The areal fidelity's options (contact.fidelity = "areal", the [areal] keys): the window across the
// face, its points, how the flanks' height maps are made from their roughness, and the solver's
// tolerance. The strip along the involute is the deterministic fidelity's (contact.element_size,
// contact.strip_halfwidths). Held whole in ContactSettings.
#pragma once

#include "core/named_choices.hpp"

#include <span>
#include <string_view>

namespace geartrib::contact::areal {

// How a flank's height map is made across the face from the flank as the case gives it:
// extruded, its profile along the involute repeated across the face (the profile fidelity's flank:
// a lay across the profile, as a ground or hobbed spur flank); isotropic, a random surface with the
// profile's statistics in every direction (a generated ground profile's Gaussian correlation turned
// about the normal: isotropic superfinishing, vibratory finishing, shot peening).
enum class ArealLay { extruded, isotropic };
std::span<const NamedChoice<ArealLay>> areal_lay_choices();

struct ArealMeshOptions {
  static constexpr int kMinPoints = 4, kMaxPoints = 4096;
  double window = 64e-6;  // across the face, periodic [m]
  int points = 128;       // across the face
  ArealLay lay = ArealLay::isotropic;
  double tolerance = 1e-6;  // the solver's residual (contact/areal/areal_bem.hpp ArealOptions::tolerance)
  double spacing() const { return window / points; }  // across the face [m]
  void validate() const;                              // core::KeyedError naming the field
};

}  // namespace geartrib::contact::areal
