// The statistical model of a pair of rough flanks: the equivalent surface (seed section 4) and
// its Greenwood-Williamson pressure-separation table, built once for the path. The statistical
// fidelities solve their strips on it, the lubricated cycle shares the load with its asperities,
// and the deterministic fidelity builds one from its flanks' profiles to run beside it.
#pragma once

#include "asperity/model.hpp"
#include "contact/contact_options.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/persson_contact.hpp"
#include "material/material.hpp"
#include "surface/flank_spec.hpp"
#include "surface/rough_surface.hpp"

#include <array>

namespace geartrib::contact {

// The flanks as the statistical model takes them (index 0 the pinion, 1 the wheel).
struct StatisticalFlanks {
  std::array<const Material*, 2> materials = {nullptr, nullptr};
  std::array<surface::FlankRoughness, 2> roughness;
  surface::HeightDistribution distribution = surface::HeightDistribution::gaussian;
  double eta_sigma_beta = surface::kTypicalEtaSigmaBeta;  // for flanks given by Ra or Rq
  const asperity::AsperityModel* model = nullptr;         // the asperity law, with the case's constants
  double friction = 0.0;  // mu of the asperities' side contact; the boundary coefficient when lubricated
};

// The equivalent rough surface of two flanks.
surface::EquivalentSurface equivalent_surface(const StatisticalFlanks& f);

// The flanks' statistical model, its table covering nominal pressures up to 1.5 max_pressure.
struct SurfaceModel {
  SurfaceModel(const StatisticalFlanks& flanks, const ContactSettings& cs, double max_pressure);
  StatisticalFlanks flanks;
  surface::EquivalentSurface surface;
  double plasticity_index = 0.0;
  GreenwoodWilliamson table;
};

// The flanks' composite power spectrum for Persson's theory (contact/persson_contact.hpp):
//  - both flanks generated ground profiles ([*.flank.profile] kind = "ground"): the sum of their
//    Gaussian spectra, exact for isotropic surfaces with the profiles' correlation in every direction
//    (the areal fidelity's isotropic lay). A lay-directed ground flank is not isotropic: Persson's
//    isotropic theory takes it through this equivalent;
//  - otherwise: the self-affine spectrum from q = 0 (H = kFittedSpectrumHurst, stated) whose profile
//    moments are the statistical model's, McCool's relations inverted on its equivalent surface:
//    m0 = sigma^2, m4 = 0.375^2 pi/beta^2, m2 = m4/(6 pi sqrt 3 eta). Flanks given by Ra or Rq take it
//    as assumed as the summits' eta sigma_s beta (bandwidth 6.93 at 0.05); std::invalid_argument where
//    the bandwidth is at most 2 (eta sigma_s beta below 0.0214), which no such spectrum has.
struct FlankSpectrum {
  RoughnessSpectrum spectrum;
  bool generated = false;  // from the ground profiles; false: fitted to the moments
};
FlankSpectrum flank_spectrum(const std::array<const surface::FlankSpec*, 2>& specs,
                             const surface::EquivalentSurface& s);

}  // namespace geartrib::contact
