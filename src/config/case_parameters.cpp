#include "config/case_parameters.hpp"

#include "output/table_writer.hpp"

#include "config/parameters/declare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <utility>

namespace geartrib::io {

namespace {

const char* const kGearPrefix[2] = {"pinion.", "wheel."};

// The table from the components' declarations, in the order of docs/reference/case-file.md.
std::vector<Parameter> build_table() {
  using namespace parameters;
  ParameterRows table;
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  add(text(
          "title", ParameterKind::text, [](auto& c, int) -> auto& { return c.title; }))
      .required(kGeometryPart)
      .doc("What the case is");
  add(text(
          "source", ParameterKind::text, [](auto& c, int) -> auto& { return c.source; }))
      .required(kGeometryPart)
      .doc("Where its data come from (provenance)");

  declare_gear_pair(table);
  declare_flanks(table);
  declare_operating(table);
  declare_lubrication(table);
  declare_friction(table);
  declare_mesh(table);
  declare_roughness(table);
  declare_contact(table);
  declare_asperity(table);
  declare_rating(table);
  return table.take();
}

std::string number_text(double v) { return fmt::format("{:g}", v); }

// Schema columns: key, kind, unit, default, range or choices, required by, aliases, meaning.
std::vector<std::vector<std::string>> schema_rows() {
  const Case defaults;
  std::vector<std::vector<std::string>> rows;
  auto parts = [](unsigned p) {
    std::string s;
    auto add = [&](unsigned bit, const char* name) {
      if (p & bit) s += (s.empty() ? "" : " ") + std::string(name);
    };
    add(kGeometryPart, "geometry");
    add(kRoughnessPart, "roughness");
    add(kFrictionPart, "friction");
    add(kCylinderPart, "cylinder");
    return s;
  };
  for (const Parameter& p : case_parameters()) {
    std::string kind;
    switch (p.kind) {
      case ParameterKind::quantity:
        kind = std::string(dimension_name(p.dimension));
        break;
      case ParameterKind::number:
        kind = "number";
        break;
      case ParameterKind::integer:
        kind = "integer";
        break;
      case ParameterKind::choice:
        kind = "choice";
        break;
      case ParameterKind::text:
        kind = "text";
        break;
      case ParameterKind::flag:
        kind = "true/false";
        break;
      case ParameterKind::choice_list:
        kind = "list of choices";
        break;
      case ParameterKind::model_constants:
        kind = "number";
        break;
    }
    std::string range = p.range_text();
    if (!p.choices.empty()) {
      std::string names;
      for (const auto& c : p.choices) names += (names.empty() ? "" : " | ") + c;
      range = range.empty() ? names : range + "; or " + names;
    }
    std::string aliases;
    for (const auto& a : p.aliases) aliases += (aliases.empty() ? "" : " ") + a;
    for (const auto& a : p.gear_aliases) aliases += (aliases.empty() ? "" : " ") + a;
    rows.push_back({p.key, kind, p.kind == ParameterKind::quantity ? std::string(si_symbol(p.dimension)) : "",
                    p.defaulted() ? p.format(p.get(defaults, 0)) : "", range, parts(p.required_by), aliases, p.meaning,
                    p.plausible_text()});
  }
  return rows;
}

const char* const kSchemaHeader[] = {"key",         "kind",    "SI unit", "default",  "range",
                                     "required by", "aliases", "meaning", "plausible"};

}  // namespace

std::string Parameter::range_text() const {
  const bool lo = std::isfinite(min), hi = std::isfinite(max);
  if (!lo && !hi) return "";
  auto shown = [&](double v) {
    if (kind == ParameterKind::integer) return fmt::format("{:.0f}", v);  // every digit (a seed's 4294967295)
    return kind == ParameterKind::quantity ? fmt::format("{:g} {}", v, si_symbol(dimension)) : number_text(v);
  };
  if (lo && !hi && min == 0.0) return min_open ? "> 0" : ">= 0";
  if (lo && !hi) return (min_open ? "> " : ">= ") + shown(min);
  if (!lo) return (max_open ? "< " : "<= ") + shown(max);
  return fmt::format("{}{}, {}{}", min_open ? "(" : "[", shown(min), shown(max), max_open ? ")" : "]");
}

bool Parameter::in_range(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above = min_open ? v > min : v >= min;
  const bool below = max_open ? v < max : v <= max;
  return above && below;
}

std::string Parameter::plausible_text() const {
  const bool lo = std::isfinite(plausible_min), hi = std::isfinite(plausible_max);
  if (!lo && !hi) return "";
  auto shown = [&](double v) {
    return kind == ParameterKind::quantity ? fmt::format("{:g} {}", v, si_symbol(dimension)) : number_text(v);
  };
  if (!hi) return ">= " + shown(plausible_min);
  if (!lo) return "<= " + shown(plausible_max);
  return fmt::format("[{}, {}]", shown(plausible_min), shown(plausible_max));
}

std::string implausible_text(const Parameter& p, double v) {
  if (p.plausible(v)) return "";
  return fmt::format("{} the plausible band {} of a spur gear (read as given; the range is {})",
                     v < p.plausible_min ? "below" : "above", p.plausible_text(), p.range_text());
}

std::string bare_number_rule(const Parameter& p, double bare) {
  const bool banded = std::isfinite(p.plausible_min) || std::isfinite(p.plausible_max);
  if (p.kind != ParameterKind::quantity || !banded || !std::isfinite(bare)) return "";
  if (p.in_range(bare) && p.plausible(bare)) return "";
  std::string meant;
  std::vector<double> factors;
  for (const UnitScale& u : units_of(p.dimension)) {
    if (u.to_si == 1.0 && u.offset == 0.0) continue;  // the SI unit's spellings: the reading itself
    if (std::find(factors.begin(), factors.end(), u.to_si) != factors.end()) continue;  // um and µm
    const double si = bare * u.to_si + u.offset;
    if (!p.in_range(si) || !p.plausible(si)) continue;
    factors.push_back(u.to_si);
    meant += fmt::format("{}\"{:g} {}\"", meant.empty() ? "" : " or ", bare, u.symbol);
  }
  if (meant.empty()) return "";
  const std::string si = fmt::format("{:g} {}", bare, si_symbol(p.dimension));
  const std::string where = !p.in_range(bare)
                                ? "outside the range " + p.range_text()
                                : fmt::format("{} the plausible band {} of a spur gear",
                                              bare < p.plausible_min ? "below" : "above", p.plausible_text());
  // Inside the range the SI reading may be meant: it is read when its unit is given.
  return fmt::format("read as {} (a bare number is SI), {}: did you mean {}? Give the unit{}", si, where, meant,
                     p.in_range(bare) ? fmt::format(" (\"{}\" if that is meant)", si) : std::string());
}

std::string Parameter::key_for(int gear) const {
  if (!per_gear()) return key;
  return kGearPrefix[gear] + key.substr(std::string_view("{gear}.").size());
}

std::string Parameter::format(const ParameterValue& v) const {
  switch (kind) {
    case ParameterKind::quantity:
      return fmt::format("{:g} {}", v.number, si_symbol(dimension));
    case ParameterKind::number:
      return v.text.empty() ? number_text(v.number) : v.text;
    case ParameterKind::integer:
      return fmt::format("{}", static_cast<long>(v.number));
    case ParameterKind::flag:
      return v.number != 0.0 ? "true" : "false";
    case ParameterKind::choice_list: {
      std::string s;
      for (const auto& e : v.list) s += (s.empty() ? "" : ", ") + e;
      return "[" + s + "]";
    }
    default:
      return v.text;
  }
}

const std::vector<Parameter>& case_parameters() {
  static const std::vector<Parameter> table = build_table();
  return table;
}

ParameterLookup find_parameter(std::string_view key) {
  for (const Parameter& p : case_parameters()) {
    if (p.kind == ParameterKind::model_constants) {
      if (key.rfind("asperity.constants.", 0) == 0) return {&p, -1};
      continue;
    }
    if (!p.per_gear()) {
      if (key == p.key) return {&p, -1};
      continue;
    }
    for (int g = 0; g < 2; ++g)
      if (key == p.key_for(g)) return {&p, g};
  }
  return {};
}

std::string case_key_of_field(std::string_view field) {
  for (const Parameter& p : case_parameters()) {
    const std::string& member = p.field.empty() ? p.key : p.field;
    if (!p.per_gear()) {
      if (member == field) return p.key;
      continue;
    }
    // "{gear}.x" names pinion.x and wheel.x; "gear_pair.teeth[{gear}]" the members [0] and [1].
    for (int g = 0; g < 2; ++g) {
      std::string m = member;
      if (m.starts_with("{gear}.")) m = kGearPrefix[g] + m.substr(std::string_view("{gear}.").size());
      if (const auto at = m.find("[{gear}]"); at != std::string::npos) m.replace(at, 8, fmt::format("[{}]", g));
      if (m == field) return p.key_for(g);
    }
  }
  return std::string(field);
}

const std::vector<CaseAlias>& case_aliases() {
  static const std::vector<CaseAlias> aliases = [] {
    std::vector<CaseAlias> out;
    for (const Parameter& p : case_parameters()) {
      for (const auto& a : p.aliases)
        out.push_back(
            {a, p.per_gear() ? std::vector<std::string>{p.key_for(0), p.key_for(1)} : std::vector<std::string>{p.key}});
      for (std::size_t g = 0; g < p.gear_aliases.size(); ++g)
        out.push_back({p.gear_aliases[g], {p.key_for(static_cast<int>(g))}});
    }
    return out;
  }();
  return aliases;
}

std::vector<std::string> resolve_case_key(const std::string& name) {
  for (const CaseAlias& a : case_aliases())
    if (a.name == name) return a.keys;
  return {name};
}

std::string parameter_text_error(const Parameter& p, const std::string& text) {
  auto named = [&] { return std::find(p.choices.begin(), p.choices.end(), text) != p.choices.end(); };
  double v = 0.0;
  switch (p.kind) {
    case ParameterKind::quantity:
      try {
        v = parse_quantity(text, p.dimension);
      } catch (const std::invalid_argument& e) {
        return e.what();
      }
      if (const auto any = parse_any_quantity(text); any && any->dimension == Dimension::dimensionless)
        if (std::string rule = bare_number_rule(p, v); !rule.empty()) return rule;
      break;
    case ParameterKind::number:
    case ParameterKind::integer: {
      if (p.kind == ParameterKind::number && named()) return "";
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(v)) return "expected a number";
      if (p.kind == ParameterKind::integer && v != std::floor(v)) return "expected an integer";
      break;
    }
    case ParameterKind::choice:
      if (!named()) {
        std::string names;
        for (const auto& c : p.choices) names += (names.empty() ? "" : ", ") + c;
        return "unknown " + p.noun + " '" + text + "' (known: " + names + ")";
      }
      return "";
    default:
      return "";
  }
  if (!p.in_range(v)) return "must lie in " + p.range_text();
  return "";
}

