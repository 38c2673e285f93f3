#include "config/case_file.hpp"

#include "asperity/critical.hpp"
#include "asperity/model.hpp"
#include "case/asperity_setup.hpp"
#include "config/fzg_load_stages.hpp"
#include "config/text_lines.hpp"
#include "config/toml_reader.hpp"
#include "contact/fidelity_registry.hpp"
#include "core/keyed_error.hpp"
#include "gear/spur_pair.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace geartrib::io {

namespace {

void require(TomlReader& r, std::string_view key, bool ok, const std::string& rule) {
  if (!ok) r.fail(key, rule);
}

double positive_quantity(TomlReader& r, std::string_view key, Dimension d) {
  const double v = r.quantity(key, d);
  require(r, key, v > 0.0, "must be positive");
  return v;
}

// A quantity of a data file (material, lubricant) within [lo, hi] (SI, checked after the unit is
// applied); `unit` names the SI unit in the rule.
double bounded_quantity(TomlReader& r, std::string_view key, Dimension d, double lo, double hi) {
  const double v = r.quantity(key, d);
  require(r, key, v > 0.0 || lo < 0.0, "must be positive");
  require(r, key, v >= lo && v <= hi,
          fmt::format("must lie in [{:g} {}, {:g} {}]", lo, si_symbol(d), hi, si_symbol(d)));
  return v;
}

// The ranges of a material file's values (SI; docs/reference/units.md): beyond them no
// engineering material lies and the contact arithmetic is not meant to go; inside the range but
// outside the band of gear materials a value is warned about.
constexpr double kMinModulus = kMinYoungsModulus, kMaxModulus = kMaxYoungsModulus;  // [Pa]
constexpr double kPlausibleMinModulus = 5e8, kPlausibleMaxModulus = 1.2e12;         // polymers to diamond [Pa]
constexpr double kMinDensity = 1.0, kMaxDensity = 1e5;                              // [kg/m^3]
constexpr double kPlausibleMinDensity = 500.0, kPlausibleMaxDensity = 25000.0;
constexpr double kMaxConductivity = 1e4, kMaxSpecificHeat = 1e5;  // [W/(m K)], [J/(kg K)]

}  // namespace

Material load_material(const std::filesystem::path& file) { return load_material(file, nullptr); }

