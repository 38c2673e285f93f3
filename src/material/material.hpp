// Material data of one gear body, SI units throughout.
#pragma once

#include "rating/iso6336_materials.hpp"

#include <string>
#include <vector>

namespace geartrib {

// One point of the plastic flow curve: true stress [Pa] at an equivalent plastic strain [-].
struct FlowPoint {
  double stress = 0.0;
  double plastic_strain = 0.0;
};

struct Material {
  std::string name;
  double youngs_modulus = 0.0;                // E [Pa]
  double poisson_ratio = 0.0;                 // nu [-], in (0, 0.5)
  double yield_strength = 0.0;                // sigma_s / S_y [Pa]
  double hardness = 0.0;                      // H [Pa]: 2.8 S_y (Tabor, seed section 2), measured, or 2.8 sigma_f(0.08)
  std::string hardness_rule = "tabor-yield";  // "tabor-yield" (2.8 S_y), "flow-curve" or "given"
  double density = 0.0;                       // [kg/m^3]
  double thermal_conductivity = 0.0;          // lambda [W/(m K)]; 0: not given (flash temperature needs it)
  double specific_heat = 0.0;                 // c [J/(kg K)]; 0: not given
  std::vector<FlowPoint> flow_curve;          // plastic part of the stress-strain curve (seed section 6)
  rating::MaterialGrade grade;                // ISO 6336-5 data of the file's [rating] table; group none: not rated

  // Throws std::invalid_argument naming the first rule broken (positive moduli, 0 < nu < 0.5,
  // H >= S_y, flow curve starting at zero strain with strictly increasing strain and
  // non-decreasing stress).
  void validate() const;

  // Flow stress [Pa] at an equivalent plastic strain: linear between table points, constant
  // beyond the last (perfectly plastic continuation); S_y when no table is given.
  double flow_stress(double plastic_strain) const;
};

// The Young's moduli a material may have (a material file's range, docs/reference/units.md):
// beyond them no engineering material lies and the contact arithmetic is not meant to go.
inline constexpr double kMinYoungsModulus = 1e6, kMaxYoungsModulus = 1e13;  // [Pa]

// Tabor's hardness-yield ratio used by the seed (H = 2.8 sigma_s, section 2).
inline constexpr double kTaborHardnessRatio = 2.8;
// Tabor (The Hardness of Metals, 1951): a work-hardening metal's indentation hardness is about
// 2.8 times its flow stress at a representative plastic strain of about 0.08 (Vickers pyramid;
// for a ball 0.2 a/D). The representative strain geartrib takes for hardness = "flow-curve".
inline constexpr double kTaborRepresentativeStrain = 0.08;
// H = 2.8 sigma_f(0.08) from the flow curve (Tabor); S_y-based 2.8 S_y without one.
double tabor_flow_curve_hardness(const Material& m);

// Composite (contact) modulus 1/E_t = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (seed section 1;
// Johnson's E*). For two 45-steel bodies: E/(2(1 - nu^2)) = 113.19 GPa.
double composite_modulus(const Material& a, const Material& b);

}  // namespace geartrib
