// The small fixed unit table: a value in a data file is an SI number or a string
// "<number> <unit>" ("206 GPa", "6 mm", "1.65 um"). Converted to SI once, at input.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

enum class Dimension {
  dimensionless,
  length,
  area,
  areal_density,
  pressure,
  force,
  torque,
  angle,
  angular_speed,
  density,
  speed,
  inertia,
  temperature,           // K; degC carries an offset
  kinematic_viscosity,   // m^2/s
  dynamic_viscosity,     // Pa s
  inverse_pressure,      // 1/Pa: pressure-viscosity coefficient, Archard wear coefficient (m^2/N)
  inverse_temperature,   // 1/K
  thermal_conductivity,  // W/(m K)
  specific_heat          // J/(kg K)
};

std::string_view dimension_name(Dimension d);
// The units accepted for a dimension, comma separated (for error messages and --help).
std::string allowed_units(Dimension d);

// The units of a dimension in the table's order, each with the SI value of one unit (and degC's
// offset): what a bare number, read as SI, may have been meant in.
struct UnitScale {
  std::string_view symbol;
  double to_si = 1.0;
  double offset = 0.0;
};
std::vector<UnitScale> units_of(Dimension d);

// SI factor of `unit` for dimension `d`; throws std::invalid_argument("unknown unit ...") when
// the unit is not in the table or belongs to another dimension.
double unit_factor(std::string_view unit, Dimension d);

// Parses "<number> <unit>" (space optional) or a bare number (SI) into SI; throws
// std::invalid_argument with the rule broken. The number is read whole, its exponent included:
// "5e-1" is 0.5 (SI), "5e-1 mm" 0.5 mm, and "2e", "2e mm" or "1.5.3" are malformed numbers (an
// exponent is never taken for a unit). The result must be finite after the unit's factor
// ("1e308 GPa" is refused).
double parse_quantity(std::string_view text, Dimension d);

// A number with any unit of the table ("4mm" -> 0.004, length), for values whose dimension the
// caller does not know (sweep axes); a bare number is dimensionless. nullopt for other text.
struct AnyQuantity {
  double si = 0.0;
  Dimension dimension = Dimension::dimensionless;
};
std::optional<AnyQuantity> parse_any_quantity(std::string_view text);
// The SI unit of a dimension as written in output files ("m", "Pa", "rad/s", "1").
std::string_view si_symbol(Dimension d);

// The number at the start of `t` and the unit text after it. The number is read whole: an
// exponent belongs to it ("5e-1 mm" is 0.5 mm) and is never taken for a unit, so a number that
// ends in a broken exponent ("2e", "2e mm", "2e+") or runs on into digits, points or another
// exponent ("1.5.3", "2e3e4") is malformed, not a number followed by a unit.
struct NumberAndUnit {
  enum Status { ok, malformed, out_of_range } status = malformed;
  double value = 0.0;
  std::string_view unit;
};
NumberAndUnit split_number(std::string_view t);  // t trimmed; the unit trimmed

}  // namespace geartrib::io