Material load_material(const std::filesystem::path& file, std::vector<std::string>* warnings) {
  TomlReader r(file);
  Material m;
  m.name = r.string("name");
  r.string("source");  // provenance is required, not interpreted
  m.youngs_modulus = bounded_quantity(r, "youngs_modulus", Dimension::pressure, kMinModulus, kMaxModulus);
  if (warnings && !(m.youngs_modulus >= kPlausibleMinModulus && m.youngs_modulus <= kPlausibleMaxModulus))
    warnings->push_back(r.warning(
        "youngs_modulus", fmt::format("outside the plausible band [{:g} Pa, {:g} Pa] of gear materials (read as given)",
                                      kPlausibleMinModulus, kPlausibleMaxModulus)));
  m.poisson_ratio = r.number("poisson_ratio");
  require(r, "poisson_ratio", m.poisson_ratio > 0.0 && m.poisson_ratio < 0.5, "Poisson's ratio must lie in (0, 0.5)");
  m.yield_strength = positive_quantity(r, "yield_strength", Dimension::pressure);
  require(r, "yield_strength", m.yield_strength < m.youngs_modulus, "yield strength must be below Young's modulus");
  // hardness: a pressure (measured), "tabor-yield" (2.8 S_y, the default) or "flow-curve"
  // (2.8 x the flow stress at Tabor's representative strain 0.08, needs [flow_curve]).
  // The rule is read here, the value after the flow curve it may need.
  const std::string named = r.is_string("hardness") ? r.string("hardness") : std::string();
  if (named == "tabor-yield" || named == "flow-curve") m.hardness_rule = named;
  else if (r.has("hardness")) m.hardness_rule = "given";
  m.density = bounded_quantity(r, "density", Dimension::density, kMinDensity, kMaxDensity);
  if (warnings && !(m.density >= kPlausibleMinDensity && m.density <= kPlausibleMaxDensity))
    warnings->push_back(r.warning(
        "density", fmt::format("outside the plausible band [{:g}, {:g}] kg/m^3 of gear materials (read as given)",
                               kPlausibleMinDensity, kPlausibleMaxDensity)));
  // Thermal data: optional, for the flash temperature of a lubricated run.
  if (r.has("thermal_conductivity"))
    m.thermal_conductivity =
        bounded_quantity(r, "thermal_conductivity", Dimension::thermal_conductivity, 1e-3, kMaxConductivity);
  if (r.has("specific_heat"))
    m.specific_heat = bounded_quantity(r, "specific_heat", Dimension::specific_heat, 1.0, kMaxSpecificHeat);
  if (r.has("flow_curve")) {
    r.string("flow_curve.source");
    const auto stress = r.quantity_array("flow_curve.stress", Dimension::pressure);
    const auto strain = r.quantity_array("flow_curve.plastic_strain", Dimension::dimensionless);
    require(r, "flow_curve.plastic_strain", strain.size() == stress.size(),
            "must have as many entries as flow_curve.stress (" + std::to_string(stress.size()) + ")");
    require(r, "flow_curve.stress", stress.size() >= 2, "needs at least two points");
    for (std::size_t i = 0; i < stress.size(); ++i) m.flow_curve.push_back({stress[i], strain[i]});
    require(r, "flow_curve.plastic_strain", strain.front() == 0.0, "must start at 0");
    require(r, "flow_curve.stress", std::abs(stress.front() - m.yield_strength) <= 0.01 * m.yield_strength,
            "first stress must equal yield_strength (within 1%)");
    for (std::size_t i = 1; i < stress.size(); ++i) {
      require(r, "flow_curve.plastic_strain", strain[i] > strain[i - 1],
              "must increase strictly (entry " + std::to_string(i) + ")");
      require(r, "flow_curve.stress", stress[i] >= stress[i - 1],
              "must not decrease (entry " + std::to_string(i) + ")");
    }
    require(r, "flow_curve.stress", stress.back() < m.youngs_modulus, "must stay below Young's modulus");
    require(r, "flow_curve.plastic_strain", strain.back() <= 10.0, "must not exceed 10 (1000% plastic strain)");
  }
  if (m.hardness_rule == "given") {
    m.hardness = bounded_quantity(r, "hardness", Dimension::pressure, 0.0, kMaxModulus);
  } else if (m.hardness_rule == "flow-curve") {
    if (m.flow_curve.empty()) r.fail("hardness", "\"flow-curve\" needs a [flow_curve] table");
    m.hardness = tabor_flow_curve_hardness(m);
  } else {
    m.hardness = kTaborHardnessRatio * m.yield_strength;
  }
  require(r, "hardness", m.hardness >= m.yield_strength, "hardness must be at least the yield strength");
  // [rating]: the ISO 6336-5 data of a rated gear (optional: a run that rates needs it).
  if (r.has("rating")) {
    rating::MaterialGrade& g = m.grade;
    try {
      g.group =
          choice_from_name(rating::material_group_choices(), r.string("rating.group"), "ISO 6336-5 material group");
    } catch (const std::invalid_argument& e) {
      r.fail("rating.group", e.what());
    }
    try {
      g.quality =
          choice_from_name(rating::material_quality_choices(), r.string("rating.quality"), "ISO 6336-5 quality");
    } catch (const std::invalid_argument& e) {
      r.fail("rating.quality", e.what());
    }
    g.surface_hardness = r.number("rating.surface_hardness_HV");
    require(r, "rating.surface_hardness_HV", g.surface_hardness >= 50.0 && g.surface_hardness <= 1200.0,
            "must lie in [50, 1200] HV");
    if (r.has("rating.contact_limit"))
      g.contact_limit = bounded_quantity(r, "rating.contact_limit", Dimension::pressure, 1e8, 3e9);
    if (r.has("rating.bending_limit"))
      g.bending_limit = bounded_quantity(r, "rating.bending_limit", Dimension::pressure, 5e7, 1.5e9);
    g.source = r.string("rating.source");
    g.assumed = r.boolean("rating.assumed");
  }
  r.check_all_used();
  m.validate();
  return m;
}

