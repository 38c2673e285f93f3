#include "io/units.hpp"

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
