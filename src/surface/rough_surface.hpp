// Statistical description of rough flanks and their reduction to one equivalent rough surface
// against a rigid flat (Greenwood & Williamson 1966; McCool 1986; seed section 4).
#pragma once

#include <numbers>
#include <string>
#include <utility>

namespace geartrib::surface {

enum class HeightDistribution { gaussian, exponential };

// One flank's roughness, in one of three forms (SI).
struct FlankRoughness {
  enum class Form { ra, rq, summits, spectral } form = Form::ra;
  double summit_radius = 0.0;           // beta [m] (all forms but spectral, where McCool's relations give it)
  double ra = 0.0;                      // [m] (form ra)
  double rq = 0.0;                      // [m] (form rq)
  double summit_density = 0.0;          // eta [1/m^2] (form summits)
  double summit_sigma = 0.0;            // std deviation of summit heights [m] (form summits)
  double m0 = 0.0, m2 = 0.0, m4 = 0.0;  // spectral moments [m^2], [-], [1/m^2] (form spectral)
  // The heights' own Rq and Ra where a surface or profile gave the form (measured, generated) [m];
  // 0: not known beyond the form (height_roughness derives them).
  double height_rq = 0.0, height_ra = 0.0;
};

// A flank's height roughness as the film's lambda and the ISO formulas take it: the heights' own
// Rq and Ra where known (measured or generated), else from the form: Ra given (Rq = 1.2533 Ra,
// Gaussian), Rq given (Ra = Rq/1.2533), spectral (Rq = sqrt(m0)). The summit form alone has no
// height statistics: `known` is false and the caller takes the summit model's.
struct HeightRoughness {
  double rq = 0.0, ra = 0.0;  // [m]
  bool known = false;
  const char* source = "";  // "measured", "given Ra", "given Rq", "spectral moments", "summit model"
};
HeightRoughness height_roughness(const FlankRoughness& f);

// The equivalent rough surface: summits of one radius with normally (or exponentially)
// distributed heights against a flat.
struct EquivalentSurface {
  double summit_density = 0.0;      // eta [1/m^2]
  double summit_radius = 0.0;       // beta [m]
  double summit_sigma = 0.0;        // sigma_s [m]
  double surface_sigma = 0.0;       // sigma of the surface heights (composite Rq) [m]
  double summit_mean_height = 0.0;  // mean summit height above the mean plane of the surface [m]
  HeightDistribution distribution = HeightDistribution::gaussian;
  // Dimensionless GW product eta sigma_s beta.
  double eta_sigma_beta() const { return summit_density * summit_sigma * summit_radius; }
  void validate() const;  // throws std::invalid_argument
};

// Gaussian heights: Rq = sqrt(pi/2) Ra.
inline constexpr double kRqOverRaGaussian = 1.2533141373155003;

// Typical Greenwood-Williamson product for engineering surfaces (GW 1966 report 0.03 to 0.05);
// the default when a flank is given by Ra/Rq and summit radius only (an assumption).
inline constexpr double kTypicalEtaSigmaBeta = 0.05;

// McCool (1986) for an isotropic Gaussian surface of bandwidth alpha = m0 m4/m2^2:
//   eta = m4/(6 pi sqrt(3) m2), beta = 0.375 sqrt(pi/m4), sigma_s^2 = (1 - 0.8968/alpha) m0,
//   mean summit height above the mean plane 4 sqrt(m0/(pi alpha)).
// Eliminating m2 and m4 gives the bandwidth from the GW product alone:
//   alpha = (6 pi sqrt 3)^2/(0.375^2 pi) (eta sigma_s beta)^2 + 0.8968  (= 6.93 at 0.05),
// so any two of the descriptions below fix one consistent set of summit statistics.
inline constexpr double kMcCoolSummitSigmaConstant = 0.8968;
inline constexpr double kMcCoolBandwidthPerEsb2 = 768.0 * std::numbers::pi;  // (6 pi sqrt 3)^2/(0.375^2 pi) = 2412.74
double mccool_bandwidth(double eta_sigma_beta);

// Combines two flanks into one equivalent surface against a flat; every form gives the summit
// density, radius, height deviation and mean height above the mean plane from one description:
//  - ra/rq + summit radius (both flanks): sigma = sqrt(sigma1^2 + sigma2^2) (independent heights,
//    seed section 4: y_e = y_u + y_d), beta = beta1 beta2/(beta1 + beta2) (as the seed's R), and
//    the stated assumption eta sigma_s beta = eta_sigma_beta: McCool's relations at the bandwidth
//    it implies give sigma_s (0.933 sigma at 0.05) and the mean summit height (0.857 sigma).
//  - summits (eta, sigma_s, beta per flank): sigma_s = sqrt(s1^2 + s2^2), beta as above, eta the
//    mean of the densities; the bandwidth from their product gives sigma and the mean height.
//  - spectral: moments add (McCool 1986, for independent surfaces), then McCool's relations.
// Mixing forms between flanks is an error (std::invalid_argument).
EquivalentSurface equivalent_surface(const FlankRoughness& pinion, const FlankRoughness& wheel,
                                     HeightDistribution distribution, double eta_sigma_beta = kTypicalEtaSigmaBeta);

// The two flanks' summit radii consistent with the equivalent surface (their series radius is its
// beta): the given radii, or for spectral flanks each flank's McCool radius 0.375 sqrt(pi/m4_i)
// scaled so that the series radius equals the radius of the summed moments. Side contact and the
// contact pair use these, so one run uses one radius.
std::pair<double, double> flank_summit_radii(const FlankRoughness& pinion, const FlankRoughness& wheel);

// Greenwood-Williamson plasticity index psi = (E_t/H) sqrt(sigma_s/beta).
double plasticity_index(const EquivalentSurface& s, double composite_modulus, double hardness);

}  // namespace geartrib::surface
