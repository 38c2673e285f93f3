// The mesh's and its dynamics' keys, declared beside gear::MeshSettings and gear::DynamicsSettings.
#include "config/parameters/declare.hpp"

#include "gear/gear_mesh.hpp"
#include "gear/load_sharing.hpp"
#include "gear/mesh_dynamics.hpp"
#include "gear/tooth_contact.hpp"

namespace geartrib::io::parameters {

// [mesh]: load sharing, positions, tooth beam, dynamics; [dynamics].
void declare_mesh(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  // [mesh]
  add(named_choice(
          "mesh.load_sharing", gear::load_sharing_choices(), "value",
          [](auto& c, int) -> auto& { return c.mesh.load_sharing; }))
      .alias({"load_sharing"})
      .doc(
          "Load sharing between tooth pairs: ISO/TS 6336-22 method B, the pairs' stiffnesses, or load-deflection "
          "compatibility with the profile modifications (static transmission error)");
  add(named_choice(
          "mesh.hertz_approach", gear::hertz_approach_choices(), "value",
          [](auto& c, int) -> auto& { return c.mesh.hertz_approach; }))
      .doc(
          "Hertzian approach of a loaded pair under compatibility sharing: Weber & Banaschek 1953, Palmgren 1959 "
          "(steel rollers) or the stiffness model's constant (linear)");
  // {gear}.tip_relief, {gear}.root_relief: ISO 21771 profile modifications (compatibility sharing).
  for (const char* end : {"tip", "root"}) {
    const bool tip = std::string(end) == "tip";
    const std::string k = std::string("{gear}.") + end + "_relief.";
    const std::string f = std::string("mesh.modification[{gear}].") + end + ".";
    auto relief = [tip](auto& c, int g) -> auto& {
      return tip ? c.mesh.modification[g].tip : c.mesh.modification[g].root;
    };
    add(quantity(
            k + "amount", D::length, [relief](auto& c, int g) -> auto& { return relief(c, g).amount; }))
        .range(0.0, 1e-3)
        .plausible(0.0, 200.0 * kUm)
        .alias({std::string(end) + "_relief"})
        .field(f + "amount")
        .doc(tip ? "Tip relief C_a at the tip circle (ISO 21771), normal to the profile; 0: none"
                 : "Root relief C_f at the root form circle (ISO 21771), normal to the profile; 0: none");
    add(named_choice(
            k + "shape", gear::relief_shape_choices(),
            "shape", [relief](auto& c, int g) -> auto& { return relief(c, g).shape; }))
        .field(f + "shape")
        .doc("Shape of the relief over its length: linear, parabolic or a circular arc tangent at its start");
    add(quantity(
            k + "start_diameter", D::length, [relief](auto& c, int g) -> auto& { return relief(c, g).start_diameter; }))
        .range(0.0, kMaxBodyLength)
        .field(f + "start_diameter")
        .doc(tip ? "Diameter d_Ca where the tip relief starts; 0: from length"
                 : "Diameter d_Cf where the root relief starts; 0: from length");
    add(quantity(
            k + "length", D::length, [relief](auto& c, int g) -> auto& { return relief(c, g).length; }))
        .range(0.0, kMaxBodyLength)
        .field(f + "length")
        .doc(tip ? "Roll length L_Ca of the tip relief, from the tip towards the root; 0: from start_diameter"
                 : "Roll length L_Cf of the root relief, from the root form circle towards the tip; 0: from "
                   "start_diameter");
  }
  add(named_choice(
          "{gear}.tip_relief.design", gear::relief_design_choices(), "design",
          [](auto& c, int g) -> auto& { return c.mesh.modification[g].tip_design; }))
      .field("mesh.modification[{gear}].tip_design")
      .doc(
          "given: the tip relief's own keys; long: ISO/TS 6336-20's C_eff = F_t/(b cos alpha_t c_gamma) at the "
          "case's load, from the point of single contact to the tip (linear)");
  add(quantity(
          "{gear}.profile_crowning", D::length,
          [](auto& c, int g) -> auto& { return c.mesh.modification[g].crowning; }))
      .range(-1e-3, 1e-3)
      .field("mesh.modification[{gear}].crowning")
      .doc("Profile crowning C_alpha at the ends of the active profile against its middle; negative: hollow");
  add(quantity(
          "{gear}.profile_slope_deviation", D::length,
          [](auto& c, int g) -> auto& { return c.mesh.modification[g].slope_deviation; }))
      .range(-1e-3, 1e-3)
      .field("mesh.modification[{gear}].slope_deviation")
      .doc("Profile slope deviation f_Halpha over the active profile (ISO 1328-1); positive: material on the tip side");
  add(quantity(
          "{gear}.base_pitch_deviation", D::length,
          [](auto& c, int g) -> auto& { return c.mesh.modification[g].base_pitch_deviation; }))
      .range(-1e-3, 1e-3)
      .field("mesh.modification[{gear}].base_pitch_deviation")
      .doc("Base pitch deviation f_pb of every tooth (ISO 1328-1); the same on all teeth");
  add(integer(
          "mesh.positions", [](auto& c, int) -> auto& { return c.mesh.positions; }))
      .range(2, 100000)
      .doc("Positions sampling one base pitch (kinematics, mesh stiffness)");
  add(mapped_choice(
          "mesh.tooth_beam", {"plane-strain", "plane-stress"},
          [](auto& c, int) -> auto& { return c.mesh.plane_strain; },
          [](const std::string& t) { return t == "plane-strain"; },
          [](bool strain) { return std::string(strain ? "plane-strain" : "plane-stress"); }))
      .field("mesh.plane_strain")
      .doc("Tooth beam of the stiffness model: plane strain (wide face) or plane stress");
  add(named_choice(
          "mesh.dynamics", gear::dynamics_engine_choices(), "value",
          [](auto& c, int) -> auto& { return c.dynamics.engine; }))
      .alias({"dynamics"})
      .field("dynamics.engine")
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
      .field("dynamics.tolerances.relative")
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
}

}  // namespace geartrib::io::parameters
