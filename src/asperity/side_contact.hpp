// Side (frictional) contact of two paraboloid asperities, seed section 2.1. The axes are offset
// so that, at first touch, the common normal is tilted by theta from the load direction,
// tan theta = mu. For paraboloids z = rho^2/(2 R_i) the touching point lies at rho_i = R_i tan theta
// on each, so the axis offset is d = (R1 + R2) tan theta and the tips are d^2/(2 (R1 + R2)) apart
// vertically.
#pragma once

#include "asperity/contact_pair.hpp"
#include "asperity/model.hpp"

namespace geartrib::asperity {

struct SideContactGeometry {
  double theta = 0.0;        // tilt of the contact normal [rad], tan theta = mu
  double axis_offset = 0.0;  // d = (R1 + R2) tan theta [m]
  double tip_gap = 0.0;      // vertical tip separation at first touch d^2/(2 (R1 + R2)) [m]
  double radius_x = 0.0;     // equivalent radius in the plane of the offset: R/cos^3 theta [m]
  double radius_y = 0.0;     // equivalent radius across it: R/cos theta [m]
  double radius_0 = 0.0;     // the seed's R0 = R1' R2'/(R1' + R2'), R_i' = R_i/cos^3 theta: = radius_x
  double radius_mean = 0.0;  // sqrt(R_x R_y), the Hertz equivalent radius of the ellipse [m]
  // Elliptical-to-circular (R0) Hertz ratios at the same approach, independent of the approach
  // and of the modulus (both contacts scale as delta^3/2 and delta).
  double load_ratio = 1.0;
  double area_ratio = 1.0;
  double aspect = 1.0;  // b/a of the contact ellipse
};

// Principal radii of a paraboloid of tip radius R at the point where its normal is tilted by
// theta: meridional R/cos^3 theta, circumferential R/cos theta (surface of revolution).
SideContactGeometry side_contact_geometry(double tip_radius1, double tip_radius2, double mu);

// The tilt produced by an axis offset d between two touching paraboloids: tan theta = d/(R1+R2).
double normal_tilt_from_offset(double tip_radius1, double tip_radius2, double axis_offset);

// Elliptical Hertz contact (Johnson eqs. 4.39-4.40) with principal relative curvatures
// 1/R_x <= 1/R_y: eccentricity e of the ellipse (semi-axis a along x, b = a sqrt(1 - e^2)),
// from (R_x/R_y) = [E(e)/(1-e^2) - K(e)] / [K(e) - E(e)] with Boost.Math's complete elliptic
// integrals; then, at a normal approach delta, a^2 = 2 R_x delta (K - E)/(e^2 K),
// p0 = E_t delta/(b K), F = 2/3 pi a b p0.
struct EllipticHertz {
  double eccentricity = 0.0;
  double semi_major = 0.0;     // a [m]
  double semi_minor = 0.0;     // b [m]
  double peak_pressure = 0.0;  // p0 [Pa]
  double load = 0.0;           // F [N]
  double area() const;
};
EllipticHertz elliptic_hertz(double radius_x, double radius_y, double modulus, double delta);

// Side contact at an approach delta along the load direction [m]: the contact normal sees
// delta_n = delta cos theta. The elastic-plastic law of `model` is evaluated with R0 (seed:
// "the same form as the normal contact but with the modified radius R0"), so delta_cn =
// (pi k H / (2 E_t))^2 R0, and its load and area are scaled by the elliptical-to-circular Hertz
// ratios (constant in delta), which makes the elastic range exactly the elliptical Hertz contact.
struct SideContactState {
  AsperityState normal;          // along the contact normal (delta = delta_n, delta_star = delta_n/delta_cn)
  double theta = 0.0;            // [rad]
  double applied_delta = 0.0;    // delta along the load direction [m]
  double vertical_load = 0.0;    // F_n cos theta [N]
  double tangential_load = 0.0;  // F_n sin theta [N]
  double semi_major = 0.0;       // contact ellipse semi-axes [m]
  double semi_minor = 0.0;
};
SideContactState evaluate_side_contact(const AsperityModel& model, const ContactPair& pair,
                                       const SideContactGeometry& geometry, double applied_delta,
                                       Detail detail = Detail::full, VonMisesTable* stress_table = nullptr);

}  // namespace geartrib::asperity
