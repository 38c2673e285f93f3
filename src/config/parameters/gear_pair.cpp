// The gear pair's keys, declared beside gear::GearPairSpec (gear/spur_pair.hpp) and the bodies' GearSpec.
#include "config/parameters/declare.hpp"

#include "gear/spur_pair.hpp"

namespace geartrib::io::parameters {

// [gear_pair]: basic rack and centre distance; [pinion], [wheel]: teeth, body, material.
void declare_gear_pair(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  using K = ParameterKind;
  auto gear = gear_of;
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
      .field("gear_pair.teeth[{gear}]")
      .doc("Number of teeth z");
  add(number(
          "{gear}.profile_shift", [](auto& c, int g) -> auto& { return c.gear_pair.profile_shift[g]; }))
      .range(-2.0, 2.0)
      .gear_alias("x1", "x2")
      .field("gear_pair.profile_shift[{gear}]")
      .doc("Profile shift coefficient x");
  add(quantity(
          "{gear}.tip_diameter", D::length, [](auto& c, int g) -> auto& { return c.gear_pair.tip_diameter[g]; }))
      .range(0.0, kMaxBodyLength)
      .field("gear_pair.tip_diameter[{gear}]")
      .doc("Tip diameter d_a; 0: from addendum, shift and tip shortening");
  add(quantity(
          "{gear}.bore_diameter", D::length, [](auto& c, int g) -> auto& { return c.gear_pair.bore_diameter[g]; }))
      .range(0.0, kMaxBodyLength)
      .field("gear_pair.bore_diameter[{gear}]")
      .doc(
          "Bore of the gear body: the shaft seat of its fillet-foundation stiffness (fitted for r_f/r_bore 1.4 to 7); "
          "0: a solid body, seated at a third of the root diameter (r_f/r_bore = 3)");
  add(text(
          "{gear}.material", K::text, [gear](auto& c, int g) -> auto& { return gear(c, g).material_file; }))
      .required(kGeometryPart)
      .alias({"material"})
      .field("{gear}.material_file")
      .doc("Material file (materials/*.toml), relative to the case file");
}

}  // namespace geartrib::io::parameters
