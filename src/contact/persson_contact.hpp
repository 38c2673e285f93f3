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
//
// The interfacial separation (Persson 2007, Phys. Rev. Lett. 99:125502; Yang & Persson 2008, J. Phys.:
// Condens. Matter 20:215214): the mean gap u between the deformed surfaces at the nominal pressure p,
// from the surface's power spectrum C(q) (below). Elastic; the same surfaces as above.
#pragma once

#include <vector>

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

// One isotropic power spectral density C(q) [m^4] of a surface's heights, in Persson's convention
// <h^2> = integral C(q) d^2q = 2 pi integral q C(q) dq (Persson et al. 2005, J. Phys.: Condens. Matter
// 17:R1, eq. 1):
//  - gaussian: C = rq^2 lambda^2/(4 pi) exp(-q^2 lambda^2/4), the exact PSD of an isotropic surface
//    whose autocorrelation is rq^2 exp(-r^2/lambda^2) (a generated ground flank's correlation taken in
//    every direction: surface/flank_profile.hpp, surface::gaussian_surface);
//  - self_affine: C0 on [q_l, q_r), C0 (q/q_r)^(-2(1 + H)) on [q_r, q_1], 0 elsewhere (a roll-off at
//    q_r, Hurst exponent H in (0, 1): surface::self_affine_surface's spectrum), C0 set by rq;
//  - tabulated: C_k at nodes q_k (a measured patch's radial average, surface::radial_spectrum), between
//    neighbours the power law through them, C_k (q/q_k)^s_k with s_k = ln(C_k+1/C_k)/ln(q_k+1/q_k)
//    (log-log linear; a segment with a zero end is zero), 0 outside [q_0, q_N]; rq the table's own.
struct SpectrumPart {
  enum class Shape { gaussian, self_affine, tabulated };
  Shape shape = Shape::gaussian;
  double rq = 0.0;                  // [m]
  double correlation_length = 0.0;  // lambda [m] (gaussian)
  double lower = 0.0;               // q_l [1/m] (self_affine; 0: the plateau reaches q = 0)
  double rolloff = 0.0;             // q_r [1/m] (self_affine)
  double cutoff = 0.0;              // q_1 [1/m] (self_affine)
  double hurst = 0.8;               // H (self_affine)
  std::vector<double> nodes;        // q_k [1/m] (tabulated): at least two, positive, increasing
  std::vector<double> values;       // C(q_k) [m^4] (tabulated): >= 0, one per node
  static SpectrumPart gaussian(double rq, double correlation_length);
  static SpectrumPart self_affine(double rq, double rolloff, double cutoff, double hurst, double lower = 0.0);
  static SpectrumPart tabulated(std::vector<double> nodes, std::vector<double> values);  // rq from the table
  void validate() const;  // std::invalid_argument naming the rule
  double psd(double q) const;
  // integral_0^q q'^n C(q') dq' for n = 1, 3, 5 [m^(3 - n)], closed forms (q = inf: the whole; tabulated:
  // segment by segment, core::power_law_integral).
  double moment(int n, double q) const;
};

// A composite surface's spectrum: the sum of its parts' (two independent flanks' spectra add).
struct RoughnessSpectrum {
  std::vector<SpectrumPart> parts;
  double psd(double q) const;            // [m^4]
  double moment(int n, double q) const;  // summed, as SpectrumPart::moment
  double rms_height() const;             // sqrt(2 pi M1(inf)) [m]
  double rms_gradient() const;           // h'_rms = sqrt(2 pi M3(inf)): the full 2-D gradient [1]
  // McCool's (1986) profile moments of the isotropic surface (any straight line through it; Nayak
  // 1971): m0 = 2 pi M1, m2 = pi M3, m4 = (3 pi/4) M5 [m^2, 1, 1/m^2].
  double profile_m0() const;
  double profile_m2() const;
  double profile_m4() const;
};

