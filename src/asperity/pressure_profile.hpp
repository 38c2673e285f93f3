// The two-zone contact pressure of the seed's elastic-plastic asperity (section 2): a plastic
// core r < r_p at a uniform pressure, and an elastic annulus r_p < r < a carrying the Hertz-type
// pressure p_e sqrt(1 - r^2/a^2). Hertz (r_p = 0) and a uniform fully plastic contact (r_p = a)
// are its limits. Every model's stress outputs (peak pressure, plastic share, von Mises
// maximum) are read off such a profile.
#pragma once

namespace geartrib::asperity {

struct AxisStress;

struct VonMisesMaximum {
  double value = 0.0;  // largest von Mises stress on the axis [Pa]
  double depth = 0.0;  // its depth below the surface [m]
};

struct PressureProfile {
  double contact_radius = 0.0;  // a [m]
  double core_radius = 0.0;     // r_p [m], 0 <= r_p <= a
  double core_pressure = 0.0;   // pressure over r < r_p [Pa]
  double annulus_peak = 0.0;    // p_e [Pa]: annulus pressure p_e sqrt(1 - r^2/a^2)

  // Total load [N]: pi r_p^2 p_core + (2 pi/3) p_e (a^2 - r_p^2)^(3/2) / a.
  double load() const;
  // Largest pressure of the profile [Pa]: max(p_core, p_e sqrt(1 - r_p^2/a^2)).
  double max_pressure() const;
  // Plastic share of the contact area (r_p/a)^2.
  double plastic_fraction() const;
  // Elastic stresses on the axis at depth z [m], superposing the uniform core and the Hertz-type
  // annulus, both in closed form (axis_stress.hpp).
  AxisStress axis_stress(double depth, double nu) const;
  // Largest von Mises stress of that elastic field on the axis, and its depth.
  VonMisesMaximum von_mises_maximum(double nu) const;
};

PressureProfile hertz_profile(double contact_radius, double peak_pressure);
PressureProfile uniform_profile(double contact_radius, double pressure);

// The two-zone profile with a given plastic share phi = (r_p/a)^2 (the yielded share of the
// contact area at the surface) carrying the mean pressure p_m, continuous at r_p:
//   p_core = 3 p_m/(2 + phi),  p_e = p_core/sqrt(1 - phi),
// since F = pi a^2 p_core (2 + phi)/3 for such a profile. phi = 0: Hertz (p0 = 3/2 p_m);
// phi = 1: uniform p_m. The continuous model's own profile and the documented profile of the
// published models (their F/A with the FEM-calibrated surface-yield share) are both this one.
PressureProfile two_zone_profile(double contact_radius, double mean_pressure, double plastic_share);

}  // namespace geartrib::asperity
