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
  // Elastic stresses on the axis at depth z [m], superposing the uniform core (closed form),
  // the full Hertz distribution (closed form) and minus its inner cap r < r_p (adaptive
  // Gauss-Kronrod over the Boussinesq kernel).
  AxisStress axis_stress(double depth, double nu) const;
  // Largest von Mises stress of that elastic field on the axis, and its depth.
  VonMisesMaximum von_mises_maximum(double nu) const;
};

PressureProfile hertz_profile(double contact_radius, double peak_pressure);
PressureProfile uniform_profile(double contact_radius, double pressure);

// Profile of a model that publishes only its load and contact area. The pressure is taken
// continuous at r_p, with the core at p_core = p_y + (H - p_y) phi, phi = (r_p/a)^2, rising from
// the first-yield Hertz peak p_y to the hardness H; the mean pressure of that profile,
// p_core (2 + phi)/3, is matched to the model's F/A. Mean pressures up to 2 p_y/3 give the Hertz
// profile (phi = 0), at or above H the uniform one (phi = 1).
PressureProfile profile_from_mean_pressure(double contact_radius, double mean_pressure,
                                           double yield_peak_pressure, double hardness);

}  // namespace geartrib::asperity