lubrication::Lubricant load_lubricant(const std::filesystem::path& file) {
  TomlReader r(file);
  lubrication::Lubricant l;
  l.name = r.string("name");
  l.source = r.string("source");
  try {
    l.base_oil = lubrication::base_oil_from_name(r.string("base_oil"));
  } catch (const std::invalid_argument& e) {
    r.fail("base_oil", e.what());
  }
  // The ranges (SI, after the unit): what an oil can have and Walther's law and the film carry.
  using D = Dimension;
  l.kinematic_viscosity_40 = bounded_quantity(r, "kinematic_viscosity_40C", D::kinematic_viscosity, 1e-7, 1.0);
  l.kinematic_viscosity_100 = bounded_quantity(r, "kinematic_viscosity_100C", D::kinematic_viscosity, 1e-7, 1.0);
  l.density_15 = bounded_quantity(r, "density_15C", D::density, 100.0, 5000.0);
  l.density_temperature_coefficient = r.quantity("density_temperature_coefficient", D::inverse_temperature);
  if (r.has("pressure_viscosity_coefficient")) {
    l.pressure_viscosity = bounded_quantity(r, "pressure_viscosity_coefficient", D::inverse_pressure, 1e-12, 1e-6);
    l.pressure_viscosity_temperature =
        bounded_quantity(r, "pressure_viscosity_temperature", D::temperature, 100.0, 1000.0);
  }
  l.thermal_conductivity = bounded_quantity(r, "thermal_conductivity", D::thermal_conductivity, 1e-3, 1e3);
  l.specific_heat = bounded_quantity(r, "specific_heat", D::specific_heat, 1.0, 1e5);
  l.eyring_stress = bounded_quantity(r, "eyring_stress", D::pressure, 1e3, 1e10);
  l.limiting_shear_coefficient = r.number("limiting_shear_coefficient");
  l.min_temperature = bounded_quantity(r, "min_temperature", D::temperature, 100.0, 1000.0);
  l.max_temperature = bounded_quantity(r, "max_temperature", D::temperature, 100.0, 1000.0);
  if (r.has("iso_lubricant_factor")) {
    l.iso_lubricant_factor = r.number("iso_lubricant_factor");
    require(r, "iso_lubricant_factor", l.iso_lubricant_factor > 0.0 && l.iso_lubricant_factor <= 2.0,
            "must lie in (0, 2] (ISO/TS 6336-20 tabulates 0.6 to 1.5)");
  }
  // FZG ratings: the failure load stages of A/8.3/90 (scuffing) and GF-C/8.3/90 (micropitting).
  for (const char* key : {"fzg_scuffing_stage", "fzg_micropitting_stage"}) {
    if (!r.has(key)) continue;
    const double stage = r.number(key);
    require(r, key, stage == std::floor(stage) && stage >= kFzgMinLoadStage && stage <= kFzgMaxLoadStage,
            fmt::format("an FZG load stage is an integer in [{}, {}]", kFzgMinLoadStage, kFzgMaxLoadStage));
    (std::string(key) == "fzg_scuffing_stage" ? l.fzg_scuffing_stage : l.fzg_micropitting_stage) =
        static_cast<int>(stage);
  }
  if (l.fzg_scuffing_stage > 0 || l.fzg_micropitting_stage > 0) {
    l.fzg_source = r.string("fzg_source");
    l.fzg_assumed = r.boolean("fzg_assumed");
  }
  if (r.has("permissible_lambda")) {
    l.permissible_lambda = r.number("permissible_lambda");
    require(r, "permissible_lambda", l.permissible_lambda > 0.0 && l.permissible_lambda <= 10.0,
            "lambda_GFP must lie in (0, 10]");
    l.permissible_lambda_source = r.string("permissible_lambda_source");
  }
  // Measured traction curves: [traction_curves.NAME] tables, each at one Hertz pressure, oil
  // temperature and entrainment speed.
  std::vector<lubrication::TractionCurve> curves;
  for (const std::string& name : r.keys_of("traction_curves")) {
    const std::string t = "traction_curves." + name + ".";
    lubrication::TractionCurve c;
    c.name = name;
    c.source = r.string(t + "source");
    c.hertz_pressure = bounded_quantity(r, t + "hertz_pressure", D::pressure, 1e6, 1e11);
    c.temperature = bounded_quantity(r, t + "temperature", D::temperature, 100.0, 1000.0);
    c.entrainment_speed = bounded_quantity(r, t + "entrainment_speed", D::speed, 1e-6, 1e3);
    c.slide_to_roll = r.quantity_array(t + "slide_to_roll", D::dimensionless);
    c.coefficient = r.quantity_array(t + "coefficient", D::dimensionless);
    curves.push_back(std::move(c));
  }
  // The curves' rules are TractionCurves' own: its message names the member ("traction_curves.NAME.
  // slide_to_roll: rule"), located here at that key's line.
  if (!curves.empty()) {
    try {
      l.traction = lubrication::TractionCurves(std::move(curves));
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      r.fail(what.substr(0, what.find(':')), what.substr(what.find(':') + 2));
    }
  }
  try {
    l.validate();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    r.fail(what.substr(0, what.find(':')), what.substr(what.find(':') + 2));
  }
  r.check_all_used();
  return l;
}

