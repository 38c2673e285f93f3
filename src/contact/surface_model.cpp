#include "contact/surface_model.hpp"

#include "asperity/contact_pair.hpp"
#include "core/named_choices.hpp"
#include "surface/areal_synthesis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

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

namespace {
constexpr NamedChoice<SpectrumSource> kSpectrumSources[] = {{SpectrumSource::generated, "generated"},
                                                            {SpectrumSource::measured, "measured"},
                                                            {SpectrumSource::fitted, "fitted"}};
}  // namespace

const char* spectrum_source_name(SpectrumSource s) {
  return choice_name(std::span<const NamedChoice<SpectrumSource>>(kSpectrumSources), s);
}

bool has_own_spectrum(const surface::FlankSpec& f) {
  return f.patch || (f.profile && f.profile->kind == surface::ProfileKind::ground);
}

std::string FlankSpectrum::sources() const {
  return source[0] == source[1] ? spectrum_source_name(source[0])
                                : std::string(spectrum_source_name(source[0])) + "/" + spectrum_source_name(source[1]);
}

namespace {

// A flank's own spectrum: its measured patch's radial average (Persson's convention: the tabulated
// part's), or its generated ground profile's Gaussian; none for the others.
struct OwnSpectrum {
  SpectrumPart part;
  SpectrumSource source = SpectrumSource::generated;
  double shortest = 0.0, longest = 0.0;  // a patch's resolved wavelengths [m]
};
std::optional<OwnSpectrum> own_spectrum(const surface::FlankSpec* f, const char* gear) {
  if (!f || !has_own_spectrum(*f)) return std::nullopt;
  if (const auto& g = f->patch) {
    try {
      const surface::RadialSpectrum r = surface::radial_spectrum(surface::areal_spectrum(*g));
      return OwnSpectrum{SpectrumPart::tabulated(r.q, r.c), SpectrumSource::measured, 2.0 * std::max(g->dx, g->dy),
                         std::max(g->nx * g->dx, g->ny * g->dy)};
    } catch (const std::invalid_argument& e) {
      throw MeasuredSpectrumError(fmt::format("the {}'s measured topography: {}", gear, e.what()));
    }
  }
  return OwnSpectrum{SpectrumPart::gaussian(f->profile->rq, f->profile->correlation_length)};  // a ground profile
}

}  // namespace

FlankSpectrum flank_spectrum(const std::array<const surface::FlankSpec*, 2>& specs, const surface::EquivalentSurface& s,
                             lubrication::PerssonSpectrum choice) {
  FlankSpectrum out;
  if (choice == lubrication::PerssonSpectrum::flanks) {
    const auto pinion = own_spectrum(specs[0], "pinion"), wheel = own_spectrum(specs[1], "wheel");
    if (pinion && wheel) {
      out.spectrum.parts = {pinion->part, wheel->part};
      out.source = {pinion->source, wheel->source};
      out.shortest = {pinion->shortest, wheel->shortest};
      out.longest = {pinion->longest, wheel->longest};
      return out;
    }
    out.fell_back = pinion || wheel;
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
