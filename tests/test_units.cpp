#include "config/units.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

using geartrib::io::Dimension;
using geartrib::io::parse_quantity;

TEST(Units, ConvertsTheTableToSi) {
  // Exact decimal factors: compare to 1 ulp-level relative tolerance.
  EXPECT_DOUBLE_EQ(parse_quantity("206 GPa", Dimension::pressure), 206e9);
  EXPECT_DOUBLE_EQ(parse_quantity("418 MPa", Dimension::pressure), 418e6);
  EXPECT_DOUBLE_EQ(parse_quantity("6 mm", Dimension::length), 6e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("1.65 um", Dimension::length), 1.65e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("0.068um", Dimension::length), 0.068e-6);
  EXPECT_DOUBLE_EQ(parse_quantity("1000 N m", Dimension::torque), 1000.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1000 rpm", Dimension::angular_speed), 1000.0 * 2.0 * std::numbers::pi / 60.0);
  EXPECT_DOUBLE_EQ(parse_quantity("20 deg", Dimension::angle), 20.0 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(parse_quantity("7850 kg/m^3", Dimension::density), 7850.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.513 um^2", Dimension::area), 0.513e-12);
  EXPECT_DOUBLE_EQ(parse_quantity("  2.5e-3 ", Dimension::length), 2.5e-3);  // bare number is SI
}

// A speed in revolutions per minute has four spellings: rpm, 1/min (DIN and ISO 6336), rev/min,
// r/min; all the same factor 2 pi/60, exactly.
TEST(Units, RevolutionsPerMinuteSpellings) {
  const double rpm = parse_quantity("1500 rpm", Dimension::angular_speed);
  EXPECT_DOUBLE_EQ(rpm, 1500.0 * 2.0 * std::numbers::pi / 60.0);
  for (const char* text : {"1500 1/min", "1500 rev/min", "1500 r/min", "1500rev/min", "1500r/min"})
    EXPECT_EQ(parse_quantity(text, Dimension::angular_speed), rpm) << text;
  // 1/min is a speed, not a length or a frequency of another kind; "15001/min" reads the digit
  // into the number (the space is needed), leaving the unknown unit "/min".
  EXPECT_THROW(parse_quantity("1500 1/min", Dimension::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("15001/min", Dimension::angular_speed), std::invalid_argument);
  const auto any = geartrib::io::parse_any_quantity("1500 1/min");
  ASSERT_TRUE(any.has_value());
  EXPECT_EQ(any->dimension, Dimension::angular_speed);
}

TEST(Units, RejectsUnknownUnitsWrongDimensionsAndGarbage) {
  EXPECT_THROW(parse_quantity("6 parsec", Dimension::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("6 MPa", Dimension::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("six mm", Dimension::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("", Dimension::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("6 mpa", Dimension::pressure), std::invalid_argument);  // case-sensitive
  try {
    parse_quantity("6 MPa", Dimension::length);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pressure"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mm"), std::string::npos) << "lists the allowed units: " << e.what();
  }
}

// An exponent belongs to the number, never to the unit: "5e-1" is a bare number, "5e-1 mm" half
// a millimetre, and a broken exponent is a malformed number (not "2" with a unit "e").
TEST(Units, ExponentIsPartOfTheNumber) {
  using geartrib::io::parse_any_quantity;
  EXPECT_DOUBLE_EQ(parse_quantity("5e-1", Dimension::length), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity("5e-1 mm", Dimension::length), 0.5e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("5e-1mm", Dimension::length), 0.5e-3);
  EXPECT_DOUBLE_EQ(parse_quantity("2E3 Pa", Dimension::pressure), 2000.0);
  for (const char* bad : {"2e", "2e mm", "2emm", "2e+", "2e-", "2E", "1.5.3 mm", "2e3e4", "5-3 mm"}) {
    EXPECT_THROW(parse_quantity(bad, Dimension::length), std::invalid_argument) << bad;
    EXPECT_FALSE(parse_any_quantity(bad).has_value()) << bad;
  }
  try {
    parse_quantity("2e", Dimension::length);
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).find("unknown unit"), std::string::npos) << "'e' is no unit: " << e.what();
  }
  const auto any = parse_any_quantity("5e-1mm");
  ASSERT_TRUE(any.has_value());
  EXPECT_DOUBLE_EQ(any->si, 0.5e-3);
  EXPECT_EQ(any->dimension, Dimension::length);
  const auto bare = parse_any_quantity("5e-1");
  ASSERT_TRUE(bare.has_value());
  EXPECT_EQ(bare->dimension, Dimension::dimensionless);
}

// Finiteness is checked after the unit's factor: a finite number can overflow in SI.
TEST(Units, OverflowAfterScalingIsRefused) {
  EXPECT_DOUBLE_EQ(parse_quantity("1e299 GPa", Dimension::pressure), 1e308);  // the largest decade that fits
  EXPECT_THROW(parse_quantity("1e300 GPa", Dimension::pressure), std::invalid_argument);
  EXPECT_THROW(parse_quantity("1e308 GPa", Dimension::pressure), std::invalid_argument);
  EXPECT_THROW(parse_quantity("1.7e308 kN m", Dimension::torque), std::invalid_argument);
  EXPECT_DOUBLE_EQ(parse_quantity("1.7e308 N m", Dimension::torque), 1.7e308);
  EXPECT_THROW(parse_quantity("1e400 Pa", Dimension::pressure), std::invalid_argument);  // beyond a double
  EXPECT_THROW(parse_quantity("inf Pa", Dimension::pressure), std::invalid_argument);
  EXPECT_THROW(parse_quantity("nan", Dimension::pressure), std::invalid_argument);
  EXPECT_FALSE(geartrib::io::parse_any_quantity("1e308 GPa").has_value());
}
