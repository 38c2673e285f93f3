#include "contact/mesh_lubrication.hpp"

#include "contact/series_columns.hpp"
#include "core/keyed_error.hpp"
#include "gear/iso6336_stiffness.hpp"
#include "gear/load_sharing.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace geartrib::contact {

namespace lub = lubrication;

CompositeRoughness composite_roughness(const std::array<surface::FlankRoughness, 2>& flanks,
                                       const surface::EquivalentSurface& s) {
  const surface::HeightRoughness a = surface::height_roughness(flanks[0]);
  const surface::HeightRoughness b = surface::height_roughness(flanks[1]);
  CompositeRoughness r;
  if (a.known && b.known) {
    r.rq = std::hypot(a.rq, b.rq);
    r.mean_ra = 0.5 * (a.ra + b.ra);
    r.source = std::string(a.source) == b.source ? a.source : std::string(a.source) + " / " + b.source;
    return r;
  }
  // Flanks given by summit statistics alone: the summit model's sigma, shared equally.
  r.rq = s.surface_sigma;
  r.mean_ra = s.surface_sigma / (std::numbers::sqrt2 * surface::kRqOverRaGaussian);
  r.from_heights = false;
  r.source = "summit model";
  return r;
}

namespace {
constexpr double kC = 273.15;  // [K] at 0 degC
using Position = MeshLubrication::Position;
double largest(const std::vector<Position>& v, double Position::*field) {
  double m = -std::numeric_limits<double>::infinity();
  for (const Position& q : v) m = std::max(m, q.*field);
  return m;
}
double smallest(const std::vector<Position>& v, double Position::*field) {
  double m = std::numeric_limits<double>::infinity();
  for (const Position& q : v) m = std::min(m, q.*field);
  return m;
}
std::vector<double> series(const std::vector<Position>& v, double Position::*field) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const Position& q : v) out.push_back(q.*field);
  return out;
}
}  // namespace

MeshLubrication::MeshLubrication(const LubricationInputs& in, const gear::GearMesh& mesh, const PathState& p,
                                 const SurfaceModel& model)
    : lubrication_(in.lubrication),
      operating_(in.operating),
      model_(model),
      mesh_(mesh),
      path_(p),
      formula_(in.lubrication.film_formula),
      inlet_(in.lubrication.inlet_heating),
      film_gap_(in.lubrication.film_gap),
      traction_(in.lubrication.traction),
      bulk_law_(in.lubrication.mean_friction) {
  reduced_modulus_ = 2.0 * mesh.composite_modulus();
  if (lubrication_.asperity_pressure == lub::AsperityPressureModel::persson) {
    if (model.flanks.distribution != surface::HeightDistribution::gaussian)
      throw core::KeyedError("lubrication.asperity_pressure",
                             "Persson's theory takes Gaussian heights (its diffusion of the pressure and its mean gap "
                             "both assume them), and roughness.distribution is exponential: take the Gaussian heights "
                             "or another asperity pressure (auto, asperity-model, bearing-area)");
    const lub::PerssonSpectrum asked = lubrication_.persson_spectrum;
    try {
      spectrum_ = flank_spectrum(in.flank_specs, model.surface, asked);
    } catch (const MeasuredSpectrumError& e) {
      throw core::KeyedError("lubrication.persson_spectrum",
                             fmt::format("Persson's theory takes the measured flanks' own power spectrum, and {}: "
                                         "correct the topography, or take \"moments\" (the statistical model's fit)",
                                         e.what()));
    } catch (const std::invalid_argument& e) {
      throw core::KeyedError(
          "lubrication.asperity_pressure",
          fmt::format("Persson's theory needs the flanks' power spectrum; {} it is fitted to the statistical model's "
                      "moments, and none fits them ({}): {}",
                      asked == lub::PerssonSpectrum::moments
                          ? "with lubrication.persson_spectrum = \"moments\""
                          : "without a spectrum of their own on both flanks (a measured areal topography or a "
                            "generated ground profile)",
                      e.what(),
                      asked == lub::PerssonSpectrum::moments
                          ? "take the flanks' own (\"flanks\"), where they have one"
                          : "give the flanks measured areal topographies or ground profiles, or a wider band "
                            "(roughness.eta_sigma_beta above 0.0214)"));
    }
  }
  for (int g = 0; g < 2; ++g) {
    const Material& m = *model.flanks.materials[static_cast<std::size_t>(g)];
    thermal_coefficient_[g] = lub::thermal_contact_coefficient(m.thermal_conductivity, m.density, m.specific_heat);
  }
  roughness_ = composite_roughness(model.flanks.roughness, model.surface);
  oil_range_ = lub::law_range(lubrication_.lubricant);
  // inside the range (io::load_case)
  oil_at_inlet_ = lub::oil_state(lubrication_.lubricant, operating_.oil_temperature);
  pitch_and_iso();
  const std::size_t n = p.s.size();
  positions_.resize(n);
  for (std::size_t i = 0; i < n; ++i) iso_temperatures(p.point(i), positions_[i]);
  bulk_temperature();
  asperity_pressure();
  ShareGuesses guesses;  // ln(film share) at the last position, per film gap
  guesses.fill(std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < n; ++i) film(p.point(i), guesses, positions_[i]);
}

