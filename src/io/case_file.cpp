#include "io/case_file.hpp"

#include "asperity/model.hpp"
#include "gear/spur_pair.hpp"
#include "io/toml_reader.hpp"
#include "io/topography_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

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

constexpr std::size_t kFewSummits = 100;  // below this a summit statistic scatters by more than 10%

GearSpec read_gear(TomlReader& r, const std::string& name) {
  GearSpec g;
  const std::string p = name + ".";
  g.teeth = static_cast<int>(r.integer(p + "teeth"));
  require(r, p + "teeth", g.teeth >= 5 && g.teeth <= 1000, "tooth number must lie in [5, 1000]");
  g.profile_shift = r.number(p + "profile_shift", 0.0);
  require(r, p + "profile_shift", std::abs(g.profile_shift) <= 2.0, "profile shift coefficient must lie in [-2, 2]");
  g.tip_diameter = r.quantity(p + "tip_diameter", Dimension::length, 0.0);
  require(r, p + "tip_diameter", g.tip_diameter >= 0.0, "must not be negative");
  g.bore_diameter = r.quantity(p + "bore_diameter", Dimension::length, 0.0);
  require(r, p + "bore_diameter", g.bore_diameter >= 0.0, "must not be negative");
  g.material_file = r.string(p + "material");
  const auto material_path = r.directory() / g.material_file;
  if (!std::filesystem::exists(material_path)) r.fail(p + "material", "material file not found: " + material_path.string());
  g.material = load_material(material_path);
  const std::string f = p + "flank.";
  auto& rough = g.flank.roughness;
  using Form = surface::FlankRoughness::Form;
  const int forms = int(r.has(f + "ra")) + int(r.has(f + "rq")) + int(r.has(f + "summit_density")) + int(r.has(f + "m0")) +
                    int(r.has(f + "topography"));
  if (forms != 1)
    r.fail(p + "flank",
           "give the roughness in exactly one form: ra, rq, summit_density + summit_sigma, m0 + m2 + m4, or a [" + p +
               "flank.topography] table naming a measured surface");
  if (r.has(f + "topography")) {
    // A measured flank: the cleaned surface's summits give density, height sigma and radius
    // (summit_radius, if given, overrides the measured radius: grid sampling biases it).
    const std::string t = f + "topography.";
    g.flank.topography_file = r.string(t + "file");
    const auto path = r.directory() / g.flank.topography_file;
    if (!std::filesystem::exists(path)) r.fail(t + "file", "topography file not found: " + path.string());
    TopographyReadOptions read;
    read.unit = r.quantity(t + "unit", Dimension::length, 1e-6);
    require(r, t + "unit", read.unit > 0.0, "must be positive");
    read.spacing = r.quantity(t + "spacing", Dimension::length, 0.0) / read.unit;
    require(r, t + "spacing", read.spacing >= 0.0, "must not be negative");
    read.resample = r.quantity(t + "resample", Dimension::length, 0.0);
    require(r, t + "resample", read.resample >= 0.0, "must not be negative");
    surface::CleanupOptions clean;
    clean.form_degree = static_cast<int>(r.integer(t + "form", 2));
    require(r, t + "form", clean.form_degree >= 0 && clean.form_degree <= 6, "polynomial degree must lie in [0, 6]");
    clean.waviness_cutoff = r.quantity(t + "cutoff", Dimension::length, 0.0);
    require(r, t + "cutoff", clean.waviness_cutoff >= 0.0, "must not be negative (0: no waviness filter)");
    clean.outlier_limit = r.number(t + "outliers", 0.0);
    require(r, t + "outliers", clean.outlier_limit == 0.0 || clean.outlier_limit >= 2.0,
            "must be 0 (off) or at least 2 robust standard deviations");
    clean.fill = r.boolean(t + "fill", false);
    const surface::HeightGrid grid = load_surface(path, read, clean).grid;
    try {
      g.flank.measured = surface::surface_statistics(grid);
      rough = surface::measured_roughness(*g.flank.measured);
    } catch (const std::invalid_argument& e) {
      r.fail(t + "file", path.string() + ": " + e.what());
    }
    if (r.has(f + "summit_radius")) rough.summit_radius = positive_quantity(r, f + "summit_radius", Dimension::length);
    g.flank.summit_radius = rough.summit_radius;
    return g;
  }
  if (r.has(f + "m0")) {
    // McCool's relations give the summit radius from the moments: one description per flank.
    if (r.has(f + "summit_radius"))
      r.fail(f + "summit_radius", "the spectral moments m0, m2, m4 give the summit radius (McCool 1986); remove summit_radius");
  } else {
    g.flank.summit_radius = positive_quantity(r, f + "summit_radius", Dimension::length);
    rough.summit_radius = g.flank.summit_radius;
  }
  if (r.has(f + "ra")) {
    rough.form = Form::ra;
    rough.ra = positive_quantity(r, f + "ra", Dimension::length);
  } else if (r.has(f + "rq")) {
    rough.form = Form::rq;
    rough.rq = positive_quantity(r, f + "rq", Dimension::length);
  } else if (r.has(f + "summit_density")) {
    rough.form = Form::summits;
    rough.summit_density = positive_quantity(r, f + "summit_density", Dimension::areal_density);
    rough.summit_sigma = positive_quantity(r, f + "summit_sigma", Dimension::length);
  } else {
    rough.form = Form::spectral;
    rough.m0 = positive_quantity(r, f + "m0", Dimension::area);
    rough.m2 = positive_quantity(r, f + "m2", Dimension::dimensionless);
    rough.m4 = positive_quantity(r, f + "m4", Dimension::areal_density);
  }
  return g;
}

}  // namespace

