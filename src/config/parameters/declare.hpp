// Declaring case parameters (the builders of config/case_parameters.hpp's rows), in the spirit of
// deal.II's add_parameter: each component's keys are declared in a file of their own beside it
// (config/parameters/<component>.cpp: the row's key, dimension, accessor of the Case member, range,
// aliases and meaning; its default is the member's initial value, read from a default Case), and
// case_parameters() assembles the table from them in the order of docs/reference/case-file.md.
#pragma once

#include "config/case_parameters.hpp"

#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace geartrib::io::parameters {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kDeg = std::numbers::pi / 180.0;
inline constexpr double kMm = 1e-3, kUm = 1e-6, kRpm = 2.0 * std::numbers::pi / 60.0;
// Lengths of the gear bodies: at most 10 km (a 10 m module, 1000 teeth). Every numeric row has
// finite bounds: a hard range beyond which a value is refused (wide: what the arithmetic carries
// without overflow or loss), and for the gear's own quantities a plausible band beyond which it is
// warned about (docs/reference/units.md, "Ranges and plausible bands").
inline constexpr double kMaxBodyLength = 1e4;

// A gear's body (0: pinion, 1: wheel), for the "{gear}." rows.
inline constexpr auto gear_of = [](auto& c, int g) -> auto& { return g == 0 ? c.pinion : c.wheel; };

inline ParameterValue number_value(double x) {
  ParameterValue v;
  v.number = x;
  return v;
}
inline ParameterValue text_value(std::string t) {
  ParameterValue v;
  v.text = std::move(t);
  return v;
}

// The builders: a row from an accessor `ref(case, gear) -> member&`, written once as a generic
// lambda so that it serves reading (const Case) and writing (Case).
template <class Ref>
Parameter numeric(std::string key, ParameterKind kind, Dimension d, Ref ref) {
  Parameter p;
  p.key = std::move(key);
  p.kind = kind;
  p.dimension = d;
  p.get = [ref](const Case& c, int g) { return number_value(static_cast<double>(ref(c, g))); };
  p.set = [ref](Case& c, int g, const ParameterValue& v) {
    auto& m = ref(c, g);
    m = static_cast<std::remove_reference_t<decltype(m)>>(v.number);
  };
  return p;
}
template <class Ref>
Parameter quantity(std::string key, Dimension d, Ref ref) {
  return numeric(std::move(key), ParameterKind::quantity, d, ref);
}
template <class Ref>
Parameter number(std::string key, Ref ref) {
  return numeric(std::move(key), ParameterKind::number, Dimension::dimensionless, ref);
}
template <class Ref>
Parameter integer(std::string key, Ref ref) {
  return numeric(std::move(key), ParameterKind::integer, Dimension::dimensionless, ref);
}
template <class Ref>
Parameter text(std::string key, ParameterKind kind, Ref ref) {
  Parameter p;
  p.key = std::move(key);
  p.kind = kind;
  p.get = [ref](const Case& c, int g) { return text_value(ref(c, g)); };
  p.set = [ref](Case& c, int g, const ParameterValue& v) { ref(c, g) = v.text; };
  return p;
}
// A choice stored as something else (a bool, an enum): `to` maps the text to the member, `from` back.
template <class Ref, class To, class From>
Parameter mapped_choice(std::string key, std::vector<std::string> choices, Ref ref, To to, From from) {
  Parameter p;
  p.key = std::move(key);
  p.kind = ParameterKind::choice;
  p.choices = std::move(choices);
  p.get = [ref, from](const Case& c, int g) { return text_value(from(ref(c, g))); };
  p.set = [ref, to](Case& c, int g, const ParameterValue& v) { ref(c, g) = to(v.text); };
  return p;
}

// A choice stored as an enum, read and written through its component's table of names.
template <class E, class Ref>
Parameter named_choice(std::string key, std::span<const NamedChoice<E>> table, std::string noun, Ref ref) {
  Parameter p;
  p.key = std::move(key);
  p.kind = ParameterKind::choice;
  p.choices = choice_names(table);
  p.noun = noun;
  p.get = [ref, table](const Case& c, int g) { return text_value(choice_name(table, ref(c, g))); };
  p.set = [ref, table, noun](Case& c, int g, const ParameterValue& v) {
    ref(c, g) = choice_from_name(table, v.text, noun);
  };
  return p;
}

// Fluent setters for the rest of a row.
struct Row {
  Parameter p;
  Row& range(double lo, double hi, bool lo_open = false, bool hi_open = false) {
    p.min = lo, p.max = hi, p.min_open = lo_open, p.max_open = hi_open;
    return *this;
  }
  Row& positive() { return range(0.0, kInf, true, false); }
  Row& non_negative() { return range(0.0, kInf); }
  // A plausible band inside the range: outside it the value is read and warned about.
  Row& plausible(double lo, double hi) {
    p.plausible_min = lo, p.plausible_max = hi;
    return *this;
  }
  Row& no_default() {
    p.has_default = false;
    return *this;
  }
  Row& required(unsigned parts) {
    p.required_by = parts;
    return *this;
  }
  Row& alias(std::vector<std::string> names) {
    p.aliases = std::move(names);
    return *this;
  }
  Row& gear_alias(std::string pinion, std::string wheel) {
    p.gear_aliases = {std::move(pinion), std::move(wheel)};
    return *this;
  }
  Row& ladder(std::vector<std::string> settings) {
    p.ladder = std::move(settings);
    return *this;
  }
  Row& choices(std::vector<std::string> names, std::string noun = "value") {
    p.choices = std::move(names);
    p.noun = std::move(noun);
    return *this;
  }
  Row& doc(std::string meaning) {
    p.meaning = std::move(meaning);
    return *this;
  }
  // The Case member the row fills, when its path differs from the key ("dynamics.tolerances.relative"
  // for dynamics.relative_tolerance): a component's refusal naming that field is located at the key.
  Row& field(std::string member) {
    p.field = std::move(member);
    return *this;
  }
};

// The rows as the components declare them, in the order of the table.
class ParameterRows {
 public:
  Row& add(Parameter p) { return rows_.emplace_back(Row{std::move(p)}); }
  std::vector<Parameter> take() {
    std::vector<Parameter> out;
    out.reserve(rows_.size());
    for (auto& r : rows_) out.push_back(std::move(r.p));
    return out;
  }

 private:
  std::vector<Row> rows_;
};

// Each component's rows, in the table's order (case_parameters.cpp calls them).
void declare_gear_pair(ParameterRows& table);  // gear_pair.*, each gear's teeth, shift, diameters, material
void declare_flanks(ParameterRows& table);  // {gear}.flank.*: roughness forms, measured topography, generated profile
void declare_operating(ParameterRows& table);    // operating.*
void declare_lubrication(ParameterRows& table);  // lubricant.*, lubrication.*
void declare_friction(ParameterRows& table);     // friction.mu
void declare_mesh(ParameterRows& table);         // mesh.*, dynamics.*
void declare_roughness(ParameterRows& table);    // roughness.*: both flanks' height distribution
void declare_contact(ParameterRows& table);      // contact.*, running_in.*
void declare_asperity(ParameterRows& table);     // asperity.*
void declare_rating(ParameterRows& table);       // rating.*, {gear}.flank_rz, {gear}.root_rz

}  // namespace geartrib::io::parameters
