// The mesh's and its dynamics' keys, declared beside gear::MeshSettings and gear::DynamicsSettings.
#include "config/parameters/declare.hpp"

#include "gear/gear_mesh.hpp"
#include "gear/load_sharing.hpp"
#include "gear/mesh_dynamics.hpp"

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
