#include "io/case_parameters.hpp"

#include "asperity/model.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/rough_line_contact.hpp"
#include "io/fzg_load_stages.hpp"
#include "lubrication/ehl_film.hpp"
#include "lubrication/film_closure.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/mixed_lubrication.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <span>
#include <type_traits>
#include <utility>

namespace geartrib::io {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const char* const kGearPrefix[2] = {"pinion.", "wheel."};

ParameterValue number_value(double x) {
  ParameterValue v;
  v.number = x;
  return v;
}
ParameterValue text_value(std::string t) {
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
};

std::vector<std::string> model_names() {
  std::vector<std::string> out;
  for (auto n : asperity::asperity_model_names()) out.emplace_back(n);
  return out;
}

// The FZG tests and their lever arms, as operating.fzg_test's meaning.
std::string fzg_tests_text() {
  std::string s = "The FZG test of operating.fzg_load_stage, which names the lever arm the stage's weights hang on:";
  for (const FzgTest& t : fzg_tests())
    s += fmt::format("{} {}: {}, {:g} m arm", s.back() == ':' ? "" : ";", t.name, t.what, t.lever_arm);
  return s;
}

std::vector<Parameter> build_table() {
  using D = Dimension;
  using K = ParameterKind;
  using contact::GreenwoodWilliamsonOptions;
  using contact::StripOptions;
  constexpr double kDeg = std::numbers::pi / 180.0;
  constexpr double kMm = 1e-3, kUm = 1e-6, kRpm = 2.0 * std::numbers::pi / 60.0;
  // Every numeric row has finite bounds: a hard range beyond which a value is refused (wide: what
  // the arithmetic carries without overflow or loss), and for the gear's own quantities a
  // plausible band beyond which it is warned about (docs/reference/units.md, "Ranges and
  // plausible bands"). Lengths of the gear bodies: at most 10 km (a 10 m module, 1000 teeth).
  constexpr double kMaxBodyLength = 1e4;
  auto gear = [](auto& c, int g) -> auto& { return g == 0 ? c.pinion : c.wheel; };
  std::vector<Row> rows;
  auto add = [&](Parameter p) -> Row& { return rows.emplace_back(Row{std::move(p)}); };

  add(text(
          "title", K::text, [](auto& c, int) -> auto& { return c.title; }))
      .required(kGeometryPart)
      .doc("What the case is");
  add(text(
          "source", K::text, [](auto& c, int) -> auto& { return c.source; }))
      .required(kGeometryPart)
      .doc("Where its data come from (provenance)");

  // [gear_pair]: basic rack and centre distance (ISO 53, ISO 21771).
  add(quantity(
          "gear_pair.module", D::length, [](auto& c, int) -> auto& { return c.gear_pair.module; }))
      .range(1e-6, 10.0)
      .plausible(0.05 * kMm, 100.0 * kMm)
      .required(kGeometryPart)
      .alias({"module"})
      .doc("Module m");
  add(quantity(
          "gear_pair.pressure_angle", D::angle, [](auto& c, int) -> auto& { return c.gear_pair.pressure_angle; }))
      .range(0.0, 45.0 * kDeg, true, true)
      .plausible(10.0 * kDeg, 35.0 * kDeg)
      .required(kGeometryPart)
      .alias({"pressure_angle"})
      .doc("Pressure angle alpha of the basic rack");
  add(quantity(
          "gear_pair.face_width", D::length, [](auto& c, int) -> auto& { return c.gear_pair.face_width; }))
      .range(1e-6, 10.0)
      .plausible(0.1 * kMm, 2.0)
      .required(kGeometryPart)
      .alias({"face_width"})
      .doc("Face width b in contact");
  add(number(
          "gear_pair.addendum_coefficient", [](auto& c, int) -> auto& { return c.gear_pair.addendum_coefficient; }))
      .range(0.0, 2.0, true, false)
      .doc("Addendum h_aP/m of the basic rack");
  add(number(
          "gear_pair.dedendum_coefficient", [](auto& c, int) -> auto& { return c.gear_pair.dedendum_coefficient; }))
      .range(0.0, 3.0, true, false)
      .doc("Dedendum h_fP/m of the basic rack; must exceed the addendum (tip clearance)");
  add(number(
          "gear_pair.root_radius_coefficient",
          [](auto& c, int) -> auto& { return c.gear_pair.root_radius_coefficient; }))
      .range(0.0, 1.0, false, true)
      .doc("Root fillet radius rho_fP/m of the basic rack");
  add(number(
          "gear_pair.tip_shortening", [](auto& c, int) -> auto& { return c.gear_pair.tip_shortening; }))
      .range(0.0, 2.0)
      .doc("Tip shortening k: both tip diameters reduced by 2 k m; below the addendum");
  add(quantity(
          "gear_pair.center_distance", D::length, [](auto& c, int) -> auto& { return c.gear_pair.center_distance; }))
      .range(0.0, kMaxBodyLength)
      .alias({"center_distance"})
      .doc("Operating centre distance a_w; 0: the zero-backlash distance of the shifts");

  // [pinion], [wheel]: each gear's teeth, body and flank.
  add(integer(
          "{gear}.teeth", [](auto& c, int g) -> auto& { return c.gear_pair.teeth[g]; }))
      .range(gear::GearPairSpec::kMinTeeth, gear::GearPairSpec::kMaxTeeth)
      .required(kGeometryPart)
      .alias({"teeth"})
      .gear_alias("z1", "z2")
      .doc("Number of teeth z");
  add(number(
          "{gear}.profile_shift", [](auto& c, int g) -> auto& { return c.gear_pair.profile_shift[g]; }))
      .range(-2.0, 2.0)
      .gear_alias("x1", "x2")
      .doc("Profile shift coefficient x");
  add(quantity(
          "{gear}.tip_diameter", D::length, [](auto& c, int g) -> auto& { return c.gear_pair.tip_diameter[g]; }))
      .range(0.0, kMaxBodyLength)
      .doc("Tip diameter d_a; 0: from addendum, shift and tip shortening");
  add(quantity(
          "{gear}.bore_diameter", D::length, [](auto& c, int g) -> auto& { return c.gear_pair.bore_diameter[g]; }))
      .range(0.0, kMaxBodyLength)
      .doc(
          "Bore of the gear body: the shaft seat of its fillet-foundation stiffness (fitted for r_f/r_bore 1.4 to 7); "
          "0: a solid body, seated at a third of the root diameter (r_f/r_bore = 3)");
  add(text(
          "{gear}.material", K::text, [gear](auto& c, int g) -> auto& { return gear(c, g).material_file; }))
      .required(kGeometryPart)
      .alias({"material"})
      .doc("Material file (materials/*.toml), relative to the case file");

  // The flank's roughness, in exactly one form (surface::FlankRoughness).
  auto rough = [gear](auto& c, int g) -> auto& { return gear(c, g).flank.roughness; };
  add(quantity(
          "{gear}.flank.ra", D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).ra; }))
      .range(1e-10, 1e-3)
      .plausible(1e-9, 25.0 * kUm)
      .no_default()
      .alias({"ra"})
      .doc("Form Ra: arithmetic mean roughness (profile)");
  add(quantity(
          "{gear}.flank.rq", D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).rq; }))
      .range(1e-10, 1e-3)
      .plausible(1e-9, 25.0 * kUm)
      .no_default()
      .alias({"rq"})
      .doc("Form Rq: root-mean-square roughness (profile)");
  add(quantity(
          "{gear}.flank.summit_density",
          D::areal_density, [rough](auto& c, int g) -> auto& { return rough(c, g).summit_density; }))
      .range(1.0, 1e20)
      .no_default()
      .doc("Form summits: summit density eta (with summit_sigma)");
  add(quantity(
          "{gear}.flank.summit_sigma",
          D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).summit_sigma; }))
      .range(1e-10, 1e-3)
      .plausible(1e-9, 25.0 * kUm)
      .no_default()
      .doc("Form summits: standard deviation of summit heights");
  add(quantity(
          "{gear}.flank.m0", D::area, [rough](auto& c, int g) -> auto& { return rough(c, g).m0; }))
      .range(1e-20, 1e-6)
      .no_default()
      .doc("Form spectral: profile moment m0 = Rq^2 (with m2, m4; McCool 1986)");
  add(quantity(
          "{gear}.flank.m2", D::dimensionless, [rough](auto& c, int g) -> auto& { return rough(c, g).m2; }))
      .range(1e-12, 100.0)
      .no_default()
      .doc("Form spectral: slope moment m2");
  add(quantity(
          "{gear}.flank.m4", D::areal_density, [rough](auto& c, int g) -> auto& { return rough(c, g).m4; }))
      .range(1.0, 1e26)
      .no_default()
      .doc("Form spectral: curvature moment m4");
  add(quantity(
          "{gear}.flank.summit_radius",
          D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).summit_radius; }))
      .range(1e-9, 1.0)
      .plausible(0.1 * kUm, 10.0 * kMm)
      .no_default()
      .alias({"summit_radius"})
      .doc(
          "Mean summit radius beta of the flank's asperities: required with ra, rq or summit_density + summit_sigma, "
          "no default (it sets the plasticity index and depends on the finish and the sampling interval). Measured: "
          "`geartrib surface stats FILE` (summit_radius_m, mccool_summit_radius_m); from a profile, McCool's beta = "
          "0.375 sqrt(pi/m4) with m4 = bandwidth x (rms slope)^4/Rq^2 (Rq 0.4 um, slope 0.05, bandwidth 5: 48 um). "
          "Typical: ground flanks tens of um; the thesis's hobbed, run-in flanks 1.65 and 1.75 um. Given with a "
          "measured flank, it overrides the measured radius");
  auto topo = [gear](auto& c, int g) -> auto& { return gear(c, g).flank.topography; };
  // A measured flank: the rows fill the topography spec (created on first use).
  auto topo_spec = [topo](Case& c, int g) -> surface::TopographySpec& {
    auto& t = topo(c, g);
    if (!t) t.emplace();
    return *t;
  };
  auto topo_get = [topo](const Case& c, int g) -> const surface::TopographySpec& {
    static const surface::TopographySpec kDefault;
    const auto& t = topo(c, g);
    return t ? *t : kDefault;
  };
  auto topo_ref = [topo_spec, topo_get](auto member) {
    return [=](auto& c, int g) -> auto& {
      if constexpr (std::is_const_v<std::remove_reference_t<decltype(c)>>) return member(topo_get(c, g));
      else return member(topo_spec(c, g));
    };
  };
  add(text("{gear}.flank.topography.file", K::text, topo_ref([](auto& t) -> auto& { return t.file; })))
      .doc(
          "Form measured: a profiler export, HDF5 or X3P surface (geartrib surface); its summits give the "
          "roughness");
  add(quantity("{gear}.flank.topography.unit", D::length, topo_ref([](auto& t) -> auto& { return t.unit; })))
      .range(1e-12, 1.0)
      .doc("Length unit of a file that does not state one");
  add(quantity("{gear}.flank.topography.spacing", D::length, topo_ref([](auto& t) -> auto& { return t.spacing; })))
      .range(0.0, 1.0)
      .doc("Grid spacing of files without one; 0: from the file");
  add(quantity("{gear}.flank.topography.resample", D::length, topo_ref([](auto& t) -> auto& { return t.resample; })))
      .range(0.0, 1.0)
      .doc("Regrid spacing; 0: as measured");
  add(integer("{gear}.flank.topography.form", topo_ref([](auto& t) -> auto& { return t.clean.form_degree; })))
      .range(0, 6)
      .doc("Degree of the polynomial form removed");
  add(quantity("{gear}.flank.topography.cutoff", D::length,
               topo_ref([](auto& t) -> auto& { return t.clean.waviness_cutoff; })))
      .range(0.0, 1.0)
      .doc("Gaussian waviness cut-off (ISO 16610-61); 0: no waviness filter");
  add(number("{gear}.flank.topography.outliers", topo_ref([](auto& t) -> auto& { return t.clean.outlier_limit; })))
      .range(0.0, 1000.0)
      .doc("Outlier limit in robust standard deviations: 0 (off) or at least 2");
  {
    Parameter fill = numeric("{gear}.flank.topography.fill", K::flag, D::dimensionless,
                             topo_ref([](auto& t) -> auto& { return t.clean.fill; }));
    add(std::move(fill)).doc("Fill missing points from their neighbours");
  }
  add(mapped_choice(
          "{gear}.flank.topography.profile_axis", {"x", "y"},
          topo_ref([](auto& t) -> auto& { return t.profile_along_x; }), [](const std::string& t) { return t == "x"; },
          [](bool x) { return std::string(x ? "x" : "y"); }))
      .doc("Deterministic: the surface's axis along the involute (root to tip), the profile's direction");
  add(number("{gear}.flank.topography.profile_at", topo_ref([](auto& t) -> auto& { return t.profile_at; })))
      .range(0.0, 1.0)
      .doc("Deterministic: where across the other axis the profile is taken (fraction of its length)");
  add(mapped_choice(
          "{gear}.flank.topography.synthesis", {"none", "psd", "iaaft"},
          topo_ref([](auto& t) -> auto& { return t.synthesis; }),
          [](const std::string& t) { return surface::synthesis_method(t); },
          [](surface::SynthesisMethod m) { return std::string(surface::synthesis_method_name(m)); }))
      .doc(
          "Deterministic: none (the line at profile_at, which must cover the flank), or a flank-long profile "
          "synthesised from the surface's profile spectrum along profile_axis (all its lines; nothing at wavelengths "
          "longer than the surface): random phases (psd), or also its height distribution kept (iaaft)");
  add(integer("{gear}.flank.topography.synthesis_seed", topo_ref([](auto& t) -> auto& { return t.synthesis_seed; })))
      .range(0, 4294967295.0)
      .doc(
          "Synthesis: random seed of the phases (tooth t of the hunting order: seed + t); give the two flanks "
          "different seeds");
  add(quantity("{gear}.flank.topography.synthesis_length", D::length,
               topo_ref([](auto& t) -> auto& { return t.synthesis_length; })))
      .range(0.0, 1.0)
      .doc(
          "Synthesis: the profile's length, centred on the active flank; 0: a module below the base circle to a "
          "module beyond the tip (as a generated profile)");
  // A generated profile along the involute (a roughness form; the deterministic fidelity's flank).
  auto prof = [gear](auto& c, int g) -> auto& { return gear(c, g).flank.profile; };
  auto prof_spec = [prof](Case& c, int g) -> surface::GeneratedProfileSpec& {
    auto& t = prof(c, g);
    if (!t) t.emplace();
    return *t;
  };
  auto prof_get = [prof](const Case& c, int g) -> const surface::GeneratedProfileSpec& {
    static const surface::GeneratedProfileSpec kDefault;
    const auto& t = prof(c, g);
    return t ? *t : kDefault;
  };
  auto prof_ref = [prof_spec, prof_get](auto member) {
    return [=](auto& c, int g) -> auto& {
      if constexpr (std::is_const_v<std::remove_reference_t<decltype(c)>>) return member(prof_get(c, g));
      else return member(prof_spec(c, g));
    };
  };
  add(mapped_choice(
          "{gear}.flank.profile.kind", {"smooth", "ground", "hobbed"},
          prof_ref([](auto& t) -> auto& { return t.kind; }),
          [](const std::string& t) { return surface::profile_kind(t); },
          [](surface::ProfileKind k) { return std::string(surface::profile_kind_name(k)); }))
      .doc(
          "Form generated profile: smooth, ground (Gaussian random, Gaussian autocorrelation) or hobbed "
          "(parabolic ridges meeting in sharp valleys, plus a ground-like random part)");
  add(quantity("{gear}.flank.profile.spacing", D::length, prof_ref([](auto& t) -> auto& { return t.spacing; })))
      .range(1e-9, 1e-4)
      .doc("Generated profile: point spacing along the involute");
  add(quantity("{gear}.flank.profile.rq", D::length, prof_ref([](auto& t) -> auto& { return t.rq; })))
      .range(0.0, 1e-4)
      .plausible(0.0, 25.0 * kUm)
      .doc("Generated profile: Rq of the random part (ground: of the profile)");
  add(quantity("{gear}.flank.profile.correlation_length", D::length,
               prof_ref([](auto& t) -> auto& { return t.correlation_length; })))
      .range(1e-9, 1e-2)
      .doc("Generated profile: lambda of the random part's autocorrelation exp(-tau^2/lambda^2)");
  add(quantity("{gear}.flank.profile.ridge_spacing", D::length,
               prof_ref([](auto& t) -> auto& { return t.ridge_spacing; })))
      .range(1e-8, 1e-2)
      .doc("Hobbed profile: distance between the ridges");
  add(quantity("{gear}.flank.profile.ridge_radius", D::length,
               prof_ref([](auto& t) -> auto& { return t.ridge_radius; })))
      .range(1e-8, 1.0)
      .doc("Hobbed profile: the ridges' tip radius");
  add(integer("{gear}.flank.profile.seed", prof_ref([](auto& t) -> auto& { return t.seed; })))
      .range(0, 4294967295.0)
      .doc("Generated profile: random seed");

  // [operating]
  add(quantity(
          "operating.pinion_torque", D::torque, [](auto& c, int) -> auto& { return c.operating.pinion_torque; }))
      .range(1e-9, 1e10)
      .plausible(1e-6, 1e7)
      .required(kGeometryPart)
      .alias({"torque"})
      .doc("Pinion torque T1; or give operating.fzg_load_stage with operating.fzg_test instead");
  add(integer(
          "operating.fzg_load_stage", [](auto& c, int) -> auto& { return c.operating.fzg_load_stage; }))
      .range(kFzgMinLoadStage, kFzgMaxLoadStage)
      .no_default()
      .alias({"fzg_load_stage"})
      .doc(
          "FZG load stage: sets the pinion torque from the FZG rig's load-stage table of operating.fzg_test's lever "
          "arm (gears/fzg/load-stages.csv); instead of operating.pinion_torque");
  add(text(
          "operating.fzg_test", K::choice, [](auto& c, int) -> auto& { return c.operating.fzg_test; }))
      .choices(fzg_test_names(), "FZG test")
      .no_default()
      .alias({"fzg_test"})
      .doc(fzg_tests_text());
  add(quantity(
          "operating.pinion_speed", D::angular_speed, [](auto& c, int) -> auto& { return c.operating.pinion_speed; }))
      .range(1e-6, 1e6)
      .plausible(0.1 * kRpm, 1e5 * kRpm)
      .required(kGeometryPart)
      .alias({"speed"})
      .doc("Pinion speed n1");

  add(quantity(
          "operating.oil_temperature", D::temperature,
          [](auto& c, int) -> auto& { return c.operating.oil_temperature; }))
      .range(100.0, 1000.0)
      .no_default()
      .alias({"oil_temperature"})
      .doc("Oil (inlet) temperature; required with [lubricant]");
  add(quantity(
          "operating.bulk_temperature", D::temperature,
          [](auto& c, int) -> auto& { return c.operating.bulk_temperature; }))
      .range(0.0, 2000.0)
      .alias({"bulk_temperature"})
      .doc(
          "Flanks' bulk temperature theta_M (film viscosity, contact temperature); 0: the ISO/TS 6336-20 "
          "estimate oil + 0.47 x mean flash temperature");

  // [lubricant]: a file, or the oil at the oil temperature given here (the fixed form).
  add(text(
          "lubricant.file", K::text, [](auto& c, int) -> auto& { return c.lubrication.lubricant_file; }))
      .alias({"lubricant"})
      .doc(
          "Lubricant file (lubricants/*.toml, relative to the case); or give dynamic_viscosity and "
          "pressure_viscosity_coefficient here");
  add(quantity(
          "lubricant.dynamic_viscosity", D::dynamic_viscosity,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.fixed_dynamic_viscosity; }))
      .range(0.0, 1e4, true, false)
      .no_default()
      .alias({"viscosity"})
      .doc("Fixed form: eta at the oil temperature (the film uses it at every temperature)");
  add(quantity(
          "lubricant.pressure_viscosity_coefficient", D::inverse_pressure,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.pressure_viscosity; }))
      .range(1e-12, 1e-6)
      .no_default()
      .alias({"alpha"})
      .doc("Fixed form: pressure-viscosity coefficient alpha at the oil temperature");
  add(quantity(
          "lubricant.temperature_viscosity_coefficient", D::inverse_temperature,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.fixed_temperature_viscosity; }))
      .range(0.0, 1.0)
      .doc(
          "Fixed form: beta = -d ln(eta)/dT for the inlet-heating correction (typical mineral oil at 70 degC; "
          "assumed)");
  add(quantity(
          "lubricant.thermal_conductivity", D::thermal_conductivity,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.thermal_conductivity; }))
      .range(1e-3, 1e3)
      .doc("Fixed form: the oil's thermal conductivity (typical mineral oil; assumed)");
  add(quantity(
          "lubricant.eyring_stress", D::pressure,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.eyring_stress; }))
      .range(1e3, 1e10)
      .doc("Fixed form: Eyring stress tau_0 of the film's traction (typical; assumed)");
  add(number(
          "lubricant.limiting_shear_coefficient",
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.limiting_shear_coefficient; }))
      .range(0.0, 1.0, true, false)
      .doc("Fixed form: limiting shear stress over pressure (typical mineral oil; assumed)");
  add(mapped_choice(
          "lubricant.base_oil", lubrication::base_oil_names(),
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.base_oil; },
          [](const std::string& t) { return lubrication::base_oil_from_name(t); },
          [](lubrication::BaseOil b) { return std::string(lubrication::base_oil_name(b)); }))
      .doc(
          "Fixed form: base stock, for the ISO lubricant factor X_L (an ester needs lubricant.iso_lubricant_factor: "
          "the standard tabulates none)");
  add(number(
          "lubricant.iso_lubricant_factor",
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.iso_lubricant_factor; }))
      .range(0.0, 2.0)
      .doc("Fixed form: the ISO lubricant factor X_L itself; 0: the base stock's tabulated value");

  // [lubrication]: the models along the path.
  add(named_choice(
          "lubrication.film_formula", lubrication::film_formula_choices(), "film formula",
          [](auto& c, int) -> auto& { return c.lubrication.film_formula; }))
      .alias({"film_formula"})
      .doc("Smooth EHL film: Dowson-Higginson minimum, Pan-Hamrock minimum or central, Dowson-Toyoda central");
  add(named_choice(
          "lubrication.inlet_heating", lubrication::inlet_heating_choices(), "inlet-heating correction",
          [](auto& c, int) -> auto& { return c.lubrication.inlet_heating; }))
      .alias({"inlet_heating"})
      .doc("Inlet shear-heating correction of the film: Gupta et al. 1992, Murch-Wilson 1975 or none");
  add(quantity(
          "lubrication.wear_coefficient", D::inverse_pressure,
          [](auto& c, int) -> auto& { return c.lubrication.wear_coefficient; }))
      .range(0.0, 1e-9)
      .alias({"wear_coefficient"})
      .doc("Archard's dimensional wear coefficient k of the asperity contacts (order of mild wear; assumed)");
  add(quantity(
          "lubrication.scuffing_temperature", D::temperature,
          [](auto& c, int) -> auto& { return c.lubrication.scuffing_temperature; }))
      .range(0.0, 2000.0)
      .doc("Scuffing temperature theta_S for the ISO/TS 6336-20 flash-temperature safety; 0: none");
  add(named_choice(
          "lubrication.film_gap", lubrication::film_gap_choices(), "film gap",
          [](auto& c, int) -> auto& { return c.lubrication.film_gap; }))
      .alias({"film_gap"})
      .doc(
          "What the shared film's thickness equals: the mean gap between the rough flanks (Patir & Cheng), the "
          "separation of their mean planes (JGP 1972), or the gap counted from the dry contact (geartrib 0.1)");
  add(named_choice(
          "lubrication.asperity_pressure", lubrication::asperity_pressure_model_choices(), "asperity pressure model",
          [](auto& c, int) -> auto& { return c.lubrication.asperity_pressure; }))
      .alias({"asperity_pressure"})
      .doc(
          "Asperity pressure in the load sharing: auto (the asperity model, or the bearing area at the hardness "
          "where its plastic area fraction exceeds 0.99, blended from 0.9), asperity-model or bearing-area");
  add(named_choice(
          "lubrication.traction", lubrication::film_traction_choices(), "film traction model",
          [](auto& c, int) -> auto& { return c.lubrication.traction; }))
      .alias({"traction"})
      .doc(
          "Film traction: thermal Eyring (Johnson & Greenwood 1980), isothermal Eyring, or the lubricant's measured "
          "traction curves");
  add(named_choice(
          "lubrication.mean_friction", lubrication::mean_friction_law_choices(), "gear-mean friction law",
          [](auto& c, int) -> auto& { return c.lubrication.mean_friction; }))
      .alias({"mean_friction"})
      .doc(
          "Gear-mean friction law of the bulk-temperature estimate: iso-flash (ISO/TS 6336-20's own), iso "
          "(ISO/TS 6336-21/-22), schlenk, fernandes; all are reported");

  // [friction]
  add(number(
          "friction.mu", [](auto& c, int) -> auto& { return c.friction_coefficient; }))
      .range(0.0, 1.0)
      .required(kFrictionPart)
      .alias({"mu"})
      .doc(
          "Coulomb friction coefficient of the asperity contacts: the side contact of sliding summits (contact "
          "normal tilted by atan(mu)) and the boundary coefficient of a lubricated run");

  // [mesh]
  add(named_choice(
          "mesh.load_sharing", gear::load_sharing_choices(), "value",
          [](auto& c, int) -> auto& { return c.mesh.load_sharing; }))
      .alias({"load_sharing"})
      .doc("Load sharing between tooth pairs: ISO/TS 6336-22 method B or the pairs' stiffnesses");
  add(integer(
          "mesh.positions", [](auto& c, int) -> auto& { return c.mesh.positions; }))
      .range(2, 100000)
      .doc("Positions sampling one base pitch (kinematics, mesh stiffness)");
  add(mapped_choice(
          "mesh.tooth_beam", {"plane-strain", "plane-stress"},
          [](auto& c, int) -> auto& { return c.mesh.plane_strain; },
          [](const std::string& t) { return t == "plane-strain"; },
          [](bool strain) { return std::string(strain ? "plane-strain" : "plane-stress"); }))
      .doc("Tooth beam of the stiffness model: plane strain (wide face) or plane stress");
  add(named_choice(
          "mesh.dynamics", gear::dynamics_engine_choices(), "value",
          [](auto& c, int) -> auto& { return c.dynamics.engine; }))
      .alias({"dynamics"})
      .doc("Mesh dynamics: none (static load sharing) or the steady dynamic cycle with an integrator");

  // [dynamics]
  add(number(
          "dynamics.damping_ratio", [](auto& c, int) -> auto& { return c.dynamics.damping_ratio; }))
      .range(0.0, 1.0, false, true)
      .alias({"damping"})
      .doc("Mesh damping ratio zeta (0.03-0.17 reported; Kasuba & Evans 1981)");
  add(number(
          "dynamics.relative_tolerance", [](auto& c, int) -> auto& { return c.dynamics.tolerances.relative; }))
      .range(1e-14, 1e-2)
      .alias({"rtol"})
      .ladder({"1e-4", "1e-6", "1e-8", "1e-10", "1e-12"})
      .doc("Relative tolerance of the integrator");
  add(quantity(
          "dynamics.backlash", D::length, [](auto& c, int) -> auto& { return c.dynamics.backlash; }))
      .range(0.0, 0.1)
      .doc("Backlash along the line of action; 0: no back-flank contact");
  add(quantity(
          "dynamics.pinion_inertia", D::inertia, [](auto& c, int) -> auto& { return c.dynamics.pinion_inertia; }))
      .range(0.0, 1e12)
      .doc("Pinion polar moment of inertia; 0: a solid disc less the bore");
  add(quantity(
          "dynamics.wheel_inertia", D::inertia, [](auto& c, int) -> auto& { return c.dynamics.wheel_inertia; }))
      .range(0.0, 1e12)
      .doc("Wheel polar moment of inertia; 0: a solid disc less the bore");

  // [roughness]: both flanks.
  add(mapped_choice(
          "roughness.distribution", {"gaussian", "exponential"},
          [](auto& c, int) -> auto& { return c.roughness.distribution; },
          [](const std::string& t) {
            return t == "gaussian" ? surface::HeightDistribution::gaussian : surface::HeightDistribution::exponential;
          },
          [](surface::HeightDistribution d) {
            return std::string(d == surface::HeightDistribution::gaussian ? "gaussian" : "exponential");
          }))
      .doc("Summit height distribution");
  add(number(
          "roughness.eta_sigma_beta", [](auto& c, int) -> auto& { return c.roughness.eta_sigma_beta; }))
      .range(0.0, 10.0, true, true)
      .plausible(0.01, 0.2)
      .doc("Summit parameter eta sigma beta for flanks given by Ra or Rq");

  // [contact]: the mesh cycle's fidelity, outputs and resolutions.
  add(mapped_choice(
          "contact.fidelity", contact::fidelity_names(), [](auto& c, int) -> auto& { return c.contact.fidelity; },
          [](const std::string& t) { return contact::find_fidelity(t).id(); },
          [](ContactFidelity f) { return std::string(f.name()); }))
      .alias({"fidelity"})
      .doc(contact::fidelity_descriptions());
  {
    Parameter outputs;
    outputs.key = "contact.outputs";
    outputs.kind = K::choice_list;
    outputs.choices = {"real_area", "plastic_fraction", "asperity_stress", "mesh_stiffness"};
    outputs.get = [](const Case& c, int) {
      ParameterValue v;
      if (c.contact.real_area) v.list.emplace_back("real_area");
      if (c.contact.plastic_fraction) v.list.emplace_back("plastic_fraction");
      if (c.contact.asperity_stress) v.list.emplace_back("asperity_stress");
      if (c.contact.mesh_stiffness) v.list.emplace_back("mesh_stiffness");
      return v;
    };
    outputs.set = [](Case& c, int, const ParameterValue& v) {
      auto has = [&](const char* n) { return std::find(v.list.begin(), v.list.end(), n) != v.list.end(); };
      c.contact.real_area = has("real_area");
      c.contact.plastic_fraction = has("plastic_fraction");
      c.contact.asperity_stress = has("asperity_stress");
      c.contact.mesh_stiffness = has("mesh_stiffness");
    };
    add(std::move(outputs))
        .doc(
            "The outputs computed (a run computes only these; mesh_stiffness: the tooth-pair stiffness along the "
            "path, computed anyway with stiffness load sharing)");
  }
  add(integer(
          "contact.positions", [](auto& c, int) -> auto& { return c.contact.positions; }))
      .range(2, 100000)
      .alias({"positions"})
      .ladder({"11", "21", "41", "81", "101", "201", "401", "801"})
      .doc("Positions along the path of contact A -> E");
  add(integer(
          "contact.strip_points", [](auto& c, int) -> auto& { return c.contact.strip_points; }))
      .range(StripOptions::kMinStripPoints, StripOptions::kMaxStripPoints)
      .alias({"strip_points"})
      .ladder({"8", "16", "32", "64", "128", "256", "512"})
      .doc("Uncoupled: quadrature points across the Hertz strip");
  add(integer(
          "contact.height_points", [](auto& c, int) -> auto& { return c.contact.height_points; }))
      .range(GreenwoodWilliamsonOptions::kMinHeightPoints, GreenwoodWilliamsonOptions::kMaxHeightPoints)
      .alias({"height_points"})
      .ladder({"8", "16", "32", "64", "128", "256", "512", "1024"})
      .doc("Quadrature points over the summit heights in contact");
  add(integer(
          "contact.table_points", [](auto& c, int) -> auto& { return c.contact.table_points; }))
      .range(GreenwoodWilliamsonOptions::kMinTablePoints, GreenwoodWilliamsonOptions::kMaxTablePoints)
      .alias({"table_points"})
      .ladder({"4", "8", "16", "32", "64", "128", "256"})
      .doc("Pressure-separation table points per summit sigma");
  add(integer(
          "contact.coupled_nodes", [](auto& c, int) -> auto& { return c.contact.coupled_nodes; }))
      .range(StripOptions::kMinCoupledNodes, StripOptions::kMaxCoupledNodes)
      .alias({"coupled_nodes"})
      .ladder({"32", "64", "128", "256"})
      .doc("Coupled: pressure elements across the contact");
  add(mapped_choice(
          "contact.strip_lookup", {"cubic", "exact"},
          [](auto& c, int) -> auto& { return c.contact.exact_strip_lookup; },
          [](const std::string& t) { return t == "exact"; },
          [](bool exact) { return std::string(exact ? "exact" : "cubic"); }))
      .alias({"strip_lookup"})
      .ladder({"cubic", "exact"})
      .doc(
          "Uncoupled: the rough surface at each strip point from cubic cells in the pressure (no transcendental "
          "call per point) or exact: the pressure table's inversion and log-linear interpolation, the reference");
  add(integer(
          "contact.stress_table", [](auto& c, int) -> auto& { return c.contact.stress_table; }))
      .range(0, asperity::VonMisesTable::kMaxIntervals)
      .alias({"stress_table"})
      .ladder({"4", "8", "16", "32", "64", "0"})
      .doc(
          "Asperity stresses: intervals of the normalised von Mises table over the square root of the plastic share "
          "(0: the exact maximisation at every position, the reference)");

  // Deterministic fidelity: the boundary elements across the strip.
  add(quantity(
          "contact.element_size", D::length, [](auto& c, int) -> auto& { return c.contact.element_size; }))
      .range(1e-9, 1e-3)
      .plausible(0.01 * kUm, 10.0 * kUm)
      .alias({"element_size"})
      .ladder({"4 um", "2 um", "1 um", "0.5 um", "0.25 um", "0.125 um"})
      .doc(
          "Deterministic: boundary-element width across the strip; not below a flank profile's spacing (the profile "
          "is averaged over each element)");
  add(number(
          "contact.strip_halfwidths", [](auto& c, int) -> auto& { return c.contact.strip_halfwidths; }))
      .range(contact::DeterministicOptions::kMinStripHalfwidths, contact::DeterministicOptions::kMaxStripHalfwidths)
      .alias({"strip_halfwidths"})
      .ladder({"1.1", "1.25", "1.5", "2", "3"})
      .doc(
          "Deterministic: the strip's half-length in the path's largest Hertz half-width (a rough contact spreads "
          "beyond the smooth one's)");
  add(mapped_choice(
          "contact.pressure_profiles", {"points", "all", "none"},
          [](auto& c, int) -> auto& { return c.contact.pressure_profiles; },
          [](const std::string& t) {
            return t == "all" ? PressureProfiles::all : t == "none" ? PressureProfiles::none : PressureProfiles::points;
          },
          [](PressureProfiles p) {
            return std::string(p == PressureProfiles::all ? "all" : p == PressureProfiles::none ? "none" : "points");
          }))
      .doc(
          "Deterministic: the pressure profiles kept in the HDF5 file: at the positions nearest A, B, C, D, E "
          "(points), at every position (all) or none");
  add(integer(
          "contact.threads", [](auto& c, int) -> auto& { return c.contact.threads; }))
      .range(0, 1024)
      .alias({"threads"})
      .doc("Deterministic: threads solving the positions of a mesh (0: all cores)");
  // [running_in]
  add(integer(
          "running_in.meshes", [](auto& c, int) -> auto& { return c.running_in.meshes; }))
      .range(0, 100000)
      .alias({"meshes"})
      .doc(
          "Deterministic: meshes of running-in, each flank's plastic deformation carried to its next mesh (0: the "
          "new flanks only); stops earlier at shakedown");
  add(quantity(
          "running_in.tolerance", D::length, [](auto& c, int) -> auto& { return c.running_in.tolerance; }))
      .range(1e-15, 1e-3, true, false)
      .doc(
          "Deterministic: plastic deformation below this counts as none (the plastic area's threshold); a mesh that "
          "deforms no flank point by more ends the running-in (shakedown)");
  add(text(
          "running_in.teeth", K::choice, [](auto& c, int) -> auto& { return c.running_in.teeth; }))
      .choices({"pair", "hunting"}, "tooth order")
      .doc(
          "pair: one pinion tooth meets one wheel tooth every mesh (the 1:1 pair's order); hunting: every tooth, "
          "in the order they mesh (pinion tooth k meets wheel tooth k mod z2)");

  // [asperity]
  add(text(
          "asperity.model", K::choice, [](auto& c, int) -> auto& { return c.asperity.model; }))
      .choices(model_names(), "asperity model")
      .alias({"model"})
      .doc("Single-asperity model of the rough contact");
  {
    Parameter constants;
    constants.key = "asperity.constants.MODEL.NAME";
    constants.kind = K::model_constants;
    constants.get = [](const Case&, int) { return ParameterValue{}; };
    constants.set = [](Case&, int, const ParameterValue&) {};
    add(std::move(constants))
        .doc("A model constant overridden (geartrib asperity --constants --model MODEL lists them)");
  }
  add(quantity(
          "asperity.side_contact.measured_offset", D::length,
          [](auto& c, int) -> auto& { return c.asperity.measured_axis_offset; }))
      .range(0.0, 1e-2)
      .doc("Measured axis offset d0 of the side contact; 0: none measured");
  add(quantity(
          "asperity.side_contact.measured_tip_gap", D::length,
          [](auto& c, int) -> auto& { return c.asperity.measured_tip_gap; }))
      .range(0.0, 1e-2)
      .doc("Measured tip gap y0 of the side contact; 0: none measured");
  add(quantity(
          "asperity.cylinder.tip_radius", D::length,
          [](auto& c, int) -> auto& { return c.asperity.cylinder_tip_radius; }))
      .range(1e-9, 1.0)
      .required(kCylinderPart)
      .doc(
          "Tip radius R_m of the parabolic-cylinder asperities (a hobbed flank's ridges) of the multi-asperity and "
          "FEM studies; geartrib surface asperities --cylinders measures it");
  add(number(
          "asperity.cylinder.yield_constant", [](auto& c, int) -> auto& { return c.asperity.cylinder_yield_constant; }))
      .range(0.5, 5.0, true, true)
      .choices({"green-2005"})
      .doc("C of the cylinder's critical interference, or green-2005 (Green's plane-strain C_L(nu))");

  std::vector<Parameter> out;
  out.reserve(rows.size());
  for (auto& r : rows) out.push_back(std::move(r.p));
  return out;
}

std::string number_text(double v) { return fmt::format("{:g}", v); }

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

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
      "Generated by `geartrib case --schema --markdown` from the parameter table (src/io/case_parameters.cpp);\n"
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