CaseChange parse_case_change(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::invalid_argument("'" + text +
                                "': expected key=value (a dotted case key or an alias such as module=4mm)");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

namespace {

// "must be positive", "must lie in [5, 1000]": the rule a value `v` outside a row's range breaks.
std::string range_rule(const Parameter& p, double v) {
  const std::string range = p.range_text();
  if (range.empty() || !std::isfinite(v)) return "must be finite";
  // A sign wrong for a row of positive values is said so ("must be positive"), whatever the range.
  const std::string within = std::isfinite(p.max) ? " (range " + range + ")" : "";
  if (p.min > 0.0 || (p.min == 0.0 && p.min_open)) {
    if (v <= 0.0) return "must be positive" + within;
  } else if (p.min == 0.0 && v < 0.0) {
    return "must not be negative" + within;
  }
  if (range == "> 0") return "must be positive";
  if (range == ">= 0") return "must not be negative";
  if (range.front() == '[' || range.front() == '(') return "must lie in " + range;
  return "must be " + range;
}

// The rule a numeric value read at `key` breaks, or empty: a bare number (SI) that a unit would
// have made plausible first (`module = 4.5` read as 4.5 m: did you mean 4.5 mm?), then the range.
// Inside the range, an implausible value is warned about, not refused.
std::string value_rule(const TomlReader& r, const Parameter& p, const std::string& key, double v) {
  if (r.is_bare_number(key))
    if (std::string rule = bare_number_rule(p, v); !rule.empty()) return rule;
  return p.in_range(v) ? "" : range_rule(p, v);
}

std::string choices_text(const std::vector<std::string>& choices) {
  std::string s;
  for (const auto& c : choices) s += (s.empty() ? "" : ", ") + c;
  return s;
}

// The torque's two forms: a torque, or an FZG load stage with its test (read_fzg_load_stage).
constexpr std::string_view kTorqueKey = "operating.pinion_torque";
constexpr std::string_view kFzgStageKey = "operating.fzg_load_stage";
constexpr std::string_view kFzgTestKey = "operating.fzg_test";

// One declared key into the case: its kind, choices and range checked, its value and origin
// recorded. An absent key keeps the case's default, or fails when a part asked for needs it.
void read_parameter(TomlReader& r, const Parameter& p, int gear, Case& c, unsigned parts) {
  const std::string key = p.key_for(gear);
  const bool flank_row = key.find(".flank.") != std::string::npos;  // forms and topography: read_flank's rules
  if (!r.has(key)) {
    const bool fzg_torque = key == kTorqueKey && r.has(kFzgStageKey);  // the load stage gives it
    if ((p.required_by & parts) && !fzg_torque) r.fail(key, "missing required key (" + p.meaning + ")");
    if (!flank_row && p.defaulted()) c.parameters.push_back({key, p.format(p.get(c, gear)), r.origin(key), ""});
    return;
  }
  ParameterValue v;
  bool numeric = true;
  switch (p.kind) {
    case ParameterKind::quantity:
      v.number = r.quantity(key, p.dimension);
      break;
    case ParameterKind::number:
      if (!p.choices.empty() && r.is_string(key)) {
        v.text = r.string(key);
        if (std::find(p.choices.begin(), p.choices.end(), v.text) == p.choices.end())
          r.fail(key, "must be a number or " + choices_text(p.choices));
        numeric = false;
      } else {
        v.number = r.number(key);
      }
      break;
    case ParameterKind::integer:
      v.number = static_cast<double>(r.integer(key));
      break;
    case ParameterKind::flag:
      v.number = r.boolean(key) ? 1.0 : 0.0;
      break;
    case ParameterKind::choice:
      v.text = r.string(key);
      if (std::find(p.choices.begin(), p.choices.end(), v.text) == p.choices.end())
        r.fail(key, "unknown " + p.noun + " '" + v.text + "' (known: " + choices_text(p.choices) + ")");
      numeric = false;
      break;
    case ParameterKind::text:
      v.text = r.string(key);
      numeric = false;
      break;
    case ParameterKind::choice_list:
      v.list = r.string_array(key);
      for (const auto& e : v.list)
        if (std::find(p.choices.begin(), p.choices.end(), e) == p.choices.end())
          r.fail(key, "unknown entry '" + e + "' (known: " + choices_text(p.choices) + ")");
      numeric = false;
      break;
    case ParameterKind::model_constants:
      return;  // read_model_constants
  }
  if (numeric)
    if (const std::string rule = value_rule(r, p, key, v.number); !rule.empty()) r.fail(key, rule);
  if (numeric && !p.plausible(v.number)) c.warnings.push_back(r.warning(key, implausible_text(p, v.number)));
  p.set(c, gear, v);
  c.parameters.push_back({key, p.format(v), r.origin(key), r.value_text(key)});
}

// [asperity.constants.MODEL]: each constant checked by the model's own ranges.
void read_model_constants(TomlReader& r, Case& c) {
  for (const auto& model_name : r.keys_of("asperity.constants")) {
    const std::string table = "asperity.constants." + model_name;
    std::unique_ptr<asperity::AsperityModel> model;
    try {
      model = asperity::make_asperity_model(model_name);
    } catch (const std::invalid_argument& e) {
      r.fail(table, e.what());
    }
    for (const auto& constant : r.keys_of(table)) {
      const std::string key = table + "." + constant;
      const double v = r.number(key);
      try {
        model->set_constant(constant, v);
      } catch (const std::invalid_argument& e) {
        r.fail(key, e.what());
      }
      c.asperity.constants[model_name].emplace_back(constant, v);
      c.parameters.push_back({key, fmt::format("{:g}", v), r.origin(key), r.value_text(key)});
    }
  }
}

// A component's validate(): its refusal (core::KeyedError naming the field) failed at the case key
// of the Case member `prefix` + field (the table's field-to-key map, io::case_key_of_field).
template <class Validate>
void check_rules(TomlReader& r, const std::string& prefix, Validate validate) {
  try {
    validate();
  } catch (const core::KeyedError& e) {
    r.fail(case_key_of_field(prefix + e.key()), e.what());
  }
}

// The flank's roughness form: exactly one of ra, rq, summits, spectral moments or a measured
// topography (loaded and reduced to its summit statistics by io::prepare_case).
void read_flank(TomlReader& r, Case& c, int gear) {
  GearSpec& g = gear == 0 ? c.pinion : c.wheel;
  const std::string p = gear == 0 ? "pinion." : "wheel.";
  const std::string f = p + "flank.";
  auto& rough = g.flank.roughness;
  using Form = surface::FlankRoughness::Form;
  const int forms = int(r.has(f + "ra")) + int(r.has(f + "rq")) + int(r.has(f + "summit_density")) +
                    int(r.has(f + "m0")) + int(r.has(f + "topography")) + int(r.has(f + "profile"));
  if (forms != 1)
    r.fail(p + "flank",
           "give the roughness in exactly one form: ra, rq, summit_density + summit_sigma, m0 + m2 + m4, a [" + p +
               "flank.topography] table naming a measured surface, or a [" + p + "flank.profile] table generating one");
  auto need = [&](const std::string& leaf) {
    if (!r.has(f + leaf))
      r.fail(f + leaf, "missing required key (" + find_parameter(f + leaf).parameter->meaning + ")");
  };
  if (g.flank.topography) {
    // A measured flank: its file is read and reduced to its summits by io::prepare_case.
    const std::string t = f + "topography.";
    need("topography.file");
    const surface::TopographySpec& spec = *g.flank.topography;
    check_rules(r, t, [&] { spec.validate(); });
    const auto path = r.directory() / spec.file;
    if (const std::string why = data_file_problem(path, kNoSizeLimit); !why.empty()) r.fail(t + "file", why);
    return;
  }
  if (g.flank.profile) {
    // A generated profile: its spectral moments (McCool's route to the summits) come from a
    // sample of it (io::prepare_case); a deterministic run takes those of the profile it rolls.
    if (r.has(f + "summit_radius"))
      r.fail(f + "summit_radius", "a generated profile gives the summit radius (its spectral moments); remove it");
    need("profile.kind");
    const surface::GeneratedProfileSpec& spec = *g.flank.profile;
    try {
      spec.validate();
      rough.form = Form::spectral;
      if (spec.kind == surface::ProfileKind::smooth) {
        if (!contact::rolls_flank_profiles(c.contact.fidelity))
          throw std::invalid_argument(
              "a smooth profile has no roughness for the statistical model: only contact.fidelity = "
              "\"deterministic\" takes it");
        if (c.lubrication.lubricated)
          throw std::invalid_argument(fmt::format(
              "a lubricated {} run takes the film's share of the load from the flanks' statistics, which a smooth "
              "profile has none of: give the flank a rough profile (ground or hobbed), or run the case dry "
              "(lubricant = none)",
              c.contact.fidelity.name()));
        rough.m0 = rough.m2 = rough.m4 = 0.0;  // no statistics: the deterministic run skips the statistical model
      }
    } catch (const core::KeyedError& e) {
      r.fail(f + "profile." + e.key(), e.what());  // the field the rule is about (rq, correlation_length, ...)
    } catch (const std::invalid_argument& e) {
      r.fail(f + "profile.kind", e.what());
    }
    return;
  }
  if (r.has(f + "m0")) {
    // McCool's relations give the summit radius from the moments: one description per flank.
    if (r.has(f + "summit_radius"))
      r.fail(f + "summit_radius",
             "the spectral moments m0, m2, m4 give the summit radius (McCool 1986); remove summit_radius");
    need("m2");
    need("m4");
    rough.form = Form::spectral;
    return;
  }
  need("summit_radius");
  if (r.has(f + "ra")) {
    rough.form = Form::ra;
  } else if (r.has(f + "rq")) {
    rough.form = Form::rq;
  } else {
    need("summit_sigma");
    rough.form = Form::summits;
  }
}

// Two flanks synthesised on the same seed take the same phases: a deterministic run's pinion and
// wheel teeth (seed + tooth, every tooth of the hunting order) would be correlated. Warned.
void warn_shared_synthesis_seeds(const TomlReader& r, Case& c) {
  const auto& t1 = c.pinion.flank.topography;
  const auto& t2 = c.wheel.flank.topography;
  using surface::SynthesisMethod;
  if (!contact::rolls_flank_profiles(c.contact.fidelity) || !t1 || !t2 || t1->synthesis == SynthesisMethod::none ||
      t2->synthesis == SynthesisMethod::none)
    return;
  const bool hunting = c.running_in.hunting();
  const auto n1 = static_cast<std::uint64_t>(hunting ? c.gear_pair.teeth[0] : 1);
  const auto n2 = static_cast<std::uint64_t>(hunting ? c.gear_pair.teeth[1] : 1);
  const std::uint64_t s1 = t1->synthesis_seed, s2 = t2->synthesis_seed;
  if (!(s1 < s2 + n2 && s2 < s1 + n1)) return;
  const auto range = [](std::uint64_t s, std::uint64_t n) {
    return n == 1 ? std::to_string(s) : fmt::format("{} to {}", s, s + n - 1);
  };
  c.warnings.push_back(r.warning("wheel.flank.topography.synthesis_seed",
                                 fmt::format("the wheel's synthesis seeds ({}) share values with the pinion's ({}): "
                                             "teeth on the same seed take the same phases, correlated flanks; give "
                                             "seeds at least {} apart",
                                             range(s2, n2), range(s1, n1), std::max(n1, n2))));
}

// The roughness forms of a flank and their keys (read_flank takes exactly one form).
const std::vector<std::vector<std::string>>& roughness_forms() {
  static const std::vector<std::vector<std::string>> forms = {
      {"ra"}, {"rq"}, {"summit_density", "summit_sigma"}, {"m0", "m2", "m4"}, {"topography"}, {"profile"}};
  return forms;
}

// The lubricant's fixed form: the table's [lubricant] rows other than the file.
bool fixed_lubricant_key(std::string_view key) { return key.starts_with("lubricant.") && key != "lubricant.file"; }
const std::vector<std::string>& fixed_lubricant_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const Parameter& p : case_parameters())
      if (fixed_lubricant_key(p.key)) k.push_back(p.key);
    return k;
  }();
  return keys;
}

}  // namespace

