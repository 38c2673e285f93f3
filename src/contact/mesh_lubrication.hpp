// The lubricated mesh cycle along A -> E: the smooth film and its inlet-heating correction, the
// load shared between film and asperities (the film filling the mean gap between the rough flanks,
// the asperities pressing by the run's Greenwood-Williamson table or Persson's separation law and,
// where the flanks are fully plastic, by their bearing area), friction (thermal Eyring traction of
// the film), flash and contact temperature, Archard wear, power loss and the ISO/TS 6336-20/-22
// rating quantities beside them: the mesh cycle's lubrication stage.
#pragma once

#include "contact/asperity_pressure.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/mesh_path.hpp"
#include "contact/surface_model.hpp"
#include "gear/gear_mesh.hpp"
#include "lubrication/ehl_film.hpp"
#include "lubrication/film_closure.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/lubricant.hpp"
#include "lubrication/lubrication_settings.hpp"
#include "lubrication/mixed_lubrication.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::contact {

// A flank pair's height roughness as lambda and the ISO formulas use it.
struct CompositeRoughness {
  double rq = 0.0;           // sqrt(Rq1^2 + Rq2^2) [m]
  double mean_ra = 0.0;      // (Ra1 + Ra2)/2 [m]
  bool from_heights = true;  // false: the summit model's sigma (flanks given by summit statistics only)
  std::string source;        // of each flank's values ("measured surface", "given Ra", ...)
};
CompositeRoughness composite_roughness(const std::array<surface::FlankRoughness, 2>& flanks,
                                       const surface::EquivalentSurface& s);

// What the lubricated cycle takes beyond the path and the flanks' statistical model.
struct LubricationInputs {
  const lubrication::LubricationSettings& lubrication;  // the oil and the models along the path
  LubricatedOperatingPoint operating;
  // The case's flanks (Persson's spectrum: their measured patches or generated ground profiles).
  std::array<const surface::FlankSpec*, 2> flank_specs = {nullptr, nullptr};
};

struct LubricationResult;

// The lubricated stage over the typed path: the film and the load shares (constructed before the
// contact), then friction, temperatures, wear and losses (finish(), after it).
class MeshLubrication {
 public:
  // Film, regime and load shares at every position, the film sharing the load with `model`'s asperities.
  MeshLubrication(const LubricationInputs& in, const gear::GearMesh& mesh, const PathState& path,
                  const SurfaceModel& model);
  // The asperities' share of the load at every position, for the contact.
  std::vector<double> asperity_shares() const;
  // Friction, temperatures, wear and losses, the summary, the verdict's text and the warnings.
  LubricationResult finish();
  // The oil at the flanks' bulk temperature, as the film and the load sharing take it.
  const lubrication::OilState& bulk_oil() const { return oil_at_bulk_; }
  // The flanks' thermal contact coefficients B = sqrt(k rho c) (0: pinion, 1: wheel) [W s^0.5/(m^2 K)].
  double thermal_contact_coefficient(int gear) const { return thermal_coefficient_[gear]; }

  // One position's lubricated state (SI); film() fills the film and the shares, rest() the rest.
  // Each field is one /lubrication series.
  struct Position {
    double film_isothermal = 0.0, heating_factor = 1.0, film = 0.0, regime = 0.0;
    double asperity_share = 0.0;
    double separation = 0.0;      // of the mean planes of heights [m]
    double mean_gap = 0.0;        // the film's gap: the mean gap (or the closure's) [m]
    double share_spread = 0.0;    // the asperity share's range over the film gaps (and Persson's, when taken)
    double iso_flash = 0.0;       // ISO/TS 6336-20 flash-temperature method [K]
    double blok_iso_flash = 0.0;  // Blok's with ISO/TS 6336-22's mu_mC [K]
    double friction = 0.0, film_traction = 0.0, midfilm_rise = 0.0, flash = 0.0, contact_temperature = 0.0,
           iso_contact_temperature = 0.0, power_loss = 0.0, wear_pinion = 0.0, wear_wheel = 0.0, iso_film = 0.0,
           iso_lambda = 0.0, lambda_film = 0.0, lambda_gap = 0.0, low_peclet = 0.0, curve_outside = 0.0,
           bearing_saturated = 0.0;
    // Persson: the share of the real area at the hardness under the asperities' pressure at the
    // strip's centre, by his elastic-plastic theory (contact/persson_contact.hpp).
    double persson_plastic = 0.0;
    double oil_extrapolated = 0.0;  // 1: an oil (bulk, surfaces, ISO contact) beyond the lubricant's data range
    double oil_clamped = 0.0;       // 1: the surfaces' or ISO contact's oil taken at the end of its law range
  };

