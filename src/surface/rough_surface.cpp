#include "surface/rough_surface.hpp"

#include "core/series_radius.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::surface {

void EquivalentSurface::validate() const {
  auto fail = [](const std::string& rule) { throw std::invalid_argument("equivalent rough surface: " + rule); };
  if (!(summit_density > 0.0 && std::isfinite(summit_density))) fail("summit density must be positive");
  if (!(summit_radius > 0.0)) fail("summit radius must be positive");
  if (!(summit_sigma > 0.0)) fail("summit height deviation must be positive");
  if (!(surface_sigma > 0.0)) fail("surface height deviation must be positive");
}

double mccool_bandwidth(double eta_sigma_beta) {
  return kMcCoolBandwidthPerEsb2 * eta_sigma_beta * eta_sigma_beta + kMcCoolSummitSigmaConstant;
}

namespace {
// McCool's summit radius of one surface from its fourth moment [m].
double mccool_summit_radius(double m4) { return 0.375 * std::sqrt(std::numbers::pi / m4); }
// Summit sigma and mean summit height of a Gaussian surface of height sigma and bandwidth alpha (McCool 1986).
void mccool_summit_heights(EquivalentSurface& s, double alpha) {
  s.summit_sigma = std::sqrt((1.0 - kMcCoolSummitSigmaConstant / alpha)) * s.surface_sigma;
  s.summit_mean_height = 4.0 * s.surface_sigma / std::sqrt(std::numbers::pi * alpha);
}
}  // namespace

std::pair<double, double> flank_summit_radii(const FlankRoughness& a, const FlankRoughness& b) {
  if (a.form != FlankRoughness::Form::spectral || b.form != FlankRoughness::Form::spectral)
    return {a.summit_radius, b.summit_radius};
  const double r1 = mccool_summit_radius(a.m4), r2 = mccool_summit_radius(b.m4);
  const double f = mccool_summit_radius(a.m4 + b.m4) / series_radius(r1, r2);
  return {f * r1, f * r2};
}

EquivalentSurface equivalent_surface(const FlankRoughness& a, const FlankRoughness& b, HeightDistribution dist,
                                     double esb) {
  using Form = FlankRoughness::Form;
  if (a.form != b.form) throw std::invalid_argument("both flanks must describe their roughness in the same form");
  EquivalentSurface s;
  s.distribution = dist;
  switch (a.form) {
    case Form::ra:
    case Form::rq: {
      const double s1 = a.form == Form::ra ? kRqOverRaGaussian * a.ra : a.rq;
      const double s2 = b.form == Form::ra ? kRqOverRaGaussian * b.ra : b.rq;
      if (!(s1 > 0.0 && s2 > 0.0)) throw std::invalid_argument("flank roughness must be positive");
      if (!(esb > 0.0)) throw std::invalid_argument("eta sigma beta must be positive");
      s.surface_sigma = std::hypot(s1, s2);
      s.summit_radius = series_radius(a.summit_radius, b.summit_radius);
      mccool_summit_heights(s, mccool_bandwidth(esb));
      s.summit_density = esb / (s.summit_sigma * s.summit_radius);
      break;
    }
    case Form::summits: {
      s.summit_radius = series_radius(a.summit_radius, b.summit_radius);
      s.summit_density = 0.5 * (a.summit_density + b.summit_density);
      const double summit_sigma = std::hypot(a.summit_sigma, b.summit_sigma);
      const double alpha = mccool_bandwidth(s.summit_density * summit_sigma * s.summit_radius);
      s.surface_sigma = summit_sigma / std::sqrt(1.0 - kMcCoolSummitSigmaConstant / alpha);
      mccool_summit_heights(s, alpha);  // gives back summit_sigma
      s.summit_sigma = summit_sigma;
      break;
    }
    case Form::spectral: {
      const double m0 = a.m0 + b.m0, m2 = a.m2 + b.m2, m4 = a.m4 + b.m4;
      if (!(m0 > 0.0 && m2 > 0.0 && m4 > 0.0)) throw std::invalid_argument("spectral moments must be positive");
      const double alpha = m0 * m4 / (m2 * m2);
      if (!(alpha > kMcCoolSummitSigmaConstant))
        throw std::invalid_argument("bandwidth parameter m0 m4/m2^2 must exceed 0.8968 (McCool)");
      s.surface_sigma = std::sqrt(m0);
      mccool_summit_heights(s, alpha);
      s.summit_density = m4 / (6.0 * std::numbers::pi * std::sqrt(3.0) * m2);
      s.summit_radius = mccool_summit_radius(m4);
      break;
    }
  }
  s.validate();
  return s;
}

HeightRoughness height_roughness(const FlankRoughness& f) {
  using Form = FlankRoughness::Form;
  if (f.height_rq > 0.0)
    return {f.height_rq, f.height_ra > 0.0 ? f.height_ra : f.height_rq / kRqOverRaGaussian, true,
            f.form == Form::summits ? "measured surface" : "profile"};
  switch (f.form) {
    case Form::ra:
      return {kRqOverRaGaussian * f.ra, f.ra, true, "given Ra"};
    case Form::rq:
      return {f.rq, f.rq / kRqOverRaGaussian, true, "given Rq"};
    case Form::spectral: {
      const double rq = std::sqrt(std::max(f.m0, 0.0));
      return {rq, rq / kRqOverRaGaussian, true, "spectral moments"};
    }
    case Form::summits:
      break;
  }
  return {0.0, 0.0, false, "summit model"};
}

double plasticity_index(const EquivalentSurface& s, double composite_modulus, double hardness) {
  return composite_modulus / hardness * std::sqrt(s.summit_sigma / s.summit_radius);
}

}  // namespace geartrib::surface
