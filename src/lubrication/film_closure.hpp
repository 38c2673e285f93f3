// The film's datum in mixed lubrication: which gap between the rough flanks the film's thickness
// is, and the bearing area of their heights. Heights are the composite surface's (the two flanks'
// heights summed), zero mean, standard deviation sigma = sqrt(Rq1^2 + Rq2^2); h is the
// separation of the two flanks' mean planes of heights [m].
#pragma once

#include "core/named_choices.hpp"
#include "surface/rough_surface.hpp"

#include <span>
#include <string>
#include <vector>

namespace geartrib::lubrication {

// What the Johnson-Greenwood-Poon film thickness is set equal to at the asperities' separation h:
//  - mean_gap (default): the mean gap E[(h - z)+] between the rough surfaces, the volume of oil
//    per nominal area (Patir & Cheng, J. Lubr. Technol. 100 (1978) 12-17, their average gap h_T).
//    Positive at every separation, it reaches the dry contact without a shift;
//  - mean_plane: the separation of the mean planes h itself (JGP 1972's own choice);
//  - dry_offset: h less the dry contact's separation where that is negative (geartrib 0.1's
//    device, kept for comparison; no physical basis).
enum class FilmGap { mean_gap, mean_plane, dry_offset };
std::span<const NamedChoice<FilmGap>> film_gap_choices();  // lubrication.film_gap
const char* film_gap_name(FilmGap g);

// The asperities' pressure in the film's load sharing (contact/asperity_pressure.hpp):
//  - automatic (auto, default): the bearing-area model's weight w rises from 0 to 1 as the asperity
//    model's own plastic area fraction under the whole load (at the strip's centre, its smallest
//    along the path) rises from 0.9 to 0.99, the bound above which the run's regime verdict calls
//    the flanks fully plastic: the asperity model where it holds, the bearing area where every
//    contact flows, linear between (continuous across a sweep);
//  - asperity_model: w = 0; bearing_area: w = 1;
//  - persson: Persson's interfacial separation law (contact/persson_contact.hpp) in place of the asperity
//    model: the film's thickness is the mean gap u between the deformed flanks at which they carry the
//    asperities' pressure, p = p_P(u) (elastic), so film_gap must be mean_gap; the bearing area blended
//    in as for auto, the plastic area fraction Persson's own (elastic-plastic, Persson 2001) under the
//    whole load at the lightest position.
enum class AsperityPressureModel { automatic, asperity_model, bearing_area, persson };
std::span<const NamedChoice<AsperityPressureModel>> asperity_pressure_model_choices();  // lubrication.asperity_pressure
const char* asperity_pressure_model_name(AsperityPressureModel m);

// The power spectrum Persson's law takes (contact::flank_spectrum):
//  - flanks (default): each flank's own, the two added (independent surfaces): a measured areal
//    topography's radial average (surface::radial_spectrum: the PSD the patch resolves), a generated
//    ground profile's Gaussian. Where a flank has neither (given by Ra, Rq, summits or moments, or a
//    profile trace), the pair's spectrum is the moments' fit below;
//  - moments: the self-affine spectrum fitted to the statistical model's moments (its summits through
//    McCool's relations), whatever the flanks are: for comparison.
enum class PerssonSpectrum { flanks, moments };
std::span<const NamedChoice<PerssonSpectrum>> persson_spectrum_choices();  // lubrication.persson_spectrum
const char* persson_spectrum_name(PerssonSpectrum s);

struct CompositeHeights {
  double sigma = 0.0;  // [m]
  surface::HeightDistribution distribution = surface::HeightDistribution::gaussian;
};

// Mean gap E[(h - z)+] [m]. Gaussian: sigma (t Phi(t) + phi(t)), t = h/sigma. Exponential
// (z = X - sigma, X ~ Exp(mean sigma)): c - sigma + sigma e^(-c/sigma) for c = h + sigma >= 0, else 0.
// Increasing in h, > 0 (Gaussian), -> h for h >> sigma. sigma = 0: max(h, 0).
double mean_gap(const CompositeHeights& heights, double h);
// Its inverse: the separation h at which the mean gap is g > 0 [m] (sigma = 0: g).
double mean_gap_height(const CompositeHeights& heights, double g);
// Bearing-area fraction P(z > h) (Abbott & Firestone, Mech. Eng. 55 (1933) 569-572): the share
// of the nominal area a plane at h cuts through material. Gaussian: Phi(-h/sigma); exponential:
// e^(-(h + sigma)/sigma) above -sigma, 1 below.
double bearing_area_fraction(const CompositeHeights& heights, double h);
// The inverse of bearing_area_fraction: the h at which a fraction a in (0, 1) bears.
double bearing_area_height(const CompositeHeights& heights, double a);

// The gap the film fills at the asperities' mean-plane separation h; h_dry is the dry contact's
// separation (dry_offset only).
double film_gap(FilmGap g, const CompositeHeights& heights, double h, double h_dry);

}  // namespace geartrib::lubrication
