// The equivalent single-asperity problem: a sphere of radius R against a rigid flat, with the
// composite modulus of the two bodies and the strength of the softer one (seed section 1).
#pragma once

#include "material/material.hpp"

namespace geartrib::asperity {

struct ContactPair {
  double radius = 0.0;          // R = R1 R2 / (R1 + R2) [m]
  double modulus = 0.0;         // E_t, composite modulus [Pa]
  double youngs_modulus = 0.0;  // E of the softer body [Pa] (Jackson-Green's B uses S_y/E)
  double poisson_ratio = 0.0;   // nu of the softer body [-]
  double yield_strength = 0.0;  // S_y of the softer body [Pa]
  double hardness = 0.0;        // H of the softer body [Pa]

  void validate() const;  // throws std::invalid_argument on a non-physical value
};

// Builds the pair from the two bodies and their asperity tip radii [m]. The softer body (lower
// hardness) supplies nu, S_y and H.
ContactPair make_contact_pair(const Material& body1, const Material& body2, double tip_radius1, double tip_radius2);

// Same pair with another radius (side contact uses R0, seed section 2.1).
ContactPair with_radius(ContactPair pair, double radius);

}  // namespace geartrib::asperity