Material load_material(const std::filesystem::path& file) {
  TomlReader r(file);
  Material m;
  m.name = r.string("name");
  r.string("source");  // provenance is required, not interpreted
  m.youngs_modulus = positive_quantity(r, "youngs_modulus", Dimension::pressure);
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
  m.density = positive_quantity(r, "density", Dimension::density);
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
      require(r, "flow_curve.stress", stress[i] >= stress[i - 1], "must not decrease (entry " + std::to_string(i) + ")");
    }
  }
  if (m.hardness_rule == "given") {
    m.hardness = r.quantity("hardness", Dimension::pressure);
  } else if (m.hardness_rule == "flow-curve") {
    if (m.flow_curve.empty()) r.fail("hardness", "\"flow-curve\" needs a [flow_curve] table");
    m.hardness = tabor_flow_curve_hardness(m);
  } else {
    m.hardness = kTaborHardnessRatio * m.yield_strength;
  }
  require(r, "hardness", m.hardness >= m.yield_strength, "hardness must be at least the yield strength");
  r.check_all_used();
  m.validate();
  return m;
}

const std::vector<CaseAlias>& case_aliases() {
  static const std::vector<CaseAlias> aliases = {
      {"module", {"gear_pair.module"}},
      {"face_width", {"gear_pair.face_width"}},
      {"pressure_angle", {"gear_pair.pressure_angle"}},
      {"center_distance", {"gear_pair.center_distance"}},
      {"teeth", {"pinion.teeth", "wheel.teeth"}},
      {"z1", {"pinion.teeth"}},
      {"z2", {"wheel.teeth"}},
      {"x1", {"pinion.profile_shift"}},
      {"x2", {"wheel.profile_shift"}},
      {"torque", {"operating.pinion_torque"}},
      {"speed", {"operating.pinion_speed"}},
      {"mu", {"friction.mu"}},
      {"ra", {"pinion.flank.ra", "wheel.flank.ra"}},
      {"rq", {"pinion.flank.rq", "wheel.flank.rq"}},
      {"summit_radius", {"pinion.flank.summit_radius", "wheel.flank.summit_radius"}},
      {"material", {"pinion.material", "wheel.material"}},
      {"model", {"asperity.model"}},
      {"fidelity", {"contact.fidelity"}},
      {"positions", {"contact.positions"}},
      {"strip_points", {"contact.strip_points"}},
      {"height_points", {"contact.height_points"}},
      {"coupled_nodes", {"contact.coupled_nodes"}},
      {"table_points", {"contact.table_points"}},
      {"load_sharing", {"mesh.load_sharing"}},
      {"dynamics", {"mesh.dynamics"}},
      {"rtol", {"dynamics.relative_tolerance"}},
      {"damping", {"dynamics.damping_ratio"}},
  };
  return aliases;
}

