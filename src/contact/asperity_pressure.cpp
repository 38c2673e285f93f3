#include "contact/asperity_pressure.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace geartrib::contact {

using lubrication::AsperityPressureModel;

double bearing_area_weight(AsperityPressureModel m, double plastic) {
  switch (m) {
    case AsperityPressureModel::asperity_model:
      return 0.0;
    case AsperityPressureModel::bearing_area:
      return 1.0;
    case AsperityPressureModel::automatic:
    case AsperityPressureModel::persson:  // by Persson's own plastic area fraction (mesh_lubrication.cpp)
      break;
  }
  return std::clamp((plastic - kPlasticBlendStart) / (kFullyPlasticAreaFraction - kPlasticBlendStart), 0.0, 1.0);
}

double smallest_plastic_fraction(const GreenwoodWilliamson& gw, const std::vector<double>& pressures) {
  // A summit's plastic share grows with its interference and a higher pressure presses every summit
  // deeper: the fraction rises with the pressure, so the path's smallest is at its lightest load.
  double lightest = std::numeric_limits<double>::infinity();
  for (double p : pressures)
    if (p > 0.0) lightest = std::min(lightest, p);
  if (!std::isfinite(lightest)) return 1.0;
  const SurfaceContact c = gw.at_separation(gw.separation_for_pressure(lightest), true);
  return c.real_area_ratio > 0.0 ? c.plastic_area_ratio / c.real_area_ratio : 1.0;
}

AsperityPressure::AsperityPressure(const GreenwoodWilliamson& gw, lubrication::CompositeHeights heights,
                                   double hardness, double w)
    : gw_(&gw), heights_(heights), hardness_(hardness), bearing_weight_(std::clamp(w, 0.0, 1.0)) {
  summit_offset_ = gw.surface().summit_mean_height;
  set_onset(gw.contact_onset() + summit_offset_);
}

AsperityPressure::AsperityPressure(const PerssonSeparation& persson, lubrication::CompositeHeights heights,
                                   double hardness, double w)
    : persson_(&persson), heights_(heights), hardness_(hardness), bearing_weight_(std::clamp(w, 0.0, 1.0)) {
  summit_offset_ = 0.0;
  persson_onset_pressure_ = kPerssonOnsetPressure * persson.modulus();
  set_onset(lubrication::mean_gap_height(heights_, persson.separation(persson_onset_pressure_)));
}

void AsperityPressure::set_onset(double elastic_onset) {
  if (bearing_weight_ > 0.0 && !(hardness_ > 0.0 && heights_.sigma > 0.0))
    throw std::invalid_argument("the bearing-area asperity pressure needs a positive hardness and roughness");
  onset_ = elastic_onset;
  onset_bearing_ = bearing_weight_ > 0.0 ? lubrication::bearing_area_fraction(heights_, onset_) : 0.0;
  saturation_height_ = -std::numeric_limits<double>::infinity();
  saturation_pressure_ = std::numeric_limits<double>::infinity();
  if (bearing_weight_ == 1.0) {  // only the bearing area: it cannot exceed H
    saturation_height_ = lubrication::bearing_area_height(heights_, 1.0 - kSaturatedBearing);
    saturation_pressure_ = pressure(saturation_height_);
  }
}

double AsperityPressure::elastic_pressure(double h) const {
  if (gw_) return gw_->pressure(h - summit_offset_);
  return std::max(0.0, persson_->pressure(lubrication::mean_gap(heights_, h)) - persson_onset_pressure_);
}

double AsperityPressure::elastic_separation(double p) const {
  if (gw_) return gw_->separation_for_pressure(p) + summit_offset_;
  return lubrication::mean_gap_height(heights_, persson_->separation(p + persson_onset_pressure_));
}

double AsperityPressure::pressure(double h) const {
  if (h >= onset_) return 0.0;
  double p = 0.0;
  if (bearing_weight_ < 1.0) p += (1.0 - bearing_weight_) * elastic_pressure(h);
  if (bearing_weight_ > 0.0)
    p += bearing_weight_ * hardness_ * (lubrication::bearing_area_fraction(heights_, h) - onset_bearing_);
  return p;
}

double AsperityPressure::separation(double p) const {
  if (!(p >= 0.0) || !std::isfinite(p)) throw std::invalid_argument("nominal pressure must be finite and >= 0");
  if (p == 0.0) return onset_;
  if (bearing_weight_ == 0.0) return elastic_separation(p);
  if (bearing_weight_ == 1.0) {
    if (p >= saturation_pressure_) return saturation_height_;
    return lubrication::bearing_area_height(heights_, p / hardness_ + onset_bearing_);
  }
  // A blend: either part alone carrying all of p lies at or below the root (the other part only adds
  // pressure), so it brackets the root from below. The bearing area's is closed-form; the asperity
  // model's (p/(1 - w) can lie far beyond GW's table: a quadrature bisection) only where the bearing
  // area cannot carry p.
  const double a = p / (bearing_weight_ * hardness_) + onset_bearing_;
  const double lo =
      a < 1.0 ? lubrication::bearing_area_height(heights_, a) : elastic_separation(p / (1.0 - bearing_weight_));
  const double hi = onset_;
  const auto f = [&](double h) { return pressure(h) - p; };
  if (f(lo) <= 0.0) return lo;
  std::uintmax_t iterations = 200;
  const double scale = heights_.sigma;
  const auto [l, r] = boost::math::tools::toms748_solve(
      f, lo, hi, [scale](double x, double y) { return std::abs(y - x) <= 1e-13 * scale; }, iterations);
  return 0.5 * (l + r);
}

}  // namespace geartrib::contact
