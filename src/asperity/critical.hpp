// Critical (first-yield) values of a Hertzian sphere-on-flat contact and the yield constants
// of the published models.
#pragma once

#include "asperity/contact_pair.hpp"

#include <cmath>
#include <numbers>

namespace geartrib::asperity {

// CEB mean contact pressure factor k = 0.454 + 0.41 nu: first yield when the Hertz peak
// pressure reaches k H (Chang, Etsion & Bogy 1987; seed section 2). k(0.3) = 0.577.
inline double ceb_pressure_factor(double nu) { return 0.454 + 0.41 * nu; }

// Jackson & Green (2005) fit of the peak pressure at first yield, p0 = C S_y:
// C(nu) = 1.295 exp(0.736 nu); C(0.3) = 1.615.
inline double jackson_green_yield_factor(double nu) { return 1.295 * std::exp(0.736 * nu); }

// Green (2005) fit for a cylinder in plane strain, p0 = C_L S_y at first yield:
// C_L(nu) = 1.164 + 2.975 nu - 2.906 nu^2; C_L(0.3) = 1.795.
inline double green_cylinder_yield_factor(double nu) { return 1.164 + 2.975 * nu - 2.906 * nu * nu; }

// Hertz sphere on flat (Johnson, Contact Mechanics, ch. 4; seed section 2), SI.
template <class T>
T hertz_load(const T& delta, double radius, double modulus) {  // F = 4/3 E_t R^1/2 delta^3/2 [N]
  using std::pow, std::sqrt;
  return (4.0 / 3.0) * modulus * std::sqrt(radius) * pow(delta, 1.5);
}
inline double hertz_contact_radius(double delta, double radius) {
  return std::sqrt(radius * delta);
}  // a = sqrt(R delta)
inline double hertz_peak_pressure(double contact_radius, double radius, double modulus) {  // p0 = 2 E_t a/(pi R)
  return 2.0 * modulus * contact_radius / (std::numbers::pi * radius);
}

// Critical interference, load and area of a model whose first-yield criterion is a Hertz peak
// pressure p_y: delta_c = (pi p_y / (2 E_t))^2 R, F_c = 4/3 E_t R^1/2 delta_c^3/2,
// A_c = pi R delta_c. With p_y = k H this is the CEB / Kogut-Etsion delta_c (seed section 2).
struct Critical {
  double interference = 0.0;   // delta_c [m]
  double load = 0.0;           // F_c [N]
  double area = 0.0;           // A_c [m^2]
  double peak_pressure = 0.0;  // p_y, Hertz peak pressure at delta_c [Pa]
};
Critical hertz_critical(const ContactPair& pair, double yield_peak_pressure);

// Hertz on-axis von Mises maximum for a given nu: depth z/a and ratio to p0
// (nu = 0.3: z = 0.481 a, sigma_vm = 0.620 p0). Solved from the exact axis stresses, not from
// the seed's garbled printed condition (ERRATA).
struct HertzYieldPoint {
  double depth_over_radius = 0.0;
  double von_mises_over_peak = 0.0;
};
HertzYieldPoint hertz_yield_point(double nu);

}  // namespace geartrib::asperity