void MeshLubrication::pitch_and_iso() {
  const auto& lubricant = lubrication_.lubricant;
  const gear::GearMesh& mesh = mesh_;
  // The pitch point as the ISO mean-friction formulas take it, and every gear-mean law there.
  const gear::SpurPair& pair = mesh.pair();
  const gear::PathOfContact& path = pair.path();
  const double face = pair.spec().face_width;
  const double omega = mesh.pinion_speed();
  const gear::FlankKinematics kc = pair.kinematics(path.c, omega);
  pitch_.tangential_load = mesh.tangential_line_load();         // w_Bt = F_t/b [N/m]
  pitch_.normal_load = mesh.normal_force() / face;              // F_bn/b [N/m]
  pitch_.pitch_line_speed = omega * pair.gear(0).pitch_radius;  // v_t at the reference circle, as ISO 6336
  pitch_.sum_speed = kc.rolling_pinion + kc.rolling_wheel;
  pitch_.radius = pair.flank(path.c).radius_equivalent;
  pitch_.eta_oil = oil_at_inlet_.dynamic_viscosity;
  pitch_.mean_ra = roughness_.mean_ra;
  pitch_.lubricant_factor = oil_at_inlet_.iso_lubricant_factor;
  for (lub::MeanFrictionLaw law : {lub::MeanFrictionLaw::iso, lub::MeanFrictionLaw::iso_flash,
                                   lub::MeanFrictionLaw::schlenk, lub::MeanFrictionLaw::fernandes})
    mean_laws_.emplace_back(law, lub::mean_friction(law, pitch_, lubricant.base_oil));
  auto law_value = [&](lub::MeanFrictionLaw law) {
    for (const auto& [l, f] : mean_laws_)
      if (l == law) return f.coefficient;
    return 0.0;
  };
  iso_mu_ = law_value(lub::MeanFrictionLaw::iso);
  iso_flash_mu_ = law_value(lub::MeanFrictionLaw::iso_flash);
  bulk_law_mu_ = law_value(bulk_law_);

  // ISO/TS 6336-20's flash-temperature method: its factors fixed by the pair.
  iso_geometry_ = iso_flash_geometry(pair);
  iso_x_m_ = lub::iso_thermo_elastic_factor(reduced_modulus_, thermal_coefficient_[0], thermal_coefficient_[1]);
  // C_eff = F_t/(b cos alpha_t c_gamma) (ISO/TR 13989-1 B.1), c_gamma_alpha of ISO 6336-1 method B;
  // C_a the wheel's tip relief under the compatibility sharing (0 otherwise: unmodified flanks).
  iso_effective_relief_ = gear::iso_effective_relief(pair, pitch_.tangential_load);
  if (const gear::LoadedToothContact* contact = mesh.tooth_contact()) iso_tip_relief_ = contact->flank(1).tip_amount();
}

void MeshLubrication::bulk_temperature() {
  const auto& lubricant = lubrication_.lubricant;
  const LubricatedOperatingPoint& op = operating_;
  // ISO/TS 6336-20 eq. 22: theta_M = theta_oil + 0.47 X_S X_mp theta_fl,m; the flash temperature is
  // linear in mu_m, so another law's estimate scales the method's by its coefficient.
  bulk_estimated_ = !(op.bulk_temperature > 0.0);
  const double law_scale = iso_flash_mu_ > 0.0 ? bulk_law_mu_ / iso_flash_mu_ : 0.0;
  bulk_temperature_ = bulk_estimated_
                          ? lub::iso_bulk_temperature(op.oil_temperature,
                                                      law_scale * path_mean(series(positions_, &Position::iso_flash)))
                          : op.bulk_temperature;
  // The film, its share and its traction all rest on the oil at the bulk temperature: an estimate
  // beyond the lubricant's laws leaves them without a viscosity, and the run fails naming it (a
  // given one is refused with the case). Per position, hotter surfaces are clamped (oil_at).
  if (!lubricant.fixed() && !oil_range_.contains(bulk_temperature_))
    throw lub::OutsideLawRange(fmt::format(
        "the flanks' bulk temperature (/lubrication bulk_temperature_K), estimated by ISO/TS 6336-20 with the {} "
        "friction law's flash temperature, is {:.1f} degC, beyond {:.1f} degC, the hottest at which {}'s laws hold "
        "(its data reach {:.1f} degC): the film, the load sharing and the friction have no viscosity there",
        lub::mean_friction_law_name(lubrication_.mean_friction), bulk_temperature_ - 273.15, oil_range_.hi - 273.15,
        lubricant.name, lubricant.max_temperature - 273.15));
  bulk_extrapolated_ = !lubricant.fixed() && !lub::data_range(lubricant).contains(bulk_temperature_);
  oil_at_bulk_ = lub::oil_state(lubricant, bulk_temperature_);
}

void MeshLubrication::asperity_pressure() {
  // The asperities' pressure against the mean-plane separation.
  const GreenwoodWilliamson& gw = model_.table;
  plasticity_index_ = surface::plasticity_index(gw.surface(), gw.pair().modulus, gw.pair().hardness);
  hardness_ = gw.pair().hardness;
  const lub::AsperityPressureModel model = lubrication_.asperity_pressure;
  // The closure's heights are the summit model's surface (its composite sigma): the gap the film
  // fills and the asperities' pressure then describe one surface. (lambda and the ISO formulas take
  // the flanks' own Rq and Ra; for flanks given by Ra or Rq the two are the same.)
  const lub::CompositeHeights heights{gw.surface().surface_sigma, model_.flanks.distribution};
  const double gw_plastic =
      model == lub::AsperityPressureModel::automatic || spectrum_ ? smallest_plastic_fraction(gw, path_.hertz_p0) : 0.0;
  if (!spectrum_) {
    plastic_fraction_ = gw_plastic;
    asperity_.emplace(gw, heights, gw.pair().hardness, bearing_area_weight(model, plastic_fraction_));
    return;
  }
  // Persson's separation law on the flanks' spectrum, the bearing area blended in by his own
  // elastic-plastic theory's plastic share under the whole load at the lightest position; beside
  // it, the asperity model as auto takes it (the closure's spread).
  persson_.emplace(spectrum_->spectrum, mesh_.composite_modulus());
  plastic_fraction_ = 1.0;
  for (double p : path_.hertz_p0)
    if (p > 0.0) plastic_fraction_ = std::min(plastic_fraction_, persson_plastic_fraction(p));
  asperity_.emplace(*persson_, heights, hardness_,
                    bearing_area_weight(lub::AsperityPressureModel::automatic, plastic_fraction_));
  comparison_.emplace(gw, heights, hardness_, bearing_area_weight(lub::AsperityPressureModel::automatic, gw_plastic));
}

