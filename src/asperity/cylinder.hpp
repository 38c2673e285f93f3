// Cylinder (line-contact) asperity of seed section 5: a long parabolic cylinder
// y = -x^2/(2 R_m) pressed by a rigid flat, in plane strain, per unit length.
#pragma once

namespace geartrib::asperity {

struct CylinderAsperity {
  double tip_radius = 0.0;      // R_m [m]
  double modulus = 0.0;         // E_t [Pa]
  double yield_strength = 0.0;  // sigma_s [Pa]
  double hardness = 0.0;        // H [Pa]
  double poisson_ratio = 0.0;   // nu [-]
  // C: peak pressure at first yield over sigma_s. The seed uses 1.64 for nu = 0.3; Green's
  // (2005) plane-strain fit C_L(nu) = 1.164 + 2.975 nu - 2.906 nu^2 gives 1.795 (and 1.64 at
  // nu = 0.2); see green_cylinder_yield_factor.
  double yield_constant = 1.64;
  void validate() const;
};

// The seed's critical interference for cylinder-plane contact (section 5):
// delta_pc = (2 R_m sigma_s / E_t) [ln(2 E_t / sigma_s) - 1] C. For R_m = 6.6 um, 45 steel and
// C = 1.64 this is 0.423 um; the seed prints 0.38 um (ERRATA: the formula is used).
double seed_critical_interference(const CylinderAsperity& c);

// Hertz line contact (seed section 5; Johnson eq. 4.45): half-width b = sqrt(4 F' R / (pi E_t))
// for a load per unit length F' [N/m]; peak pressure p0 = E_t b/(2 R); mean (pi/4) p0.
double hertz_half_width(double load_per_length, double radius, double modulus);

// First yield of the line contact: p0 = C sigma_s with the same C, so b_c = 2 R C sigma_s/E_t
// and F'_c = pi R (C sigma_s)^2/E_t.
struct LineCritical {
  double half_width = 0.0;       // b_c [m]
  double load_per_length = 0.0;  // F'_c [N/m]
  double peak_pressure = 0.0;    // C_L S_y [Pa]
};
LineCritical line_critical(const CylinderAsperity& c);

// Elastic-plastic load-width law per unit length (a closure to be refitted against the
// boundary-element and finite-element results of the later issues): Hertz up to F'_c; beyond,
// the mean pressure rises from the first-yield value p_mc = (pi/4) C sigma_s toward H as
//   p_m = H - (H - p_mc) (F'/F'_c)^-beta,  beta = p_mc / (2 (H - p_mc)),
// the exponent that makes p_m and its slope continuous at F'_c (Hertz: p_m ~ F'^1/2). Then
// b = F'/(2 p_m).
struct LineContactState {
  double load_per_length = 0.0;  // F' [N/m]
  double half_width = 0.0;       // b [m]
  double mean_pressure = 0.0;    // p_m = F'/(2b) [Pa]
  double area_per_length = 0.0;  // 2 b [m^2/m]
  bool plastic = false;          // F' > F'_c
};
LineContactState line_contact(const CylinderAsperity& c, double load_per_length);

}  // namespace geartrib::asperity
