// Loading the data files, and the error each kind of bad input produces.
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/input_error.hpp"
#include "config/text_lines.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/rough_line_contact.hpp"
#include "gear/mesh_dynamics.hpp"
#include "surface/surface_statistics.hpp"
#include "surface/synthetic_surface.hpp"
#include "test_support.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

using namespace geartrib;

namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A scratch copy of gears/, materials/ and lubricants/ in which one file's text is edited.
class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("geartrib-test-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "gears");
    std::filesystem::create_directories(dir_ / "materials");
    std::filesystem::copy_file(test::source_dir() / "gears/m6z30.toml", dir_ / "gears/m6z30.toml");
    std::filesystem::copy_file(test::source_dir() / "materials/steel-45.toml", dir_ / "materials/steel-45.toml");
    std::filesystem::copy(test::source_dir() / "lubricants", dir_ / "lubricants");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void edit(const std::string& rel, const std::string& from, const std::string& to) {
    std::string text = read(dir_ / rel);
    const auto pos = text.find(from);
    ASSERT_NE(pos, std::string::npos) << from;
    text.replace(pos, from.size(), to);
    std::ofstream(dir_ / rel) << text;
  }
  io::InputError load_error() {
    try {
      io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml"));
    } catch (const io::InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError";
    return io::InputError("", 0, "", "", "");
  }
  int line_of(const std::string& rel, const std::string& needle) {
    std::ifstream in(dir_ / rel);
    std::string l;
    for (int n = 1; std::getline(in, l); ++n)
      if (l.find(needle) != std::string::npos) return n;
    return -1;
  }
  std::filesystem::path dir_;
};

}  // namespace

