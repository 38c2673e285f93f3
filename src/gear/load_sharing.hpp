// How the transmitted load divides between tooth pairs in contact at the same instant.
#pragma once

#include "core/named_choices.hpp"
#include "gear/spur_pair.hpp"
#include "gear/tooth_stiffness.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace geartrib::gear {

enum class LoadSharing {
  iso,            // ISO/TS 6336-22 method B, unmodified spur profiles
  stiffness,      // in proportion to the tooth-pair stiffness (equal deflection, no profile errors)
  compatibility,  // load-deflection compatibility with profile modifications (gear/tooth_contact.hpp)
};
std::span<const NamedChoice<LoadSharing>> load_sharing_choices();  // mesh.load_sharing
std::string_view to_string(LoadSharing method);

// ISO/TS 6336-22 (method B) load-sharing factor of one pair at s, for 1 <= eps_alpha < 2:
// 1/3 at A rising linearly to 2/3 at B, 1 from B to D, 2/3 at D falling to 1/3 at E. At B and D
// it takes the double-contact value (2/3) unless `single_side` asks for the single-pair one (1).
double iso_load_sharing_factor(const PathOfContact& path, double s, bool single_side = false);

// The positions of every pair in contact when one pair is at s: s + k p_b within [A, E].
std::vector<double> pairs_in_contact(const PathOfContact& path, double s);

// Shares of the pairs at `positions` (as from pairs_in_contact), summing to 1. `stiffness` is
// needed for LoadSharing::stiffness. For eps_alpha >= 2 the ISO factors are normalised.
std::vector<double> load_shares(const PathOfContact& path, const std::vector<double>& positions, LoadSharing method,
                                const MeshStiffnessModel* stiffness);

}  // namespace geartrib::gear
