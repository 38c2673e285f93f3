#include "case/asperity_setup.hpp"

#include <string>

namespace geartrib::asperity {

ContactPair contact_pair(const Case& c) {
  return make_contact_pair(c.pinion.material, c.wheel.material, c.pinion.flank.roughness.summit_radius,
                           c.wheel.flank.roughness.summit_radius);
}

std::unique_ptr<AsperityModel> make_case_model(const Case& c, std::string_view name) {
  auto model = make_asperity_model(name);
  if (const auto it = c.asperity.constants.find(std::string(name)); it != c.asperity.constants.end())
    for (const auto& [constant, value] : it->second) model->set_constant(constant, value);
  return model;
}

const Material& softer_material(const Case& c) {
  return c.pinion.material.hardness <= c.wheel.material.hardness ? c.pinion.material : c.wheel.material;
}

CylinderAsperity cylinder_asperity(const Case& c) {
  const ContactPair p = contact_pair(c);
  CylinderAsperity cyl;
  cyl.tip_radius = c.asperity.cylinder_tip_radius;
  cyl.modulus = p.modulus;
  cyl.yield_strength = p.yield_strength;
  cyl.hardness = p.hardness;
  cyl.poisson_ratio = p.poisson_ratio;
  cyl.yield_constant = c.asperity.cylinder_yield_constant;
  cyl.validate();
  return cyl;
}

}  // namespace geartrib::asperity
