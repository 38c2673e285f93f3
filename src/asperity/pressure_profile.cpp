#include "asperity/pressure_profile.hpp"

#include "asperity/axis_stress.hpp"
#include "core/maximize.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geartrib::asperity {

namespace {
constexpr double kPi = std::numbers::pi;
}

double PressureProfile::load() const {
  const double a = contact_radius;
  if (a <= 0.0) return 0.0;
  const double ann = std::max(0.0, a * a - core_radius * core_radius);
  return kPi * core_radius * core_radius * core_pressure + (2.0 * kPi / 3.0) * annulus_peak * ann * std::sqrt(ann) / a;
}

double PressureProfile::max_pressure() const {
  if (contact_radius <= 0.0) return 0.0;
  const double rho = core_radius / contact_radius;
  const double edge = annulus_peak * std::sqrt(std::max(0.0, 1.0 - rho * rho));
  return std::max(core_radius > 0.0 ? core_pressure : 0.0, edge);
}

double PressureProfile::plastic_fraction() const {
  if (contact_radius <= 0.0) return 0.0;
  const double rho = core_radius / contact_radius;
  return rho * rho;
}

AxisStress PressureProfile::axis_stress(double depth, double nu) const {
  const double a = contact_radius;
  AxisStress s{};
  if (a <= 0.0) return s;
  auto add = [&](const AxisStress& t, double scale) {
    s.radial += scale * t.radial;
    s.axial += scale * t.axial;
  };
  if (core_radius > 0.0) add(uniform_disc_axis_stress(depth / core_radius, nu), core_pressure);
  if (core_radius < a && annulus_peak != 0.0)
    add(hertz_annulus_axis_stress(depth / a, core_radius / a, nu), annulus_peak);
  return s;
}

VonMisesMaximum PressureProfile::von_mises_maximum(double nu) const {
  const double a = contact_radius;
  if (a <= 0.0) return {};
  const auto m =
      maximize_on_interval([&](double z) { return von_mises_on_axis(axis_stress(z * a, nu)); }, 1e-4, 3.0, 48);
  return {m.value, m.x * a};
}

PressureProfile hertz_profile(double contact_radius, double peak_pressure) {
  return {contact_radius, 0.0, 0.0, peak_pressure};
}

PressureProfile uniform_profile(double contact_radius, double pressure) {
  return {contact_radius, contact_radius, pressure, 0.0};
}

PressureProfile two_zone_profile(double contact_radius, double mean_pressure, double plastic_share) {
  const double phi = std::clamp(plastic_share, 0.0, 1.0);
  if (phi == 0.0) return hertz_profile(contact_radius, 1.5 * mean_pressure);
  if (phi == 1.0) return uniform_profile(contact_radius, mean_pressure);
  const double core = 3.0 * mean_pressure / (2.0 + phi);
  return {contact_radius, std::sqrt(phi) * contact_radius, core, core / std::sqrt(1.0 - phi)};
}

}  // namespace geartrib::asperity
