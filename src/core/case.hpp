// A case (scene): the gear pair, the bodies' materials and flanks, the operating point and the
// contact-model choices, all SI. Read from gears/*.toml by io::load_case; the physics takes the
// pieces it needs from here.
#pragma once

#include "material/material.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace geartrib {

// Basic-rack and pair geometry (ISO 53 basic rack by default).
struct GearPairSpec {
  double module = 0.0;                    // m [m]
  double pressure_angle = 0.0;            // alpha [rad]
  double face_width = 0.0;                // b [m]
  double addendum_coefficient = 1.0;      // h_aP / m
  double dedendum_coefficient = 1.25;     // h_fP / m
  double root_radius_coefficient = 0.38;  // rho_fP / m
};

// The rough flank of one gear, as far as the asperity models see it.
struct FlankSpec {
  double summit_radius = 0.0;  // mean asperity tip radius [m]
  double ra = 0.0;             // arithmetic mean roughness Ra [m]
};

struct GearSpec {
  int teeth = 0;
  double profile_shift = 0.0;  // x [-]
  std::string material_file;   // as written in the case file
  Material material;
  FlankSpec flank;
};

struct OperatingPoint {
  double pinion_torque = 0.0;  // [N m]
  double pinion_speed = 0.0;   // [rad/s]
};

// Single-asperity settings: the model by name, per-model constant overrides, the measured
// side-contact offsets, and the cylinder asperity of seed section 5.
struct AsperitySettings {
  std::string model = "continuous";
  std::map<std::string, std::vector<std::pair<std::string, double>>> constants;  // model -> (name, value)
  double measured_axis_offset = 0.0;  // seed's d0 [m]
  double measured_tip_gap = 0.0;      // seed's y0 [m]
  double cylinder_tip_radius = 0.0;   // R_m [m]
  double cylinder_yield_constant = 1.64;  // C of delta_pc
};

struct Case {
  std::string title;
  std::string source;
  GearPairSpec gear_pair;
  GearSpec pinion;
  GearSpec wheel;
  OperatingPoint operating;
  double friction_coefficient = 0.0;  // mu [-]
  AsperitySettings asperity;
};

}  // namespace geartrib
