#include "asperity/axis_stress.hpp"

#include <cmath>
#include <numbers>

namespace geartrib::asperity {

AxisStress hertz_axis_stress(double z_over_a, double nu) {
  const double z = z_over_a;
  const double q = 1.0 / (1.0 + z * z);
  const double zat = z > 0.0 ? z * std::atan(1.0 / z) : 0.0;
  return {-(1.0 + nu) * (1.0 - zat) + 0.5 * q, -q};
}

AxisStress uniform_disc_axis_stress(double z_over_c, double nu) {
  const double z = z_over_c;
  const double rho = std::sqrt(1.0 + z * z);
  const double z_rho = z / rho;
  const double z3 = z_rho * z_rho * z_rho;
  return {-0.5 * ((1.0 + 2.0 * nu) - 2.0 * (1.0 + nu) * z_rho + z3), -(1.0 - z3)};
}

AxisStress hertz_annulus_axis_stress(double z_over_a, double c_over_a, double nu) {
  const double z = z_over_a, c = c_over_a;
  if (!(c < 1.0)) return {};
  if (z == 0.0) return c > 0.0 ? AxisStress{} : hertz_axis_stress(0.0, nu);  // the surface: only the load over it
  const double zs = z * std::sqrt((1.0 - c * c) / (c * c + z * z));
  const double s = zs / z;
  // s - atan s, with its series where the difference cancels.
  const double s_minus_atan = s < 1e-3 ? s * s * s * (1.0 / 3.0 - s * s / 5.0) : s - std::atan(s);
  const double axial = -zs * zs * zs / (1.0 + z * z);
  return {-(1.0 + nu) * z * s_minus_atan - 0.5 * axial, axial};
}

AxisStress boussinesq_axis_kernel(double r, double z, double nu) {
  const double rho2 = r * r + z * z;
  const double rho = std::sqrt(rho2);
  const double rho3 = rho2 * rho;
  const double rho5 = rho3 * rho2;
  const double sz = -3.0 * z * z * z / (2.0 * std::numbers::pi * rho5);
  const double horizontal_sum = -(1.0 + nu) * z / (std::numbers::pi * rho3) - sz;
  return {0.5 * horizontal_sum, sz};
}

}  // namespace geartrib::asperity
