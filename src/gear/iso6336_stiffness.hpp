// ISO 6336-1:2019 method B: single stiffness c' and mesh stiffness c_gamma_alpha of a spur
// pair of solid steel gears (clause 9).
#pragma once

#include "gear/spur_pair.hpp"

namespace geartrib::gear {

struct IsoMeshStiffness {
  double flexibility_q = 0.0;  // q' [m^2/N per m width]: 1/c'_th, ISO in mm um/N
  double theoretical = 0.0;    // c'_th [N/m per m width]
  double single = 0.0;         // c' = c'_th C_M C_R C_B cos(beta) (x load factor below 100 N/mm) [N/m/m]
  double mesh = 0.0;           // c_gamma_alpha = c' (0.75 eps_alpha + 0.25) [N/m/m]
};

// The line load F_t K_A/b below which ISO scales c' down (real gears' profile deviations leave part
// of the face unloaded at light load) [N/m].
inline constexpr double kIsoFullLineLoad = 100e3;  // 100 N/mm

// line_load: F_t K_A / b [N/m]; below kIsoFullLineLoad ISO scales c' by ((F_t K_A/b)/(100 N/mm))^0.25
// (ISO 6336-1:2006 9.3; two public transcriptions agree, docs/theory/ratings.md).
// C_M = 0.8 (solid disc), C_R = 1 (solid), C_B from the basic rack dedendum and angle.
IsoMeshStiffness iso6336_mesh_stiffness(const SpurPair& pair, double tangential_line_load);

// The effective tip relief C_eff = (F_t/b)/(cos alpha_t c_gamma_alpha) [m] (ISO/TR 13989-1 B.1,
// ISO/TS 6336-20): the relief that the mesh's deflection at this load takes up.
double iso_effective_relief(const SpurPair& pair, double tangential_line_load);

}  // namespace geartrib::gear