std::string case_schema_csv() {
  std::string out;
  for (std::size_t i = 0; i < std::size(kSchemaHeader); ++i) {
    if (i) out += ',';
    out += kSchemaHeader[i];  // (not "," + std::string: GCC 12's -Wrestrict misfires on it inlined)
  }
  out += '\n';
  for (const auto& row : schema_rows()) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) out += ',';
      out += csv_field(row[i]);
    }
    out += '\n';
  }
  return out;
}

std::string case_schema_markdown() {
  std::string out =
      "# Case file reference\n\n"
      "Generated by `geartrib case --schema --markdown` from the parameter table (src/config/case_parameters.cpp);\n"
      "do not edit by hand. Values with a dimension take a unit from the unit table (\"6 mm\", \"20 deg\",\n"
      "\"1000 rpm\") or a bare SI number. `{gear}` stands for `pinion` and `wheel`. A key without a default\n"
      "is required when a command uses its part (\"required by\"): geometry by every command; roughness by\n"
      "run, sweep, tradeoff, asperity, fit and fem single-asperity; friction by run, sweep, tradeoff and\n"
      "asperity --contact side or --summary; cylinder by multi-asperity, fem three-cylinders and asperity\n"
      "--summary. `geartrib case CASE` shows what a case resolves to. Aliases are the short names `--set`\n"
      "and `geartrib sweep` accept. A flank takes exactly one roughness form: ra; rq; summit_density +\n"
      "summit_sigma; m0 + m2 + m4; or a topography table.\n\n"
      "A value outside its range is refused (exit 2, naming the file, line or --set, and the key); ranges are\n"
      "checked in SI, after the unit is applied, and a value must be finite. A gear value inside its range but\n"
      "outside the plausible band of a spur gear (a 6 m module, 1e6 rpm) is read and warned about, naming the\n"
      "key; given as a bare number that another unit would make plausible (module = 4.5, read as 4.5 m), it\n"
      "is refused, naming the unit probably meant. Units, limits and the bands' sources:\n"
      "[units.md](units.md#ranges-and-plausible-bands).\n\n";
  out += "|";
  for (const char* h : kSchemaHeader) out += std::string(" ") + h + " |";
  out += "\n|";
  for (std::size_t i = 0; i < std::size(kSchemaHeader); ++i) out += "---|";
  out += '\n';
  for (const auto& row : schema_rows()) {
    out += "|";
    for (std::size_t i = 0; i < row.size(); ++i) {
      std::string cell = row[i];
      for (std::size_t pos = 0; (pos = cell.find('|', pos)) != std::string::npos; pos += 2) cell.replace(pos, 1, "\\|");
      out += i == 0 && !cell.empty() ? fmt::format(" `{}` |", cell) : fmt::format(" {} |", cell);
    }
    out += '\n';
  }
  return out;
}

}  // namespace geartrib::io
