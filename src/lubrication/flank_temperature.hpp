// Flash and contact temperature of a gear contact, the ISO/TS 6336-20 mean friction coefficient,
// bulk temperature and scuffing safety, and the ISO/TS 6336-22 film h_Y.
#pragma once

#include "lubrication/lubricant.hpp"

namespace geartrib::lubrication {

// Thermal contact coefficient B_M = sqrt(lambda rho c) of a body [W s^0.5/(m^2 K)].
double thermal_contact_coefficient(double conductivity, double density, double specific_heat);

// Blok's flash temperature (Blok 1937; the high-Peclet moving band source with the semi-elliptic
// Hertz flux, heat partitioned so that both surfaces reach the same peak):
//   theta_fl = 1.11 mu w |v1 - v2| / (2 sqrt(b) (B1 sqrt(v1) + B2 sqrt(v2)))   [K],
// which for B1 = B2 is ISO/TS 6336-20's 1.11 mu w |sqrt v1 - sqrt v2| / ((B1 + B2) sqrt b).
// mu friction coefficient, w line load [N/m], b Hertz half-width [m], v1, v2 surface speeds
// [m/s] (>= 0), B1, B2 thermal contact coefficients.
double blok_flash_temperature(double mu, double line_load, double half_width, double v1, double v2, double b1,
                              double b2);
// Peclet number of a surface: v b / (2 kappa), kappa = lambda/(rho c). Blok's formula assumes
// it large (> 5: the band source's high-speed limit).
double peclet_number(double speed, double half_width, double conductivity, double density, double specific_heat);
inline constexpr double kMinBlokPeclet = 5.0;

// ISO/TS 6336-20 (ISO/TR 13989-1) mean friction coefficient of the flash-temperature method, at
// the pitch point C: mu_m = 0.045 (w_Bt K_Bgamma / (v_SigmaC rho_redC))^0.2 eta_oil^-0.05 X_R X_L,
// X_R = 2.2 (Ra/rho_redC)^0.25, in the standard's units (N/mm, m/s, mm, mPa s, um); here SI in
// and out. transverse_load w_Bt [N/m] (spur: K_Bgamma = 1), sum_speed v1 + v2 at C [m/s],
// radius rho_redC [m], eta_oil at the oil temperature [Pa s], mean_ra (Ra1 + Ra2)/2 [m].
double iso_mean_friction(double transverse_load, double sum_speed, double radius, double eta_oil, double mean_ra,
                         double lubricant_factor);

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
