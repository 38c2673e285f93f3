#include "case/contact_setup.hpp"

namespace geartrib::contact {

surface::EquivalentSurface case_equivalent_surface(const Case& c) {
  return surface::equivalent_surface(c.pinion.flank.roughness, c.wheel.flank.roughness, c.roughness.distribution,
                                     c.roughness.eta_sigma_beta);
}

}  // namespace geartrib::contact