 private:
  // ln(film share) of the last solution per film gap (lubrication::FilmGap) and, last, Persson's:
  // the next one's start.
  using ShareGuesses = std::array<double, 4>;
  // The mixed friction at a position and what the film's traction found on the way.
  struct FilmFriction {
    double friction = 0.0, film_coefficient = 0.0, rise = 0.0;
    bool curve_outside = false, surface_extrapolated = false, surface_clamped = false;
  };
  void pitch_and_iso();      // the pitch point, the gear-mean laws, ISO/TS 6336-20's factors
  void bulk_temperature();   // given, or ISO/TS 6336-20's estimate; the oil there
  void asperity_pressure();  // the asperities' pressure against the separation
  // Persson's elastic-plastic share of the real area at the hardness under the nominal pressure p.
  double persson_plastic_fraction(double p) const;
  void film(const PathPoint& p, ShareGuesses& guesses, Position& q) const;
  void rest(const PathPoint& p, Position& q) const;
  FilmFriction film_friction(const PathPoint& p, const Position& q) const;
  double blok(const PathPoint& p, double mu) const;  // Blok's flash temperature at friction mu [K]
  double iso_flash(const PathPoint& p) const;
  // The oil at a temperature a position reaches: beyond the lubricant's data range `extrapolated`
  // set; beyond its law range taken at the range's end and `clamped` set. The fixed form's
  // constants hold at any temperature.
  lubrication::OilState oil_at(double temperature, bool& extrapolated, bool& clamped) const;
  void iso_temperatures(const PathPoint& p, Position& q) const;  // the ISO method's and Blok's with mu_mC
  LubricationSummary summary() const;
  void losses(LubricationSummary& sum) const;  // power loss, efficiency, loss factors, the gear-mean friction
  std::vector<LubricationSummary::NamedPoint> named_points() const;
  double sigma_ratio() const;  // the summit model's composite sigma over the flanks' Rq
  bool surfaces_disagree() const;
  std::string spectrum_text() const;  // Persson's spectrum, for the verdict
  std::string verdict_text(const LubricationSummary& sum) const;
  std::vector<std::string> warnings(const LubricationSummary& sum) const;
  void oil_warnings(const LubricationSummary& sum, std::vector<std::string>& out) const;
  void curve_warnings(std::vector<std::string>& out) const;

  const lubrication::LubricationSettings& lubrication_;
  const LubricatedOperatingPoint operating_;
  const SurfaceModel& model_;
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
  double bulk_law_mu_ = 0.0;   // the bulk estimate's law's
  double iso_x_m_ = 0.0, iso_effective_relief_ = 0.0;
  double iso_tip_relief_ = 0.0;  // C_a: the wheel's tip relief [m] (compatibility sharing)
  lubrication::IsoFlashGeometry iso_geometry_;
  lubrication::TemperatureRange oil_range_;  // where the lubricant's laws hold
  double bulk_temperature_ = 0.0;
  bool bulk_extrapolated_ = false;  // beyond the lubricant's data range
  bool bulk_estimated_ = false;
  CompositeRoughness roughness_;
  double plasticity_index_ = 0.0;
  double plastic_fraction_ = 0.0;  // the asperity model's (Persson's) smallest along the path: the blend's weight
  std::optional<FlankSpectrum> spectrum_;       // Persson's
  std::optional<PerssonSeparation> persson_;    // Persson's separation law
  std::optional<AsperityPressure> asperity_;    // the closure's asperity pressure
  std::optional<AsperityPressure> comparison_;  // beside Persson's: the asperity model's, as auto takes it
  double hardness_ = 0.0;                       // of the softer flank [Pa]
  std::vector<Position> positions_;
};

// The lubricated stage's typed results.
struct LubricationResult {
  std::vector<MeshLubrication::Position> positions;
  LubricationSummary summary;
  std::string verdict;                // what the run's verdict gains
  std::vector<std::string> warnings;  // in order
  bool bearing_saturated_column = false, traction_curve_column = false, persson_column = false;
};
// Its /lubrication series.
// ISO/TS 6336-20's flash-temperature geometry of a pair: u, a, alpha_wt, alpha_t, Gamma at A and E.
lubrication::IsoFlashGeometry iso_flash_geometry(const gear::SpurPair& pair);

void add_lubrication_series(const LubricationResult& l, std::vector<Series>& group);

// Roughness: the summit model's composite sigma against the heights' differs by more than this
// factor: the GW parameters describe another surface than the one lambda is measured on.
inline constexpr double kRoughnessDisagreementFactor = 1.25;
// The asperity share's spread over the film gaps above which it "depends on the closure".
inline constexpr double kClosureSpreadFlag = 0.1;
// Persson's closure: the share of the real area at the hardness above which his elastic separation
// law is flagged (flag_persson_plastic): the yielded contacts carry less than it says at that gap.
inline constexpr double kPerssonPlasticFlag = 0.1;

}  // namespace geartrib::contact
