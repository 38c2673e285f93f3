#include "lubrication/lubricant.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace geartrib::lubrication {

namespace {
constexpr double kZeroCelsius = 273.15;  // [K]
constexpr double kT40 = kZeroCelsius + 40.0, kT100 = kZeroCelsius + 100.0, kT15 = kZeroCelsius + 15.0;
constexpr double kCentistokes = 1e-6;  // [m^2/s]

// Walther's constants A, B through the 40 and 100 degC points.
struct Walther {
  double a, b;
};
double walther_w(double nu) { return std::log10(std::log10(nu / kCentistokes + Lubricant::kWaltherOffset)); }
Walther walther(const Lubricant& l) {
  const double w40 = walther_w(l.kinematic_viscosity_40), w100 = walther_w(l.kinematic_viscosity_100);
  const double b = (w40 - w100) / (std::log10(kT100) - std::log10(kT40));
  return {w40 + b * std::log10(kT40), b};
}

// ISO/TR 15144-1 temperature law of alpha, relative to 38 degC (311 K in the standard).
double iso_alpha_temperature_factor(double t) { return 1.0 + 516.0 * (1.0 / t - 1.0 / 311.0); }
}  // namespace

BaseOil base_oil_from_name(const std::string& name) {
  for (BaseOil b : {BaseOil::mineral, BaseOil::pao, BaseOil::ester, BaseOil::polyglycol})
    if (name == base_oil_name(b)) return b;
  throw std::invalid_argument("unknown base oil '" + name + "' (known: mineral, pao, ester, polyglycol)");
}

const char* base_oil_name(BaseOil b) {
  switch (b) {
    case BaseOil::mineral:
      return "mineral";
    case BaseOil::pao:
      return "pao";
    case BaseOil::ester:
      return "ester";
    case BaseOil::polyglycol:
      return "polyglycol";
  }
  return "mineral";
}

double iso_lubricant_factor(BaseOil b) {
  switch (b) {
    case BaseOil::mineral:
      return 1.0;
    case BaseOil::pao:
      return 0.8;
    case BaseOil::ester:
      return 0.7;
    case BaseOil::polyglycol:
      return 0.6;
  }
  return 1.0;
}

void Lubricant::validate() const {
  auto fail = [](const char* member, const std::string& rule) {
    throw std::invalid_argument(fmt::format("{}: {}", member, rule));
  };
  if (fixed()) {
    if (!(pressure_viscosity > 0.0)) fail("pressure_viscosity_coefficient", "must be positive");
    if (!(fixed_temperature_viscosity >= 0.0)) fail("temperature_viscosity_coefficient", "must be >= 0");
  } else {
    if (!(kinematic_viscosity_100 >= 2.0 * kCentistokes))
      fail("kinematic_viscosity_100C", "must be at least 2 mm^2/s (Walther's law, ASTM D341)");
    if (!(kinematic_viscosity_40 > kinematic_viscosity_100))
      fail("kinematic_viscosity_40C", "must exceed the 100 degC viscosity");
    if (!(density_15 > 0.0)) fail("density_15C", "must be positive");
    if (!(density_temperature_coefficient >= 0.0 && density_temperature_coefficient < 2e-3))
      fail("density_temperature_coefficient", "must lie in [0, 2e-3) 1/K");
    if (!(pressure_viscosity >= 0.0)) fail("pressure_viscosity_coefficient", "must be positive (or omitted)");
    if (!(pressure_viscosity_temperature > 0.0)) fail("pressure_viscosity_temperature", "must be positive (K)");
  }
  if (!(thermal_conductivity > 0.0)) fail("thermal_conductivity", "must be positive");
  if (!(specific_heat >= 0.0)) fail("specific_heat", "must be >= 0");
  if (!(eyring_stress > 0.0)) fail("eyring_stress", "must be positive");
  if (!(limiting_shear_coefficient > 0.0 && limiting_shear_coefficient <= 1.0))
    fail("limiting_shear_coefficient", "must lie in (0, 1]");
  if (!(min_temperature > 0.0 && max_temperature > min_temperature))
    fail("max_temperature", "must exceed min_temperature (both in K, positive)");
}

double kinematic_viscosity(const Lubricant& l, double t) {
  const Walther w = walther(l);
  return (std::pow(10.0, std::pow(10.0, w.a - w.b * std::log10(t))) - Lubricant::kWaltherOffset) * kCentistokes;
}

double density(const Lubricant& l, double t) {
  return l.density_15 * (1.0 - l.density_temperature_coefficient * (t - kT15));
}

double pressure_viscosity_coefficient(const Lubricant& l, double t) {
  if (l.fixed()) return l.pressure_viscosity;
  if (l.pressure_viscosity > 0.0)
    return l.pressure_viscosity * iso_alpha_temperature_factor(t) /
           iso_alpha_temperature_factor(l.pressure_viscosity_temperature);
  const double t38 = kZeroCelsius + 38.0;
  const double eta38 = kinematic_viscosity(l, t38) * density(l, t38);  // [Pa s]
  return 2.657e-8 * std::pow(eta38, 0.1348) * iso_alpha_temperature_factor(t);
}

OilState oil_state(const Lubricant& l, double t) {
  OilState s;
  s.temperature = t;
  s.pressure_viscosity = pressure_viscosity_coefficient(l, t);
  s.thermal_conductivity = l.thermal_conductivity;
  s.eyring_stress = l.eyring_stress;
  s.limiting_shear_coefficient = l.limiting_shear_coefficient;
  s.iso_lubricant_factor = iso_lubricant_factor(l.base_oil);
  if (l.fixed()) {
    s.dynamic_viscosity = l.fixed_dynamic_viscosity;
    s.temperature_viscosity = l.fixed_temperature_viscosity;
    s.density = l.density_15;
    return s;
  }
  s.density = density(l, t);
  const double nu = kinematic_viscosity(l, t);
  s.dynamic_viscosity = nu * s.density;
  // beta = -d ln(nu)/dT - d ln(rho)/dT, Walther differentiated:
  // d nu/dT = -(nu + 0.7) ln10 10^Z B / T with Z = A - B log10 T (nu in cSt).
  const Walther w = walther(l);
  const double nu_cst = nu / kCentistokes;
  const double dnu_dt =
      -(nu_cst + Lubricant::kWaltherOffset) * std::log(10.0) * std::pow(10.0, w.a - w.b * std::log10(t)) * w.b / t;
  s.temperature_viscosity =
      -dnu_dt / nu_cst + l.density_temperature_coefficient / (1.0 - l.density_temperature_coefficient * (t - kT15));
  return s;
}

}  // namespace geartrib::lubrication
