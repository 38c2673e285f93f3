// The lubricated mesh cycle along A -> E: the smooth film and its inlet-heating correction, the
// load shared between film and asperities (the film filling the mean gap between the rough flanks,
// the asperities pressing by the run's Greenwood-Williamson table or, where the flanks are fully
// plastic, by their bearing area), friction (thermal Eyring traction of the film), flash and
// contact temperature, Archard wear, power loss and the ISO/TS 6336-20/-22 rating quantities
// beside them. Used by run_mesh_contact.
#pragma once

#include "case/case.hpp"
#include "contact/asperity_pressure.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "lubrication/ehl_film.hpp"
#include "lubrication/film_closure.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/lubricant.hpp"
#include "lubrication/mixed_lubrication.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::contact {

// One position's loading and kinematics.
struct PathPoint {
  double s = 0.0, line_load = 0.0, half_width = 0.0, hertz_p0 = 0.0, radius = 0.0, v1 = 0.0, v2 = 0.0;
  double load_sharing_factor = 0.0;  // the pair's share of the normal load (ISO X_Gamma for ISO sharing)
};

// The path's loading and kinematics, one value per position (the run's /mesh series), and
// ISO/TS 6336-22's named points A, AB, B, C, D, DE, E computed at their exact places (B and D on
// the single-pair side of the load's jump).
struct PathState {
  std::vector<double> s, line_load, half_width, hertz_p0, radius, v1, v2, share;
  std::vector<std::pair<std::string, PathPoint>> named;
  PathPoint point(std::size_t i) const {
    return {s[i], line_load[i], half_width[i], hertz_p0[i], radius[i], v1[i], v2[i], share[i]};
  }
};

// A flank pair's height roughness as lambda and the ISO formulas use it.
struct CompositeRoughness {
  double rq = 0.0;           // sqrt(Rq1^2 + Rq2^2) [m]
  double mean_ra = 0.0;      // (Ra1 + Ra2)/2 [m]
  bool from_heights = true;  // false: the summit model's sigma (flanks given by summit statistics only)
  std::string source;        // of each flank's values ("measured surface", "given Ra", ...)
};
CompositeRoughness composite_roughness(const Case& c, const surface::EquivalentSurface& s);

class MeshLubrication {
 public:
  // Film, regime and load shares at every position (before the strips are solved).
  MeshLubrication(const Case& c, const gear::GearMesh& mesh, const PathState& path, const GreenwoodWilliamson& gw);
  // The asperities' share of the load at position i, for the strip contact.
  double asperity_share(std::size_t i) const { return positions_[i].asperity_share; }
  // Friction, temperatures, wear and losses; fills r.lubrication and r.lubrication_summary and adds
  // the lubricated models' findings to r.verdict and r.warnings.
  void finish(MeshContactResult& r);

  // One position's lubricated state (SI); film() fills the film and the shares, rest() the rest.
  // Each field is one /lubrication series.
  struct Position {
    double film_isothermal = 0.0, heating_factor = 1.0, film = 0.0, regime = 0.0;
    double asperity_share = 0.0;
    double separation = 0.0;      // of the mean planes of heights [m]
    double mean_gap = 0.0;        // the film's gap: the mean gap (or the closure's) [m]
    double share_spread = 0.0;    // the asperity share's range over the film gaps
    double iso_flash = 0.0;       // ISO/TS 6336-20 flash-temperature method [K]
    double blok_iso_flash = 0.0;  // Blok's with ISO/TS 6336-22's mu_mC [K]
    double friction = 0.0, film_traction = 0.0, midfilm_rise = 0.0, flash = 0.0, contact_temperature = 0.0,
           iso_contact_temperature = 0.0, power_loss = 0.0, wear_pinion = 0.0, wear_wheel = 0.0, iso_film = 0.0,
           iso_lambda = 0.0, lambda_film = 0.0, lambda_gap = 0.0, low_peclet = 0.0, curve_outside = 0.0,
           bearing_saturated = 0.0;
    double oil_extrapolated = 0.0;  // 1: an oil (bulk, surfaces, ISO contact) beyond the lubricant's data range
    double oil_clamped = 0.0;       // 1: the surfaces' or ISO contact's oil taken at the end of its law range
  };

 private:
  // ln(film share) of the last solution per film gap (lubrication::FilmGap), the next one's start.
  using ShareGuesses = std::array<double, 3>;
  void film(const PathPoint& p, ShareGuesses& guesses, Position& q) const;
  void rest(const PathPoint& p, Position& q) const;
  double iso_flash(const PathPoint& p) const;
  // The oil at a temperature a position reaches: beyond the lubricant's data range `extrapolated`
  // set; beyond its law range taken at the range's end and `clamped` set. The fixed form's
  // constants hold at any temperature.
  lubrication::OilState oil_at(double temperature, bool& extrapolated, bool& clamped) const;
  void iso_temperatures(const PathPoint& p, Position& q) const;  // the ISO method's and Blok's with mu_mC

  const Case& case_;
  const gear::GearMesh& mesh_;
  const PathState& path_;
  lubrication::FilmFormula formula_;
  lubrication::InletHeating inlet_;
  lubrication::FilmGap film_gap_;
  lubrication::FilmTraction traction_;
  lubrication::MeanFrictionLaw bulk_law_;
  lubrication::OilState oil_at_inlet_, oil_at_bulk_;
  double reduced_modulus_ = 0.0;                // E' = 2 E* [Pa]
  double thermal_coefficient_[2] = {0.0, 0.0};  // B_M of pinion and wheel
  lubrication::PitchPointLoad pitch_;
  std::vector<std::pair<lubrication::MeanFrictionLaw, lubrication::MeanFriction>> mean_laws_;
  double iso_mu_ = 0.0;        // ISO/TS 6336-22 mu_mC (h_Y's contact temperature)
  double iso_flash_mu_ = 0.0;  // ISO/TS 6336-20 mu_m (its flash-temperature method)
  double iso_x_m_ = 0.0, iso_effective_relief_ = 0.0;
  lubrication::IsoFlashGeometry iso_geometry_;
  lubrication::TemperatureRange oil_range_;  // where the lubricant's laws hold
  double bulk_temperature_ = 0.0;
  bool bulk_extrapolated_ = false;  // beyond the lubricant's data range
  bool bulk_estimated_ = false;
  CompositeRoughness roughness_;
  double plasticity_index_ = 0.0;
  double plastic_fraction_ = 0.0;  // the asperity model's smallest along the path (auto's weight)
  std::optional<AsperityPressure> asperity_;
  std::vector<Position> positions_;
};

// Roughness: the summit model's composite sigma against the heights' differs by more than this
// factor: the GW parameters describe another surface than the one lambda is measured on.
inline constexpr double kRoughnessDisagreementFactor = 1.25;
// The asperity share's spread over the film gaps above which it "depends on the closure".
inline constexpr double kClosureSpreadFlag = 0.1;

}  // namespace geartrib::contact
