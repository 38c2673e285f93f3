// Reference solutions the tests compare the code against: closed forms from the literature, each
// typed once here with its source. They are the published results restated, never a call into
// src/: a test that checks src/'s formula against one of these compares two independent writings
// of the same published result, and a numerical solver (boundary elements, the strip contact)
// checked against one meets an independent derivation.
#pragma once

#include <cmath>
#include <numbers>

namespace geartrib::reference {

// Hertz line contact: two cylinders (plane strain) pressed by a load per unit length w [N/m], of
// equivalent radius r = 1/(1/R1 + 1/R2) [m] and composite modulus e = E* with 1/E* =
// (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [Pa] (Johnson 1985, Contact Mechanics, section 4.3, eq. 4.45;
// the pressure is semi-elliptic, p0 sqrt(1 - x^2/b^2), so that w = pi b p0/2).
// E' = 2 E* in the EHL literature's convention.

// b = sqrt(4 w R/(pi E*)) [m].
inline double hertz_line_half_width(double w, double r, double e) {
  return std::sqrt(4.0 * w * r / (std::numbers::pi * e));
}
// p0 = sqrt(w E*/(pi R)) [Pa].
inline double hertz_line_peak(double w, double r, double e) { return std::sqrt(w * e / (std::numbers::pi * r)); }
// p0 = 2 w/(pi b): the semi-elliptic pressure of half-width b carrying w [Pa].
inline double hertz_line_peak_of_half_width(double w, double b) { return 2.0 * w / (std::numbers::pi * b); }
// w = pi E* b^2/(4 R): the load that makes the half-width b (inverted) [N/m].
inline double hertz_line_load_of_half_width(double b, double r, double e) {
  return std::numbers::pi * e * b * b / (4.0 * r);
}
// w = pi R p0^2/E*: the load that makes the peak p0 (inverted) [N/m].
inline double hertz_line_load_of_peak(double p0, double r, double e) { return std::numbers::pi * r * p0 * p0 / e; }

// Summits of an isotropic Gaussian surface from its profile's spectral moments m0 [m^2], m2 [1],
// m4 [1/m^2] (Nayak 1971, J. Lubr. Technol. 93, 398-407; as McCool 1986, Wear 107, 37-60, states
// them), with the bandwidth parameter alpha = m0 m4/m2^2.

// eta = m4/(6 pi sqrt(3) m2) [1/m^2].
inline double mccool_summit_density(double m2, double m4) {
  return m4 / (6.0 * std::numbers::pi * std::sqrt(3.0) * m2);
}
// beta = 0.375 sqrt(pi/m4) [m].
inline double mccool_summit_radius(double m4) { return 0.375 * std::sqrt(std::numbers::pi / m4); }
// sigma_s/sigma = sqrt(1 - 0.8968/alpha): the summits' height spread over the surface's.
inline double mccool_summit_sigma_ratio(double alpha) { return std::sqrt(1.0 - 0.8968 / alpha); }
// y_s/sigma = 4/sqrt(pi alpha): the summits' mean height above the mean plane over sigma.
inline double mccool_summit_mean_height_ratio(double alpha) { return 4.0 / std::sqrt(std::numbers::pi * alpha); }

}  // namespace geartrib::reference
