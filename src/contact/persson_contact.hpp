// Persson's theory of rough contact (Persson 2001, J. Chem. Phys. 115:3840; 2006, Surf. Sci. Rep.
// 61:201): the contact pressure's distribution P(sigma) spreads by diffusion as the magnification
// takes in shorter wavelengths, dP/dG = d^2P/dsigma^2 with G = (pi/4) E*^2 integral q^3 C(q) dq =
// E*^2 h'_rms^2/8 at full magnification, from a delta at the mean pressure. A point whose pressure
// reaches 0 leaves the contact (P(0) = 0); elastic-perfectly-plastic, one reaching the hardness H
// yields (P(H) = 0) and carries H from then on.
//
// Here E* is the composite plane-strain modulus (1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2) and h'_rms
// the rms gradient over the whole 2-D composite surface (sqrt 2 times an isotropic surface's profile
// slope), so that V = 2G = E*^2 h'_rms^2/4 is the variance of the complete contact's pressure.
//
// Holds: a Gaussian, isotropic surface (an anisotropic one through its full gradient, as Persson's
// own extension does to first order), any contact fraction (the theory is exact at complete contact
// and grows less so towards vanishing contact, where it underestimates the area by 25-30 % against
// exact numerics: kappa = sqrt(8/pi) = 1.60 against about 2.0-2.4), any ratio of H to E* h'_rms.
// Xu et al.'s (2024) correction of the elastic theory, fitted to GFMD data, is offered beside it.
#pragma once

namespace geartrib::contact {

// The elastic theory's contact fraction, A/A0 = erf(sqrt 2 pbar/(E* h'_rms)) (Persson 2001).
// pbar [Pa] >= 0, E* [Pa] > 0, h'_rms [1] >= 0 (0: a flat surface, complete contact).
double persson_elastic_area(double pbar, double e_star, double rms_gradient);

// Xu, Zhu, Xiao & Zhou (2024, Tribol. Lett., doi:10.1007/s11249-024-01838-4): the full-contact
// variance scaled by gamma + (1 - gamma) A, A = erf(pbar/sqrt(2 (gamma + (1 - gamma) A) V)), solved
// for A (a fixed point, monotone); gamma = 0.45 as fitted there to GFMD for H = 0.8. Small loads:
// kappa = sqrt(8/(pi gamma)) = 2.38.
inline constexpr double kXuGamma = 0.45;
double persson_corrected_area(double pbar, double e_star, double rms_gradient, double gamma = kXuGamma);

// Elastic-perfectly-plastic: the fractions of the nominal area in elastic contact and yielded.
struct PerssonAreas {
  double elastic = 0.0;  // A_el/A0
  double plastic = 0.0;  // A_pl/A0, carrying H
  double contact() const { return elastic + plastic; }
  // The mean pressure over the elastic contact [Pa] (pbar - H A_pl)/A_el, 0 without elastic contact.
  double elastic_mean_pressure(double pbar, double hardness) const;
};
// P on (0, H) with both ends absorbing: by images of the free Gaussian when sqrt(2G) is small beside
// H, by the sine series (Persson 2006 section 6) otherwise; the two agree to 1e-12 where they meet.
// pbar in [0, H); H = inf gives the elastic theory.
PerssonAreas persson_elastic_plastic(double pbar, double e_star, double rms_gradient, double hardness);

// The same by each form alone, for their test: r = pbar/H, g_y = G/H^2; n_terms of the series, or
// images k = -n_images..n_images.
PerssonAreas persson_elastic_plastic_series(double r, double g_y, int n_terms);
PerssonAreas persson_elastic_plastic_images(double r, double g_y, int n_images);

// Persson's theory across a Hertz strip (the uncoupled strip: the nominal pressure imposed,
// p(x) = p0 sqrt(1 - x^2/b^2)): the real area over 2b, the share of it yielded and the mean real
// pressure, by Gauss-Legendre in x = b sin(theta) (the elliptic profile's square root taken out).
// rms_gradient: the composite surface's full gradient (an isotropic one's sqrt 2 times its profile
// slope; a lay-directed one's, the slope across the lay).
struct PerssonStrip {
  double real_area_ratio = 0.0;        // real area / 2b
  double plastic_area_fraction = 0.0;  // of the real area
  double mean_real_pressure = 0.0;     // [Pa]
};
PerssonStrip persson_hertz_strip(double p0, double e_star, double rms_gradient, double hardness);

}  // namespace geartrib::contact
