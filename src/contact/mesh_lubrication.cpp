#include "contact/mesh_lubrication.hpp"

#include "contact/series_columns.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/mixed_lubrication.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

namespace geartrib::contact {

namespace lub = lubrication;

double mean_arithmetic_roughness(const Case& c, const surface::EquivalentSurface& s) {
  using Form = surface::FlankRoughness::Form;
  const auto& a = c.pinion.flank.roughness;
  const auto& b = c.wheel.flank.roughness;
  if (a.form == Form::ra && b.form == Form::ra) return 0.5 * (a.ra + b.ra);
  if (a.form == Form::rq && b.form == Form::rq) return 0.5 * (a.rq + b.rq) / surface::kRqOverRaGaussian;
  return s.surface_sigma / (std::numbers::sqrt2 * surface::kRqOverRaGaussian);
}

namespace {
using Position = MeshLubrication::Position;
// Linear interpolation of one field over the evenly spaced positions s at x.
double at(const std::vector<double>& s, const std::vector<Position>& v, double Position::*field, double x) {
  if (v.size() < 2) return v.empty() ? 0.0 : v.front().*field;
  const double t = std::clamp((x - s.front()) / (s.back() - s.front()), 0.0, 1.0) * double(v.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(t), v.size() - 2);
  return v[i].*field + (t - double(i)) * (v[i + 1].*field - v[i].*field);
}
double largest(const std::vector<Position>& v, double Position::*field) {
  double m = -std::numeric_limits<double>::infinity();
  for (const Position& q : v) m = std::max(m, q.*field);
  return m;
}
}  // namespace

MeshLubrication::MeshLubrication(const Case& c, const gear::GearMesh& mesh, const PathState& p,
                                 const GreenwoodWilliamson& gw)
    : case_(c),
      mesh_(mesh),
      path_(p),
      formula_(lub::film_formula_from_name(c.lubrication.film_formula)),
      inlet_(lub::inlet_heating_from_name(c.lubrication.inlet_heating)) {
  const auto& lubricant = c.lubrication.lubricant;
  reduced_modulus_ = 2.0 * mesh.composite_modulus();
  for (int g = 0; g < 2; ++g) {
    const Material& m = (g == 0 ? c.pinion : c.wheel).material;
    thermal_coefficient_[g] = lub::thermal_contact_coefficient(m.thermal_conductivity, m.density, m.specific_heat);
  }
  composite_rq_ = gw.surface().surface_sigma;
  mean_ra_ = mean_arithmetic_roughness(c, gw.surface());
  oil_at_inlet_ = lub::oil_state(lubricant, c.operating.oil_temperature);

  // ISO/TS 6336-20 mean friction at the pitch point and its flash temperature along the path.
  const gear::SpurPair& pair = mesh.pair();
  const double face = pair.spec().face_width;
  const double tangential_load = c.operating.pinion_torque / pair.gear(0).pitch_radius / face;  // w_Bt [N/m]
  const gear::FlankKinematics kc = pair.kinematics(pair.path().c, mesh.pinion_speed());
  iso_friction_ = lub::iso_mean_friction(tangential_load, kc.rolling_pinion + kc.rolling_wheel,
                                         pair.flank(pair.path().c).radius_equivalent, oil_at_inlet_.dynamic_viscosity,
                                         mean_ra_, oil_at_inlet_.iso_lubricant_factor);
  const std::size_t n = p.s.size();
  positions_.resize(n);
  std::vector<double> iso_flash;
  for (std::size_t i = 0; i < n; ++i)
    iso_flash.push_back(positions_[i].iso_flash =
                            lub::blok_flash_temperature(iso_friction_, p.line_load[i], p.half_width[i], p.v1[i],
                                                        p.v2[i], thermal_coefficient_[0], thermal_coefficient_[1]));
  bulk_estimated_ = !(c.operating.bulk_temperature > 0.0);
  bulk_temperature_ = bulk_estimated_ ? lub::iso_bulk_temperature(c.operating.oil_temperature, path_mean(iso_flash))
                                      : c.operating.bulk_temperature;
  oil_at_bulk_ = lub::oil_state(lubricant, bulk_temperature_);

  // The smooth film at the bulk temperature, corrected for inlet heating, and the load shares.
  const lub::FilmLaw& law = lub::film_law(formula_);
  const double summit_offset = gw.surface().summit_mean_height;
  const auto& oil = oil_at_bulk_;
  double guess = std::numeric_limits<double>::quiet_NaN();  // ln(film share) at the last position
  for (std::size_t i = 0; i < n; ++i) {
    Position& q = positions_[i];
    const double u = 0.5 * (p.v1[i] + p.v2[i]);
    const lub::EhlGroups g = lub::ehl_groups(oil.dynamic_viscosity, oil.pressure_viscosity, u, p.line_load[i],
                                             p.radius[i], reduced_modulus_);
    q.film_isothermal = lub::smooth_film(formula_, g, p.radius[i]);
    const double load =
        lub::thermal_loading(oil.temperature_viscosity, oil.dynamic_viscosity, u, oil.thermal_conductivity);
    const double srr = u > 0.0 ? std::abs(p.v1[i] - p.v2[i]) / u : 0.0;
    q.heating_factor = lub::inlet_heating_factor(inlet_, load, srr, p.hertz_p0[i] / reduced_modulus_);
    q.film = q.heating_factor * q.film_isothermal;
    q.regime = static_cast<double>(lub::ehl_regime(g));
    const double p0 = p.hertz_p0[i];
    // Mean-plane separation of the asperities carrying `share` of the Hertz pressure. Where the
    // dry contact (share 1) would press them below the mean plane (GW beyond its range; the
    // validity flags say so), the film's gap is counted from the dry contact's separation, so that
    // a vanishing film gives the dry result and the film never carries load at a negative gap.
    const double dry = gw.separation_for_pressure(p0) + summit_offset;
    const double below = std::min(0.0, dry);
    const auto gap = [&](double share) { return gw.separation_for_pressure(share * p0) + summit_offset - below; };
    q.gap_from_dry = below < 0.0 ? 1.0 : 0.0;
    if (p.line_load[i] > 0.0) {
      const lub::LoadShare s = lub::share_load(q.film, law.speed_exponent - law.material_exponent, gap, guess);
      if (s.film_share > 0.0) guess = std::log(s.film_share);
      q.asperity_share = s.asperity_share;
      q.film_gap = s.film_thickness;
    } else {
      q.film_gap = gap(0.0);
    }
    q.separation = q.film_gap + below;
  }
}

void MeshLubrication::finish(MeshContactResult& r) {
  const Case& c = case_;
  const auto& p = path_;
  const std::size_t n = p.s.size();
  const double face = mesh_.pair().spec().face_width;
  const double mu_b = c.friction_coefficient, k_wear = c.lubrication.wear_coefficient;
  for (std::size_t i = 0; i < n; ++i) {
    Position& q = positions_[i];
    const double vs = p.v1[i] - p.v2[i];
    const lub::LoadShare share{q.asperity_share, 1.0 - q.asperity_share, q.film_gap};
    const lub::MixedFriction f = lub::mixed_friction(oil_at_bulk_, share, mu_b, p.line_load[i], p.half_width[i], vs);
    q.friction = f.coefficient;
    q.film_traction = f.film_coefficient;
    q.flash = lub::blok_flash_temperature(f.coefficient, p.line_load[i], p.half_width[i], p.v1[i], p.v2[i],
                                          thermal_coefficient_[0], thermal_coefficient_[1]);
    q.contact_temperature = bulk_temperature_ + q.flash;
    q.iso_contact_temperature = bulk_temperature_ + q.iso_flash;
    q.power_loss = f.coefficient * p.line_load[i] * face * std::abs(vs);
    // Archard per engagement: a flank point crosses 2b at its own speed v_i while the other slides
    // |v_s| 2b/v_i past it under the asperities' mean pressure share w/(2b): h = k share w |v_s|/v_i.
    const double asperity_load = q.asperity_share * p.line_load[i];
    q.wear_pinion = p.v1[i] > 0.0 ? k_wear * asperity_load * std::abs(vs) / p.v1[i] : 0.0;
    q.wear_wheel = p.v2[i] > 0.0 ? k_wear * asperity_load * std::abs(vs) / p.v2[i] : 0.0;
    const lub::OilState local = lub::oil_state(c.lubrication.lubricant, q.iso_contact_temperature);
    q.iso_film = lub::iso_film_hy(p.radius[i], reduced_modulus_, p.hertz_p0[i], p.v1[i] + p.v2[i], oil_at_bulk_, local);
    q.iso_lambda = q.iso_film / mean_ra_;
    q.lambda = q.film / composite_rq_;
    bool low = false;
    for (int g = 0; g < 2; ++g) {
      const Material& m = (g == 0 ? c.pinion : c.wheel).material;
      low = low || lub::peclet_number(g == 0 ? p.v1[i] : p.v2[i], p.half_width[i], m.thermal_conductivity, m.density,
                                      m.specific_heat) < lub::kMinBlokPeclet;
    }
    q.low_peclet = low ? 1.0 : 0.0;
  }
  using C = Column<Position>;
  add_columns<Position>(r.lubrication, positions_,
                        {C{"film_isothermal_m", "m", [](const Position& q) { return q.film_isothermal; }},
                         C{"inlet_heating_factor", "1", [](const Position& q) { return q.heating_factor; }},
                         C{"film_m", "m", [](const Position& q) { return q.film; }},
                         C{"lambda", "1", [](const Position& q) { return q.lambda; }},
                         C{"ehl_regime", "1", [](const Position& q) { return q.regime; }},
                         C{"separation_m", "m", [](const Position& q) { return q.separation; }},
                         C{"asperity_load_share", "1", [](const Position& q) { return q.asperity_share; }},
                         C{"film_load_share", "1", [](const Position& q) { return 1.0 - q.asperity_share; }},
                         C{"friction_coefficient", "1", [](const Position& q) { return q.friction; }},
                         C{"film_traction_coefficient", "1", [](const Position& q) { return q.film_traction; }}});
  add_series(r.lubrication, "iso_friction_coefficient", "1").assign(n, iso_friction_);
  add_columns<Position>(
      r.lubrication, positions_,
      {C{"power_loss_W", "W", [](const Position& q) { return q.power_loss; }},
       C{"flash_temperature_K", "K", [](const Position& q) { return q.flash; }},
       C{"contact_temperature_K", "K", [](const Position& q) { return q.contact_temperature; }},
       C{"iso_flash_temperature_K", "K", [](const Position& q) { return q.iso_flash; }},
       C{"iso_contact_temperature_K", "K", [](const Position& q) { return q.iso_contact_temperature; }},
       C{"iso_film_hy_m", "m", [](const Position& q) { return q.iso_film; }},
       C{"iso_lambda_gf", "1", [](const Position& q) { return q.iso_lambda; }},
       C{"wear_depth_pinion_m", "m", [](const Position& q) { return q.wear_pinion; }},
       C{"wear_depth_wheel_m", "m", [](const Position& q) { return q.wear_wheel; }},
       C{"flag_low_peclet", "1", [](const Position& q) { return q.low_peclet; }},
       C{"flag_gap_from_dry_contact", "1", [](const Position& q) { return q.gap_from_dry; }}});

  LubricationSummary sum;
  sum.lubricant = c.lubrication.lubricant.name;
  sum.film_formula = c.lubrication.film_formula;
  sum.inlet_heating = c.lubrication.inlet_heating;
  sum.oil_temperature = c.operating.oil_temperature;
  sum.bulk_temperature = bulk_temperature_;
  sum.bulk_estimated = bulk_estimated_;
  sum.dynamic_viscosity = oil_at_bulk_.dynamic_viscosity;
  sum.pressure_viscosity = oil_at_bulk_.pressure_viscosity;
  sum.iso_friction = iso_friction_;
  sum.composite_rq = composite_rq_;
  sum.mean_ra = mean_ra_;
  const gear::SpurPair& pair = mesh_.pair();
  const gear::PathOfContact& path = pair.path();
  // Time average over one mesh cycle of all pairs in contact: each pair sweeps A -> E at the
  // base speed, so the mean is (1/p_b) int_A^E P ds.
  sum.mean_power_loss = path_mean(r.find("power_loss_W")->values) * path.length / path.base_pitch;
  const double omega = mesh_.pinion_speed();
  sum.input_power = c.operating.pinion_torque * omega;
  {
    const double base_load = c.operating.pinion_torque / pair.gear(0).base_radius / face;  // F_bt/b [N/m]
    const double base_speed = omega * pair.gear(0).base_radius;
    std::vector<double> integrand;
    for (std::size_t i = 0; i < n; ++i)
      integrand.push_back(p.line_load[i] / base_load * std::abs(p.v1[i] - p.v2[i]) / base_speed);
    sum.loss_factor_path = path_mean(integrand) * path.length / path.base_pitch;
    const double z1 = pair.gear(0).teeth, u = double(pair.gear(1).teeth) / z1;
    const double e1 = (path.e - path.c) / path.base_pitch, e2 = (path.c - path.a) / path.base_pitch;
    sum.loss_factor_ohlendorf =
        std::numbers::pi * (u + 1.0) / (z1 * u) * (1.0 - path.contact_ratio + e1 * e1 + e2 * e2);
  }
  if (c.lubrication.scuffing_temperature > 0.0) {
    const double t_s = c.lubrication.scuffing_temperature, t_oil = c.operating.oil_temperature;
    sum.iso_scuffing_safety =
        lub::iso_scuffing_safety(t_s, t_oil, largest(positions_, &Position::iso_contact_temperature));
    sum.scuffing_safety = lub::iso_scuffing_safety(t_s, t_oil, largest(positions_, &Position::contact_temperature));
  }
  const std::pair<const char*, double> named[] = {
      {"A", path.a}, {"AB", 0.5 * (path.a + path.b)}, {"B", path.b}, {"C", path.c},
      {"D", path.d}, {"DE", 0.5 * (path.d + path.e)}, {"E", path.e}};
  for (const auto& [name, s] : named)
    sum.points.push_back({name, s, at(p.s, positions_, &Position::film, s), at(p.s, positions_, &Position::lambda, s),
                          at(p.s, positions_, &Position::iso_film, s), at(p.s, positions_, &Position::iso_lambda, s),
                          at(p.s, positions_, &Position::asperity_share, s)});
  r.lubrication_summary = std::move(sum);

  // Where the lubricated models leave their ranges: said, not silent.
  const auto& l = c.lubrication.lubricant;
  if (!l.fixed()) {
    constexpr double kC = 273.15;
    if (bulk_temperature_ < l.min_temperature || bulk_temperature_ > l.max_temperature)
      r.warnings.push_back(
          fmt::format("bulk temperature {:.1f} degC{} lies outside {}'s data range [{:.0f}, {:.0f}] "
                      "degC: the film's viscosity is extrapolated (Walther)",
                      bulk_temperature_ - kC, bulk_estimated_ ? " (ISO estimate)" : "", l.name, l.min_temperature - kC,
                      l.max_temperature - kC));
    const double hottest = largest(positions_, &Position::iso_contact_temperature);
    if (hottest > l.max_temperature)
      r.warnings.push_back(
          fmt::format("ISO/TS 6336-22 h_Y evaluates the oil at contact temperatures up to {:.1f} degC, "
                      "beyond {}'s data ({:.0f} degC): its sliding parameter S_GF is extrapolated",
                      hottest - kC, l.name, l.max_temperature - kC));
  }
  const auto low = std::count_if(positions_.begin(), positions_.end(), [](const Position& q) { return q.low_peclet; });
  if (low > 0)
    r.warnings.push_back(
        fmt::format("{} of {} positions with a Peclet number below {:g} (flag_low_peclet): Blok's "
                    "flash temperature assumes fast-moving surfaces and overestimates there",
                    low, n, lub::kMinBlokPeclet));
}

}  // namespace geartrib::contact
