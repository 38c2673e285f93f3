#include "case/contact_setup.hpp"

namespace geartrib::contact {

surface::EquivalentSurface case_equivalent_surface(const Case& c) {
  return surface::equivalent_surface(c.pinion.flank.roughness, c.wheel.flank.roughness, c.roughness.distribution,
                                     c.roughness.eta_sigma_beta);
}

GreenwoodWilliamsonOptions greenwood_williamson_options(const Case& c) {
  return greenwood_williamson_options(c.contact);
}

StripOptions strip_options(const Case& c) {
  return strip_options(
      c.contact, c.contact.fidelity == ContactFidelity::coupled ? StripFidelity::coupled : StripFidelity::uncoupled);
}

DeterministicOptions deterministic_options(const Case& c) {
  return deterministic_options(c.contact, c.running_in, c.pinion.material, c.wheel.material);
}

}  // namespace geartrib::contact
