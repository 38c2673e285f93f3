#include "gear/tooth_root.hpp"

#include "gear/involute.hpp"

#include <fmt/format.h>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace geartrib::gear {

namespace {

constexpr double kPi = std::numbers::pi;

struct Vec {
  double x = 0.0, y = 0.0;
};

// The rack's tip-rounding centre in the gear's frame (tooth centreline +y, the flank considered at
// x > 0) when the gear has turned by phi from the position where the rack's tooth beside that flank
// is centred on the line through the axis at u = pi m/2: rack point (u, w) of the rolling frame
// (w from the axis) -> Rot(-phi) (u - r phi, w).
struct RackRounding {
  double r = 0.0;    // reference radius (the rolling circle) [m]
  double u = 0.0;    // the centre's distance from the gear tooth's centreline at phi = 0: pi m/2 - E [m]
  double w = 0.0;    // its distance from the axis at phi = 0: r + G m [m]
  double rho = 0.0;  // rho_fP [m]

  Vec centre(double phi) const {
    const double a = u - r * phi, c = std::cos(phi), s = std::sin(phi);
    return {c * a + s * w, -s * a + c * w};
  }
  Vec centre_d1(double phi) const {
    const double a = u - r * phi, c = std::cos(phi), s = std::sin(phi);
    return {-s * a + c * (w - r), -c * a - s * (w - r)};
  }
  Vec centre_d2(double phi) const {
    const double a = u - r * phi, c = std::cos(phi), s = std::sin(phi);
    return {-c * a - s * (w - 2.0 * r), s * a - c * (w - 2.0 * r)};
  }
  // Unit normal of the fillet at phi, into the gear's material: from the instantaneous pitch point
  // (r sin phi, r cos phi) through the centre (Willis), Rot(-phi) (u - r phi, w - r).
  Vec normal(double phi) const {
    const double a = u - r * phi, g = w - r, n = std::hypot(a, g), c = std::cos(phi), s = std::sin(phi);
    return {(c * a + s * g) / n, (-s * a + c * g) / n};
  }
  Vec fillet(double phi) const {
    const Vec c = centre(phi), n = normal(phi);
    return {c.x + rho * n.x, c.y + rho * n.y};
  }
  // The fillet's radius of curvature: the centre's path's own (its curvature centre lies on the
  // space's side, against the normal) plus rho, the fillet being that path's offset.
  double fillet_radius(double phi) const {
    const Vec d1 = centre_d1(phi), d2 = centre_d2(phi), n = normal(phi);
    const double speed2 = d1.x * d1.x + d1.y * d1.y, tangential = (d2.x * d1.x + d2.y * d1.y) / speed2;
    const Vec k = {(d2.x - tangential * d1.x) / speed2, (d2.y - tangential * d1.y) / speed2};  // curvature vector
    const double curvature = std::hypot(k.x, k.y);
    if (curvature == 0.0) return INFINITY;
    const double radius = 1.0 / curvature;
    return k.x * n.x + k.y * n.y < 0.0 ? radius + rho : radius - rho;
  }
};

}  // namespace

RootSection iso6336_root_section(const SpurPair& pair, int gear) {
  const PathOfContact& p = pair.path();
  const GearBody& g = pair.gear(gear);
  // The outer point of single-pair contact: D on the pinion, B on the wheel (roll lengths from
  // each gear's own base tangent point).
  const double roll = gear == 0 ? p.d : p.line_length - p.b;
  return iso6336_root_section(pair, gear, 2.0 * std::hypot(g.base_radius, roll));
}

