// Flash and contact temperature of a gear contact: Blok's flash temperature, the ISO/TS 6336-20
// flash-temperature method with its mean friction coefficient, the ISO/TS 6336-21/-22 mean
// friction coefficient and the published gear-mean friction laws beside it, bulk temperature and
// scuffing safety, and the ISO/TS 6336-22 film h_Y.
#pragma once

#include "core/named_choices.hpp"
#include "lubrication/lubricant.hpp"

#include <span>
#include <string>
#include <vector>

namespace geartrib::lubrication {

// Thermal contact coefficient B_M = sqrt(lambda rho c) of a body [W s^0.5/(m^2 K)].
double thermal_contact_coefficient(double conductivity, double density, double specific_heat);

// Blok's flash temperature (Blok 1937): the peak surface temperature rise under a semi-elliptic
// (Hertzian) frictional heat flux moving at high Peclet number, the heat partitioned so that both
// surfaces reach the same peak:
//   theta_fl = 1.11 mu w |v1 - v2| / (sqrt(2 b) (B1 sqrt(v1) + B2 sqrt(v2)))   [K],
// b the Hertz half-width (2b the band, to which Blok's 1.11 belongs; Stolarski, Tribology in
// Machine Design, 1990, p. 76). Integrating Jaeger's high-Peclet response to the semi-elliptic
// source gives 0.78598/sqrt(b), i.e. 1.11155/sqrt(2b): Blok's 1.11 is that to three digits
// (tests/test_lubrication.cpp and validation/flash-temperature integrate it independently).
// mu friction coefficient, w line load [N/m], v1, v2 surface speeds [m/s] (>= 0), B1, B2 thermal
// contact coefficients.
double blok_flash_temperature(double mu, double line_load, double half_width, double v1, double v2, double b1,
                              double b2);
inline constexpr double kBlokConstant = 1.11;
// The mean of that temperature rise over the band |x| < b, over its peak (the same integration).
inline constexpr double kBlokMeanOverPeak = 0.68934;
// Peclet number of a surface: v b / (2 kappa), kappa = lambda/(rho c). Blok's formula assumes
// it large (> 5: the band source's high-speed limit).
double peclet_number(double speed, double half_width, double conductivity, double density, double specific_heat);
inline constexpr double kMinBlokPeclet = 5.0;

// The pitch point C of a spur pair as the ISO mean-friction formulas take it (SI).
struct PitchPointLoad {
  double tangential_load = 0.0;   // w_Bt = F_t/b, F_t at the reference circle [N/m] (K factors 1)
  double normal_load = 0.0;       // F_bn/b = F_t/(b cos alpha_t) [N/m]
  double pitch_line_speed = 0.0;  // v_t at the reference circle [m/s] (ISO 6336's pitch-line velocity)
  double sum_speed = 0.0;         // v_SigmaC = v1 + v2 at C [m/s]
  double radius = 0.0;            // rho_redC [m]
  double eta_oil = 0.0;           // dynamic viscosity at the oil (inlet) temperature [Pa s]
  double mean_ra = 0.0;           // (Ra1 + Ra2)/2 [m]
  double lubricant_factor = 1.0;  // X_L of the ISO table (lubrication/lubricant.hpp)
};

// A gear-mean friction coefficient and where its formula was taken beyond its range.
struct MeanFriction {
  double coefficient = 0.0;
  bool below_speed_range = false;  // v_t < 1 m/s: the standards expect more friction than the formula gives
  bool load_raised = false;        // w_Bt below 150 N/mm, evaluated at 150 N/mm (ISO/TS 6336-21 5.1)
  bool speed_capped = false;       // v_t above 50 m/s, evaluated at 50 m/s
};
inline constexpr double kIsoMinSpeed = 1.0, kIsoMaxSpeed = 50.0;  // v_t [m/s]
inline constexpr double kIsoMinTangentialLoad = 150e3;            // w_Bt [N/m]

// The gear-mean friction laws (each evaluated at C with the standard's units inside: N/mm, m/s,
// mm, mPa s, um):
//  - iso: ISO/TS 6336-21 (ISO/TR 13989-2, eqs. 1-7) and ISO/TS 6336-22 (ISO/TR 15144-1), the
//    integral-temperature and micropitting methods' mu_mC = 0.045 (w_Bt/(v_SigmaC rho_redC))^0.2
//    eta_oil^-0.05 X_R X_L, X_R = 2.2 (Ra/rho_redC)^0.25; w_Bt >= 150 N/mm and v_t <= 50 m/s as
//    ISO/TS 6336-21 clause 5.1 says;
//  - iso-flash: ISO/TS 6336-20 (ISO/TR 13989-1, eqs. 25-28), the flash-temperature method's
//    mu_m = 0.060 (w_Bt/(v_SigmaC rho_redC))^0.2 X_L eta_oil^-0.05 Ra^0.25, v_t <= 50 m/s (the
//    standard's text was not available: as two public implementations citing its equations
//    transcribe it; one of their authors reports KISSsoft using sqrt(Ra) instead of Ra^0.25);
//  - schlenk: Schlenk (1994, TU Munich dissertation), mu_mz = 0.048 (F_bt/b/(v_SigmaC rho_C))^0.2
//    eta_oil^-0.05 Ra^0.25 X_L, F_bt the transverse force on the base circle;
//  - fernandes: Schlenk's law with the lubricant factors Fernandes, Marques, Martins & Seabra
//    (Tribol. Int. 88, 2015, 309-316) calibrated on FZG power-loss tests of wind-turbine gear oils,
//    per base stock (mineral 0.846, PAO 0.65, ester 0.65, polyglycol 0.585, as the authors' own
//    public code states them; other stocks: the ISO table's value).
enum class MeanFrictionLaw { iso, iso_flash, schlenk, fernandes };
std::span<const NamedChoice<MeanFrictionLaw>> mean_friction_law_choices();  // lubrication.mean_friction
const char* mean_friction_law_name(MeanFrictionLaw law);
MeanFriction mean_friction(MeanFrictionLaw law, const PitchPointLoad& c, BaseOil base_oil);
double fernandes_lubricant_factor(BaseOil b, double iso_factor);

// ISO/TS 6336-20 (ISO/TR 13989-1 annex A, eq. A.5) flash temperature at a point Gamma of the path
// of an external spur pair:
//   theta_fl = mu_m X_M X_J X_G (X_Gamma w_Bt)^0.75 v_t^0.5 / a^0.25
// (w_Bt in N/mm, v_t in m/s, a in mm, X_M in K N^-3/4 s^1/2 m^-1/2 mm), with
//   X_M = E_r^0.25/B_M (50 for steel; mixed units, x 1000), E_r = 2/((1 - nu1^2)/E1 + (1 - nu2^2)/E2);
//   X_G = 0.51 X_ab sqrt(u + 1) |sqrt(1 + Gamma) - sqrt(1 - Gamma/u)| / ((1 + Gamma)^0.25 (u - Gamma)^0.25);
//   X_ab = 1.22 sin^0.25(alpha_wt) cos^0.25(alpha_n) / (cos^0.5(alpha_wt) cos^0.5(alpha_t)) (spur);
//   X_J = 1 + (C_eff - C_a)/50 (-Gamma/(Gamma_E - Gamma_A))^3 in the approach (Gamma < 0, pinion
//   driving; C in um, C_a the wheel's tip relief), 1 elsewhere; C_eff = F_t/(b cos alpha_t c_gamma);
//   X_Gamma the load-sharing factor (ISO/TR 13989-1 9.2, unmodified spur profiles, accuracy grade
//   Q <= 7: 1/3 at A to 2/3 at B, 1 from B to D, 2/3 at D to 1/3 at E).
// Sources: the equation numbers as two public implementations of ISO/TR 13989-1 cite them; the
// standard's text itself was not available. With X_J = X_Gamma = 1 it is Blok's formula with the
// semi-elliptic constant (0.51 x 0.978 and X_M = 50 against 0.786/sqrt(b): within 0.2 %).
// Dissimilar materials: B_M is the mean of the two (the standard's X_M is written for one B_M).
struct IsoFlashGeometry {
  double gear_ratio = 1.0;              // u = z2/z1
  double center_distance = 0.0;         // a [m]
  double operating_angle = 0.0;         // alpha_wt [rad]
  double reference_angle = 0.0;         // alpha_t = alpha_n (spur) [rad]
  double gamma_a = 0.0, gamma_e = 0.0;  // Gamma at A and E
};
double iso_angle_factor(double operating_angle, double reference_angle);         // X_alpha_beta, spur
double iso_geometry_factor(const IsoFlashGeometry& g, double gamma);             // X_G
double iso_thermo_elastic_factor(double reduced_modulus, double b1, double b2);  // X_M, E_r = reduced_modulus [Pa]
double iso_approach_factor(const IsoFlashGeometry& g, double gamma, double effective_relief, double tip_relief);  // X_J
// theta_fl [K]: mu_m, X_M (ISO units), X_J, X_G, X_Gamma, w_Bt [N/m], v_t [m/s], a [m].
double iso_flash_temperature(double mu_m, double x_m, double x_j, double x_g, double x_gamma, double tangential_load,
                             double pitch_line_speed, double center_distance);

// ISO/TS 6336-20 bulk temperature estimate theta_M = theta_oil + 0.47 X_S X_mp theta_fl,m with
// the mean flash temperature along the path; X_S = 1.0 (dip lubrication), X_mp = 1 (one mesh).
double iso_bulk_temperature(double oil_temperature, double mean_flash_temperature);
// Scuffing safety of the flash-temperature method: (theta_S - theta_oil)/(theta_B,max - theta_oil).
double iso_scuffing_safety(double scuffing_temperature, double oil_temperature, double max_contact_temperature);

// ISO/TS 6336-22 (ISO/TR 15144-1) local film of the micropitting method, the Dowson-Higginson
// 1966 form with the standard's sliding parameter:
//   h_Y = 1.6 rho G^0.6 U^0.7 W^-0.13 S_GF^0.22,
// G = alpha_M E', U = eta_M (v1 + v2)/(2 E' rho), W = 2 pi p_H^2/E'^2, with eta_M and alpha_M at
// the bulk temperature and S_GF = alpha(theta_B) eta(theta_B)/(alpha_M eta_M) at the local contact
// temperature theta_B = theta_M + theta_fl(mu_m). Arguments SI; returns h_Y [m].
double iso_film_hy(double radius, double reduced_modulus, double hertz_pressure, double sum_speed, const OilState& bulk,
                   const OilState& contact);

}  // namespace geartrib::lubrication
