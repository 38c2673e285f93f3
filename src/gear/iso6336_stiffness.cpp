#include "gear/iso6336_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geartrib::gear {

IsoMeshStiffness iso6336_mesh_stiffness(const SpurPair& pair, double line_load) {
  const double zn1 = pair.pinion().teeth, zn2 = pair.wheel().teeth;  // spur: z_n = z
  const double x1 = pair.pinion().profile_shift, x2 = pair.wheel().profile_shift;
  // ISO 6336-1 eq. (99), table 8: q' in mm um / N.
  const double q_mm_um = 0.04723 + 0.15551 / zn1 + 0.25791 / zn2 - 0.00635 * x1 - 0.11654 * x1 / zn1 - 0.00193 * x2 -
                         0.24188 * x2 / zn2 + 0.00529 * x1 * x1 + 0.00182 * x2 * x2;
  IsoMeshStiffness r;
  r.flexibility_q = q_mm_um * 1e-9;  // mm um/N = 1e-3 m * 1e-6 m / N
  r.theoretical = 1.0 / r.flexibility_q;
  const double cm = 0.8, cr = 1.0;
  const double alpha_deg = pair.spec().pressure_angle * 180.0 / std::numbers::pi;
  const double cb = (1.0 + 0.5 * (1.2 - pair.spec().dedendum_coefficient)) * (1.0 - 0.02 * (20.0 - alpha_deg));
  const double load_factor = std::pow(std::min(1.0, line_load / kIsoFullLineLoad), 0.25);
  r.single = r.theoretical * cm * cr * cb * load_factor;
  r.mesh = r.single * (0.75 * pair.path().contact_ratio + 0.25);
  return r;
}

double iso_effective_relief(const SpurPair& pair, double tangential_line_load) {
  const double c_gamma = iso6336_mesh_stiffness(pair, tangential_line_load).mesh;
  return c_gamma > 0.0 ? tangential_line_load / (std::cos(pair.spec().pressure_angle) * c_gamma) : 0.0;
}

}  // namespace geartrib::gear
