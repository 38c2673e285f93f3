// The asperity model's keys, declared beside asperity::AsperitySettings (asperity/asperity_settings.hpp).
#include "config/parameters/declare.hpp"

#include "asperity/model.hpp"

namespace geartrib::io::parameters {

namespace {

std::vector<std::string> model_names() {
  std::vector<std::string> out;
  for (auto n : asperity::asperity_model_names()) out.emplace_back(n);
  return out;
}

}  // namespace

// [friction]: the asperity contacts' Coulomb coefficient.
void declare_friction(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  // [friction]
  add(number(
          "friction.mu", [](auto& c, int) -> auto& { return c.friction_coefficient; }))
      .range(0.0, 1.0)
      .required(kFrictionPart)
      .alias({"mu"})
      .field("friction_coefficient")
      .doc(
          "Coulomb friction coefficient of the asperity contacts: the side contact of sliding summits (contact "
          "normal tilted by atan(mu)) and the boundary coefficient of a lubricated run");
}

// [asperity]: the model, its constants, the side contact, the cylinder asperity.
void declare_asperity(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  using K = ParameterKind;
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
      .field("asperity.measured_axis_offset")
      .doc("Measured axis offset d0 of the side contact; 0: none measured");
  add(quantity(
          "asperity.side_contact.measured_tip_gap", D::length,
          [](auto& c, int) -> auto& { return c.asperity.measured_tip_gap; }))
      .range(0.0, 1e-2)
      .field("asperity.measured_tip_gap")
      .doc("Measured tip gap y0 of the side contact; 0: none measured");
  add(quantity(
          "asperity.cylinder.tip_radius", D::length,
          [](auto& c, int) -> auto& { return c.asperity.cylinder_tip_radius; }))
      .range(1e-9, 1.0)
      .required(kCylinderPart)
      .field("asperity.cylinder_tip_radius")
      .doc(
          "Tip radius R_m of the parabolic-cylinder asperities (a hobbed flank's ridges) of the multi-asperity and "
          "FEM studies; geartrib surface asperities --cylinders measures it");
  add(number(
          "asperity.cylinder.yield_constant", [](auto& c, int) -> auto& { return c.asperity.cylinder_yield_constant; }))
      .range(0.5, 5.0, true, true)
      .choices({"green-2005"})
      .field("asperity.cylinder_yield_constant")
      .doc("C of the cylinder's critical interference, or green-2005 (Green's plane-strain C_L(nu))");
}

}  // namespace geartrib::io::parameters
