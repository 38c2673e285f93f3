// Every key of a case file, declared once, in the spirit of deal.II's ParameterHandler: the
// member it fills, its physical dimension (the unit table of config/units.hpp), its default (the
// member's initial value in case/case.hpp), its range or choices and a one-line meaning.
// From this table come the case reader and its located errors (io::load_case), the --set keys
// and their aliases, the sweep's axes, the trade tool's knobs and `geartrib case --schema`
// (docs/reference/case-file.md is its Markdown).
#pragma once

#include "case/case.hpp"
#include "config/units.hpp"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace geartrib::io {

// The parts of a case a command uses. A key without a default is required only when a part
// that needs it is asked for: the kinematics need no friction coefficient, flank roughness or
// cylinder radius.
enum CasePart : unsigned {
  kGeometryPart = 1u,   // gear pair, materials, operating point, mesh, dynamics
  kRoughnessPart = 2u,  // flank roughness and the asperity model
  kFrictionPart = 4u,   // the asperity side contact (mesh cycle, `geartrib asperity --contact side`)
  kCylinderPart = 8u,   // the cylinder asperity of the multi-asperity and FEM studies
  kAllParts = 15u,
};
// What the mesh cycle uses (`geartrib run`, `sweep`, `tradeoff`, the Python module): every part
// but the cylinder asperity, which only the multi-asperity and FEM studies (and `geartrib asperity
// --summary`) ask for. The default of the case loaders.
inline constexpr unsigned kMeshCycleParts = kGeometryPart | kRoughnessPart | kFrictionPart;

enum class ParameterKind {
  quantity,  // a number with a unit of its dimension, or a bare SI number
  number,    // dimensionless; may also be one of `choices` (a named rule)
  integer,
  choice,           // one of `choices`
  text,             // free text (title, source, file names)
  flag,             // true or false
  choice_list,      // an array of `choices`
  model_constants,  // asperity.constants.MODEL.NAME = number (checked by the model's own ranges)
};

// A value as read, SI: `number` for quantity/number/integer/flag (1 or 0), `text` for
// choice/text (and a number given by name), `list` for choice_list.
struct ParameterValue {
  double number = 0.0;
  std::string text;
  std::vector<std::string> list;
};

struct Parameter {
  std::string key;  // dotted case-file key; "{gear}." rows stand for "pinion." and "wheel."
  // The Case member it fills, by its path ("dynamics.tolerances.relative"), where that differs
  // from the key; empty: the key. A component's refusal names the field (core::KeyedError), and
  // case_key_of_field() maps it to the key.
  std::string field;
  ParameterKind kind = ParameterKind::number;
  Dimension dimension = Dimension::dimensionless;
  unsigned required_by = 0;  // parts that need it given; 0: optional
  bool has_default = true;   // false: absent means "not this form/choice" (a flank's roughness forms)
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false, max_open = false;
  // The band a spur gear's value plausibly lies in: a value inside the range but outside the band
  // is read and warned about, naming the key (a 6 m module, a 1e6 rpm speed). Infinite: no band.
  double plausible_min = -std::numeric_limits<double>::infinity();
  double plausible_max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;
  std::string noun = "value";  // what a choice names, for errors ("unknown asperity model 'x'")
  std::string meaning;
  std::vector<std::string> aliases;       // short --set/sweep names standing for the key (all gears)
  std::vector<std::string> gear_aliases;  // "{gear}" rows: a short name per gear (z1, z2)
  std::vector<std::string> ladder;        // a fidelity knob's settings, cheapest first (geartrib tradeoff)
  std::function<ParameterValue(const Case&, int gear)> get;
  std::function<void(Case&, int gear, const ParameterValue&)> set;

  // The range and its rule as an error message says it ("must lie in [5, 1000]"); empty: none.
  std::string range_text() const;
  // Within the range: finite (an infinite or NaN value never is) and inside the declared bounds.
  bool in_range(double v) const;
  // The plausible band as text ("[0.05 mm, 100 mm]" in the key's SI unit); empty: none.
  std::string plausible_text() const;
  bool plausible(double v) const { return !(v < plausible_min || v > plausible_max); }
  bool per_gear() const { return key.rfind("{gear}.", 0) == 0; }
  // An absent key takes a default value (the schema shows it, the reader records it).
  bool defaulted() const {
    return has_default && required_by == 0 && kind != ParameterKind::text && kind != ParameterKind::model_constants;
  }
  // The key for gear 0 (pinion) or 1 (wheel); the key itself for other rows.
  std::string key_for(int gear) const;
  // The value as a case file would write it, SI unit appended ("0.006 m", "iso", "[a, b]").
  std::string format(const ParameterValue& v) const;
};

// The table, in the order of docs/reference/case-file.md.
const std::vector<Parameter>& case_parameters();

// The row of a dotted key and the gear it addresses (-1 for rows that are not per gear);
// {nullptr, -1} when the key is not declared. asperity.constants.MODEL.NAME finds its row.
struct ParameterLookup {
  const Parameter* parameter = nullptr;
  int gear = -1;
};
ParameterLookup find_parameter(std::string_view key);

// The case key of a Case member by its path: the row whose field (or key) it is, per gear for
// "pinion."/"wheel." paths ("dynamics.tolerances.relative": dynamics.relative_tolerance;
// "wheel.flank.topography.clean.outlier_limit": wheel.flank.topography.outliers); the path itself
// when no row declares it.
std::string case_key_of_field(std::string_view field);

// A short name and the dotted keys it stands for (rq: both flanks' rq), from the table's aliases.
struct CaseAlias {
  std::string name;
  std::vector<std::string> keys;
};
const std::vector<CaseAlias>& case_aliases();
// The dotted keys a --set name stands for: an alias's keys, or the name itself.
std::vector<std::string> resolve_case_key(const std::string& name);

// A value typed on the command line ("4mm", "30", "iso") checked against its row: kind, unit,
// choices and range. The rule it breaks, or empty when it is fine (sweep axes, checked before
// any point runs).
std::string parameter_text_error(const Parameter& p, const std::string& text);

// A value of a row (SI) outside its plausible band: the warning's text, naming the band and the
// range; empty when the value is plausible.
std::string implausible_text(const Parameter& p, double v);

// A bare number (SI: `module = 4.5` is 4.5 m) outside a quantity row's plausible band, or its
// range, that another unit of its dimension puts inside both: the rule naming the SI reading and
// the units probably meant ("read as 4.5 m (a bare number is SI), above the plausible band ...:
// did you mean \"4.5 mm\"? ..."). Empty when the row has no band, the value is plausible, or no
// unit helps (a value with its unit is only warned about: the unit says what was meant).
std::string bare_number_rule(const Parameter& p, double bare);

// The schema: one row per key (gear rows once, as "{gear}.key"), as CSV or Markdown.
std::string case_schema_csv();
std::string case_schema_markdown();

}  // namespace geartrib::io
