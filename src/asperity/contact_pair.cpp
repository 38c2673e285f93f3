#include "asperity/contact_pair.hpp"

#include "core/series_radius.hpp"

#include <stdexcept>
#include <string>

namespace geartrib::asperity {

void ContactPair::validate() const {
  auto fail = [](const std::string& rule) { throw std::invalid_argument("contact pair: " + rule); };
  if (!(radius > 0.0)) fail("radius must be positive");
  if (!(modulus > 0.0)) fail("composite modulus must be positive");
  if (!(youngs_modulus > 0.0)) fail("Young's modulus must be positive");
  if (!(poisson_ratio > 0.0 && poisson_ratio < 0.5)) fail("Poisson's ratio must lie in (0, 0.5)");
  if (!(yield_strength > 0.0)) fail("yield strength must be positive");
  if (!(hardness >= yield_strength)) fail("hardness must be at least the yield strength");
}

ContactPair make_contact_pair(const Material& body1, const Material& body2, double tip_radius1, double tip_radius2) {
  if (!(tip_radius1 > 0.0 && tip_radius2 > 0.0)) throw std::invalid_argument("asperity tip radii must be positive");
  const Material& soft = body1.hardness <= body2.hardness ? body1 : body2;
  ContactPair p;
  p.radius = series_radius(tip_radius1, tip_radius2);
  p.modulus = composite_modulus(body1, body2);
  p.youngs_modulus = soft.youngs_modulus;
  p.poisson_ratio = soft.poisson_ratio;
  p.yield_strength = soft.yield_strength;
  p.hardness = soft.hardness;
  p.validate();
  return p;
}

ContactPair with_radius(ContactPair pair, double radius) {
  pair.radius = radius;
  pair.validate();
  return pair;
}

}  // namespace geartrib::asperity
