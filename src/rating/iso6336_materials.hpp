// The material side of an ISO 6336 rating: ISO 6336-5's allowable stress numbers by material
// group and quality, the life factors of ISO 6336-2/-3, the slip-layer and surface factors of
// ISO 6336-3 method B, and the size factors. Hardness is Vickers (HV) throughout; SI stresses.
#pragma once

#include "core/named_choices.hpp"

#include <span>
#include <string>

namespace geartrib::rating {

// ISO 6336-5 material groups rated here (St, V, Eh of its figures; nitrided and cast materials are
// not offered).
enum class MaterialGroup {
  none,                     // not rated (a material file without [rating])
  normalized,               // St: normalised low-carbon wrought steel
  through_hardened_carbon,  // V: through-hardened wrought carbon steel
  through_hardened_alloy,   // V: through-hardened wrought alloy steel
  case_hardened,            // Eh: case-carburised wrought steel
};
std::span<const NamedChoice<MaterialGroup>> material_group_choices();
const char* material_group_name(MaterialGroup g);
// ISO 6336-5 material quality: ML modest, MQ the normal industrial one, ME the highest.
enum class MaterialQuality { ML, MQ, ME };
std::span<const NamedChoice<MaterialQuality>> material_quality_choices();
const char* material_quality_name(MaterialQuality q);

// One gear's rating data (a material file's [rating] table).
struct MaterialGrade {
  MaterialGroup group = MaterialGroup::none;
  MaterialQuality quality = MaterialQuality::MQ;
  double surface_hardness = 0.0;  // HV of the flank (Eh: the case)
  double contact_limit = 0.0;     // sigma_Hlim given [Pa]; 0: ISO 6336-5's line at the hardness
  double bending_limit = 0.0;     // sigma_Flim given [Pa]; 0: ISO 6336-5's line
  std::string source;             // where the grade and the hardness come from
  bool assumed = false;           // the grade or the hardness is assumed, not measured
  void validate() const;          // throws core::KeyedError naming the field ("surface_hardness")
};

// An allowable stress number and whether its hardness lay inside the line's range.
struct Allowable {
  double value = 0.0;  // [Pa]
  bool in_range = true;
  std::string clause;  // e.g. "ISO 6336-5 Fig. 9, MQ: 0.963 HV + 283"
};
// sigma_Hlim and sigma_Flim of ISO 6336-5's lines (A x + B, x the hardness); given values pass
// through. Outside the line's hardness range the line is evaluated at the nearest end and flagged.
Allowable contact_allowable(const MaterialGrade& g);
Allowable bending_allowable(const MaterialGrade& g);

// Life factors (ISO 6336-2 Table 2 / ISO 6336-3 Table 3, the curves for steel without pitting
// allowed): log-log between the static and the reference point, 1 beyond the knee when
// `optimum` (the standard's upper branch: optimum lubrication, material, manufacture and
// experience), else falling to 0.85 at 1e10 cycles.
double contact_life_factor(MaterialGroup g, double load_cycles, bool optimum);  // Z_NT
double bending_life_factor(MaterialGroup g, double load_cycles, bool optimum);  // Y_NT

// ISO 6336-2 9 and 10: lubricant and speed factors from sigma_Hlim [Pa], nu40 [m^2/s], v [m/s].
double lubricant_factor(double contact_limit, double viscosity_40);  // Z_L
double speed_factor(double contact_limit, double pitch_line_speed);  // Z_v
// ISO 6336-2 11: roughness factor from the mean peak-to-valley roughness Rz of the pair's flanks
// and the relative radius of curvature at the pitch point [m]: (3 um / Rz10)^C_ZR.
double roughness_factor(double contact_limit, double mean_rz, double relative_radius);  // Z_R

// ISO 6336-3 method B relative notch sensitivity from the slip-layer thickness rho' of the group
// (and, through-hardened, the 0.2 % proof stress [Pa]): Y_deltarelT.
double slip_layer_thickness(MaterialGroup g, double proof_stress);  // rho' [m]
// Whether the proof stress lies inside the rows of Table 4 (Eh: any); outside, the end row is taken.
bool slip_layer_in_range(MaterialGroup g, double proof_stress);
double relative_notch_sensitivity(MaterialGroup g, double proof_stress, double notch_parameter);
// ISO 6336-3 method B relative surface factor from the root's Rz [m].
double relative_surface_factor(MaterialGroup g, double root_rz);  // Y_RrelT
// ISO 6336-2 size factor from the module [m]: 1, but case-hardened 1.05 - 0.005 m_n for
// 10 < m_n < 30 mm (0.9 beyond).
double contact_size_factor(MaterialGroup g, double module);  // Z_X
// ISO 6336-3 size factor from the module [m].
double bending_size_factor(MaterialGroup g, double module);  // Y_X

}  // namespace geartrib::rating
