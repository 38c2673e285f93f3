// Elastic stresses on the axis of symmetry below an axisymmetric surface pressure on a
// half-space (compression negative). On the axis sigma_r = sigma_theta and tau_rz = 0, so the
// von Mises stress is |sigma_r - sigma_z|.
#pragma once

namespace geartrib::asperity {

struct AxisStress {
  double radial = 0.0;  // sigma_r = sigma_theta
  double axial = 0.0;   // sigma_z
};

inline double von_mises_on_axis(const AxisStress& s) {
  return s.radial > s.axial ? s.radial - s.axial : s.axial - s.radial;
}

// Hertz pressure p0 sqrt(1 - r^2/a^2), per unit p0, at depth z/a (Johnson, Contact Mechanics,
// eq. 3.45): sigma_z = -1/(1 + z^2/a^2); sigma_r = -(1+nu)[1 - (z/a) atan(a/z)] + 1/(2(1 + z^2/a^2)).
AxisStress hertz_axis_stress(double z_over_a, double nu);

// Uniform pressure q on a disc of radius c, per unit q, at depth z/c (Johnson eq. 3.104 on the
// axis): sigma_z = -(1 - z^3/rho^3); sigma_r = -[(1+2nu) - 2(1+nu) z/rho + z^3/rho^3]/2,
// rho = sqrt(c^2 + z^2).
AxisStress uniform_disc_axis_stress(double z_over_c, double nu);

// The Hertz pressure sqrt(1 - r^2/a^2) (per unit p_e) restricted to the annulus c <= r <= a, at
// depth z/a, c/a in [0, 1]: the kernel integrated in closed form. With X = (1 - c^2)/(c^2 + z^2)
// (lengths over a) and s = sqrt(X): sigma_z = -z^3 s^3/(1 + z^2), sigma_r = -(1+nu) z (s - atan s)
// - sigma_z/2 (u = r^2: int sqrt(1-u) (u+z^2)^(-5/2) du = -2/(3(1+z^2)) X^(3/2) and
// int sqrt(1-u) (u+z^2)^(-3/2) du = 2 (atan s - s)). c = 0 gives hertz_axis_stress.
AxisStress hertz_annulus_axis_stress(double z_over_a, double c_over_a, double nu);

// Point-load kernel of Boussinesq on the axis: stresses at depth z [m] from a unit normal
// force at horizontal distance r [m] (ring average; Johnson eq. 3.21):
// sigma_z = -3 z^3 / (2 pi rho^5); sigma_r = [-(1+nu) z/(pi rho^3) + 3 z^3/(2 pi rho^5)] / 2.
AxisStress boussinesq_axis_kernel(double r, double z, double nu);

}  // namespace geartrib::asperity