std::vector<std::string> keys_replaced_by(const std::string& key, const std::string& value) {
  // lubricant=none runs a lubricated case dry: the [lubricant] table goes (the [lubrication]
  // models and the oil temperature are then unused).
  if (key == "lubricant.file" && value == "none") return {"lubricant"};
  std::vector<std::string> out;
  // The lubricant's two forms replace each other: a file, or eta and alpha given in the case.
  if (key == "lubricant.file") out = fixed_lubricant_keys();
  else if (fixed_lubricant_key(key)) out.emplace_back("lubricant.file");
  // The torque's two forms replace each other: a torque, or an FZG load stage with its test.
  if (key == kTorqueKey) {
    out.emplace_back(kFzgStageKey);
    out.emplace_back(kFzgTestKey);
  } else if (key == kFzgStageKey || key == kFzgTestKey) {
    out.emplace_back(kTorqueKey);
  }
  // pinion.flank.rq = ... replaces the flank's other roughness forms.
  for (const char* gear : {"pinion.flank.", "wheel.flank."}) {
    const std::string flank(gear);
    if (key.rfind(flank, 0) != 0) continue;
    const std::string leaf = key.substr(flank.size(), key.find('.', flank.size()) - flank.size());
    auto in = [&](const std::vector<std::string>& form) {
      return std::find(form.begin(), form.end(), leaf) != form.end();
    };
    const auto& forms = roughness_forms();
    if (std::none_of(forms.begin(), forms.end(), in)) continue;  // e.g. summit_radius: not a roughness form
    for (const auto& form : forms)
      if (!in(form))
        for (const auto& k : form) out.push_back(flank + k);
    if (leaf == "m0" || leaf == "m2" || leaf == "m4") out.push_back(flank + "summit_radius");  // the moments give it
  }
  return out;
}