double MeshLubrication::persson_plastic_fraction(double p) const {
  // Persson's theory holds below the hardness: a nominal pressure at it has yielded everywhere.
  if (!(p < hardness_)) return 1.0;
  const PerssonAreas a = persson_elastic_plastic(p, mesh_.composite_modulus(), persson_->rms_gradient(), hardness_);
  return a.contact() > 0.0 ? a.plastic / a.contact() : 0.0;
}

std::vector<double> MeshLubrication::asperity_shares() const {
  std::vector<double> out;
  out.reserve(positions_.size());
  for (const Position& q : positions_) out.push_back(q.asperity_share);
  return out;
}

lub::OilState MeshLubrication::oil_at(double t, bool& extrapolated, bool& clamped) const {
  const auto& lubricant = lubrication_.lubricant;
  if (lubricant.fixed()) return lub::oil_state(lubricant, t);
  if (!lub::data_range(lubricant).contains(t)) extrapolated = true;
  if (!oil_range_.contains(t)) {
    clamped = true;
    if (t > oil_range_.hi) t = oil_range_.hi;
    if (t < oil_range_.lo) t = oil_range_.lo;  // (NaN stays NaN: oil_state refuses it)
  }
  return lub::oil_state(lubricant, t, oil_range_);
}

void MeshLubrication::iso_temperatures(const PathPoint& p, Position& q) const {
  q.iso_flash = iso_flash(p);
  q.blok_iso_flash = lub::blok_flash_temperature(iso_mu_, p.line_load, p.half_width, p.v1, p.v2,
                                                 thermal_coefficient_[0], thermal_coefficient_[1]);
}

double MeshLubrication::iso_flash(const PathPoint& p) const {
  const gear::SpurPair& pair = mesh_.pair();
  const double gamma = pair.flank(p.s).roll_parameter;
  // X_Gamma of unmodified profiles; at B and D the single-pair side where the point stands for it
  // (its load sharing factor is then 1).
  const bool single = p.load_sharing_factor >= 1.0;
  const double x_gamma = gear::iso_load_sharing_factor(pair.path(), p.s, single);
  return lub::iso_flash_temperature(
      iso_flash_mu_, iso_x_m_, lub::iso_approach_factor(iso_geometry_, gamma, iso_effective_relief_, iso_tip_relief_),
      lub::iso_geometry_factor(iso_geometry_, gamma), x_gamma, pitch_.tangential_load, pitch_.pitch_line_speed,
      iso_geometry_.center_distance);
}

