#include "gear/spur_pair.hpp"

#include "gear/involute.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <fmt/format.h>

namespace geartrib::gear {

namespace {
constexpr double kPi = std::numbers::pi;
const char* kGearName[2] = {"pinion", "wheel"};
}  // namespace

void GearPairSpec::validate() const {
  if (!(module > 0.0)) throw GeometryError("gear_pair.module", "module must be positive");
  if (!(pressure_angle > 0.0 && pressure_angle < kPi / 4.0))
    throw GeometryError("gear_pair.pressure_angle", "pressure angle must lie in (0, 45) deg");
  if (!(face_width > 0.0)) throw GeometryError("gear_pair.face_width", "face width must be positive");
  for (int i = 0; i < 2; ++i)
    if (teeth[i] < kMinTeeth || teeth[i] > kMaxTeeth)
      throw GeometryError(std::string(kGearName[i]) + ".teeth",
                          fmt::format("tooth number must lie in [{}, {}]", kMinTeeth, kMaxTeeth));
}

SpurPair::SpurPair(const GearPairSpec& spec) : spec_(spec) {
  spec.validate();
  const double m = spec.module, alpha = spec.pressure_angle;
  const int z1 = spec.teeth[0], z2 = spec.teeth[1];

  reference_center_distance_ = 0.5 * m * (z1 + z2);
  // Zero-backlash operating pressure angle for the shifts (ISO 21771 eq. for inv alpha_w).
  const double inv_w0 =
      involute(alpha) + 2.0 * std::tan(alpha) * (spec.profile_shift[0] + spec.profile_shift[1]) / (z1 + z2);
  if (inv_w0 < 0.0)
    throw GeometryError("pinion.profile_shift", "the sum of profile shifts leaves no operating pressure angle");
  const double alpha_w0 = inverse_involute(inv_w0);
  const double a_w0 = reference_center_distance_ * std::cos(alpha) / std::cos(alpha_w0);
  if (spec.center_distance > 0.0) {
    const double cos_w = reference_center_distance_ * std::cos(alpha) / spec.center_distance;
    if (!(cos_w < 1.0))
      throw GeometryError("gear_pair.center_distance", "centre distance too small: the base circles overlap");
    // 1e-5 relative (0.9 um at 90 mm) allows for profile shifts published to four decimals.
    if (spec.center_distance < a_w0 * (1.0 - 1e-5))
      throw GeometryError(
          "gear_pair.center_distance",
          fmt::format(
              "centre distance {:.6g} mm is below the zero-backlash distance {:.6g} mm for these profile shifts",
              spec.center_distance * 1e3, a_w0 * 1e3));
    center_distance_ = spec.center_distance;
    operating_pressure_angle_ = std::acos(cos_w);
  } else {
    center_distance_ = a_w0;
    operating_pressure_angle_ = alpha_w0;
  }
  const double alpha_w = operating_pressure_angle_;

  for (int i = 0; i < 2; ++i) {
    GearBody& g = gear_[i];
    const std::string name = kGearName[i];
    const double x = spec.profile_shift[i];
    g.teeth = spec.teeth[i];
    g.profile_shift = x;
    g.pitch_radius = 0.5 * m * g.teeth;
    g.base_radius = g.pitch_radius * std::cos(alpha);
    g.operating_pitch_radius = g.base_radius / std::cos(alpha_w);
    g.tip_radius = spec.tip_diameter[i] > 0.0
                       ? 0.5 * spec.tip_diameter[i]
                       : g.pitch_radius + m * (spec.addendum_coefficient + x - spec.tip_shortening);
    g.root_radius = g.pitch_radius - m * (spec.dedendum_coefficient - x);
    g.bore_radius = 0.5 * spec.bore_diameter[i];
    // Half tooth angle on the base circle: s/(2r) + inv(alpha), s = m (pi/2 + 2 x tan alpha).
    g.base_half_angle = kPi / (2.0 * g.teeth) + 2.0 * x * std::tan(alpha) / g.teeth + involute(alpha);
    const std::string tip_key = spec.tip_diameter[i] > 0.0 ? name + ".tip_diameter" : "gear_pair.addendum_coefficient";
    if (!(g.tip_radius > g.base_radius)) throw GeometryError(tip_key, name + " tip circle lies inside its base circle");
    if (!(g.root_radius > 0.0))
      throw GeometryError(name + ".profile_shift", name + " root circle radius is not positive");
    if (g.bore_radius > 0.0 && !(g.bore_radius < g.root_radius))
      throw GeometryError(name + ".bore_diameter", name + " bore must lie inside the root circle");
    // A bore so small that r_f/r_bore leaves any fillet-foundation model: Sainsot et al.'s fit
    // (1.4 <= r_f/r_bore <= 7) turns negative near 65 and overflows to NaN for a vanishing bore.
    if (g.bore_radius > 0.0 && g.root_radius / g.bore_radius > kMaxRootOverBore)
      throw GeometryError(name + ".bore_diameter",
                          fmt::format("{} bore {:.4g} mm is below 1/{:g} of the root diameter {:.4g} mm: no "
                                      "fillet-foundation model covers it; give 0 for a solid body",
                                      name, 2e3 * g.bore_radius, kMaxRootOverBore, 2e3 * g.root_radius));
    // Tooth thickness at the tip must stay positive (no pointed teeth).
    const double alpha_a = std::acos(g.base_radius / g.tip_radius);
    if (!(g.base_half_angle - involute(alpha_a) > 0.0))
      throw GeometryError(tip_key, name + " teeth are pointed: the flanks cross below the tip circle");
    // Start of the generated involute (rack tip line incl. its fillet): roll length from T.
    const double rack_tip =
        m * (spec.dedendum_coefficient - x) - spec.root_radius_coefficient * m * (1.0 - std::sin(alpha));
    g.form_roll_length = g.pitch_radius * std::sin(alpha) - rack_tip / std::sin(alpha);
    if (g.form_roll_length < 0.0) {
      warnings_.push_back({name + ".teeth", fmt::format("{} is undercut by the generating rack (z = {}, x = {:.3g}): "
                                                        "the involute starts {:.3g} mm below the base-circle tangent",
                                                        name, g.teeth, x, -g.form_roll_length * 1e3)});
      g.form_roll_length = 0.0;
    }
  }
  // Tip-to-root clearance.
  for (int i = 0; i < 2; ++i) {
    const double clearance = center_distance_ - gear_[i].tip_radius - gear_[1 - i].root_radius;
    if (clearance < 0.0)
      throw GeometryError(
          spec.tip_diameter[i] > 0.0 ? std::string(kGearName[i]) + ".tip_diameter" : "gear_pair.dedendum_coefficient",
          fmt::format("{} tip reaches {:.3g} mm into the {} root circle", kGearName[i], -clearance * 1e3,
                      kGearName[1 - i]));
  }

  PathOfContact& p = path_;
  p.line_length = center_distance_ * std::sin(alpha_w);
  p.base_pitch = kPi * m * std::cos(alpha);
  p.e = std::sqrt(gear_[0].tip_radius * gear_[0].tip_radius - gear_[0].base_radius * gear_[0].base_radius);
  p.a = p.line_length -
        std::sqrt(gear_[1].tip_radius * gear_[1].tip_radius - gear_[1].base_radius * gear_[1].base_radius);
  p.c = gear_[0].base_radius * std::tan(alpha_w);
  // Involute interference: contact must stay on both gears' generated involutes.
  if (p.a <= gear_[0].form_roll_length)
    throw GeometryError("wheel.teeth",
                        fmt::format("the wheel tip meets the pinion {:.3g} mm below the start of its involute "
                                    "(tip interference: no involute exists there)",
                                    (gear_[0].form_roll_length - p.a) * 1e3));
  if (p.line_length - p.e <= gear_[1].form_roll_length)
    throw GeometryError("pinion.teeth",
                        fmt::format("the pinion tip meets the wheel {:.3g} mm below the start of its involute "
                                    "(tip interference: no involute exists there)",
                                    (gear_[1].form_roll_length - (p.line_length - p.e)) * 1e3));
  p.length = p.e - p.a;
  p.contact_ratio = p.length / p.base_pitch;
  if (!(p.contact_ratio >= 1.0))
    throw GeometryError(
        "gear_pair.addendum_coefficient",
        fmt::format("transverse contact ratio {:.4g} is below 1: the mesh is not continuous", p.contact_ratio));
  p.b = p.e - p.base_pitch;
  p.d = p.a + p.base_pitch;
  if (p.contact_ratio >= 2.0)
    warnings_.push_back({"gear_pair.addendum_coefficient",
                         fmt::format("transverse contact ratio {:.4g} >= 2: no single-tooth zone; the ISO/TS 6336-22 "
                                     "load-sharing factors (defined for 1 <= eps < 2) are normalised over the pairs",
                                     p.contact_ratio)});
}

FlankGeometry SpurPair::flank(double s) const {
  FlankGeometry f;
  f.s = s;
  f.radius_pinion = s;
  f.radius_wheel = path_.line_length - s;
  f.radius_equivalent = f.radius_pinion * f.radius_wheel / path_.line_length;
  f.roll_parameter = s / path_.c - 1.0;
  return f;
}

FlankKinematics SpurPair::kinematics(double s, double pinion_speed) const {
  FlankKinematics k;
  const double omega2 = pinion_speed * gear_[0].teeth / gear_[1].teeth;
  k.rolling_pinion = pinion_speed * s;
  k.rolling_wheel = omega2 * (path_.line_length - s);
  k.entrainment = 0.5 * (k.rolling_pinion + k.rolling_wheel);
  k.sliding = k.rolling_pinion - k.rolling_wheel;
  k.slide_to_roll = k.entrainment > 0.0 ? k.sliding / k.entrainment : 0.0;
  k.specific_sliding_pinion =
      k.rolling_pinion > 0.0 ? k.sliding / k.rolling_pinion : -std::numeric_limits<double>::infinity();
  k.specific_sliding_wheel = k.rolling_wheel > 0.0 ? (k.rolling_wheel - k.rolling_pinion) / k.rolling_wheel
                                                   : -std::numeric_limits<double>::infinity();
  return k;
}

double SpurPair::roll_angle(int i, double s) const {
  return (i == 0 ? s : path_.line_length - s) / gear_[i].base_radius;
}

}  // namespace geartrib::gear