namespace {

void apply_change(TomlReader& r, const std::string& key, const std::string& value) {
  for (const std::string& k : keys_replaced_by(key, value)) r.erase(k);
  if (key == "lubricant.file" && value == "none") return;  // the [lubricant] table removed, nothing set
  r.set(key, value);
}

// A --set value checked as soon as it is applied, against its row's kind and range: a later
// change of the same key (`--set positions=4294967298 --positions 11`) does not hide it.
void check_change(TomlReader& r, const std::string& key) {
  const auto [p, gear] = find_parameter(key);
  if (!p || !r.has(key)) return;
  double v = 0.0;
  switch (p->kind) {
    case ParameterKind::quantity:
      v = r.quantity(key, p->dimension);
      break;
    case ParameterKind::number:
      if (!p->choices.empty() && r.is_string(key)) return;  // a named rule: read_parameter checks it
      v = r.number(key);
      break;
    case ParameterKind::integer:
      v = static_cast<double>(r.integer(key));
      break;
    default:
      return;
  }
  if (const std::string rule = value_rule(r, *p, key, v); !rule.empty()) r.fail(key, rule);
}

// An FZG load stage and its test in place of the torque: the torque from the compiled load-stage
// table (config/fzg_load_stages.hpp), recorded where the torque's row stands with the table as its
// origin. Both forms given, or one of the pair without the other, is refused naming the keys.
void read_fzg_load_stage(TomlReader& r, Case& c) {
  const bool stage = r.has(kFzgStageKey), test = r.has(kFzgTestKey);
  if (!stage && !test) return;
  if (!stage)
    r.fail(kFzgTestKey,
           "names the test of operating.fzg_load_stage, which is not given: give the stage or remove "
           "the test");
  if (!test)
    r.fail(kFzgStageKey, "needs operating.fzg_test, the test whose lever arm sets the stage's torque (known: " +
                             choices_text(fzg_test_names()) + ")");
  if (r.has(kTorqueKey))
    r.fail(kTorqueKey,
           fmt::format("give the torque or the FZG load stage, not both (operating.fzg_load_stage = {} at {})",
                       c.operating.fzg_load_stage, r.where(kFzgStageKey)));
  FzgTorque t;
  try {
    t = fzg_pinion_torque(c.operating.fzg_test, c.operating.fzg_load_stage);
  } catch (const std::invalid_argument& e) {
    r.fail(kFzgStageKey, e.what());
  }
  c.operating.pinion_torque = t.torque;
  const Parameter& row = *find_parameter(kTorqueKey).parameter;
  ParameterValue v;
  v.number = t.torque;
  const auto at = std::find_if(c.parameters.begin(), c.parameters.end(),
                               [](const ResolvedParameter& p) { return p.key == kFzgStageKey; });
  c.parameters.insert(at, {std::string(kTorqueKey), row.format(v), Origin::data_file(t.origin), ""});
}

// [lubricant] given: the oil from its file or the fixed form, its temperatures checked against the
// data range, and the bodies' thermal data the flash temperature needs.
void read_lubrication(TomlReader& r, Case& c) {
  lubrication::LubricationSettings& lc = c.lubrication;
  lc.lubricated = true;
  if (!r.has("operating.oil_temperature"))
    r.fail("operating.oil_temperature", "missing required key (a lubricated run needs the oil temperature)");
  if (!lc.lubricant_file.empty()) {
    for (const std::string& k : fixed_lubricant_keys())
      if (r.has(k)) r.fail(k, "the lubricant file gives the oil's data; remove this key or lubricant.file");
    const auto path = r.directory() / lc.lubricant_file;
    if (const std::string why = data_file_problem(path, kMaxTomlFileBytes); !why.empty()) r.fail("lubricant.file", why);
    lc.lubricant = load_lubricant(path);
    // The oil's data as run are the file's: its values and origin replace the fixed form's
    // defaults in the record (beta comes from Walther's law, not a key).
    std::erase_if(c.parameters, [](const ResolvedParameter& p) {
      return p.key == "lubricant.temperature_viscosity_coefficient" || p.key == "lubricant.dynamic_viscosity" ||
             p.key == "lubricant.pressure_viscosity_coefficient";
    });
    for (ResolvedParameter& p : c.parameters)
      if (fixed_lubricant_key(p.key)) {
        const Parameter& row = *find_parameter(p.key).parameter;
        p.value = row.format(row.get(c, -1));
        p.origin = Origin::data_file(path.string());
        p.written.clear();
      }
  } else {
    for (const char* k : {"dynamic_viscosity", "pressure_viscosity_coefficient"})
      if (!r.has(std::string("lubricant.") + k))
        r.fail(std::string("lubricant.") + k,
               "missing required key (give lubricant.file, or the oil's dynamic_viscosity and "
               "pressure_viscosity_coefficient at the oil temperature)");
    lc.lubricant.name = "given in the case at the oil temperature";
    lc.lubricant.min_temperature = lc.lubricant.max_temperature = c.operating.oil_temperature;
  }
  const auto& l = lc.lubricant;
  // Beyond the lubricant's operating range (its data range, the laws extrapolated at most 40 K below
  // and 60 K above it) refused; outside the data range, warned.
  auto check_temperature = [&](const char* key, double t) {
    if (l.fixed()) return;
    if (const lubrication::TemperatureRange range = lubrication::operating_range(l); !range.contains(t))
      r.fail(key, fmt::format("{:.1f} degC is beyond the lubricant's data range [{:.1f}, {:.1f}] degC and the range "
                              "its laws are taken to for the oil, [{:.1f}, {:.1f}] degC (at most {:g} K below and {:g} "
                              "K above the data)",
                              t - 273.15, l.min_temperature - 273.15, l.max_temperature - 273.15, range.lo - 273.15,
                              range.hi - 273.15, lubrication::kColdExtrapolation, lubrication::kHotExtrapolation));
    if (t < l.min_temperature || t > l.max_temperature)
      c.warnings.push_back(
          fmt::format("{}: warning: key '{}': {:.1f} degC lies outside {}'s data range [{:.1f}, "
                      "{:.1f}] degC; its viscosity is extrapolated",
                      r.where(key), key, t - 273.15, l.name, l.min_temperature - 273.15, l.max_temperature - 273.15));
  };
  check_temperature("operating.oil_temperature", c.operating.oil_temperature);
  if (c.operating.bulk_temperature > 0.0) {
    if (c.operating.bulk_temperature < c.operating.oil_temperature)
      r.fail("operating.bulk_temperature", "must not be below the oil temperature (or 0 for the ISO estimate)");
    check_temperature("operating.bulk_temperature", c.operating.bulk_temperature);
  }
  if (lc.scuffing_temperature > 0.0 && !(lc.scuffing_temperature > c.operating.oil_temperature))
    r.fail("lubrication.scuffing_temperature", "must exceed the oil temperature (or be 0: no safety)");
  if (l.fixed() && !(l.lubricant_factor() > 0.0))
    r.fail("lubricant.base_oil", fmt::format("ISO/TS 6336-20 tabulates no lubricant factor X_L for '{}': give "
                                             "lubricant.iso_lubricant_factor with its source",
                                             lubrication::base_oil_name(l.base_oil)));
  if (lc.traction == lubrication::FilmTraction::curve && l.traction.empty())
    r.fail("lubrication.traction",
           l.fixed() ? std::string("\"curve\" needs measured traction curves: give a lubricant file with "
                                   "[traction_curves.NAME] tables")
                     : "\"curve\" needs measured traction curves, and " + lc.lubricant_file +
                           " has no [traction_curves.NAME] table");
  for (int gear = 0; gear < 2; ++gear) {
    const Material& m = (gear == 0 ? c.pinion : c.wheel).material;
    if (!(m.thermal_conductivity > 0.0 && m.specific_heat > 0.0))
      r.fail(gear == 0 ? "pinion.material" : "wheel.material",
             "the material file must give thermal_conductivity and specific_heat (a lubricated run computes "
             "the flash temperature)");
  }
}

}  // namespace

