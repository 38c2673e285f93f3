#include "contact/surface_model.hpp"

#include "asperity/contact_pair.hpp"

namespace geartrib::contact {

surface::EquivalentSurface equivalent_surface(const StatisticalFlanks& f) {
  return surface::equivalent_surface(f.roughness[0], f.roughness[1], f.distribution, f.eta_sigma_beta);
}

namespace {

asperity::ContactPair contact_pair(const StatisticalFlanks& f) {
  return asperity::make_contact_pair(*f.materials[0], *f.materials[1], f.roughness[0].summit_radius,
                                     f.roughness[1].summit_radius);
}

// The case's table options, the plastic area tabulated when an output asks for it.
GreenwoodWilliamsonOptions table_options(const ContactSettings& cs) {
  GreenwoodWilliamsonOptions o = cs.greenwood_williamson;
  o.plastic = cs.plastic_fraction;
  return o;
}

}  // namespace

SurfaceModel::SurfaceModel(const StatisticalFlanks& f, const ContactSettings& cs, double max_pressure)
    : flanks(f),
      surface(equivalent_surface(f)),
      plasticity_index(surface::plasticity_index(surface, contact_pair(f).modulus, contact_pair(f).hardness)),
      table(surface, *f.model, contact_pair(f), 1.5 * max_pressure + 1.0, table_options(cs)) {}

}  // namespace geartrib::contact
