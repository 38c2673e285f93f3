#include "material/material.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

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
