#include "config/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::io {

namespace {

struct UnitEntry {
  std::string_view symbol;
  Dimension dimension;
  double to_si;
  double offset = 0.0;  // SI = value * to_si + offset (degC only)
};

constexpr double kPi = std::numbers::pi;

// The whole table. Symbols are matched exactly (case-sensitive: "MPa" is not "mpa").
constexpr std::array<UnitEntry, 59> kUnits{{
    {"m", Dimension::length, 1.0},
    {"mm", Dimension::length, 1e-3},
    {"um", Dimension::length, 1e-6},
    {"µm", Dimension::length, 1e-6},
    {"nm", Dimension::length, 1e-9},
    {"m^2", Dimension::area, 1.0},
    {"mm^2", Dimension::area, 1e-6},
    {"um^2", Dimension::area, 1e-12},
    {"nm^2", Dimension::area, 1e-18},
    {"1/m^2", Dimension::areal_density, 1.0},
    {"1/mm^2", Dimension::areal_density, 1e6},
    {"1/um^2", Dimension::areal_density, 1e12},
    {"Pa", Dimension::pressure, 1.0},
    {"kPa", Dimension::pressure, 1e3},
    {"MPa", Dimension::pressure, 1e6},
    {"GPa", Dimension::pressure, 1e9},
    {"N", Dimension::force, 1.0},
    {"kN", Dimension::force, 1e3},
    {"N m", Dimension::torque, 1.0},
    {"Nm", Dimension::torque, 1.0},
    {"N*m", Dimension::torque, 1.0},
    {"kN m", Dimension::torque, 1e3},
    {"rad", Dimension::angle, 1.0},
    {"deg", Dimension::angle, kPi / 180.0},
    {"rad/s", Dimension::angular_speed, 1.0},
    {"rpm", Dimension::angular_speed, 2.0 * kPi / 60.0},
    {"1/min", Dimension::angular_speed, 2.0 * kPi / 60.0},  // a speed n in revolutions per minute (DIN, ISO 6336)
    {"rev/min", Dimension::angular_speed, 2.0 * kPi / 60.0},
    {"r/min", Dimension::angular_speed, 2.0 * kPi / 60.0},
    {"kg/m^3", Dimension::density, 1.0},
    {"kg/m3", Dimension::density, 1.0},
    {"g/cm^3", Dimension::density, 1e3},
    {"m/s", Dimension::speed, 1.0},
    {"kg m^2", Dimension::inertia, 1.0},
    {"kg*m^2", Dimension::inertia, 1.0},
    {"mm/s", Dimension::speed, 1e-3},
    {"K", Dimension::temperature, 1.0},
    {"degC", Dimension::temperature, 1.0, 273.15},
    {"m^2/s", Dimension::kinematic_viscosity, 1.0},
    {"mm^2/s", Dimension::kinematic_viscosity, 1e-6},
    {"cSt", Dimension::kinematic_viscosity, 1e-6},
    {"Pa s", Dimension::dynamic_viscosity, 1.0},
    {"mPa s", Dimension::dynamic_viscosity, 1e-3},
    {"cP", Dimension::dynamic_viscosity, 1e-3},
    {"1/Pa", Dimension::inverse_pressure, 1.0},
    {"1/MPa", Dimension::inverse_pressure, 1e-6},
    {"1/GPa", Dimension::inverse_pressure, 1e-9},
    {"m^2/N", Dimension::inverse_pressure, 1.0},
    {"mm^2/N", Dimension::inverse_pressure, 1e-6},
    {"m^3/(N m)", Dimension::inverse_pressure, 1.0},
    {"mm^3/(N m)", Dimension::inverse_pressure, 1e-9},
    {"1/K", Dimension::inverse_temperature, 1.0},
    {"W/(m K)", Dimension::thermal_conductivity, 1.0},
    {"W/m/K", Dimension::thermal_conductivity, 1.0},
    {"J/(kg K)", Dimension::specific_heat, 1.0},
    {"J/kg/K", Dimension::specific_heat, 1.0},
    {"kJ/(kg K)", Dimension::specific_heat, 1e3},
    {"1", Dimension::dimensionless, 1.0},
    {"%", Dimension::dimensionless, 1e-2},
}};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

NumberAndUnit split_number(std::string_view t) {
  NumberAndUnit out;
  const char* const first = t.data();
  const char* const last = t.data() + t.size();
  const auto [end, ec] = std::from_chars(first, last, out.value);
  if (end == first || (ec != std::errc{} && ec != std::errc::result_out_of_range)) return out;
  if (end != last) {
    const char c = *end;
    if (c == 'e' || c == 'E' || c == '.' || (c >= '0' && c <= '9') || c == '+' || c == '-') return out;
  }
  out.status = ec == std::errc::result_out_of_range ? NumberAndUnit::out_of_range : NumberAndUnit::ok;
  out.unit = trim(std::string_view(end, static_cast<std::size_t>(last - end)));
  return out;
}

std::string_view dimension_name(Dimension d) {
  switch (d) {
    case Dimension::dimensionless:
      return "dimensionless number";
    case Dimension::length:
      return "length";
    case Dimension::area:
      return "area";
    case Dimension::areal_density:
      return "areal density";
    case Dimension::pressure:
      return "pressure";
    case Dimension::force:
      return "force";
    case Dimension::torque:
      return "torque";
    case Dimension::angle:
      return "angle";
    case Dimension::angular_speed:
      return "angular speed";
    case Dimension::density:
      return "density";
    case Dimension::speed:
      return "speed";
    case Dimension::inertia:
      return "moment of inertia";
    case Dimension::temperature:
      return "temperature";
    case Dimension::kinematic_viscosity:
      return "kinematic viscosity";
    case Dimension::dynamic_viscosity:
      return "dynamic viscosity";
    case Dimension::inverse_pressure:
      return "inverse pressure";
    case Dimension::inverse_temperature:
      return "inverse temperature";
    case Dimension::thermal_conductivity:
      return "thermal conductivity";
    case Dimension::specific_heat:
      return "specific heat";
  }
  return "quantity";
}

std::string allowed_units(Dimension d) {
  std::string out;
  for (const auto& u : kUnits)
    if (u.dimension == d) out += (out.empty() ? "" : ", ") + std::string(u.symbol);
  return out;
}

std::vector<UnitScale> units_of(Dimension d) {
  std::vector<UnitScale> out;
  for (const auto& u : kUnits)
    if (u.dimension == d) out.push_back({u.symbol, u.to_si, u.offset});
  return out;
}

double unit_factor(std::string_view unit, Dimension d) {
  for (const auto& u : kUnits) {
    if (u.symbol != unit) continue;
    if (u.dimension != d)
      throw std::invalid_argument("unit '" + std::string(unit) + "' is a " + std::string(dimension_name(u.dimension)) +
                                  ", expected a " + std::string(dimension_name(d)) + " (" + allowed_units(d) + ")");
    return u.to_si;
  }
  throw std::invalid_argument("unknown unit '" + std::string(unit) + "' (a " + std::string(dimension_name(d)) +
                              " takes: " + allowed_units(d) + ")");
}

double parse_quantity(std::string_view text, Dimension d) {
  const NumberAndUnit n = split_number(trim(text));
  if (n.status == NumberAndUnit::malformed)
    throw std::invalid_argument("expected '<number> <unit>' for a " + std::string(dimension_name(d)) +
                                " (a number such as 6, 0.5 or 5e-1, then one of: " + allowed_units(d) + ")");
  if (n.status == NumberAndUnit::out_of_range)
    throw std::invalid_argument("number beyond the range of a double (magnitudes 1e-308 to 1e308)");
  if (!std::isfinite(n.value)) throw std::invalid_argument("value must be finite");
  if (n.unit.empty()) return n.value;  // bare number: SI
  const double factor = unit_factor(n.unit, d);
  double si = n.value * factor;
  for (const auto& u : kUnits)
    if (u.symbol == n.unit) si += u.offset;
  // A finite number times its unit's factor can leave double's range ("1e308 GPa").
  if (!std::isfinite(si)) throw std::invalid_argument("value must be finite in SI units (it overflows)");
  return si;
}

std::optional<AnyQuantity> parse_any_quantity(std::string_view text) {
  const NumberAndUnit n = split_number(trim(text));
  if (n.status != NumberAndUnit::ok || !std::isfinite(n.value)) return std::nullopt;
  if (n.unit.empty()) return AnyQuantity{n.value, Dimension::dimensionless};
  for (const auto& u : kUnits)
    if (u.symbol == n.unit) {
      const double si = n.value * u.to_si + u.offset;
      if (!std::isfinite(si)) return std::nullopt;
      return AnyQuantity{si, u.dimension};
    }
  return std::nullopt;
}

std::string_view si_symbol(Dimension d) {
  switch (d) {
    case Dimension::dimensionless:
      return "1";
    case Dimension::length:
      return "m";
    case Dimension::area:
      return "m^2";
    case Dimension::areal_density:
      return "1/m^2";
    case Dimension::pressure:
      return "Pa";
    case Dimension::force:
      return "N";
    case Dimension::torque:
      return "N m";
    case Dimension::angle:
      return "rad";
    case Dimension::angular_speed:
      return "rad/s";
    case Dimension::density:
      return "kg/m^3";
    case Dimension::speed:
      return "m/s";
    case Dimension::inertia:
      return "kg m^2";
    case Dimension::temperature:
      return "K";
    case Dimension::kinematic_viscosity:
      return "m^2/s";
    case Dimension::dynamic_viscosity:
      return "Pa s";
    case Dimension::inverse_pressure:
      return "1/Pa";
    case Dimension::inverse_temperature:
      return "1/K";
    case Dimension::thermal_conductivity:
      return "W/(m K)";
    case Dimension::specific_heat:
      return "J/(kg K)";
  }
  return "1";
}

}  // namespace geartrib::io
