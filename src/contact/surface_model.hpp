// The statistical model of a pair of rough flanks: the equivalent surface (seed section 4) and
// its Greenwood-Williamson pressure-separation table, built once for the path. The statistical
// fidelities solve their strips on it, the lubricated cycle shares the load with its asperities,
// and the deterministic fidelity builds one from its flanks' profiles to run beside it.
#pragma once

#include "asperity/model.hpp"
#include "contact/contact_options.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/persson_contact.hpp"
#include "lubrication/film_closure.hpp"
#include "material/material.hpp"
#include "surface/flank_spec.hpp"
#include "surface/rough_surface.hpp"

#include <array>
#include <stdexcept>
#include <string>

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

// The flanks' composite power spectrum for Persson's theory (contact/persson_contact.hpp), as
// lubrication.persson_spectrum asks:
//  - flanks: each flank's own spectrum, the two added (independent surfaces):
//    - a measured areal topography (its cleaned patch kept: FlankSpec::patch): the radial average of
//      the patch's areal spectrum (surface::radial_spectrum), a tabulated part holding the patch's
//      variance and full 2-D gradient variance. It holds what the patch resolves: no wavelength longer
//      than the patch (its mirror's half periods aside), none shorter than two of its spacings;
//      Persson's u and plastic share rest on its short-wavelength end, the instrument's resolution, as
//      the summit model's summits do. An anisotropic patch enters through its full gradient, as
//      Persson's isotropic theory takes one;
//    - a generated ground profile ([*.flank.profile] kind = "ground"): its Gaussian spectrum, exact for
//      an isotropic surface with the profile's correlation in every direction (the areal fidelity's
//      isotropic lay). A lay-directed ground flank is not isotropic: Persson's isotropic theory takes
//      it through this equivalent.
//    Where either flank has neither (given by Ra, Rq, summits or moments, or a profile trace), the pair
//    is fitted as below: one flank's own spectrum is not added to a fit, the fit being to the
//    composite moments that already hold that flank (fell_back says so);
//  - moments, or flanks without their own: the self-affine spectrum from q = 0 (H = kFittedSpectrumHurst,
//    stated) whose profile moments are the statistical model's, McCool's relations inverted on its
//    equivalent surface: m0 = sigma^2, m4 = 0.375^2 pi/beta^2, m2 = m4/(6 pi sqrt 3 eta). Flanks given
//    by Ra or Rq take it as assumed as the summits' eta sigma_s beta (bandwidth 6.93 at 0.05);
//    std::invalid_argument where the bandwidth is at most 2 (eta sigma_s beta below 0.0214), which no
//    such spectrum has (measured summits can lie there: gears/m6z30-measured.toml's do).
// A measured patch whose spectrum cannot be taken (too few points, a missing point, no power) throws
// MeasuredSpectrumError naming the flank.
enum class SpectrumSource { generated, measured, fitted };
const char* spectrum_source_name(SpectrumSource s);  // "generated", "measured", "fitted"
struct FlankSpectrum {
  RoughnessSpectrum spectrum;  // fitted: one part; else the pinion's part, then the wheel's
  std::array<SpectrumSource, 2> source = {SpectrumSource::fitted, SpectrumSource::fitted};  // pinion, wheel
  bool fell_back = false;  // flanks asked for, one flank alone had its own: the pair fitted instead
  // A measured flank's wavelengths its patch resolves [m]: two of its (coarser) spacings to its (longer)
  // side; 0 for the others.
  std::array<double, 2> shortest = {0.0, 0.0}, longest = {0.0, 0.0};
  // "measured", "generated", "fitted", or "measured/generated" (the pinion's, then the wheel's).
  std::string sources() const;
};
struct MeasuredSpectrumError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
FlankSpectrum flank_spectrum(const std::array<const surface::FlankSpec*, 2>& specs, const surface::EquivalentSurface& s,
                             lubrication::PerssonSpectrum choice = lubrication::PerssonSpectrum::flanks);
// Whether a flank has a spectrum of its own (a measured areal patch, or a generated ground profile):
// what flank_spectrum's `flanks` takes for it.
bool has_own_spectrum(const surface::FlankSpec& f);

}  // namespace geartrib::contact
