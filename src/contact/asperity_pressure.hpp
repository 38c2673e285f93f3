// The asperities' nominal pressure against the separation h of the flanks' mean planes of heights,
// for the mixed-lubrication load sharing: the case's asperity model (Greenwood-Williamson over the
// model's law) where it holds, and the bearing-area model p = H A_b(h) where the flanks are fully
// plastic (every contact at the hardness H over the area a plane at h cuts through the heights:
// Abbott & Firestone 1933; the fully plastic limit of GW 1966 and of Pullen & Williamson, Proc. R.
// Soc. A 327 (1972) 159-173, without their volume conservation). Or, in the asperity model's place,
// Persson's interfacial separation law (contact/persson_contact.hpp): the pressure at which the
// deformed flanks' mean gap is the mean gap of the heights at h.
#pragma once

#include "contact/greenwood_williamson.hpp"
#include "contact/persson_contact.hpp"
#include "contact/validity.hpp"
#include "lubrication/film_closure.hpp"

#include <string>
#include <vector>

namespace geartrib::contact {

// The bearing-area model's weight w of the choice (lubrication::AsperityPressureModel, where the
// choice and its names are stated) at the asperity model's plastic area fraction (persson: at
// Persson's, as auto).
double bearing_area_weight(lubrication::AsperityPressureModel m, double plastic_area_fraction);
inline constexpr double kPlasticBlendStart = 0.9;  // the blend's start; its end: kFullyPlasticAreaFraction
// The asperity model's smallest plastic area fraction over the nominal pressures p0 (each the
// whole load at the strip's centre), at the lightest of them: what `auto` weighs by.
double smallest_plastic_fraction(const GreenwoodWilliamson& gw, const std::vector<double>& pressures);

class AsperityPressure {
 public:
  // p(h) = (1 - w) p_GW(h - y_s) + w H (A_b(h) - A_b(h_on)), y_s the summits' mean height above
  // the mean plane, h_on = GW's contact onset + y_s (p = 0 there and above; A_b(h_on) < 1e-15).
  AsperityPressure(const GreenwoodWilliamson& gw, lubrication::CompositeHeights heights, double hardness,
                   double bearing_weight);
  // p(h) = (1 - w) (p_P(g(h)) - p_P(g(h_on))) + w H (A_b(h) - A_b(h_on)), g the mean gap of the heights
  // (lubrication::mean_gap) and p_P Persson's pressure at that mean gap; Persson's pressure never
  // vanishes (p ~ exp(-u/u0)): the onset h_on is where it falls to kPerssonOnsetPressure E*.
  AsperityPressure(const PerssonSeparation& persson, lubrication::CompositeHeights heights, double hardness,
                   double bearing_weight);
  double pressure(double h) const;  // [Pa], non-increasing in h
  // The separation h at which the asperities carry nominal pressure p >= 0 (onset() at p = 0). The
  // bearing-area part cannot carry H or more: there h is that of A_b = 1 - kSaturatedBearing and
  // saturated() says so.
  double separation(double p) const;
  bool saturated(double p) const { return bearing_weight_ > 0.0 && p >= saturation_pressure_; }
  double onset() const { return onset_; }
  double bearing_weight() const { return bearing_weight_; }
  const lubrication::CompositeHeights& heights() const { return heights_; }
  static constexpr double kSaturatedBearing = 1e-9;
  static constexpr double kPerssonOnsetPressure = 1e-15;  // of E*: 1e-4 Pa on steel

 private:
  void set_onset(double elastic_onset);
  double elastic_pressure(double h) const;    // the asperity model's or Persson's [Pa]
  double elastic_separation(double p) const;  // its inverse [m]
  const GreenwoodWilliamson* gw_ = nullptr;
  const PerssonSeparation* persson_ = nullptr;
  double persson_onset_pressure_ = 0.0;  // p_P at the onset [Pa]
  lubrication::CompositeHeights heights_;
  double hardness_;
  double bearing_weight_;
  double summit_offset_;        // y_s [m]
  double onset_;                // h_on [m]
  double onset_bearing_;        // A_b(h_on)
  double saturation_pressure_;  // the largest pressure the blend reaches where A_b saturates [Pa]
  double saturation_height_;    // h there [m]
};

}  // namespace geartrib::contact