void MeshLubrication::film(const PathPoint& p, ShareGuesses& guesses, Position& q) const {
  const auto& oil = oil_at_bulk_;
  const lub::FilmLaw& law = lub::film_law(formula_);
  const double u = 0.5 * (p.v1 + p.v2);
  const lub::EhlGroups g =
      lub::ehl_groups(oil.dynamic_viscosity, oil.pressure_viscosity, u, p.line_load, p.radius, reduced_modulus_);
  q.film_isothermal = lub::smooth_film(formula_, g, p.radius);
  const double load =
      lub::thermal_loading(oil.temperature_viscosity, oil.dynamic_viscosity, u, oil.thermal_conductivity);
  const double srr = u > 0.0 ? std::abs(p.v1 - p.v2) / u : 0.0;
  q.heating_factor = lub::inlet_heating_factor(inlet_, load, srr, p.hertz_p0 / reduced_modulus_);
  q.film = q.heating_factor * q.film_isothermal;
  q.regime = static_cast<double>(lub::ehl_regime(g));
  const AsperityPressure& ap = *asperity_;
  const lub::CompositeHeights& heights = ap.heights();
  const double p0 = p.hertz_p0;
  if (!(p.line_load > 0.0)) {
    q.separation = ap.onset();
    q.mean_gap = lub::film_gap(film_gap_, heights, q.separation, q.separation);
    return;
  }
  // The asperities carrying `share` of the Hertz peak at the strip's centre sit at h(share p0); the
  // film fills the closure's gap there (lubrication/film_closure.hpp).
  q.bearing_saturated = ap.saturated(p0) ? 1.0 : 0.0;
  const double exponent = law.speed_exponent - law.material_exponent;
  // A closure's share at a datum, from its own solution at the last position (the path moves
  // smoothly): guesses[slot].
  auto share_for = [&](const AsperityPressure& c, lub::FilmGap gap, std::size_t slot) {
    const double h_dry = c.separation(p0);
    double& guess = guesses[slot];
    const lub::LoadShare s = lub::share_load(
        q.film, exponent, [&](double share) { return lub::film_gap(gap, heights, c.separation(share * p0), h_dry); },
        guess);
    if (s.film_share > 0.0) guess = std::log(s.film_share);
    return s;
  };
  const std::size_t persson_slot = guesses.size() - 1;
  const lub::LoadShare s = share_for(ap, film_gap_, persson_ ? persson_slot : static_cast<std::size_t>(film_gap_));
  q.asperity_share = s.asperity_share;
  q.mean_gap = s.film_thickness;
  q.separation = ap.separation(s.asperity_share * p0);
  if (persson_) q.persson_plastic = persson_plastic_fraction(s.asperity_share * p0);
  // The spread: over the other film gaps; with Persson's law, over the asperity model's closure (as
  // auto takes it) at each film gap beside it.
  double lo = s.asperity_share, hi = s.asperity_share;
  for (lub::FilmGap other : {lub::FilmGap::mean_gap, lub::FilmGap::mean_plane, lub::FilmGap::dry_offset}) {
    if (other == film_gap_ && !persson_) continue;
    const double a = share_for(persson_ ? *comparison_ : ap, other, static_cast<std::size_t>(other)).asperity_share;
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  q.share_spread = hi - lo;
}

MeshLubrication::FilmFriction MeshLubrication::film_friction(const PathPoint& p, const Position& q) const {
  const auto& lubricant = lubrication_.lubricant;
  const double mu_b = model_.flanks.friction;
  const double vs = p.v1 - p.v2, u = 0.5 * (p.v1 + p.v2);
  const double film_share = 1.0 - q.asperity_share;
  const double p_f = p.half_width > 0.0 ? film_share * p.line_load / (2.0 * p.half_width) : 0.0;
  FilmFriction out;
  // The film's traction coefficient at a friction mu: the surfaces at the bulk temperature plus the
  // mean flash temperature over the band that mu makes (Eyring models); the curve at the bulk.
  auto film_coefficient = [&](double mu) {
    if (!(film_share > 0.0) || !(p_f > 0.0) || vs == 0.0) return 0.0;
    if (traction_ == lub::FilmTraction::curve) {
      const lub::TractionValue t =
          lubricant.traction.at(u > 0.0 ? std::abs(vs) / u : 0.0, p.hertz_p0, bulk_temperature_);
      out.curve_outside = t.outside;
      return t.coefficient;
    }
    out.surface_extrapolated = out.surface_clamped = false;
    const lub::OilState surface =
        oil_at(bulk_temperature_ + lub::kBlokMeanOverPeak * blok(p, mu), out.surface_extrapolated, out.surface_clamped);
    const lub::FilmShear shear = lub::film_shear_stress(traction_, surface, p_f, vs, q.mean_gap);
    out.rise = shear.midfilm_rise;
    return shear.shear_stress / p_f;
  };
  // The mixed friction coefficient: mu = share_a mu_b + share_f tau_f/p_f, with p_f the film's mean
  // pressure over the Hertz width (film_share w / 2b).
  auto mix = [&](double film_coef) { return q.asperity_share * mu_b + film_share * film_coef; };
  auto mixed = [&](double mu) { return mix(film_coefficient(mu)); };
  double mu = mixed(0.0);
  if (traction_ != lub::FilmTraction::curve && !lubricant.fixed() && vs != 0.0 && film_share > 0.0) {
    // mu = F(mu): F falls as mu heats the surfaces, so mu - F(mu) rises through one root in [0, top].
    const double top = std::max({mu_b, lubricant.limiting_shear_coefficient, mu});
    const auto g = [&](double m) { return m - mixed(m); };
    if (g(top) > 0.0) {
      std::uintmax_t iterations = 100;
      const auto [a, b] = boost::math::tools::toms748_solve(
          g, 0.0, top, [](double l, double r) { return std::abs(r - l) <= 1e-12 * std::max(1e-6, r); }, iterations);
      mu = 0.5 * (a + b);
    } else {
      mu = top;
    }
  }
  out.film_coefficient = film_coefficient(mu);  // also sets rise, curve_outside and surface_* at the answer
  out.friction = mix(out.film_coefficient);
  return out;
}

double MeshLubrication::blok(const PathPoint& p, double mu) const {
  return lub::blok_flash_temperature(mu, p.line_load, p.half_width, p.v1, p.v2, thermal_coefficient_[0],
                                     thermal_coefficient_[1]);
}

void MeshLubrication::rest(const PathPoint& p, Position& q) const {
  const double face = mesh_.pair().spec().face_width;
  const double k_wear = lubrication_.wear_coefficient;
  const double vs = p.v1 - p.v2;
  const FilmFriction f = film_friction(p, q);
  q.friction = f.friction;
  q.film_traction = f.film_coefficient;
  q.midfilm_rise = f.rise;
  q.curve_outside = f.curve_outside ? 1.0 : 0.0;
  q.flash = blok(p, q.friction);
  q.contact_temperature = bulk_temperature_ + q.flash;
  q.iso_contact_temperature = bulk_temperature_ + q.iso_flash;
  q.power_loss = q.friction * p.line_load * face * std::abs(vs);
  // Archard per engagement: a flank point crosses 2b at its own speed v_i while the other slides
  // |v_s| 2b/v_i past it under the asperities' mean pressure share w/(2b): h = k share w |v_s|/v_i.
  const double asperity_load = q.asperity_share * p.line_load;
  q.wear_pinion = p.v1 > 0.0 ? k_wear * asperity_load * std::abs(vs) / p.v1 : 0.0;
  q.wear_wheel = p.v2 > 0.0 ? k_wear * asperity_load * std::abs(vs) / p.v2 : 0.0;
  // ISO/TS 6336-22: the oil at theta_B = theta_M + theta_fl(mu_mC) (Blok's form with its mu).
  bool contact_extrapolated = false, contact_clamped = false;
  const lub::OilState local = oil_at(bulk_temperature_ + q.blok_iso_flash, contact_extrapolated, contact_clamped);
  q.oil_extrapolated = bulk_extrapolated_ || f.surface_extrapolated || contact_extrapolated ? 1.0 : 0.0;
  q.oil_clamped = f.surface_clamped || contact_clamped ? 1.0 : 0.0;
  q.iso_film = lub::iso_film_hy(p.radius, reduced_modulus_, p.hertz_p0, p.v1 + p.v2, oil_at_bulk_, local);
  q.iso_lambda = q.iso_film / roughness_.mean_ra;
  q.lambda_film = q.film / roughness_.rq;
  q.lambda_gap = q.mean_gap / roughness_.rq;
  bool low = false;
  for (std::size_t g = 0; g < 2; ++g) {
    const Material& m = *model_.flanks.materials[g];
    low = low || lub::peclet_number(g == 0 ? p.v1 : p.v2, p.half_width, m.thermal_conductivity, m.density,
                                    m.specific_heat) < lub::kMinBlokPeclet;
  }
  q.low_peclet = low ? 1.0 : 0.0;
}

LubricationResult MeshLubrication::finish() {
  for (std::size_t i = 0; i < path_.s.size(); ++i) rest(path_.point(i), positions_[i]);
  LubricationResult out;
  out.summary = summary();
  out.verdict = verdict_text(out.summary);
  out.warnings = warnings(out.summary);
  out.bearing_saturated_column = asperity_->bearing_weight() >= 1.0;
  out.persson_column = persson_.has_value();
  out.traction_curve_column = traction_ == lub::FilmTraction::curve;
  out.positions = positions_;
  return out;
}

lub::IsoFlashGeometry iso_flash_geometry(const gear::SpurPair& pair) {
  lub::IsoFlashGeometry g;
  g.gear_ratio = double(pair.gear(1).teeth) / double(pair.gear(0).teeth);
  g.center_distance = pair.center_distance();
  g.operating_angle = pair.operating_pressure_angle();
  g.reference_angle = pair.spec().pressure_angle;
  g.gamma_a = pair.flank(pair.path().a).roll_parameter;
  g.gamma_e = pair.flank(pair.path().e).roll_parameter;
  return g;
}

void add_lubrication_series(const LubricationResult& l, std::vector<Series>& g) {
  using C = Column<Position>;
  add_columns<Position>(
      g, l.positions,
      {C{"film_isothermal_m", "m", [](const Position& q) { return q.film_isothermal; }},
       C{"inlet_heating_factor", "1", [](const Position& q) { return q.heating_factor; }},
       C{"film_m", "m", [](const Position& q) { return q.film; }},
       C{"lambda_smooth_film", "1", [](const Position& q) { return q.lambda_film; }},
       C{"ehl_regime", "1", [](const Position& q) { return q.regime; }},
       C{"mean_plane_separation_m", "m", [](const Position& q) { return q.separation; }},
       C{"mean_gap_m", "m", [](const Position& q) { return q.mean_gap; }},
       C{"lambda_mean_gap", "1", [](const Position& q) { return q.lambda_gap; }},
       C{"asperity_load_share", "1", [](const Position& q) { return q.asperity_share; }},
       C{"film_load_share", "1", [](const Position& q) { return 1.0 - q.asperity_share; }},
       C{"asperity_share_closure_spread", "1", [](const Position& q) { return q.share_spread; }},
       C{"friction_coefficient", "1", [](const Position& q) { return q.friction; }},
       C{"film_traction_coefficient", "1", [](const Position& q) { return q.film_traction; }},
       C{"film_midplane_temperature_rise_K", "K", [](const Position& q) { return q.midfilm_rise; }},
       C{"pair_power_loss_W", "W", [](const Position& q) { return q.power_loss; }},
       C{"flash_temperature_K", "K", [](const Position& q) { return q.flash; }},
       C{"contact_temperature_K", "K", [](const Position& q) { return q.contact_temperature; }},
       C{"iso_flash_temperature_K", "K", [](const Position& q) { return q.iso_flash; }},
       C{"iso_contact_temperature_K", "K", [](const Position& q) { return q.iso_contact_temperature; }},
       C{"blok_flash_temperature_iso_mu_K", "K", [](const Position& q) { return q.blok_iso_flash; }},
       C{"iso_film_hy_m", "m", [](const Position& q) { return q.iso_film; }},
       C{"iso_lambda_gf", "1", [](const Position& q) { return q.iso_lambda; }},
       C{"wear_depth_pinion_m", "m", [](const Position& q) { return q.wear_pinion; }},
       C{"wear_depth_wheel_m", "m", [](const Position& q) { return q.wear_wheel; }},
       C{"flag_low_peclet", "1", [](const Position& q) { return q.low_peclet; }},
       C{"flag_oil_extrapolated", "1", [](const Position& q) { return q.oil_extrapolated; }},
       C{"flag_oil_temperature_clamped", "1", [](const Position& q) { return q.oil_clamped; }},
       C{"flag_share_depends_on_closure", "1",
         [](const Position& q) { return q.share_spread > kClosureSpreadFlag ? 1.0 : 0.0; }}});
  if (l.bearing_saturated_column)
    add_columns<Position>(
        g, l.positions, {C{"flag_bearing_area_saturated", "1", [](const Position& q) { return q.bearing_saturated; }}});
  if (l.persson_column)
    add_columns<Position>(g, l.positions,
                          {C{"persson_plastic_area_fraction", "1", [](const Position& q) { return q.persson_plastic; }},
                           C{"flag_persson_plastic", "1",
                             [](const Position& q) { return q.persson_plastic > kPerssonPlasticFlag ? 1.0 : 0.0; }}});
  if (l.traction_curve_column)
    add_columns<Position>(
        g, l.positions,
        {C{"flag_traction_curve_extrapolated", "1", [](const Position& q) { return q.curve_outside; }}});
}

LubricationSummary MeshLubrication::summary() const {
  const lub::LubricationSettings& lc = lubrication_;
  LubricationSummary sum;
  sum.lubricant = lc.lubricant.name;
  sum.film_formula = lub::film_formula_name(lc.film_formula);
  sum.inlet_heating = lub::inlet_heating_name(lc.inlet_heating);
  sum.film_gap = lub::film_gap_name(lc.film_gap);
  sum.asperity_pressure = lub::asperity_pressure_model_name(lc.asperity_pressure);
  sum.bearing_area_weight = asperity_->bearing_weight();
  sum.traction = lub::film_traction_name(lc.traction);
  sum.bulk_friction_law = lub::mean_friction_law_name(lc.mean_friction);
  sum.oil_temperature = operating_.oil_temperature;
  sum.bulk_temperature = bulk_temperature_;
  sum.bulk_estimated = bulk_estimated_;
  sum.dynamic_viscosity = oil_at_bulk_.dynamic_viscosity;
  sum.pressure_viscosity = oil_at_bulk_.pressure_viscosity;
  sum.composite_rq = roughness_.rq;
  sum.mean_ra = roughness_.mean_ra;
  sum.roughness_source = roughness_.source;
  sum.summit_model_sigma = model_.surface.surface_sigma;
  if (persson_) {
    sum.persson_spectrum = spectrum_->sources();
    sum.persson_rms_height = persson_->rms_height();
    sum.persson_rms_gradient = persson_->rms_gradient();
  }
  sum.iso_effective_relief = iso_effective_relief_;
  for (const auto& [law, f] : mean_laws_)
    sum.mean_friction.push_back({lub::mean_friction_law_name(law), f.coefficient});
  losses(sum);
  sum.max_contact_temperature = largest(positions_, &Position::contact_temperature);
  sum.max_iso_contact_temperature = largest(positions_, &Position::iso_contact_temperature);
  sum.min_iso_lambda = smallest(positions_, &Position::iso_lambda);
  sum.min_lambda_film = smallest(positions_, &Position::lambda_film);
  sum.max_share_spread = largest(positions_, &Position::share_spread);
  sum.oil_clamped_positions = static_cast<int>(
      std::count_if(positions_.begin(), positions_.end(), [](const Position& q) { return q.oil_clamped > 0.0; }));
  sum.closure_dependent_positions = static_cast<int>(std::count_if(
      positions_.begin(), positions_.end(), [](const Position& q) { return q.share_spread > kClosureSpreadFlag; }));
  if (lc.scuffing_temperature > 0.0) {
    const double t_s = lc.scuffing_temperature, t_oil = operating_.oil_temperature;
    sum.iso_scuffing_safety = lub::iso_scuffing_safety(t_s, t_oil, sum.max_iso_contact_temperature);
    sum.scuffing_safety = lub::iso_scuffing_safety(t_s, t_oil, sum.max_contact_temperature);
  }
  sum.points = named_points();
  return sum;
}

void MeshLubrication::losses(LubricationSummary& sum) const {
  const auto& p = path_;
  const std::size_t n = p.s.size();
  const gear::SpurPair& pair = mesh_.pair();
  const gear::PathOfContact& path = pair.path();
  // Time average over one mesh cycle of all pairs in contact: each pair sweeps A -> E at the
  // base speed, so the mean is (1/p_b) int_A^E P ds.
  sum.mesh_power_loss = path_mean(series(positions_, &Position::power_loss)) * path.length / path.base_pitch;
  const double omega = mesh_.pinion_speed();
  sum.input_power = operating_.pinion_torque * omega;
  sum.efficiency = sum.input_power > 0.0 ? 1.0 - sum.mesh_power_loss / sum.input_power : 1.0;
  const double base_load = pitch_.normal_load;  // F_bn/b [N/m]
  const double base_speed = omega * pair.gear(0).base_radius;
  std::vector<double> integrand;
  for (std::size_t i = 0; i < n; ++i)
    integrand.push_back(p.line_load[i] / base_load * std::abs(p.v1[i] - p.v2[i]) / base_speed);
  sum.loss_factor_path = path_mean(integrand) * path.length / path.base_pitch;
  const double z1 = pair.gear(0).teeth, u = double(pair.gear(1).teeth) / z1;
  const double e1 = (path.e - path.c) / path.base_pitch, e2 = (path.c - path.a) / path.base_pitch;
  sum.loss_factor_ohlendorf = std::numbers::pi * (u + 1.0) / (z1 * u) * (1.0 - path.contact_ratio + e1 * e1 + e2 * e2);
  // The gear-mean friction the FZG power-loss test measures: P = mu_mz P_in H_V (Ohlendorf's
  // definition), with the path's H_V.
  sum.mesh_mean_friction = sum.loss_factor_path > 0.0 && sum.input_power > 0.0
                               ? sum.mesh_power_loss / (sum.input_power * sum.loss_factor_path)
                               : 0.0;
}

std::vector<LubricationSummary::NamedPoint> MeshLubrication::named_points() const {
  // The named points, each evaluated where it stands (B and D with the single pair's load).
  std::vector<LubricationSummary::NamedPoint> out;
  for (const auto& [name, point] : path_.named) {
    ShareGuesses guesses;
    guesses.fill(std::numeric_limits<double>::quiet_NaN());
    Position q;
    iso_temperatures(point, q);
    film(point, guesses, q);
    rest(point, q);
    LubricationSummary::NamedPoint np;
    np.name = name;
    np.s = point.s;
    np.line_load = point.line_load;
    np.film = q.film;
    np.lambda_film = q.lambda_film;
    np.mean_gap = q.mean_gap;
    np.lambda_gap = q.lambda_gap;
    np.iso_film = q.iso_film;
    np.iso_lambda = q.iso_lambda;
    np.asperity_share = q.asperity_share;
    np.share_spread = q.share_spread;
    np.friction = q.friction;
    np.flash = q.flash;
    np.iso_flash = q.iso_flash;
    np.contact_temperature = q.contact_temperature;
    np.iso_contact_temperature = q.iso_contact_temperature;
    out.push_back(np);
  }
  return out;
}

double MeshLubrication::sigma_ratio() const { return model_.surface.surface_sigma / roughness_.rq; }

bool MeshLubrication::surfaces_disagree() const {
  // The summit model's sigma against the flanks' Rq: a measured surface can disagree.
  const double r = sigma_ratio();
  return roughness_.from_heights && (r > kRoughnessDisagreementFactor || r < 1.0 / kRoughnessDisagreementFactor);
}

std::string MeshLubrication::spectrum_text() const {
  const FlankSpectrum& f = *spectrum_;
  if (f.source[0] == SpectrumSource::fitted) {
    const SpectrumPart& p = f.spectrum.parts.front();
    return fmt::format(
        "a self-affine spectrum fitted to the summit model's moments (H = {:g}, roll-off {:.3g} um, shortest "
        "wavelength {:.3g} um{})",
        p.hurst, 2e6 * std::numbers::pi / p.rolloff, 2e6 * std::numbers::pi / p.cutoff,
        lubrication_.persson_spectrum == lub::PerssonSpectrum::moments ? "; lubrication.persson_spectrum = moments"
        : f.fell_back ? "; one flank alone has a spectrum of its own, and it is not added to a fit that holds it"
                      : "");
  }
  // A measured patch's wavelengths [um], what it resolves.
  const auto band = [&](std::size_t g) {
    return fmt::format("{:.3g}-{:.3g} um", f.shortest[g] * 1e6, f.longest[g] * 1e6);
  };
  if (f.source[0] == f.source[1])
    return f.source[0] == SpectrumSource::measured
               ? fmt::format("the measured patches' radial spectra (the wavelengths they resolve: {} and {})", band(0),
                             band(1))
               : std::string("the ground profiles' Gaussian spectra taken isotropic");
  std::string text;
  for (std::size_t g = 0; g < 2; ++g) {
    text += g == 0 ? "the pinion's " : " and the wheel's ";
    text += f.source[g] == SpectrumSource::measured
                ? "measured patch's radial spectrum (the wavelengths it resolves: " + band(g) + ")"
                : std::string("ground profile's Gaussian spectrum taken isotropic");
  }
  return text;
}

std::string MeshLubrication::verdict_text(const LubricationSummary& sum) const {
  // What produced the numbers and where they rest on a choice: said in the verdict.
  const std::size_t n = positions_.size();
  const std::string asperity_model(model_.table.model().name());
  const double w = sum.bearing_area_weight;
  const std::string why =
      lubrication_.asperity_pressure == lub::AsperityPressureModel::automatic
          ? fmt::format(" (its plastic area fraction under the whole load at least {:.3g}; plasticity index {:.3g})",
                        plastic_fraction_, plasticity_index_)
          : fmt::format(" (lubrication.asperity_pressure = {})",
                        lub::asperity_pressure_model_name(lubrication_.asperity_pressure));
  std::string pressure = w >= 1.0   ? "by their bearing area at the hardness, the flanks fully plastic" + why
                         : w <= 0.0 ? fmt::format("by the {} model{}", asperity_model, why)
                                    : fmt::format("by a blend, {:.2f} bearing area and {:.2f} {} model{}", w, 1.0 - w,
                                                  asperity_model, why);
  if (persson_) {
    // The spectrum named in either case: it sets his plastic share (the blend's weight) as well as his law.
    const std::string law =
        fmt::format("Persson's interfacial separation law (elastic; u0 {:.3g} um)", persson_->decay_length() * 1e6);
    const std::string plastic = fmt::format(
        "; Persson's theory on {} (rq {:.3g} um, h'_rms {:.3g}): his elastic-plastic share puts at least {:.3g} of "
        "the real area at the hardness under the whole load",
        spectrum_text(), persson_->rms_height() * 1e6, persson_->rms_gradient(), plastic_fraction_);
    pressure = w >= 1.0   ? "by their bearing area at the hardness, the flanks fully plastic" + plastic
               : w <= 0.0 ? "by " + law + plastic
                          : fmt::format("by a blend, {:.2f} bearing area and {:.2f} {}{}", w, 1.0 - w, law, plastic);
  }
  std::string text =
      fmt::format(" Lubricated ({}): the film fills the {} and the asperities press {}", sum.lubricant,
                  persson_ && w < 1.0                     ? "mean gap between the deformed rough flanks (Persson's)"
                  : film_gap_ == lub::FilmGap::mean_gap   ? "mean gap between the rough flanks"
                  : film_gap_ == lub::FilmGap::mean_plane ? "separation of the mean planes between the rough flanks"
                                                          : "gap counted from the dry contact between the rough flanks",
                  pressure);
  const std::string between =
      persson_ ? fmt::format(
                     "Persson's law and the {} model's closure at the mean gap, the mean plane and the "
                     "dry-contact datum",
                     asperity_model)
               : "the mean gap, the mean plane and the dry-contact datum";
  if (sum.closure_dependent_positions > 0) {
    const auto worst = std::max_element(positions_.begin(), positions_.end(), [](const Position& a, const Position& b) {
      return a.share_spread < b.share_spread;
    });
    text += fmt::format(
        "; the asperity share depends on that choice at {} of {} positions (it moves by up to {:.3f} between {}, at "
        "s = {:.3f} mm): there it is a model's estimate",
        sum.closure_dependent_positions, n, worst->share_spread, between,
        path_.s[static_cast<std::size_t>(worst - positions_.begin())] * 1e3);
  } else {
    text += fmt::format("; the asperity share moves by at most {:.3f} between {}", sum.max_share_spread,
                        persson_ ? between : std::string("the film datums"));
  }
  const auto& l = lubrication_.lubricant;
  text += traction_ == lub::FilmTraction::curve
              ? fmt::format(". Friction: the film's traction from {}'s measured traction curves", l.name)
              : fmt::format(". Friction: the film's {} traction (tau0 {:.3g} MPa, Lambda {:.3g}, from {})",
                            traction_ == lub::FilmTraction::thermal_eyring ? "thermal Eyring" : "isothermal Eyring",
                            l.eyring_stress * 1e-6, l.limiting_shear_coefficient,
                            l.fixed() ? "the case's fixed oil" : "the lubricant file");
  text += fmt::format(
      " and the asperities' boundary coefficient {:g} (friction.mu); the model's gear-mean {:.4f} "
      "against ISO/TS 6336-21/-22's {:.4f}.",
      model_.flanks.friction, sum.mesh_mean_friction, iso_mu_);
  if (sum.oil_clamped_positions > 0)
    text += fmt::format(
        " At {} of {} positions the surfaces pass {:.1f} degC, the hottest at which the oil's laws hold: its "
        "traction and h_Y there are upper bounds (flag_oil_temperature_clamped).",
        sum.oil_clamped_positions, n, oil_range_.hi - kC);
  if (surfaces_disagree())
    text += fmt::format(
        " The asperity model's surface is not the measured one: its composite sigma is {:.3g} times the flanks' Rq "
        "(lambda and the ISO formulas take the Rq; the sharing, the summit model).",
        sigma_ratio());
  return text;
}

// Where the oil's laws are left behind: the bulk, the surfaces and ISO's contact temperature.
void MeshLubrication::oil_warnings(const LubricationSummary& sum, std::vector<std::string>& out) const {
  const auto& l = lubrication_.lubricant;
  const std::size_t n = positions_.size();
  if (l.fixed()) return;
  if (bulk_temperature_ < l.min_temperature || bulk_temperature_ > l.max_temperature)
    out.push_back(
        fmt::format("bulk temperature {:.1f} degC{} lies outside {}'s data range [{:.0f}, {:.0f}] "
                    "degC: the film's viscosity is extrapolated (Walther; flag_oil_extrapolated everywhere)",
                    bulk_temperature_ - kC, bulk_estimated_ ? " (ISO estimate)" : "", l.name, l.min_temperature - kC,
                    l.max_temperature - kC));
  const double hottest = bulk_temperature_ + largest(positions_, &Position::blok_iso_flash);
  const double hottest_surface = bulk_temperature_ + lub::kBlokMeanOverPeak * largest(positions_, &Position::flash);
  if (sum.oil_clamped_positions > 0)
    out.push_back(fmt::format(
        "{} of {} positions (flag_oil_temperature_clamped) where the film's surfaces or ISO/TS 6336-22's contact "
        "temperature (up to {:.1f} degC) pass {:.1f} degC, the hottest at which {}'s laws hold: the oil's viscosity "
        "and alpha are taken at {:.1f} degC there, a thicker oil than it is: the film's traction and h_Y there are "
        "upper bounds, not values",
        sum.oil_clamped_positions, n, std::max(hottest, hottest_surface) - kC, oil_range_.hi - kC, l.name,
        oil_range_.hi - kC));
  if (hottest > l.max_temperature)
    out.push_back(
        fmt::format("ISO/TS 6336-22 h_Y evaluates the oil at contact temperatures up to {:.1f} degC, "
                    "beyond {}'s data ({:.0f} degC): its sliding parameter S_GF is extrapolated "
                    "(flag_oil_extrapolated)",
                    hottest - kC, l.name, l.max_temperature - kC));
  if (hottest_surface > l.max_temperature)
    out.push_back(
        fmt::format("the film's traction takes the oil at the surfaces' temperature, up to {:.1f} degC, beyond "
                    "{}'s data ({:.0f} degC): its viscosity there is extrapolated (flag_oil_extrapolated)",
                    hottest_surface - kC, l.name, l.max_temperature - kC));
}

// The traction curves used beyond where they were measured.
void MeshLubrication::curve_warnings(std::vector<std::string>& out) const {
  if (traction_ != lub::FilmTraction::curve) return;
  if (largest(positions_, &Position::curve_outside) > 0.0)
    out.push_back(fmt::format(
        "{} of {} positions beyond the traction curves' measured SRR, pressure or "
        "temperature (flag_traction_curve_extrapolated): the nearest values are used",
        std::count_if(positions_.begin(), positions_.end(), [](const Position& q) { return q.curve_outside > 0.0; }),
        positions_.size()));
  for (const auto& curve : lubrication_.lubricant.traction.curves()) {
    const double u = 0.5 * pitch_.sum_speed;
    if (u > 2.0 * curve.entrainment_speed || u < 0.5 * curve.entrainment_speed) {
      out.push_back(
          fmt::format("traction curve '{}' was measured at {:.3g} m/s entrainment speed; the "
                      "pitch point runs at {:.3g} m/s (the curves are used as measured)",
                      curve.name, curve.entrainment_speed, u));
      break;
    }
  }
}

std::vector<std::string> MeshLubrication::warnings(const LubricationSummary& sum) const {
  // Where the lubricated models leave their ranges: said, not silent.
  std::vector<std::string> out;
  const std::size_t n = positions_.size();
  oil_warnings(sum, out);
  const auto low = std::count_if(positions_.begin(), positions_.end(), [](const Position& q) { return q.low_peclet; });
  if (low > 0)
    out.push_back(
        fmt::format("{} of {} positions with a Peclet number below {:g} (flag_low_peclet): Blok's "
                    "flash temperature assumes fast-moving surfaces and overestimates there",
                    low, n, lub::kMinBlokPeclet));
  for (const auto& [law, f] : mean_laws_)
    if (f.below_speed_range) {
      out.push_back(fmt::format(
          "the ISO and gear-mean friction formulas are fitted above 1 m/s pitch-line speed; here {:.3g} m/s: their "
          "mean coefficients ({} {:.4f}) are extrapolations (the standards expect more friction at such speeds)",
          pitch_.pitch_line_speed, lub::mean_friction_law_name(law), f.coefficient));
      break;
    }
  if (!roughness_.from_heights)
    out.emplace_back(
        "the flanks are given by summit statistics alone: lambda and the ISO formulas take the summit model's "
        "composite sigma, not a measured Rq and Ra");
  else if (surfaces_disagree())
    out.push_back(fmt::format(
        "the summit model's composite sigma {:.4g} um differs from the flanks' Rq {:.4g} um ({}) by a factor {:.3g}: "
        "the Greenwood-Williamson parameters describe another surface than the one measured; lambda and the ISO "
        "formulas take the flanks' Rq and Ra, the asperity contact and the sharing the summit model",
        model_.surface.surface_sigma * 1e6, roughness_.rq * 1e6, roughness_.source, sigma_ratio()));
  if (persson_) {
    const auto yielded = std::count_if(positions_.begin(), positions_.end(),
                                       [](const Position& q) { return q.persson_plastic > kPerssonPlasticFlag; });
    if (yielded > 0 && asperity_->bearing_weight() < 1.0)
      out.push_back(fmt::format(
          "{} of {} positions (flag_persson_plastic) where Persson's elastic-plastic theory puts more than {:g} of the "
          "real area at the hardness under the asperities' share (up to {:.3g}): his separation law is elastic and "
          "overstates the pressure the yielded contacts carry at a gap, and with it the asperities' share",
          yielded, n, kPerssonPlasticFlag, largest(positions_, &Position::persson_plastic)));
  }
  if (largest(positions_, &Position::bearing_saturated) > 0.0)
    out.emplace_back(
        "the Hertz pressure reaches the hardness at some positions (flag_bearing_area_saturated): the bearing-area "
        "model has flattened the flanks completely there");
  curve_warnings(out);
  return out;
}

}  // namespace geartrib::contact
