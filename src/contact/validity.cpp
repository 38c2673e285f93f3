#include "contact/validity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geartrib::contact {

PositionValidity position_validity(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width,
                                   const ValidityRules& rules) {
  PositionValidity v;
  const auto& s = gw.surface();
  v.separation_over_sigma = strip.min_separation / s.summit_sigma;
  v.loaded = strip.line_load > 0.0;
  v.deep_separation = v.loaded && v.separation_over_sigma < rules.deep_separation_over_sigma;
  // The highest asperity in normal contact (the stress stage may tilt it; its size is the same).
  const double delta = highest_asperity_interference(gw, strip, face_width);
  if (delta <= 0.0) return v;
  const asperity::AsperityState a = gw.model().evaluate(gw.pair(), delta, asperity::Detail::load_area);
  const double half_spacing = 0.5 / std::sqrt(s.summit_density);
  v.max_delta_star = a.delta_star;
  v.max_interference_over_radius = delta / s.summit_radius;
  v.max_contact_radius_over_radius = a.contact_radius / s.summit_radius;
  v.max_contact_radius_over_half_spacing = a.contact_radius / half_spacing;
  v.beyond_fitted_range = a.beyond_fitted_range;
  v.beyond_paraboloid = a.beyond_paraboloid;
  v.fully_plastic_limit = a.fully_plastic_limit;
  v.summits_interact = v.max_contact_radius_over_half_spacing > rules.interaction_over_half_spacing;
  return v;
}

ValidityVerdict validity_verdict(const std::vector<PositionValidity>& pos, double psi, const GreenwoodWilliamson& gw,
                                 const PathContact& path, const ValidityRules& rules) {
  const auto& plastic = path.plastic_area_fraction;
  const auto& mean_pressure = path.mean_real_pressure;
  ValidityVerdict v;
  const int n = static_cast<int>(pos.size());
  double max_delta_star = 0.0, max_a_spacing = 0.0, max_a_radius = 0.0, min_sep = 0.0;
  for (const auto& p : pos) {
    v.beyond_fitted_range += p.beyond_fitted_range;
    v.beyond_paraboloid += p.beyond_paraboloid;
    v.fully_plastic_limit += p.fully_plastic_limit;
    v.summits_interact += p.summits_interact;
    v.deep_separation += p.deep_separation;
    max_delta_star = std::max(max_delta_star, p.max_delta_star);
    max_a_spacing = std::max(max_a_spacing, p.max_contact_radius_over_half_spacing);
    max_a_radius = std::max(max_a_radius, p.max_contact_radius_over_radius);
    min_sep = std::min(min_sep, p.separation_over_sigma);
  }
  // Regime: from the plastic area fraction along the path where it was computed, else from psi
  // (Greenwood & Williamson 1966: elastic below 0.6, plastic above 1).
  // Unloaded positions (zero share by definition, e.g. a dynamic loss of contact) do not count.
  double pf_lo = 1.0, pf_hi = 0.0, yielded = 0.0;
  double pm_lo = std::numeric_limits<double>::infinity(), pm_hi = 0.0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    if (!pos[i].loaded) continue;
    if (i < plastic.size()) pf_lo = std::min(pf_lo, plastic[i]), pf_hi = std::max(pf_hi, plastic[i]);
    if (i < path.plastic_contact_fraction.size()) yielded = std::max(yielded, path.plastic_contact_fraction[i]);
    if (i < mean_pressure.size()) pm_lo = std::min(pm_lo, mean_pressure[i]), pm_hi = std::max(pm_hi, mean_pressure[i]);
  }
  if (!plastic.empty())
    v.regime = pf_lo > kFullyPlasticAreaFraction  ? "fully plastic"
               : (pf_hi < 0.01 && yielded < 0.01) ? "elastic"
                                                  : "elastic-plastic";
  else v.regime = psi < 0.6 ? "elastic" : psi > 1.0 ? "fully plastic" : "elastic-plastic";
  const auto& model = gw.model();
  const double hardness = gw.pair().hardness;
  std::string t = fmt::format("{} regime, plasticity index {:.3g}", v.regime, psi);
  if (!plastic.empty()) t += fmt::format(", plastic area fraction {:.5g} to {:.5g} along the path", pf_lo, pf_hi);
  if (v.regime == "fully plastic") {
    t += ": the real area is the load over the hardness";
    if (pm_hi > 0.0) t += fmt::format(" (mean real pressure {:.4g} to {:.4g} H)", pm_lo / hardness, pm_hi / hardness);
    t += " and the asperity stresses saturate at those of a uniform pressure H, whatever the roughness";
  }
  t += ".";
  if (v.beyond_fitted_range)
    t +=
        fmt::format(" {} of {} positions beyond {}'s range (delta* <= {:g}; highest asperity up to delta* {:.3g}): {}.",
                    v.beyond_fitted_range, n, model.name(), model.range().fitted_delta_star_max, max_delta_star,
                    model.range().past_range);
  if (v.fully_plastic_limit)
    t += fmt::format(" At {} of {} positions the fully plastic limit governs the highest asperity.",
                     v.fully_plastic_limit, n);
  if (v.beyond_paraboloid)
    t += fmt::format(
        " {} of {} positions with a contact radius beyond {:g} x the summit radius (up to {:.3g}): "
        "the asperity is no longer a paraboloid tip.",
        v.beyond_paraboloid, n, model.range().contact_radius_over_radius_max, max_a_radius);
  if (v.summits_interact)
    t += fmt::format(
        " {} of {} positions where the highest contact's radius exceeds {:g} x half the summit spacing "
        "(up to {:.3g}): neighbouring contacts interact, which GW leaves out.",
        v.summits_interact, n, rules.interaction_over_half_spacing, max_a_spacing);
  if (v.deep_separation)
    t += fmt::format(
        " {} of {} positions with the separation below {:g} summit sigma (down to {:.3g}): most summits "
        "touch, GW's sparse contacts do not hold.",
        v.deep_separation, n, rules.deep_separation_over_sigma, min_sep);
  if (!(v.beyond_fitted_range || v.beyond_paraboloid || v.fully_plastic_limit || v.summits_interact ||
        v.deep_separation))
    t += " Every position is within the models' ranges.";
  v.text = t;
  return v;
}

}  // namespace geartrib::contact