namespace {

Case load_case_from(TomlReader& r, const std::vector<CaseChange>& changes, unsigned parts) {
  for (const CaseChange& ch : changes)
    for (const std::string& key : resolve_case_key(ch.key)) {
      apply_change(r, key, ch.value);
      check_change(r, key);
    }

  Case c;
  for (const Parameter& p : case_parameters()) {
    if (p.kind == ParameterKind::model_constants) read_model_constants(r, c);
    else if (p.per_gear())
      for (int gear = 0; gear < 2; ++gear) read_parameter(r, p, gear, c, parts);
    else read_parameter(r, p, -1, c, parts);
  }

  // Rules between keys.
  read_fzg_load_stage(r, c);
  const auto& gp = c.gear_pair;
  if (!(gp.dedendum_coefficient > gp.addendum_coefficient))
    r.fail("gear_pair.dedendum_coefficient", "must exceed the addendum coefficient (tip clearance)");
  if (!(gp.tip_shortening < gp.addendum_coefficient))
    r.fail("gear_pair.tip_shortening", "must lie in [0, addendum_coefficient)");
  for (int gear = 0; gear < 2; ++gear) {
    const auto& topography = (gear == 0 ? c.pinion : c.wheel).flank.topography;
    const std::string key = std::string(gear == 0 ? "pinion" : "wheel") + ".flank.topography.outliers";
    if (topography && !(topography->clean.outlier_limit == 0.0 || topography->clean.outlier_limit >= 2.0))
      r.fail(key, "must be 0 (off) or at least 2 robust standard deviations");
  }

  // The bodies' materials.
  for (int gear = 0; gear < 2; ++gear) {
    GearSpec& g = gear == 0 ? c.pinion : c.wheel;
    const std::string key = std::string(gear == 0 ? "pinion" : "wheel") + ".material";
    if (g.material_file.empty()) continue;  // not asked for
    const auto path = r.directory() / g.material_file;
    if (const std::string why = data_file_problem(path, kMaxTomlFileBytes); !why.empty()) r.fail(key, why);
    std::vector<std::string> material_warnings;
    g.material = load_material(path, &material_warnings);
    for (auto& w : material_warnings)  // one file for both gears: warned once
      if (std::find(c.warnings.begin(), c.warnings.end(), w) == c.warnings.end()) c.warnings.push_back(std::move(w));
  }
  if (r.has("lubricant")) read_lubrication(r, c);
  // A fidelity that solves the lubricant's film refuses a dry case.
  if (const std::string rule = contact::dry_case_rule(contact::find_fidelity(c.contact.fidelity));
      !rule.empty() && !c.lubrication.lubricated)
    r.fail("contact.fidelity", rule);
  if (r.is_string("asperity.cylinder.yield_constant")) {
    // green-2005: Green's plane-strain C_L(nu) of the softer body.
    c.asperity.cylinder_yield_constant =
        asperity::green_cylinder_yield_factor(asperity::softer_material(c).poisson_ratio);
  }
  // The components' own rules (the ranges above hold most of them), each refusal at its key.
  check_rules(r, "lubrication.", [&] { c.lubrication.validate(); });
  check_rules(r, "mesh.", [&] { c.mesh.validate(); });
  check_rules(r, "roughness.", [&] { c.roughness.validate(); });
  check_rules(r, "dynamics.", [&] { c.dynamics.validate(); });
  check_rules(r, "asperity.", [&] { c.asperity.validate(); });
  check_rules(r, "contact.", [&] { c.contact.validate(); });
  check_rules(r, "rating.settings.", [&] { c.rating.settings.validate(); });

  // The flanks, when asked for (or given): one roughness form each, the same on both (a measured
  // flank's form, areal summits or a profile trace's moments, is its file's: io::prepare_case).
  const bool flanks = (parts & kRoughnessPart) || r.has("pinion.flank") || r.has("wheel.flank");
  if (flanks) {
    read_flank(r, c, 0);
    read_flank(r, c, 1);
    const bool measured = c.pinion.flank.topography || c.wheel.flank.topography;
    if (!measured && c.pinion.flank.roughness.form != c.wheel.flank.roughness.form)
      r.fail("wheel.flank", "give both flanks' roughness in the same form as the pinion's");
    warn_shared_synthesis_seeds(r, c);
  }

  r.check_all_used();
  c.directory = r.directory().string();
  c.source_text = r.text();
  for (const CaseChange& ch : changes) c.source_text += "\n# --set " + ch.key + "=" + ch.value;

  return c;
}

}  // namespace

Case load_case(const std::filesystem::path& file, const std::vector<CaseChange>& changes, unsigned parts) {
  TomlReader r(file);
  return load_case_from(r, changes, parts);
}

Case load_case_text(const std::string& text, const std::filesystem::path& name, const std::vector<CaseChange>& changes,
                    unsigned parts, const std::filesystem::path& directory) {
  TomlReader r(text, name, directory);
  return load_case_from(r, changes, parts);
}

}  // namespace geartrib::io