// The self-affine spectrum (q_l = 0) whose profile moments are m0, m2, m4 at a stated Hurst
// exponent: its bandwidth m0 m4/m2^2 (2 for the plateau alone, growing as q_1/q_r grows) fixes
// q_1/q_r, then m2/m0 q_r and m0 rq. A bandwidth below 2 has no such spectrum:
// std::invalid_argument saying so.
inline constexpr double kFittedSpectrumHurst = 0.8;
SpectrumPart fit_self_affine_spectrum(double m0, double m2, double m4, double hurst = kFittedSpectrumHurst);

// Persson's interfacial separation, the mean gap between a rigid rough surface and an elastic flat
// pressed on it (Persson 2007, eqs. 4-6; Yang & Persson 2008, eq. 2; Almqvist, Campana, Prodanov &
// Persson 2011, J. Mech. Phys. Solids 59:2355, eq. 5):
//   u(p) = sqrt(pi) integral q^2 C(q) w(q) integral_p^inf (1/p') [gamma + 3 (1 - gamma) P(q, p')^2]
//          exp(-(w(q) p'/E*)^2) dp' dq,
//   w(q) = (pi integral_0^q q'^3 C(q') dq')^(-1/2),   P(q, p') = erf(w(q) p'/E*),
// from -dU_el/du = p A0 and the elastic energy U_el/A0 = (pi/2) E* integral q^2 C P [gamma + (1 -
// gamma) P^2] dq. gamma: the elastic energy stored in a partly touching wavelength, fitted to
// numerical contact; Yang & Persson fit 0.4-0.45; 0.42 as Afferrante et al. (2018, Tribol. Lett.
// 66:75) and Xu et al. (2024; their repository PerssonModelFudgeFactor, Persson_LE_SE_YP08.m) take it.
// Small p: u = u0 ln(beta E*/p), u0 = gamma sqrt(pi) integral q^2 C w dq, i.e. p = beta E*
// exp(-u/u0) (Persson 2007 eq. 7); large p: u -> 0 as exp(-2 p^2/(E* h'_rms)^2) (complete contact).
// Holds where the area theory holds (a Gaussian, isotropic surface; elastic), and for the mean gap
// better than for the area: within a few percent of boundary elements at moderate loads (Almqvist et
// al. 2011; measured here against areal::solve_contact, tests/test_persson_separation.cpp).
inline constexpr double kPerssonSeparationGamma = 0.42;
class PerssonSeparation {
 public:
  // e_star: the composite plane-strain modulus [Pa]. Throws std::invalid_argument on an empty or
  // invalid spectrum.
  PerssonSeparation(const RoughnessSpectrum& spectrum, double e_star, double gamma = kPerssonSeparationGamma);
  // u [m] at the nominal pressure p [Pa] >= 0: decreasing, inf at p = 0, -> 0 as p -> inf.
  double separation(double p) const;
  // Its inverse: p [Pa] at u [m] > 0 (0 as u -> inf, inf at u <= 0).
  double pressure(double u) const;
  double decay_length() const { return u0_; }  // u0 [m]
  double prefactor() const { return beta_; }   // beta [1]
  double modulus() const { return e_star_; }   // E* [Pa]
  double rms_gradient() const { return rms_gradient_; }
  double rms_height() const { return rms_height_; }

 private:
  // -du/ds at s = ln(p/E*): sqrt(pi) integral q^2 C w [gamma + 3 (1 - gamma) P^2] exp(-(w p/E*)^2) dq [m].
  double slope(double s) const;
  // u where every wavelength is near complete contact (w p/E* >= 6 at every node: erf = 1 to 2e-17):
  // ((3 - 2 gamma)/2) sqrt(pi) integral q^2 C w E1((w p/E*)^2) dq.
  double near_complete(double s) const;
  double e_star_, gamma_, rms_gradient_, rms_height_;
  std::vector<double> w_, weight_;  // the q quadrature's nodes: w(q_i), and weight_i sqrt(pi) q_i^2 C(q_i) w(q_i) [m]
  // ln u and d(ln u)/ds on s_k = top_ - k step_ (k = 0..n): cubic Hermite between, the asymptotes beyond.
  double top_ = 0.0, step_ = 0.0;
  std::vector<double> log_u_, log_slope_;
  double u0_ = 0.0, beta_ = 0.0;
};

}  // namespace geartrib::contact
