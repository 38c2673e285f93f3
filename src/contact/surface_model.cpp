#include "contact/surface_model.hpp"

#include "asperity/contact_pair.hpp"

#include <cmath>
#include <numbers>

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

FlankSpectrum flank_spectrum(const std::array<const surface::FlankSpec*, 2>& specs,
                             const surface::EquivalentSurface& s) {
  FlankSpectrum out;
  const auto ground = [](const surface::FlankSpec* f) {
    return f && f->profile && f->profile->kind == surface::ProfileKind::ground;
  };
  if (ground(specs[0]) && ground(specs[1])) {
    for (const surface::FlankSpec* f : specs)
      out.spectrum.parts.push_back(SpectrumPart::gaussian(f->profile->rq, f->profile->correlation_length));
    out.generated = true;
    return out;
  }
  if (!(s.summit_density > 0.0 && s.summit_radius > 0.0 && s.surface_sigma > 0.0))
    throw std::invalid_argument(
        "the flanks' spectrum needs a rough equivalent surface (summit density, radius, sigma)");
  // McCool (1986) inverted: eta = m4/(6 pi sqrt 3 m2), beta = 0.375 sqrt(pi/m4).
  const double m4 = 0.375 * 0.375 * std::numbers::pi / (s.summit_radius * s.summit_radius);
  const double m2 = m4 / (6.0 * std::numbers::pi * std::numbers::sqrt3 * s.summit_density);
  out.spectrum.parts.push_back(fit_self_affine_spectrum(s.surface_sigma * s.surface_sigma, m2, m4));
  return out;
}

}  // namespace geartrib::contact