TEST(CaseFile, LoadsTheSeedCaseInSi) {
  const Case& c = test::seed_case();
  EXPECT_DOUBLE_EQ(c.gear_pair.module, 6e-3);
  EXPECT_DOUBLE_EQ(c.gear_pair.face_width, 80e-3);
  EXPECT_DOUBLE_EQ(c.gear_pair.pressure_angle, 20.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(c.gear_pair.teeth[0], 30);
  EXPECT_EQ(c.gear_pair.teeth[1], 30);
  EXPECT_DOUBLE_EQ(c.pinion.flank.roughness.summit_radius, 1.65e-6);
  EXPECT_DOUBLE_EQ(c.wheel.flank.roughness.summit_radius, 1.75e-6);
  EXPECT_DOUBLE_EQ(c.pinion.flank.roughness.ra, 0.8e-6);
  EXPECT_EQ(c.pinion.flank.roughness.form, surface::FlankRoughness::Form::ra);
  EXPECT_DOUBLE_EQ(c.operating.pinion_torque, 1000.0);
  EXPECT_DOUBLE_EQ(c.operating.pinion_speed, 1000.0 * 2.0 * std::numbers::pi / 60.0);
  EXPECT_DOUBLE_EQ(c.friction_coefficient, 0.1);
  EXPECT_DOUBLE_EQ(c.asperity.measured_axis_offset, 0.68e-6);
  EXPECT_DOUBLE_EQ(c.asperity.measured_tip_gap, 0.068e-6);
  EXPECT_DOUBLE_EQ(c.asperity.cylinder_tip_radius, 6.6e-6);
  EXPECT_EQ(c.asperity.model, "continuous");
  const Material& m = c.pinion.material;
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 206e9);
  EXPECT_DOUBLE_EQ(m.poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(m.yield_strength, 418e6);
  EXPECT_DOUBLE_EQ(m.hardness, 2.8 * 418e6);  // not given: Tabor's 2.8 x yield
  ASSERT_EQ(m.flow_curve.size(), 13u);        // seed section 6 table
  EXPECT_DOUBLE_EQ(m.flow_curve.back().stress, 1040e6);
  EXPECT_DOUBLE_EQ(m.flow_curve.back().plastic_strain, 0.85);
}

TEST_F(BadInput, NegativeModulusNamesFileLineKeyValueRule) {
  edit("materials/steel-45.toml", "youngs_modulus = \"206 GPa\"", "youngs_modulus = \"-206 GPa\"");
  const auto e = load_error();
  EXPECT_NE(e.file().find("steel-45.toml"), std::string::npos);
  EXPECT_EQ(e.line(), line_of("materials/steel-45.toml", "youngs_modulus"));
  EXPECT_EQ(e.key(), "youngs_modulus");
  EXPECT_EQ(e.value(), "\"-206 GPa\"");
  EXPECT_EQ(e.rule(), "must be positive");
}

// Control characters are escapes in the message (a NUL ended it wherever what() is read as a C
// string), the parts keep their text; a rule keeps its line breaks.
TEST(InputErrorMessage, ControlCharactersEscaped) {
  const io::InputError e("a\x01.toml", 3, "k\x1b", std::string("1\0 Nm", 5), "rule\nnext\x7f");
  EXPECT_STREQ(e.what(), "a\\x01.toml:3: key 'k\\x1b' = 1\\x00 Nm: rule\nnext\\x7f");
  EXPECT_EQ(e.value(), std::string("1\0 Nm", 5));
  // A --set value with one is refused whole, before any unit is read from it.
  try {
    io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", {{"torque", std::string("1000\0 Nm", 8)}}));
    ADD_FAILURE() << "accepted";
  } catch (const io::InputError& err) {
    EXPECT_EQ(err.rule(), "a --set key or value may not hold control characters (shown as \\xNN)");
    EXPECT_NE(std::string(err.what()).find("(--set operating.pinion_torque=1000\\x00 Nm)"), std::string::npos);
  }
}

TEST_F(BadInput, PoissonRatioOutOfRange) {
  edit("materials/steel-45.toml", "poisson_ratio = 0.3", "poisson_ratio = 0.5");
  const auto e = load_error();
  EXPECT_EQ(e.key(), "poisson_ratio");
  EXPECT_EQ(e.value(), "0.5");
  EXPECT_NE(e.rule().find("(0, 0.5)"), std::string::npos);
}

TEST_F(BadInput, UnknownUnit) {
  edit("gears/m6z30.toml", "module = \"6 mm\"", "module = \"6 parsec\"");
  const auto e = load_error();
  EXPECT_EQ(e.key(), "gear_pair.module");
  EXPECT_EQ(e.line(), line_of("gears/m6z30.toml", "module = "));
  EXPECT_NE(e.rule().find("unknown unit 'parsec'"), std::string::npos) << e.rule();
}

TEST_F(BadInput, WrongDimension) {
  edit("gears/m6z30.toml", "face_width = \"80 mm\"", "face_width = \"80 MPa\"");
  EXPECT_NE(load_error().rule().find("expected a length"), std::string::npos);
}

TEST_F(BadInput, WrongType) {
  edit("gears/m6z30.toml", "teeth = 30", "teeth = \"thirty\"");  // the first one: the pinion
  const auto e = load_error();
  EXPECT_EQ(e.key(), "pinion.teeth");
  EXPECT_EQ(e.rule(), "expected an integer");
}

TEST_F(BadInput, MissingKey) {
  edit("gears/m6z30.toml", "face_width = \"80 mm\"", "");
  const auto e = load_error();
  EXPECT_EQ(e.key(), "gear_pair.face_width");
  EXPECT_NE(e.rule().find("missing required key"), std::string::npos);
  EXPECT_EQ(e.line(), line_of("gears/m6z30.toml", "[gear_pair]"));  // points at the table
}

TEST_F(BadInput, MisspeltKeyIsUnknown) {
  edit("gears/m6z30.toml", "mu = 0.1", "mu = 0.1\nmue = 0.2");
  const auto e = load_error();
  EXPECT_EQ(e.key(), "friction.mue");
  EXPECT_NE(e.rule().find("unknown key"), std::string::npos);
}

TEST_F(BadInput, UnknownModelAndConstantOutOfRange) {
  edit("gears/m6z30.toml", "model = \"continuous\"", "model = \"greenwood\"");
  EXPECT_NE(load_error().rule().find("known: hertz"), std::string::npos);
}

TEST_F(BadInput, ModelConstantOutOfRange) {
  edit("gears/m6z30.toml", "# [asperity.constants.continuous]\n# plastic_scale = 3.27",
       "[asperity.constants.continuous]\nplastic_exponent = 0.1");
  const auto e = load_error();
  EXPECT_EQ(e.key(), "asperity.constants.continuous.plastic_exponent");
  EXPECT_NE(e.rule().find("must lie in [0.2"), std::string::npos) << e.rule();
}

TEST_F(BadInput, ModelConstantOverrideIsApplied) {
  edit("gears/m6z30.toml", "# [asperity.constants.continuous]\n# plastic_scale = 3.27",
       "[asperity.constants.continuous]\nplastic_scale = 5.0");
  const Case c = io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml"));
  EXPECT_DOUBLE_EQ(asperity::make_case_model(c, "continuous")->constant("plastic_scale"), 5.0);
  EXPECT_DOUBLE_EQ(asperity::make_case_model(c, "continuous")->constant("area_scale"),
                   asperity::fitted::continuous_area_scale);
}

TEST_F(BadInput, TomlSyntaxError) {
  edit("gears/m6z30.toml", "mu = 0.1", "mu = = 0.1");
  const auto e = load_error();
  EXPECT_EQ(e.line(), line_of("gears/m6z30.toml", "mu = = 0.1"));
  EXPECT_NE(e.rule().find("TOML syntax error"), std::string::npos);
}

TEST_F(BadInput, FlowCurveMustStartAtYield) {
  edit("materials/steel-45.toml", "stress = [\"418 MPa\"", "stress = [\"450 MPa\"");
  const auto e = load_error();
  EXPECT_EQ(e.key(), "flow_curve.stress");
  EXPECT_NE(e.rule().find("yield_strength"), std::string::npos);
}

TEST_F(BadInput, GreenCylinderConstantByName) {
  edit("gears/m6z30.toml", "yield_constant = 1.64", "yield_constant = \"green-2005\"");
  const Case c = io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml"));
  EXPECT_NEAR(c.asperity.cylinder_yield_constant, 1.795, 5e-4);  // Green 2005 at nu = 0.3, 4 digits
}

namespace {
// Replaces the whole line containing `needle` in the scratch case.
void replace_line(const std::filesystem::path& file, const std::string& needle, const std::string& with) {
  std::string text = read(file);
  const auto pos = text.find(needle);
  ASSERT_NE(pos, std::string::npos) << needle;
  const auto begin = text.rfind('\n', pos) + 1, end = text.find('\n', pos);
  text.replace(begin, end - begin, with);
  std::ofstream(file) << text;
}
}  // namespace

TEST_F(BadInput, MeasuredFlanksGiveTheirSummitStatistics) {
  // Both flanks named by generated topography files: the case takes the summit statistics of the
  // cleaned surfaces (the same pipeline as `geartrib surface stats`), exactly.
  surface::SelfAffineSpec spec;
  spec.nx = spec.ny = 96;
  spec.seed = 5;
  io::write_topography(dir_ / "gears/pinion.h5", surface::self_affine_surface(spec));
  spec.seed = 6;
  io::write_topography(dir_ / "gears/wheel.csv", surface::self_affine_surface(spec));
  const auto toml = dir_ / "gears/m6z30.toml";
  replace_line(toml, "summit_radius = \"1.65 um\"", "");
  replace_line(toml, "ra = \"0.8 um\"", "topography = { file = \"pinion.h5\", form = 1, outliers = 5.0 }");
  replace_line(toml, "summit_radius = \"1.75 um\"", "summit_radius = \"2 um\"");
  replace_line(toml, "ra = \"0.8 um\"", "topography = { file = \"wheel.csv\", fill = true }");
  const Case c = io::prepare_case(io::load_case(toml));
  ASSERT_TRUE(c.pinion.flank.measured.has_value());
  surface::HeightGrid g = io::read_topography(dir_ / "gears/pinion.h5");
  surface::CleanupOptions o;
  o.form_degree = 1;
  o.outlier_limit = 5.0;
  surface::clean_surface(g, o);
  const surface::SurfaceStatistics s = surface::surface_statistics(g);
  EXPECT_EQ(c.pinion.flank.roughness.form, surface::FlankRoughness::Form::summits);
  EXPECT_DOUBLE_EQ(c.pinion.flank.roughness.summit_density, s.summit_density);
  EXPECT_DOUBLE_EQ(c.pinion.flank.roughness.summit_sigma, s.summit_sigma);
  EXPECT_DOUBLE_EQ(c.pinion.flank.roughness.summit_radius, s.summit_radius);
  EXPECT_DOUBLE_EQ(c.wheel.flank.roughness.summit_radius, 2e-6);  // the case's radius overrides the measured one
  EXPECT_EQ(c.wheel.flank.topography->file, "wheel.csv");
}

// A measured pinion beside a wheel given by Ra: refused at the wheel's flank, at the line of the
// form it was given in (its Ra), not at the case file without a line.
TEST_F(BadInput, MixedRoughnessFormsLocatedAtTheWheelsFlank) {
  surface::SelfAffineSpec spec;
  spec.nx = spec.ny = 96;
  io::write_topography(dir_ / "gears/pinion.h5", surface::self_affine_surface(spec));
  const auto toml = dir_ / "gears/m6z30.toml";
  replace_line(toml, "summit_radius = \"1.65 um\"", "");
  replace_line(toml, "ra = \"0.8 um\"", "topography = { file = \"pinion.h5\" }");
  const io::InputError e = load_error();
  EXPECT_EQ(e.key(), "wheel.flank");
  EXPECT_NE(std::string(e.what()).find("same form"), std::string::npos) << e.what();
  EXPECT_NE(e.file().find("m6z30.toml"), std::string::npos) << e.what();
  EXPECT_EQ(e.line(), line_of("gears/m6z30.toml", "ra = \"0.8 um\"")) << e.what();
}

TEST(CaseFile, MeasuredPatchSynthesisKeys) {
  // The shipped measured case synthesises both flanks (psd, seeds 1 and 1001, the default length):
  // the loader keeps each patch's profile spectrum along x, that of the cleaned surface (every line).
  const auto path = test::source_dir() / "gears/m6z30-measured.toml";
  const Case c = io::prepare_case(io::load_case(path));
  ASSERT_TRUE(c.pinion.flank.topography.has_value());
  const surface::TopographySpec& t = *c.pinion.flank.topography;
  EXPECT_EQ(t.synthesis, surface::SynthesisMethod::psd);
  EXPECT_EQ(t.synthesis_seed, 1u);
  EXPECT_EQ(c.wheel.flank.topography->synthesis_seed, 1001u);
  EXPECT_EQ(t.synthesis_length, 0.0);
  EXPECT_TRUE(t.profile_along_x);
  ASSERT_TRUE(c.pinion.flank.patch_spectrum.has_value());
  surface::HeightGrid g = io::read_topography(test::source_dir() / "gears/surfaces/pinion-flank.h5");
  surface::clean_surface(g, t.clean);
  const surface::ProfileSpectrum want = surface::profile_spectrum(g, true);
  const surface::ProfileSpectrum& got = *c.pinion.flank.patch_spectrum;
  EXPECT_EQ(got.lines, 384u);
  EXPECT_EQ(got.points, 384u);
  EXPECT_EQ(got.spacing, 0.25e-6);
  EXPECT_EQ(got.psd, want.psd);
  EXPECT_EQ(got.heights, want.heights);
  // Changed on the command line; none keeps no spectrum (a case without the keys loads as before).
  const Case d = io::prepare_case(io::load_case(path, {{"pinion.flank.topography.synthesis", "iaaft"},
                                                       {"pinion.flank.topography.synthesis_length", "12 mm"},
                                                       {"wheel.flank.topography.synthesis", "none"}}));
  EXPECT_EQ(d.pinion.flank.topography->synthesis, surface::SynthesisMethod::iaaft);
  EXPECT_DOUBLE_EQ(d.pinion.flank.topography->synthesis_length, 12e-3);
  EXPECT_FALSE(d.wheel.flank.patch_spectrum.has_value());
  // The same seed on both flanks is warned about at the wheel's key (the same phases), not refused.
  const Case e = io::prepare_case(
      io::load_case(path, {{"contact.fidelity", "deterministic"}, {"wheel.flank.topography.synthesis_seed", "1"}}));
  bool warned = false;
  for (const auto& w : e.warnings)
    warned = warned || w.find("wheel.flank.topography.synthesis_seed") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST_F(BadInput, MeasuredFlankErrorsNameTheFile) {
  const auto toml = dir_ / "gears/m6z30.toml";
  replace_line(toml, "ra = \"0.8 um\"", "topography = { file = \"missing.xyz\" }");
  const io::InputError e = load_error();
  EXPECT_EQ(e.key(), "pinion.flank.topography.file");
  EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  // Two forms at once are refused.
  std::ofstream(dir_ / "gears/bad.txt") << "# spacing: 1 um\n1 2 3\n4 x 6\n";
  replace_line(toml, "topography = { file = \"missing.xyz\" }", "ra = \"0.8 um\"\ntopography = { file = \"bad.txt\" }");
  EXPECT_NE(std::string(load_error().what()).find("exactly one form"), std::string::npos);
  // A malformed surface: the error names the surface file and its line.
  replace_line(toml, "ra = \"0.8 um\"", "");
  const io::InputError bad = load_error();
  EXPECT_NE(bad.file().find("bad.txt"), std::string::npos) << bad.what();
  EXPECT_EQ(bad.line(), 3);
}

// The parameter table: a kinematics-only case needs no friction, flank roughness or cylinder
// radius; a run (the mesh cycle's parts, the default) requires the friction but not the cylinder
// radius it never uses; the cylinder studies (all parts) require it, at the key that is missing.
TEST_F(BadInput, PartsRequireOnlyTheKeysTheyUse) {
  edit("gears/m6z30.toml", "[friction]\nmu = 0.1", "[friction]");
  edit("gears/m6z30.toml", "tip_radius = \"6.6 um\"", "");
  const Case c = io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml", {}, io::kGeometryPart | io::kRoughnessPart));
  EXPECT_EQ(c.friction_coefficient, 0.0);
  EXPECT_EQ(c.asperity.cylinder_tip_radius, 0.0);
  const io::InputError e = load_error();
  EXPECT_EQ(e.key(), "friction.mu");
  EXPECT_NE(e.rule().find("missing required key"), std::string::npos) << e.rule();
  EXPECT_EQ(io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml", {{"mu", "0.1"}})).asperity.cylinder_tip_radius,
            0.0);
  try {
    io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml", {{"mu", "0.1"}}, io::kAllParts));
    ADD_FAILURE() << "no InputError for the cylinder radius";
  } catch (const io::InputError& ce) {
    EXPECT_EQ(ce.key(), "asperity.cylinder.tip_radius");
  }
}

// What ran is what the case records: every key with its value in SI and its origin.
TEST(CaseParameters, RecordsEveryKeyWithItsOrigin) {
  const Case c = io::prepare_case(
      io::load_case(test::source_dir() / "gears/m6z30.toml", {{"module", "5mm"}, {"positions", "21"}}));
  auto find = [&](const std::string& key) -> const ResolvedParameter& {
    for (const auto& p : c.parameters)
      if (p.key == key) return p;
    static const ResolvedParameter none;
    ADD_FAILURE() << key << " not recorded";
    return none;
  };
  EXPECT_EQ(find("gear_pair.module").value, "0.005 m");
  EXPECT_EQ(find("gear_pair.module").origin.text(), "--set");
  EXPECT_EQ(find("contact.positions").value, "21");
  EXPECT_EQ(find("gear_pair.face_width").value, "0.08 m");
  EXPECT_NE(find("gear_pair.face_width").origin.text().find("m6z30.toml:"), std::string::npos);
  EXPECT_EQ(find("gear_pair.center_distance").origin.text(), "default");
  EXPECT_EQ(find("pinion.teeth").value, "30");
  EXPECT_EQ(c.gear_pair.module, 5e-3);
  EXPECT_EQ(c.contact.positions, 21);
}

// Every row is complete, each key is declared once, each alias names declared keys, and each
// default lies in its own range (the table is the only place these are stated).
TEST(CaseParameters, TableIsConsistent) {
  const Case defaults;
  std::set<std::string> keys;
  for (const io::Parameter& p : io::case_parameters()) {
    EXPECT_TRUE(keys.insert(p.key).second) << p.key << " declared twice";
    EXPECT_FALSE(p.meaning.empty()) << p.key;
    EXPECT_TRUE(p.get && p.set) << p.key;
    const bool numeric = p.kind == io::ParameterKind::quantity || p.kind == io::ParameterKind::number ||
                         p.kind == io::ParameterKind::integer;
    if (numeric && p.has_default && p.required_by == 0) {
      EXPECT_TRUE(p.in_range(p.get(defaults, 0).number)) << p.key << " default outside " << p.range_text();
    }
    for (const auto& v : p.ladder) EXPECT_EQ(io::parameter_text_error(p, v), "") << p.key << " ladder " << v;
  }
  for (const io::CaseAlias& a : io::case_aliases())
    for (const auto& k : a.keys) EXPECT_NE(io::find_parameter(k).parameter, nullptr) << a.name << " -> " << k;
  // The physics option structs' ranges are the table's (declared once, with the struct).
  EXPECT_EQ(io::find_parameter("contact.strip_points").parameter->min, contact::StripOptions::kMinStripPoints);
  EXPECT_EQ(io::find_parameter("contact.height_points").parameter->min,
            contact::GreenwoodWilliamsonOptions::kMinHeightPoints);
  EXPECT_EQ(io::find_parameter("wheel.teeth").gear, 1);
  // Sweep values are checked against the row: unit, kind, choices and range.
  const io::Parameter& module = *io::find_parameter("gear_pair.module").parameter;
  EXPECT_EQ(io::parameter_text_error(module, "4mm"), "");
  EXPECT_NE(io::parameter_text_error(module, "4 GPa"), "");
  EXPECT_NE(io::parameter_text_error(module, "-4mm"), "");
  EXPECT_NE(io::parameter_text_error(*io::find_parameter("contact.fidelity").parameter, "fine"), "");
  EXPECT_NE(io::parameter_text_error(*io::find_parameter("contact.positions").parameter, "2.5"), "");
}

// The fidelity registry names case keys (those a run reads, the trade tool's knobs, the key whose
// ladder gives a family's settings): each must be a declared key, with a ladder where the trade
// tool runs one, and every registered name a choice of contact.fidelity.
TEST(CaseParameters, EveryFidelityNamesDeclaredKeys) {
  const io::Parameter* fidelity = io::find_parameter("contact.fidelity").parameter;
  ASSERT_NE(fidelity, nullptr);
  ASSERT_FALSE(contact::fidelities().empty());
  for (const contact::FidelityEntry& f : contact::fidelities()) {
    EXPECT_NE(std::find(fidelity->choices.begin(), fidelity->choices.end(), std::string(f.name)),
              fidelity->choices.end())
        << f.name;
    for (std::string_view key : f.traits.keys)
      EXPECT_NE(io::find_parameter(key).parameter, nullptr) << f.name << ": key " << key;
    for (const contact::TradeKnob& k : f.traits.knobs) {
      if (k.key.empty()) continue;  // one of the trade tool's own knobs
      const io::Parameter* p = io::find_parameter(k.key).parameter;
      ASSERT_NE(p, nullptr) << f.name << ": knob " << k.name << " key " << k.key;
      EXPECT_FALSE(p->ladder.empty()) << f.name << ": knob " << k.name << " has no ladder";
    }
    if (!f.traits.setting_key.empty()) {
      const io::Parameter* p = io::find_parameter(f.traits.setting_key).parameter;
      ASSERT_NE(p, nullptr) << f.name << ": setting key " << f.traits.setting_key;
      EXPECT_FALSE(p->ladder.empty()) << f.name << ": setting key without a ladder";
    }
  }
}

// The case's defaults (case/case.hpp, what a case file gets) and the physics option structs'
// defaults (what a library caller gets) must agree: the contact resolutions are the physics'
// option structs held whole in ContactSettings, the dynamics' are one struct.
TEST(CaseParameters, CaseDefaultsAreThePhysicsDefaults) {
  const Case c;
  const contact::StripOptions strip;
  const contact::GreenwoodWilliamsonOptions gw;
  EXPECT_EQ(c.contact.strip.strip_points, strip.strip_points);
  EXPECT_EQ(c.contact.strip.coupled_nodes, strip.coupled_nodes);
  EXPECT_EQ(c.contact.greenwood_williamson.height_points, gw.height_points);
  EXPECT_EQ(c.contact.greenwood_williamson.table_points_per_sigma, gw.table_points_per_sigma);
  const gear::DynamicsSettings dyn;
  EXPECT_EQ(c.dynamics.damping_ratio, dyn.damping_ratio);
  EXPECT_EQ(c.dynamics.tolerances.relative, dyn.tolerances.relative);
}

// --- Fuzz findings 04, 08, 11 (tests/corpus/): values and files that must end in a located error.

namespace {
// The InputError a load with these changes throws (a failed expectation when none).
io::InputError change_error(const std::vector<io::CaseChange>& changes) {
  try {
    io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", changes));
  } catch (const io::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return io::InputError("", 0, "", "", "");
}
const std::vector<io::CaseChange> kSolidBodies{{"pinion.bore_diameter", "0"}, {"wheel.bore_diameter", "0"}};
std::vector<io::CaseChange> solid(std::vector<io::CaseChange> more) {
  more.insert(more.begin(), kSolidBodies.begin(), kSolidBodies.end());
  return more;
}
bool warned(const Case& c, const std::string& key) {
  for (const auto& w : c.warnings)
    if (w.find("key '" + key + "'") != std::string::npos && w.find("plausible") != std::string::npos) return true;
  return false;
}
}  // namespace

// A TOML integer beyond 2^53 is not a double: refused at its line and key (was bad_optional_access).
TEST_F(BadInput, IntegerBeyondTwoToThe53IsRefusedAtItsKey) {
  edit("gears/m6z30.toml", "face_width = \"80 mm\"", "face_width = 9007199254740993");
  io::InputError e = load_error();
  EXPECT_EQ(e.key(), "gear_pair.face_width");
  EXPECT_EQ(e.line(), line_of("gears/m6z30.toml", "face_width ="));
  EXPECT_NE(e.rule().find("2^53"), std::string::npos) << e.rule();
  // 2^53 itself is exact: read, then refused by the range (10 m) rather than by the reader.
  edit("gears/m6z30.toml", "face_width = 9007199254740993", "face_width = 9007199254740992");
  e = load_error();
  EXPECT_EQ(e.key(), "gear_pair.face_width");
  EXPECT_NE(e.rule().find("must lie in"), std::string::npos) << e.rule();
  edit("gears/m6z30.toml", "face_width = 9007199254740992", "face_width = -9007199254740993");
  EXPECT_NE(load_error().rule().find("2^53"), std::string::npos);
  // In a material file and in an array.
  edit("gears/m6z30.toml", "face_width = -9007199254740993", "face_width = \"80 mm\"");
  edit("materials/steel-45.toml", "plastic_strain = [0.0,", "plastic_strain = [9007199254740993,");
  e = load_error();
  EXPECT_EQ(e.key(), "flow_curve.plastic_strain[0]");
  EXPECT_NE(e.rule().find("2^53"), std::string::npos) << e.rule();
}

// Integers are range-checked as read, before the member's int takes them: no wrap to 30 or 2.
TEST(CaseLimits, IntegersAreRangeCheckedBeforeNarrowing) {
  io::InputError e = change_error({{"teeth", "4294967326"}});  // 2^32 + 30
  EXPECT_EQ(e.key(), "pinion.teeth");
  EXPECT_NE(e.file().find("--set"), std::string::npos) << e.what();
  EXPECT_NE(e.rule().find("[5, 1000]"), std::string::npos) << e.rule();
  EXPECT_EQ(change_error(solid({{"teeth", "1001"}})).key(), "pinion.teeth");
  EXPECT_EQ(io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", solid({{"teeth", "1000"}})))
                .gear_pair.teeth[1],
            1000);
  // A later change of the same key does not hide a value out of range (--set ... --positions 11).
  e = change_error({{"contact.positions", "4294967298"}, {"positions", "11"}});
  EXPECT_EQ(e.key(), "contact.positions");
  EXPECT_NE(e.rule().find("100000"), std::string::npos) << e.rule();
  EXPECT_EQ(change_error({{"positions", "100001"}}).key(), "contact.positions");
  EXPECT_EQ(io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", {{"positions", "100000"}}))
                .contact.positions,
            100000);
}

// Finiteness after the unit: "1e308 GPa" is inf in SI; and each quantity's range holds in SI.
TEST_F(BadInput, InfiniteAfterTheUnitIsRefused) {
  edit("materials/steel-45.toml", "youngs_modulus = \"206 GPa\"", "youngs_modulus = \"1e308 GPa\"");
  const io::InputError e = load_error();
  EXPECT_NE(e.file().find("steel-45.toml"), std::string::npos);
  EXPECT_EQ(e.key(), "youngs_modulus");
  EXPECT_NE(e.rule().find("finite"), std::string::npos) << e.rule();
  edit("materials/steel-45.toml", "\"1e308 GPa\"", "\"1e4 GPa\"");  // 1e13 Pa: at the limit
  EXPECT_NO_THROW(io::prepare_case(io::load_case(dir_ / "gears/m6z30.toml")));
  edit("materials/steel-45.toml", "\"1e4 GPa\"", "\"1.0001e4 GPa\"");
  EXPECT_NE(load_error().rule().find("must lie in"), std::string::npos);
}

TEST(CaseLimits, QuantitiesAreRangeCheckedInSi) {
  io::InputError e = change_error({{"speed", "1e308rpm"}});  // finite in rad/s, far beyond the range
  EXPECT_EQ(e.key(), "operating.pinion_speed");
  EXPECT_NE(e.rule().find("must lie in"), std::string::npos) << e.rule();
  EXPECT_EQ(change_error({{"torque", "1e11Nm"}}).key(), "operating.pinion_torque");
  EXPECT_EQ(change_error({{"module", "1e300m"}}).key(), "gear_pair.module");
  EXPECT_EQ(change_error({{"ra", "0.8e300 um"}}).key(), "pinion.flank.ra");
  EXPECT_EQ(change_error({{"module", "9007199254740993"}}).key(), "gear_pair.module");
  // The limit itself is accepted and warned about; one past it is refused.
  const Case at = io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", solid({{"module", "10 m"}})));
  EXPECT_EQ(at.gear_pair.module, 10.0);
  EXPECT_TRUE(warned(at, "gear_pair.module"));
  EXPECT_EQ(change_error(solid({{"module", "10.0001 m"}})).key(), "gear_pair.module");
  EXPECT_EQ(io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", {{"torque", "1e10 N m"}}))
                .operating.pinion_torque,
            1e10);
  EXPECT_EQ(change_error({{"torque", "1.0001e10 N m"}}).key(), "operating.pinion_torque");
}

// A gear value inside its range but outside the plausible band is read and warned about, naming the key.
TEST(CaseLimits, ImplausibleGearValuesAreWarned) {
  const auto path = test::source_dir() / "gears/m6z30.toml";
  EXPECT_TRUE(io::prepare_case(io::load_case(path)).warnings.empty());
  const Case c =
      io::prepare_case(io::load_case(path, solid({{"module", "6 m"}, {"torque", "1e8 N m"}, {"speed", "1e6 rpm"}})));
  EXPECT_TRUE(warned(c, "gear_pair.module"));
  EXPECT_TRUE(warned(c, "operating.pinion_torque"));
  EXPECT_TRUE(warned(c, "operating.pinion_speed"));
  for (const auto& w : c.warnings) EXPECT_NE(w.find("--set"), std::string::npos) << w;
  // The band's edge is plausible, one past it is not.
  EXPECT_FALSE(warned(io::prepare_case(io::load_case(path, {{"torque", "1e7 N m"}})), "operating.pinion_torque"));
  EXPECT_TRUE(warned(io::prepare_case(io::load_case(path, {{"torque", "1.0001e7 N m"}})), "operating.pinion_torque"));
  EXPECT_FALSE(warned(io::prepare_case(io::load_case(path, {{"ra", "25 um"}})), "pinion.flank.ra"));
  EXPECT_TRUE(warned(io::prepare_case(io::load_case(path, {{"ra", "26 um"}})), "pinion.flank.ra"));
}

// A bare number is SI: one that is implausible (or out of range) as SI but plausible in another
// unit of its dimension is refused at its key, saying how it was read and what was probably
// meant, before any geometry built from it can blame another key. With its unit the SI value is
// read (and warned about).
TEST(CaseLimits, BareNumbersAUnitWouldMakePlausibleAreRefused) {
  const auto path = test::source_dir() / "gears/m6z30.toml";
  io::InputError e = change_error({{"module", "4.5"}});
  EXPECT_EQ(e.key(), "gear_pair.module");
  EXPECT_NE(e.rule().find("read as 4.5 m (a bare number is SI), above the plausible band"), std::string::npos)
      << e.rule();
  EXPECT_NE(e.rule().find("did you mean \"4.5 mm\"? Give the unit (\"4.5 m\" if that is meant)"), std::string::npos)
      << e.rule();
  EXPECT_TRUE(warned(io::prepare_case(io::load_case(path, solid({{"module", "4.5 m"}}))), "gear_pair.module"));
  // Out of range as SI: the unit probably meant (no "if that is meant": it would be refused).
  e = change_error({{"pressure_angle", "20"}});
  EXPECT_EQ(e.key(), "gear_pair.pressure_angle");
  EXPECT_NE(e.rule().find("read as 20 rad (a bare number is SI), outside the range (0 rad, 0.785398 rad): did "
                          "you mean \"20 deg\"? Give the unit"),
            std::string::npos)
      << e.rule();
  EXPECT_EQ(e.rule().find("if that is meant"), std::string::npos) << e.rule();
  // Every unit that fits, once each (um and µm are one).
  e = change_error({{"summit_radius", "5"}});
  EXPECT_NE(e.rule().find("did you mean \"5 mm\" or \"5 um\"?"), std::string::npos) << e.rule();
  // A bare number plausible as SI is read; one no unit makes plausible is warned about, as before.
  EXPECT_TRUE(io::prepare_case(io::load_case(path, {{"module", "0.006"}})).warnings.empty());
  const Case heavy = io::prepare_case(io::load_case(path, {{"torque", "1e8"}}));  // 1e8 kN m would be out of range
  EXPECT_TRUE(warned(heavy, "operating.pinion_torque"));
  // A sweep axis is checked the same way before any point runs.
  const io::Parameter& module = *io::find_parameter("gear_pair.module").parameter;
  EXPECT_NE(io::parameter_text_error(module, "4").find("did you mean \"4 mm\"?"), std::string::npos);
  EXPECT_EQ(io::parameter_text_error(module, "4 m"), "");
  EXPECT_EQ(io::parameter_text_error(module, "0.004"), "");
}

// A --set list may be typed without TOML's quotes: [real_area, plastic_fraction] is the array of
// those strings (each item a TOML value when it is one); quoted, the same. A string where the
// list is expected says how to write one.
TEST(CaseParameters, SetListsTakeBareWords) {
  const auto path = test::source_dir() / "gears/m6z30.toml";
  for (const char* typed : {"[real_area, plastic_fraction]", "[\"real_area\", \"plastic_fraction\"]",
                            " [ real_area ,plastic_fraction ] ", "[real_area, \"plastic_fraction\"]"}) {
    const Case c = io::prepare_case(io::load_case(path, {{"contact.outputs", typed}}));
    EXPECT_TRUE(c.contact.real_area) << typed;
    EXPECT_TRUE(c.contact.plastic_fraction) << typed;
    EXPECT_FALSE(c.contact.asperity_stress) << typed;
  }
  io::InputError e = change_error({{"contact.outputs", "[real_area, nope]"}});
  EXPECT_EQ(e.key(), "contact.outputs");
  EXPECT_NE(e.rule().find("unknown entry 'nope'"), std::string::npos) << e.rule();
  e = change_error({{"contact.outputs", "real_area"}});
  EXPECT_NE(e.rule().find("expected an array of strings, written [\"a\", \"b\"] in a case file; --set takes the "
                          "same or bare words: KEY=[a, b]"),
            std::string::npos)
      << e.rule();
  // An empty item is no list: the text stays a string, refused as above.
  EXPECT_NE(change_error({{"contact.outputs", "[real_area,,plastic_fraction]"}}).rule().find("expected an array"),
            std::string::npos);
}

// An impossible pair built from an implausible geometry value is refused at that value, naming
// the geometry's own complaint after it (was: only the centre distance was blamed).
TEST(CaseLimits, ImplausibleGeometryIsBlamedBeforeThePairItGives) {
  const auto fzg = test::source_dir() / "validation/fzg-type-c/fzg-c.toml";
  try {
    io::prepare_case(io::load_case(fzg, {{"module", "4.5 m"}}));
    ADD_FAILURE() << "no InputError";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "gear_pair.module");
    EXPECT_NE(e.rule().find("above the plausible band"), std::string::npos) << e.rule();
    EXPECT_NE(e.rule().find("the pair it gives cannot exist: centre distance too small"), std::string::npos)
        << e.rule();
    EXPECT_NE(e.rule().find("(key 'gear_pair.center_distance')"), std::string::npos) << e.rule();
  }
  // A plausible module with an impossible centre distance still blames the centre distance.
  try {
    io::prepare_case(io::load_case(fzg, {{"center_distance", "80 mm"}}));
    ADD_FAILURE() << "no InputError";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "gear_pair.center_distance");
  }
}

// A vanishing bore (NaN fillet-foundation stiffness) is refused at the bore; 1/50 of the root
// diameter is the smallest bore accepted.
TEST(CaseLimits, TinyBoreIsRefusedAtTheBore) {
  const auto path = test::source_dir() / "gears/m6z30.toml";
  io::InputError e = change_error({{"pinion.bore_diameter", "60e-300 mm"}});
  EXPECT_EQ(e.key(), "pinion.bore_diameter");
  EXPECT_NE(e.rule().find("1/50"), std::string::npos) << e.rule();
  const Case c = io::prepare_case(io::load_case(path));
  const double root_diameter = c.gear_pair.module * (c.gear_pair.teeth[0] - 2.0 * c.gear_pair.dedendum_coefficient);
  const std::string at = fmt::format("{:.17g} m", root_diameter / 50.0 * (1.0 + 1e-12));
  const std::string past = fmt::format("{:.17g} m", root_diameter / 50.0 * (1.0 - 1e-9));
  EXPECT_NO_THROW(io::prepare_case(io::load_case(path, {{"pinion.bore_diameter", at}})));
  EXPECT_EQ(change_error({{"pinion.bore_diameter", past}}).key(), "pinion.bore_diameter");
}

// A material path must be a regular file of at most 1 MiB, checked before reading (was: /dev/zero
// read forever; a long name escaped as filesystem_error).
TEST_F(BadInput, MaterialPathMustBeABoundedRegularFile) {
  const auto toml = dir_ / "gears/m6z30.toml";
  auto material_error = [&](const std::string& path) {
    try {
      io::prepare_case(io::load_case(toml, {{"pinion.material", path}}));
    } catch (const io::InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for " << path;
    return io::InputError("", 0, "", "", "");
  };
  io::InputError e = material_error("/dev/zero");
  EXPECT_EQ(e.key(), "pinion.material");
  EXPECT_NE(e.rule().find("not a regular file"), std::string::npos) << e.rule();
  EXPECT_NE(material_error(std::string(300, 'x')).rule().find("too long"), std::string::npos);
  EXPECT_NE(material_error("../materials").rule().find("folder"), std::string::npos);
  EXPECT_NE(material_error("../materials/none.toml").rule().find("not found"), std::string::npos);
  // 1 MiB accepted, one byte more refused.
  std::string text = read(dir_ / "materials/steel-45.toml") + "\n#";
  text += std::string(io::kMaxTomlFileBytes - text.size(), 'x');
  std::ofstream(dir_ / "materials/big.toml") << text;
  ASSERT_EQ(std::filesystem::file_size(dir_ / "materials/big.toml"), io::kMaxTomlFileBytes);
  EXPECT_NO_THROW(io::prepare_case(io::load_case(toml, {{"pinion.material", "../materials/big.toml"}})));
  std::ofstream(dir_ / "materials/big.toml", std::ios::app) << 'x';
  e = material_error("../materials/big.toml");
  EXPECT_EQ(e.key(), "pinion.material");
  EXPECT_NE(e.rule().find("1 MiB"), std::string::npos) << e.rule();
  // The case file itself.
  EXPECT_THROW(io::prepare_case(io::load_case("/dev/zero")), io::InputError);
}

// Profile modifications: a negative amount, a relief across the active flank, both starts given,
// and a modification under a sharing that ignores it are refused at their key and line.
TEST_F(BadInput, ProfileModificationsRefusedAtTheirKeyAndLine) {
  const std::string sharing = "load_sharing = \"iso\"";
  edit("gears/m6z30.toml", sharing, "load_sharing = \"compatibility\"");
  const std::string case_file = "gears/m6z30.toml";
  auto with_relief = [&](const std::string& body) {
    std::ofstream(dir_ / case_file, std::ios::app) << "\n[pinion.tip_relief]\n" << body;
  };
  with_relief("amount = \"-5 um\"\nlength = \"4 mm\"\n");
  io::InputError e = load_error();
  EXPECT_EQ(e.key(), "pinion.tip_relief.amount");
  EXPECT_EQ(e.line(), line_of(case_file, "amount = \"-5 um\""));
  EXPECT_EQ(e.value(), "\"-5 um\"");
  SetUp();
  edit(case_file, sharing, "load_sharing = \"compatibility\"");
  with_relief("amount = \"5 um\"\nlength = \"30 mm\"\n");  // the active flank: 29 mm of roll
  e = load_error();
  EXPECT_EQ(e.key(), "pinion.tip_relief.length");
  EXPECT_EQ(e.line(), line_of(case_file, "length = \"30 mm\""));
  EXPECT_NE(e.rule().find("longer than the active flank"), std::string::npos) << e.rule();
  SetUp();
  edit(case_file, sharing, "load_sharing = \"compatibility\"");
  with_relief("amount = \"5 um\"\nlength = \"4 mm\"\nstart_diameter = \"190 mm\"\n");
  e = load_error();
  EXPECT_EQ(e.key(), "pinion.tip_relief.length");
  EXPECT_NE(e.rule().find("not both"), std::string::npos) << e.rule();
  SetUp();
  with_relief("amount = \"5 um\"\nlength = \"4 mm\"\n");  // under ISO sharing
  e = load_error();
  EXPECT_EQ(e.key(), "pinion.tip_relief.amount");
  EXPECT_NE(e.rule().find("compatibility"), std::string::npos) << e.rule();
  SetUp();
  edit(case_file, sharing, "load_sharing = \"compatibility\"");
  with_relief("amount = \"5 um\"\nstart_diameter = \"200 mm\"\n");  // beyond the 192 mm tip
  e = load_error();
  EXPECT_EQ(e.key(), "pinion.tip_relief.start_diameter");
  EXPECT_NE(e.rule().find("off the flank"), std::string::npos) << e.rule();
}

TEST_F(BadInput, RatingDataRefusedAtTheirKeyAndLine) {
  // An unknown ISO 6336-5 quality in the material file.
  edit("materials/steel-45.toml", "quality = \"MQ\"", "quality = \"MX\"");
  io::InputError e = load_error();
  EXPECT_EQ(e.key(), "rating.quality");
  EXPECT_EQ(e.line(), line_of("materials/steel-45.toml", "quality = \"MX\""));
  EXPECT_NE(e.file().find("steel-45.toml"), std::string::npos) << e.file();
  EXPECT_NE(e.rule().find("MX"), std::string::npos) << e.rule();
  // An FZG stage outside 1..14 in the lubricant file.
  SetUp();
  edit("lubricants/mineral-vg220.toml", "fzg_scuffing_stage = 12", "fzg_scuffing_stage = 15");
  e = load_error();
  EXPECT_EQ(e.key(), "fzg_scuffing_stage");
  EXPECT_EQ(e.line(), line_of("lubricants/mineral-vg220.toml", "fzg_scuffing_stage = 15"));
  EXPECT_NE(e.rule().find("[1, 14]"), std::string::npos) << e.rule();
  // A K factor below 1 in the case.
  SetUp();
  edit("gears/m6z30.toml", "application_factor = 1.0", "application_factor = 0.8");
  e = load_error();
  EXPECT_EQ(e.key(), "rating.application_factor");
  EXPECT_EQ(e.line(), line_of("gears/m6z30.toml", "application_factor = 0.8"));
  EXPECT_EQ(e.value(), "0.8");
  SetUp();
  std::ofstream(dir_ / "gears/m6z30.toml", std::ios::app) << "\n";
  edit("gears/m6z30.toml", "accuracy_grade = 6", "accuracy_grade = 6\nface_load_factor = 0.9");
  e = load_error();
  EXPECT_EQ(e.key(), "rating.face_load_factor");
  EXPECT_NE(e.rule().find("[1, 10]"), std::string::npos) << e.rule();
}
