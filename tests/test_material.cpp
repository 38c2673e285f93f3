#include "config/case_file.hpp"
#include "config/input_error.hpp"
#include "material/material.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace geartrib;

TEST(Material, CompositeModulusOfTwoSteelBodies) {
  const Material& m = test::seed_case().pinion.material;
  // Identity: equal bodies give E/(2(1 - nu^2)) (seed section 1).
  EXPECT_DOUBLE_EQ(composite_modulus(m, m), 206e9 / (2.0 * (1.0 - 0.09)));
  Material rigid = m;
  rigid.youngs_modulus = 1e30;  // limit: a rigid counterface leaves E/(1 - nu^2)
  EXPECT_NEAR(composite_modulus(m, rigid), 206e9 / 0.91, 1e-6 * 206e9);
}

TEST(Material, FlowStressInterpolatesTheSeedTable) {
  const Material& m = test::seed_case().pinion.material;
  EXPECT_DOUBLE_EQ(m.flow_stress(0.0), 418e6);
  EXPECT_DOUBLE_EQ(m.flow_stress(0.056), 695e6);
  EXPECT_DOUBLE_EQ(m.flow_stress(0.5), 0.5 * (921e6 + 932e6));  // midway between 0.45 and 0.55
  EXPECT_DOUBLE_EQ(m.flow_stress(5.0), 1040e6);                 // perfectly plastic beyond the table
}

TEST(Material, ValidateNamesTheRule) {
  Material m = test::seed_case().pinion.material;
  m.hardness = 0.5 * m.yield_strength;
  EXPECT_THROW(m.validate(), std::invalid_argument);
  m = test::seed_case().pinion.material;
  m.flow_curve[3].plastic_strain = m.flow_curve[2].plastic_strain;
  EXPECT_THROW(m.validate(), std::invalid_argument);
}

// Material files: values checked in SI against their ranges, and warned about outside the band
// of gear materials (naming the file, line and key).
TEST(Material, FileValuesHaveRangesAndPlausibleBands) {
  const auto dir = std::filesystem::temp_directory_path() / "geartrib-test-material-ranges";
  std::filesystem::create_directories(dir);
  const std::string base = "name = \"x\"\nsource = \"test\"\npoisson_ratio = 0.3\nyield_strength = \"418 MPa\"\n";
  auto load = [&](const std::string& more, std::vector<std::string>* warnings) {
    std::ofstream(dir / "m.toml") << base << more;
    return io::load_material(dir / "m.toml", warnings);
  };
  std::vector<std::string> w;
  load("youngs_modulus = \"206 GPa\"\ndensity = \"7850 kg/m^3\"\n", &w);
  EXPECT_TRUE(w.empty());
  load("youngs_modulus = \"2000 GPa\"\ndensity = \"7850 kg/m^3\"\n", &w);  // harder than diamond
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("m.toml:5: warning: key 'youngs_modulus'"), std::string::npos) << w[0];
  w.clear();
  load("youngs_modulus = \"206 GPa\"\ndensity = \"1e5 kg/m^3\"\n", &w);  // at the limit: read, warned
  EXPECT_EQ(w.size(), 1u);
  try {
    load("youngs_modulus = \"206 GPa\"\ndensity = \"1.0001e5 kg/m^3\"\n", nullptr);
    ADD_FAILURE() << "no InputError";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "density");
    EXPECT_EQ(e.line(), 6);
  }
  try {
    load("youngs_modulus = \"1e308 GPa\"\ndensity = \"7850 kg/m^3\"\n", nullptr);  // inf in SI
    ADD_FAILURE() << "no InputError";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "youngs_modulus");
    EXPECT_NE(e.rule().find("finite"), std::string::npos) << e.rule();
  }
  std::filesystem::remove_all(dir);
}
