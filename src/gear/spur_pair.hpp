// Involute spur gear pair: geometry, path of contact on the line of action, and the contact
// geometry and kinematics at any point of it (ISO 21771; Niemann-Winter; Litvin).
#pragma once

#include "core/keyed_error.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace geartrib::gear {

// A geometry the pair cannot have. `key` names the case-file key to change.
class GeometryError : public core::KeyedError {
 public:
  using KeyedError::KeyedError;
};

// A finding that does not stop the computation (e.g. undercut), with the key it concerns.
struct GeometryWarning {
  std::string key;
  std::string message;
};

// The pair's geometry: basic rack (ISO 53 by default), centre distance and both gears' teeth,
// shifts, tip and bore diameters; index 0 the pinion, 1 the wheel. SpurPair builds on it.
struct GearPairSpec {
  static constexpr int kMinTeeth = 5;  // below this no involute spur gear is cut in practice
  static constexpr int kMaxTeeth = 1000;
  double module = 0.0;                    // m [m]
  double pressure_angle = 0.0;            // alpha of the basic rack [rad]
  double face_width = 0.0;                // b [m]
  double addendum_coefficient = 1.0;      // h_aP / m
  double dedendum_coefficient = 1.25;     // h_fP / m
  double root_radius_coefficient = 0.38;  // rho_fP / m
  double tip_shortening = 0.0;            // k: tip diameter reduced by 2 k m on both gears
  double center_distance = 0.0;           // a_w [m]; 0: zero-backlash distance from the shifts
  int teeth[2] = {0, 0};                  // z
  double profile_shift[2] = {0.0, 0.0};   // x [-]
  double tip_diameter[2] = {0.0, 0.0};    // d_a [m]; 0: from addendum, shift and tip shortening
  double bore_diameter[2] = {0.0, 0.0};   // gear-body bore [m], for the fillet-foundation stiffness
  // The rules of each value on its own (the pair's rules between values: SpurPair); throws
  // GeometryError naming the key ("gear_pair.module", "pinion.teeth").
  void validate() const;
};

struct GearBody {
  int teeth = 0;
  double profile_shift = 0.0;
  double pitch_radius = 0.0;            // r = m z/2
  double base_radius = 0.0;             // r_b = r cos alpha
  double tip_radius = 0.0;              // r_a
  double root_radius = 0.0;             // r_f = r - m (h_fP* - x)
  double operating_pitch_radius = 0.0;  // r_w = r_b / cos alpha_w
  double base_half_angle = 0.0;         // half the tooth's angular thickness on the base circle [rad]
  double form_roll_length = 0.0;        // roll length (distance from T) where the generated involute starts [m]
  double bore_radius = 0.0;             // [m]
};

// Points on the line of action, as distances from T1 (the pinion's base-circle tangent point).
struct PathOfContact {
  double line_length = 0.0;    // T1T2 = a_w sin alpha_w
  double a = 0.0;              // start of contact (wheel tip)
  double b = 0.0;              // lowest point of single-tooth contact on the pinion, E - p_b
  double c = 0.0;              // pitch point, r_b1 tan alpha_w
  double d = 0.0;              // highest point of single-tooth contact on the pinion, A + p_b
  double e = 0.0;              // end of contact (pinion tip)
  double base_pitch = 0.0;     // p_b = pi m cos alpha
  double length = 0.0;         // g_alpha = E - A
  double contact_ratio = 0.0;  // eps_alpha = g_alpha / p_b
};

// Contact geometry at a point s of the line of action.
struct FlankGeometry {
  double s = 0.0;                  // distance from T1 [m]
  double radius_pinion = 0.0;      // rho1 = s, the pinion flank's radius of curvature [m]
  double radius_wheel = 0.0;       // rho2 = T1T2 - s [m]
  double radius_equivalent = 0.0;  // rho1 rho2 / (rho1 + rho2) [m]
  double roll_parameter = 0.0;     // ISO Gamma = tan(alpha_y1)/tan(alpha_w) - 1 = s / T1C - 1
};

// Surface velocities at s (tangential to the flanks, perpendicular to the line of action).
struct FlankKinematics {
  double rolling_pinion = 0.0;           // v1 = omega1 rho1 [m/s]
  double rolling_wheel = 0.0;            // v2 = omega2 rho2 [m/s]
  double entrainment = 0.0;              // u = (v1 + v2)/2 [m/s]
  double sliding = 0.0;                  // v1 - v2 [m/s], zero at the pitch point
  double slide_to_roll = 0.0;            // (v1 - v2)/u
  double specific_sliding_pinion = 0.0;  // (v1 - v2)/v1
  double specific_sliding_wheel = 0.0;   // (v2 - v1)/v2
};

class SpurPair {
 public:
  // Validates and builds; throws GeometryError naming the key to change.
  explicit SpurPair(const GearPairSpec& spec);
  // The largest root radius over bore radius a bore may have (a smaller bore is refused; 0 is a
  // solid body): near 65 the fillet-foundation fit's terms change sign (tooth_stiffness.cpp).
  static constexpr double kMaxRootOverBore = 50.0;

  const GearPairSpec& spec() const { return spec_; }
  const GearBody& pinion() const { return gear_[0]; }
  const GearBody& wheel() const { return gear_[1]; }
  const GearBody& gear(int i) const { return gear_[i]; }
  double reference_center_distance() const { return reference_center_distance_; }
  double center_distance() const { return center_distance_; }
  double operating_pressure_angle() const { return operating_pressure_angle_; }
  const PathOfContact& path() const { return path_; }
  const std::vector<GeometryWarning>& warnings() const { return warnings_; }

  FlankGeometry flank(double s) const;
  // ISO's tangential line load F_t/b = T1/(r1 b) at pinion torque T1 [N m] -> [N/m].
  double tangential_line_load(double pinion_torque) const {
    return pinion_torque / gear_[0].pitch_radius / spec_.face_width;
  }
  FlankKinematics kinematics(double s, double pinion_speed) const;
  // Roll angle of gear i's involute at the contact point s: rho_i / r_bi [rad].
  double roll_angle(int i, double s) const;

 private:
  GearPairSpec spec_;
  GearBody gear_[2];
  double reference_center_distance_ = 0.0;
  double center_distance_ = 0.0;
  double operating_pressure_angle_ = 0.0;
  PathOfContact path_;
  std::vector<GeometryWarning> warnings_;
};

}  // namespace geartrib::gear