CaseChange parse_case_change(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::invalid_argument("'" + text + "': expected key=value (a dotted case key or an alias such as module=4mm)");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

namespace {
// The roughness forms of a flank and their keys (read_gear takes exactly one form).
const std::vector<std::vector<std::string>>& roughness_forms() {
  static const std::vector<std::vector<std::string>> forms = {
      {"ra"}, {"rq"}, {"summit_density", "summit_sigma"}, {"m0", "m2", "m4"}, {"topography"}};
  return forms;
}

void apply_change(TomlReader& r, const std::string& key, const std::string& value) {
  // pinion.flank.rq = ... replaces the flank's other roughness forms.
  for (const char* gear : {"pinion.flank.", "wheel.flank."}) {
    const std::string flank(gear);
    if (key.rfind(flank, 0) != 0) continue;
    const std::string leaf = key.substr(flank.size(), key.find('.', flank.size()) - flank.size());
    auto in = [&](const std::vector<std::string>& form) { return std::find(form.begin(), form.end(), leaf) != form.end(); };
    const auto& forms = roughness_forms();
    if (std::none_of(forms.begin(), forms.end(), in)) continue;  // e.g. summit_radius: not a roughness form
    for (const auto& form : forms)
      if (!in(form))
        for (const auto& k : form) r.erase(flank + k);
    if (leaf == "m0" || leaf == "m2" || leaf == "m4") r.erase(flank + "summit_radius");  // the moments give it
  }
  r.set(key, value);
}
}  // namespace

Case load_case(const std::filesystem::path& file, const std::vector<CaseChange>& changes) {
  TomlReader r(file);
  for (const CaseChange& ch : changes) {
    const auto alias = std::find_if(case_aliases().begin(), case_aliases().end(),
                                    [&](const CaseAlias& a) { return ch.key == a.name; });
    if (alias == case_aliases().end()) apply_change(r, ch.key, ch.value);
    else
      for (const char* k : alias->keys) apply_change(r, k, ch.value);
  }
  Case c;
  c.title = r.string("title");
  c.source = r.string("source");

  auto& gp = c.gear_pair;
  gp.module = positive_quantity(r, "gear_pair.module", Dimension::length);
  gp.pressure_angle = r.quantity("gear_pair.pressure_angle", Dimension::angle);
  require(r, "gear_pair.pressure_angle", gp.pressure_angle > 0.0 && gp.pressure_angle < std::numbers::pi / 4.0,
          "pressure angle must lie in (0, 45) deg");
  gp.face_width = positive_quantity(r, "gear_pair.face_width", Dimension::length);
  gp.addendum_coefficient = r.number("gear_pair.addendum_coefficient", 1.0);
  require(r, "gear_pair.addendum_coefficient", gp.addendum_coefficient > 0.0 && gp.addendum_coefficient <= 2.0,
          "must lie in (0, 2]");
  gp.dedendum_coefficient = r.number("gear_pair.dedendum_coefficient", 1.25);
  require(r, "gear_pair.dedendum_coefficient", gp.dedendum_coefficient > gp.addendum_coefficient,
          "must exceed the addendum coefficient (tip clearance)");
  gp.root_radius_coefficient = r.number("gear_pair.root_radius_coefficient", 0.38);
  require(r, "gear_pair.root_radius_coefficient", gp.root_radius_coefficient >= 0.0 && gp.root_radius_coefficient < 1.0,
          "must lie in [0, 1)");
  gp.tip_shortening = r.number("gear_pair.tip_shortening", 0.0);
  require(r, "gear_pair.tip_shortening", gp.tip_shortening >= 0.0 && gp.tip_shortening < gp.addendum_coefficient,
          "must lie in [0, addendum_coefficient)");
  gp.center_distance = r.quantity("gear_pair.center_distance", Dimension::length, 0.0);
  require(r, "gear_pair.center_distance", gp.center_distance >= 0.0, "must not be negative (omit it for the zero-backlash distance)");

  c.pinion = read_gear(r, "pinion");
  c.wheel = read_gear(r, "wheel");
  // Summit statistics from a few dozen summits scatter by ~1/sqrt(n): say so.
  for (const char* name : {"pinion", "wheel"}) {
    const GearSpec& g = std::string(name) == "pinion" ? c.pinion : c.wheel;
    if (g.flank.measured && g.flank.measured->summits < kFewSummits) {
      const std::string key = std::string(name) + ".flank.topography.file";
      c.warnings.push_back(fmt::format("{}: warning: key '{}': only {} summits on the measured surface (statistics scatter "
                                       "by ~1/sqrt(n)); measure a larger area",
                                       r.where(key), key, g.flank.measured->summits));
    }
  }

  c.operating.pinion_torque = positive_quantity(r, "operating.pinion_torque", Dimension::torque);
  c.operating.pinion_speed = positive_quantity(r, "operating.pinion_speed", Dimension::angular_speed);

  c.mesh.load_sharing = r.string("mesh.load_sharing", std::string("iso"));
  require(r, "mesh.load_sharing", c.mesh.load_sharing == "iso" || c.mesh.load_sharing == "stiffness",
          "must be \"iso\" or \"stiffness\"");
  c.mesh.positions = static_cast<int>(r.integer("mesh.positions", 64));
  require(r, "mesh.positions", c.mesh.positions >= 2 && c.mesh.positions <= 100000, "must lie in [2, 100000]");
  const std::string beam = r.string("mesh.tooth_beam", std::string("plane-strain"));
  require(r, "mesh.tooth_beam", beam == "plane-strain" || beam == "plane-stress", "must be \"plane-strain\" or \"plane-stress\"");
  c.mesh.plane_strain = beam == "plane-strain";
  c.dynamics.engine = r.string("mesh.dynamics", std::string("none"));
  require(r, "mesh.dynamics", c.dynamics.engine == "none" || c.dynamics.engine == "cvode" || c.dynamics.engine == "odeint",
          "must be \"none\", \"cvode\" or \"odeint\"");
  c.dynamics.damping_ratio = r.number("dynamics.damping_ratio", 0.07);
  require(r, "dynamics.damping_ratio", c.dynamics.damping_ratio >= 0.0 && c.dynamics.damping_ratio < 1.0, "must lie in [0, 1)");
  c.dynamics.relative_tolerance = r.number("dynamics.relative_tolerance", 1e-8);
  require(r, "dynamics.relative_tolerance", c.dynamics.relative_tolerance >= 1e-14 && c.dynamics.relative_tolerance <= 1e-2,
          "must lie in [1e-14, 1e-2]");
  c.dynamics.backlash = r.quantity("dynamics.backlash", Dimension::length, 0.0);
  require(r, "dynamics.backlash", c.dynamics.backlash >= 0.0, "must not be negative");
  c.dynamics.pinion_inertia = r.quantity("dynamics.pinion_inertia", Dimension::inertia, 0.0);
  c.dynamics.wheel_inertia = r.quantity("dynamics.wheel_inertia", Dimension::inertia, 0.0);
  require(r, "dynamics.pinion_inertia", c.dynamics.pinion_inertia >= 0.0, "must not be negative");
  require(r, "dynamics.wheel_inertia", c.dynamics.wheel_inertia >= 0.0, "must not be negative");

  {
    const std::string dist = r.string("roughness.distribution", std::string("gaussian"));
    require(r, "roughness.distribution", dist == "gaussian" || dist == "exponential", "must be \"gaussian\" or \"exponential\"");
    c.roughness.distribution = dist == "gaussian" ? surface::HeightDistribution::gaussian : surface::HeightDistribution::exponential;
    c.roughness.eta_sigma_beta = r.number("roughness.eta_sigma_beta", surface::kTypicalEtaSigmaBeta);
    require(r, "roughness.eta_sigma_beta", c.roughness.eta_sigma_beta > 0.0 && c.roughness.eta_sigma_beta < 10.0,
            "must lie in (0, 10)");
  }
  {
    auto& ct = c.contact;
    const std::string fidelity = r.string("contact.fidelity", std::string("uncoupled"));
    require(r, "contact.fidelity", fidelity == "uncoupled" || fidelity == "coupled", "must be \"uncoupled\" or \"coupled\"");
    ct.coupled = fidelity == "coupled";
    if (r.has("contact.outputs")) {
      const auto outputs = r.string_array("contact.outputs");
      ct.real_area = ct.plastic_fraction = ct.asperity_stress = false;
      for (const auto& o : outputs) {
        if (o == "real_area") ct.real_area = true;
        else if (o == "plastic_fraction") ct.plastic_fraction = true;
        else if (o == "asperity_stress") ct.asperity_stress = true;
        else r.fail("contact.outputs", "unknown output '" + o + "' (known: real_area, plastic_fraction, asperity_stress)");
      }
    }
    ct.positions = static_cast<int>(r.integer("contact.positions", 201));
    require(r, "contact.positions", ct.positions >= 2 && ct.positions <= 100000, "must lie in [2, 100000]");
    ct.strip_points = static_cast<int>(r.integer("contact.strip_points", 64));
    require(r, "contact.strip_points", ct.strip_points >= 8 && ct.strip_points <= 100000, "must lie in [8, 100000]");
    ct.height_points = static_cast<int>(r.integer("contact.height_points", 128));
    require(r, "contact.height_points", ct.height_points >= 8 && ct.height_points <= 100000, "must lie in [8, 100000]");
    ct.table_points = static_cast<int>(r.integer("contact.table_points", 32));
    require(r, "contact.table_points", ct.table_points >= 4 && ct.table_points <= 10000, "must lie in [4, 10000]");
    ct.coupled_nodes = static_cast<int>(r.integer("contact.coupled_nodes", 128));
    require(r, "contact.coupled_nodes", ct.coupled_nodes >= 16 && ct.coupled_nodes <= 4000, "must lie in [16, 4000]");
  }

  c.friction_coefficient = r.number("friction.mu");
  require(r, "friction.mu", c.friction_coefficient >= 0.0 && c.friction_coefficient <= 1.0, "must lie in [0, 1]");

  auto& a = c.asperity;
  a.model = r.string("asperity.model", std::string("continuous"));
  {
    bool known = false;
    for (auto n : asperity::asperity_model_names()) known = known || n == a.model;
    if (!known) {
      std::string names;
      for (auto n : asperity::asperity_model_names()) names += (names.empty() ? "" : ", ") + std::string(n);
      r.fail("asperity.model", "unknown asperity model (known: " + names + ")");
    }
  }
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
      a.constants[model_name].emplace_back(constant, v);
    }
  }
  a.measured_axis_offset = r.quantity("asperity.side_contact.measured_offset", Dimension::length, 0.0);
  a.measured_tip_gap = r.quantity("asperity.side_contact.measured_tip_gap", Dimension::length, 0.0);
  require(r, "asperity.side_contact.measured_offset", a.measured_axis_offset >= 0.0, "must not be negative");
  require(r, "asperity.side_contact.measured_tip_gap", a.measured_tip_gap >= 0.0, "must not be negative");
  a.cylinder_tip_radius = positive_quantity(r, "asperity.cylinder.tip_radius", Dimension::length);
  if (r.is_string("asperity.cylinder.yield_constant")) {
    const std::string choice = r.string("asperity.cylinder.yield_constant");
    require(r, "asperity.cylinder.yield_constant", choice == "green-2005",
            "must be a number or \"green-2005\" (Green's plane-strain C_L(nu))");
    const auto& soft = c.pinion.material.hardness <= c.wheel.material.hardness ? c.pinion.material : c.wheel.material;
    a.cylinder_yield_constant = asperity::green_cylinder_yield_factor(soft.poisson_ratio);
  } else {
    a.cylinder_yield_constant = r.number("asperity.cylinder.yield_constant", 1.64);
  }
  require(r, "asperity.cylinder.yield_constant", a.cylinder_yield_constant > 0.5 && a.cylinder_yield_constant < 5.0,
          "must lie in (0.5, 5)");

  r.check_all_used();
  c.source_text = r.text();
  for (const CaseChange& ch : changes) c.source_text += "\n# --set " + ch.key + "=" + ch.value;
  if (c.pinion.flank.roughness.form != c.wheel.flank.roughness.form)
    r.fail("wheel.flank", "give both flanks' roughness in the same form as the pinion's");
  // One radius per run: the flanks' radii consistent with the equivalent surface (spectral: McCool's).
  const auto [r1, r2] = surface::flank_summit_radii(c.pinion.flank.roughness, c.wheel.flank.roughness);
  c.pinion.flank.summit_radius = c.pinion.flank.roughness.summit_radius = r1;
  c.wheel.flank.summit_radius = c.wheel.flank.roughness.summit_radius = r2;

  // The pair must exist: an impossible geometry is an error at the key to change; findings
  // such as undercut are kept as located warnings.
  try {
    const gear::SpurPair pair(gear::spur_pair_spec(c));
    for (const auto& w : pair.warnings())
      c.warnings.push_back(fmt::format("{}: warning: key '{}': {}", r.where(w.key), w.key, w.message));
  } catch (const gear::GeometryError& e) {
    r.fail(e.key(), e.what());
  }
  return c;
}

}  // namespace geartrib::io
