// Single-asperity settings: the model by name (asperity/model.hpp's registry), per-model constant
// overrides, the measured side-contact offsets, and the cylinder asperity of seed section 5.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::asperity {

struct AsperitySettings {
  std::string model = "continuous";
  std::map<std::string, std::vector<std::pair<std::string, double>>> constants;  // model -> (name, value)
  double measured_axis_offset = 0.0;                                             // seed's d0 [m]
  double measured_tip_gap = 0.0;                                                 // seed's y0 [m]
  double cylinder_tip_radius = 0.0;       // R_m [m]; 0: not given (only the cylinder studies need it)
  double cylinder_yield_constant = 1.64;  // C of delta_pc
  void validate() const;                  // throws core::KeyedError naming the field
};

}  // namespace geartrib::asperity
