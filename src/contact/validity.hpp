// Where the rough-contact answer holds, position by position, and one verdict for the run.
// Greenwood-Williamson sums independent, sparse summit contacts on paraboloid tips; each
// asperity law holds over the interferences it was fitted to. The highest asperity expected in
// the strip (highest_asperity) is the one that leaves these ranges first.
#pragma once

#include "contact/greenwood_williamson.hpp"
#include "contact/rough_line_contact.hpp"

#include <string>
#include <vector>

namespace geartrib::contact {

// The regime verdict calls the flanks fully plastic where the plastic share of the real area
// exceeds this at every position (the lubricated sharing's bearing-area switch uses it too).
inline constexpr double kFullyPlasticAreaFraction = 0.99;

// The rules, declared once (threshold and reason).
struct ValidityRules {
  // Separation below -1 summit sigma: more than 84% of the summits touch, so GW's sparse
  // contacts at the tail of the height distribution (GW 1966; Greenwood & Tripp 1967) are not
  // what the surface does.
  double deep_separation_over_sigma = -1.0;
  // The highest contact's radius reaching half the mean summit spacing 1/sqrt(eta): it touches
  // where its neighbours stand, so contacts merge and their elastic-plastic fields interact,
  // which GW's independent summits leave out (interaction models: Zhao & Chang, J. Tribol. 123
  // (2001) 857). For GW's elastic contacts a^2/(s/2)^2 = 4 (eta sigma_s beta) delta/sigma_s,
  // so at eta sigma_s beta = 0.05 the highest summit reaches it when pressed 5 sigma_s deep.
  double interaction_over_half_spacing = 1.0;
};

// One position's figures: the highest asperity's interference and contact radius against the
// summit radius, the summit spacing and the law's range; the strip's separation.
struct PositionValidity {
  double separation_over_sigma = 0.0;                 // min separation / sigma_s [-]
  double max_delta_star = 0.0;                        // highest asperity delta/delta_c [-]
  double max_interference_over_radius = 0.0;          // highest asperity delta / beta [-]
  double max_contact_radius_over_radius = 0.0;        // a / beta [-]
  double max_contact_radius_over_half_spacing = 0.0;  // a / (1/(2 sqrt(eta))) [-]
  bool loaded = false;                                // the position carries load (the regime counts only these)
  bool beyond_fitted_range = false;                   // delta* past the law's fitted range
  bool beyond_paraboloid = false;                     // a/beta past the law's paraboloid limit
  bool fully_plastic_limit = false;                   // the switch to the fully plastic limit governs
  bool summits_interact = false;                      // rule interaction_over_half_spacing
  bool deep_separation = false;                       // rule deep_separation_over_sigma
};

PositionValidity position_validity(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width,
                                   const ValidityRules& rules = {});

// The run's verdict: the regime from the plastic area fraction along the path and the
// plasticity index, then, per rule, at how many positions it is broken and how far.
struct ValidityVerdict {
  // "elastic": below 1% of the real area yielded and below 1% of the contacts past first yield
  // at every position; "fully plastic": more than 99% of the real area yielded at the surface at
  // every loaded position; "elastic-plastic" between.
  std::string regime;
  std::string text;  // one paragraph for the user
  int beyond_fitted_range = 0, beyond_paraboloid = 0, fully_plastic_limit = 0, summits_interact = 0,
      deep_separation = 0;  // positions where each flag is set
};
// The path's plastic area fraction, plastic contact fraction and mean real pressure may be empty
// (not asked for); the regime then comes from the plasticity index.
struct PathContact {
  std::vector<double> plastic_area_fraction, plastic_contact_fraction, mean_real_pressure;
};
ValidityVerdict validity_verdict(const std::vector<PositionValidity>& positions, double plasticity_index,
                                 const GreenwoodWilliamson& gw, const PathContact& path,
                                 const ValidityRules& rules = {});

}  // namespace geartrib::contact
