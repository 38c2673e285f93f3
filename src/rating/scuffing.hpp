// Scuffing and micropitting ratings of a spur pair: ISO/TS 6336-20's flash-temperature method (its
// contact temperature from the lubricated path, at the load factors), ISO/TS 6336-21's
// integral-temperature method (closed form at the pinion tip and over the path), their scuffing
// temperatures from the oil's FZG A/8.3/90 failure load stage, and ISO/TS 6336-22's micropitting
// safety from the path's least lambda_GF.
//
// Sources: the equation numbers as a public implementation of ISO/TR 13989-1/-2:2000 cites them
// (the standards' texts were not available; /work notes of the session and docs/theory/ratings.md
// mark each read, derived or assumed). Where it holds (ISO/TS 6336-20/-21 scope): alpha_n 15..25 deg,
// 1 <= eps_alpha <= 2.5, v < 80 m/s; outside: flagged.
#pragma once

#include "gear/spur_pair.hpp"
#include "rating/load_capacity.hpp"

#include <string>
#include <vector>

namespace geartrib::rating {

inline constexpr double kMaxScuffingSpeed = 80.0;  // [m/s]: the scuffing methods' tests (ISO/TS 6336-20/-21 scope)

// ISO/TS 6336-20 (ISO/TR 13989-1 eq. 99): the scuffing temperature from the FZG A/8.3/90 failure
// load stage: theta_S = 80 degC + (0.85 + 1.4 X_W) X_L S_FZG^2 K [K], X_W the structural factor.
double fzg_scuffing_temperature(int stage, double structural_factor, double lubricant_factor);
// ISO/TR 13989-2 eq. (97): the pinion torque of the FZG A gear at load stage S: 3.726 S^2 N m.
double fzg_a_torque(int stage);
// The structural factor X_W of a material group (through-hardened 1.0, case-carburised with the
// average retained austenite 1.0).
double structural_factor(MaterialGroup g);

// ISO/TS 6336-22 (ISO/TR 15144-1) method B's permissible film: lambda_GFP = 1.4 W_W lambda_GFT, with
// lambda_GFT the test gear's least lambda_GF at the oil's GF-C/8.3/90 failure stage and W_W the
// material factor (case-carburised 1.0, through-hardened 0.5). Recollected from ISO/TR 15144-1:2010,
// not confirmed in a source (docs/theory/ratings.md).
double micropitting_material_factor(MaterialGroup g);  // W_W
inline constexpr double kMicropittingTestFactor = 1.4;

// The integral-temperature method's inputs (SI).
struct IntegralTemperatureInputs {
  const gear::SpurPair* pair = nullptr;
  double tangential_force = 0.0;      // F_t [N]
  double pitch_line_speed = 0.0;      // v [m/s]
  double load_factor = 1.0;           // K_A K_v K_Hbeta K_Halpha (K_Balpha = K_Halpha, K_Bbeta = K_Hbeta)
  double application_factor = 1.0;    // K_A (C_eff)
  double single_stiffness = 0.0;      // c' [N/m^2] (C_eff)
  double eta_oil = 0.0;               // at the oil temperature [Pa s]
  double viscosity_40 = 0.0;          // nu40 [m^2/s] (the test's flash temperature)
  double oil_temperature = 0.0;       // theta_oil [K]
  double mean_ra = 0.0;               // (Ra1 + Ra2)/2 [m]
  double lubricant_factor = 1.0;      // X_L
  double thermo_elastic_factor = 50;  // X_M (ISO units)
  double oil_supply_factor = 1.0;     // X_S: dip 1.0, spray 1.2
  double tip_relief[2] = {0.0, 0.0};  // C_a1, C_a2 [m]
  int accuracy_grade = 6;             // tip relief credited only for Q <= 6
  double structural_factor = 1.0;     // X_W of the rated pair (X_WrelT = X_W / 1)
  int fzg_stage = 0;                  // A/8.3/90 failure stage; 0: no permissible temperature
};
struct IntegralTemperature {
  std::vector<RatingFactor> factors;
  double integral_temperature = 0.0;     // theta_int [K]
  double permissible_temperature = 0.0;  // theta_intS [K]; 0: no FZG stage
  double safety = 0.0;                   // S_intS = theta_intS/theta_int in degC (the standard's); 0: none
  std::vector<std::string> findings;
};
IntegralTemperature iso_integral_temperature(const IntegralTemperatureInputs& in);

}  // namespace geartrib::rating