RootSection iso6336_root_section(const SpurPair& pair, int gear, double load_diameter) {
  const GearPairSpec& spec = pair.spec();
  const GearBody& g = pair.gear(gear);
  const double m = spec.module, alpha = spec.pressure_angle;
  const double h = spec.dedendum_coefficient * m, rho = spec.root_radius_coefficient * m;
  // ISO 6336-3 eq. (8): E, the rounding centre's distance from the rack tooth's centreline.
  const double e = kPi * m / 4.0 - h * std::tan(alpha) + rho * std::tan(alpha) - rho / std::cos(alpha);
  if (!(e >= 0.0))
    throw GeometryError("gear_pair.root_radius_coefficient",
                        "the rack's tip rounding is wider than its tip: no fillet the ISO 6336-3 construction covers");
  const RackRounding rack{g.pitch_radius, kPi * m / 2.0 - e, g.pitch_radius + g.profile_shift * m - h + rho, rho};
  if (!(rack.w < rack.r))
    throw GeometryError(std::string(gear == 0 ? "pinion" : "wheel") + ".profile_shift",
                        "the rack's tip-rounding centre lies outside the reference circle (G >= 0): the 30-degree "
                        "tangent construction of ISO 6336-3 does not cover this fillet");
  // The fillet runs from the root circle (phi0: the centre over the axis) to where the rack's
  // rounding meets its straight flank (phi1: the normal at the flank's angle).
  const double phi0 = rack.u / rack.r, phi1 = (rack.u - (rack.w - rack.r) / std::tan(alpha)) / rack.r;
  // The 30 deg tangent: the fillet's normal into the tooth at -150 deg from +x, i.e. its tangent at
  // 30 deg to the centreline. The normal turns monotonically from -90 deg - phi0 at the root circle.
  // (In the rack's frame the normal lies in the third quadrant, so its angle does not wrap.)
  auto angle_gap = [&](double phi) {
    return std::atan2(rack.w - rack.r, rack.u - rack.r * phi) - phi + 5.0 * kPi / 6.0;
  };
  if (!(angle_gap(phi1) < 0.0))
    throw GeometryError("gear_pair.pressure_angle",
                        "no point of the root fillet has its tangent at 30 deg to the centreline (pressure angle too "
                        "large for ISO 6336-3's critical section)");
  std::uintmax_t iterations = 100;
  const auto [lo, hi] = boost::math::tools::toms748_solve(angle_gap, phi0, phi1, angle_gap(phi0), angle_gap(phi1),
                                                          boost::math::tools::eps_tolerance<double>(50), iterations);
  const double phi = 0.5 * (lo + hi);
  const Vec section = rack.fillet(phi);

  RootSection r;
  r.chord = 2.0 * section.x;
  r.section_radius = section.y;
  r.fillet_radius = rack.fillet_radius(phi);
  // The load at d_en along the involute's normal: the involute point at angle gamma_e from the
  // centreline (the half tooth angle at that radius), the normal tangent to the base circle at
  // alpha_en further towards the centreline.
  const double r_en = 0.5 * load_diameter;
  if (!(r_en > g.base_radius))
    throw GeometryError(std::string(gear == 0 ? "pinion" : "wheel") + ".tip_diameter",
                        "the load point lies inside the base circle");
  const double alpha_en = std::acos(g.base_radius / r_en);
  const double gamma_e = g.base_half_angle - involute(alpha_en);
  const Vec q = {r_en * std::sin(gamma_e), r_en * std::cos(gamma_e)};
  const Vec t = {g.base_radius * std::sin(gamma_e - alpha_en), g.base_radius * std::cos(gamma_e - alpha_en)};
  const double y_load = q.y + (t.y - q.y) * q.x / (q.x - t.x);  // where the normal crosses the centreline
  r.load_diameter = load_diameter;
  r.load_angle = std::atan2(std::abs(t.y - q.y), std::abs(t.x - q.x));
  r.moment_arm = y_load - section.y;
  // ISO 6336-3 eqs. (6) and (26) on the generated section.
  r.form_factor = 6.0 * (r.moment_arm / m) * std::cos(r.load_angle) / ((r.chord / m) * (r.chord / m) * std::cos(alpha));
  r.notch_parameter = r.chord / (2.0 * r.fillet_radius);
  const double l = r.chord / r.moment_arm;
  r.stress_correction = (1.2 + 0.13 * l) * std::pow(r.notch_parameter, 1.0 / (1.21 + 2.3 / l));
  r.stress_correction_in_range = r.notch_parameter >= 1.0 && r.notch_parameter < 8.0;
  return r;
}

}  // namespace geartrib::gear
