#include "case/contact_setup.hpp"

#include <algorithm>

namespace geartrib::contact {

surface::EquivalentSurface case_equivalent_surface(const Case& c) {
  return surface::equivalent_surface(c.pinion.flank.roughness, c.wheel.flank.roughness, c.roughness.distribution,
                                     c.roughness.eta_sigma_beta);
}

GreenwoodWilliamsonOptions greenwood_williamson_options(const Case& c) {
  GreenwoodWilliamsonOptions o;
  o.height_points = c.contact.height_points;
  o.table_points_per_sigma = c.contact.table_points;
  o.plastic = c.contact.plastic_fraction;
  return o;
}

StripOptions strip_options(const Case& c) {
  const ContactSettings& cs = c.contact;
  StripOptions o;
  o.fidelity = cs.coupled() ? StripFidelity::coupled : StripFidelity::uncoupled;
  o.strip_points = cs.strip_points;
  o.lookup = cs.exact_strip_lookup ? StripLookup::exact : StripLookup::cubic;
  o.coupled_nodes = cs.coupled_nodes;
  return o;
}

DeterministicOptions deterministic_options(const Case& c) {
  const ContactSettings& cs = c.contact;
  const Material& m1 = c.pinion.material;
  const Material& m2 = c.wheel.material;
  DeterministicOptions o;
  o.element_size = cs.element_size;
  o.strip_halfwidths = cs.strip_halfwidths;
  o.pressure_cap = std::min(m1.hardness, m2.hardness);
  o.poisson_ratio = m1.hardness <= m2.hardness ? m1.poisson_ratio : m2.poisson_ratio;
  o.pinion_plastic_share = m1.hardness < 0.99 * m2.hardness ? 1.0 : m2.hardness < 0.99 * m1.hardness ? 0.0 : 0.5;
  o.subsurface_stress = cs.asperity_stress;
  o.plastic_overlap = c.running_in.tolerance;
  return o;
}

}  // namespace geartrib::contact
