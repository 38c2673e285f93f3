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
//  - extruded: its profile along the involute repeated across the face (the profile fidelity's flank:
//    an endless lay across the profile);
//  - isotropic: a random surface with a generated ground profile's Rq and Gaussian correlation in
//    every direction (isotropic superfinishing, vibratory finishing, shot peening);
//  - directional: the same with the correlation across the face lay_ratio times that along the
//    involute (a ground or hobbed spur flank's lay across the profile, of finite length: Peklenik's
//    gamma); 1 is isotropic, and it tends to extruded as the ratio grows;
//  - patch: from the flank's measured topography, a patch smaller than the flank, synthesised from its
//    areal spectrum with random phases or tiled (ArealPatch; surface/areal_synthesis.hpp).
enum class ArealLay { extruded, isotropic, directional, patch };
std::span<const NamedChoice<ArealLay>> areal_lay_choices();

// How a measured patch makes a flank-sized map: synthesis (its areal spectrum, random phases seeded by
// the topography's synthesis_seed) or tiled (the patch itself, mirrored at its sides).
enum class ArealPatch { synthesis, tiled };
std::span<const NamedChoice<ArealPatch>> areal_patch_choices();

struct ArealMeshOptions {
  static constexpr int kMinPoints = 4, kMaxPoints = 4096;
  static constexpr double kMaxLayRatio = 1000.0;
  double window = 64e-6;  // across the face, periodic [m]
  int points = 128;       // across the face
  ArealLay lay = ArealLay::isotropic;
  // Directional: the correlation length across the face over that along the involute. Default 8:
  // ground surfaces' Peklenik gamma lies from about 3 to well over 10 (Peklenik, Proc. IMechE 182
  // (1967) 108; Thomas, Rough Surfaces, 2nd ed., 1999, ch. 5).
  double lay_ratio = 8.0;
  ArealPatch patch = ArealPatch::synthesis;
  double tolerance = 1e-6;  // the solver's residual (contact/areal/areal_bem.hpp ArealOptions::tolerance)
  double spacing() const { return window / points; }  // across the face [m]
  void validate() const;                              // core::KeyedError naming the field
};

}  // namespace geartrib::contact::areal
