#include "contact/mesh_lubrication.hpp"

#include "lubrication/flank_temperature.hpp"
#include "lubrication/mixed_lubrication.hpp"

#include <algorithm>
#include <cmath>
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
// Linear interpolation of a series over the evenly spaced positions at s.
double at(const std::vector<double>& s, const std::vector<double>& v, double x) {
  if (v.size() < 2) return v.empty() ? 0.0 : v.front();
  const double t = std::clamp((x - s.front()) / (s.back() - s.front()), 0.0, 1.0) * double(v.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(t), v.size() - 2);
  return v[i] + (t - double(i)) * (v[i + 1] - v[i]);
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
  for (std::size_t i = 0; i < n; ++i)
    iso_flash_.push_back(lub::blok_flash_temperature(iso_friction_, p.line_load[i], p.half_width[i], p.v1[i], p.v2[i],
                                                     thermal_coefficient_[0], thermal_coefficient_[1]));
  bulk_estimated_ = !(c.operating.bulk_temperature > 0.0);
  bulk_temperature_ = bulk_estimated_ ? lub::iso_bulk_temperature(c.operating.oil_temperature, path_mean(iso_flash_))
                                      : c.operating.bulk_temperature;
  oil_at_bulk_ = lub::oil_state(lubricant, bulk_temperature_);

  // The smooth film at the bulk temperature, corrected for inlet heating, and the load shares.
  const lub::FilmLaw& law = lub::film_law(formula_);
  const double summit_offset = gw.surface().summit_mean_height;
  const auto& oil = oil_at_bulk_;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = 0.5 * (p.v1[i] + p.v2[i]);
    const lub::EhlGroups g = lub::ehl_groups(oil.dynamic_viscosity, oil.pressure_viscosity, u, p.line_load[i],
                                             p.radius[i], reduced_modulus_);
    const double h_iso = lub::smooth_film(formula_, g, p.radius[i]);
    const double load =
        lub::thermal_loading(oil.temperature_viscosity, oil.dynamic_viscosity, u, oil.thermal_conductivity);
    const double srr = u > 0.0 ? std::abs(p.v1[i] - p.v2[i]) / u : 0.0;
    const double phi = lub::inlet_heating_factor(inlet_, load, srr, p.hertz_p0[i] / reduced_modulus_);
    film_isothermal_.push_back(h_iso);
    heating_factor_.push_back(phi);
    film_.push_back(phi * h_iso);
    regime_.push_back(static_cast<double>(lub::ehl_regime(g)));
    const double p0 = p.hertz_p0[i];
    // Mean-plane separation of the asperities carrying `share` of the Hertz pressure. Where the
    // dry contact (share 1) would press them below the mean plane (GW beyond its range; the
    // validity flags say so), the film's gap is counted from the dry contact's separation, so that
    // a vanishing film gives the dry result and the film never carries load at a negative gap.
    const double dry = gw.separation_for_pressure(p0) + summit_offset;
    const double below = std::min(0.0, dry);
    const auto gap = [&](double share) { return gw.separation_for_pressure(share * p0) + summit_offset - below; };
    gap_from_dry_.push_back(below < 0.0 ? 1.0 : 0.0);
    if (!(p.line_load[i] > 0.0)) {
      asperity_share_.push_back(0.0);
      film_gap_.push_back(gap(0.0));
      separation_.push_back(gap(0.0) + below);
      continue;
    }
    const lub::LoadShare s = lub::share_load(phi * h_iso, law.speed_exponent - law.material_exponent, gap);
    asperity_share_.push_back(s.asperity_share);
    film_gap_.push_back(s.film_thickness);
    separation_.push_back(s.film_thickness + below);
  }
}

void MeshLubrication::finish(MeshContactResult& r) const {
  const Case& c = case_;
  const auto& p = path_;
  const std::size_t n = p.s.size();
  const double face = mesh_.pair().spec().face_width;
  const double mu_b = c.friction_coefficient, k_wear = c.lubrication.wear_coefficient;
  std::vector<double> mu, mu_film, flash, contact_t, iso_contact_t, power, wear1, wear2, hy, lambda_gf, lambda, peclet;
  for (std::size_t i = 0; i < n; ++i) {
    const double vs = p.v1[i] - p.v2[i];
    lub::LoadShare share{asperity_share_[i], 1.0 - asperity_share_[i], film_gap_[i]};
    const lub::MixedFriction f = lub::mixed_friction(oil_at_bulk_, share, mu_b, p.line_load[i], p.half_width[i], vs);
    mu.push_back(f.coefficient);
    mu_film.push_back(f.film_coefficient);
    flash.push_back(lub::blok_flash_temperature(f.coefficient, p.line_load[i], p.half_width[i], p.v1[i], p.v2[i],
                                                thermal_coefficient_[0], thermal_coefficient_[1]));
    contact_t.push_back(bulk_temperature_ + flash.back());
    iso_contact_t.push_back(bulk_temperature_ + iso_flash_[i]);
    power.push_back(f.coefficient * p.line_load[i] * face * std::abs(vs));
    // Archard per engagement: a flank point crosses 2b at its own speed v_i while the other slides
    // |v_s| 2b/v_i past it under the asperities' mean pressure share w/(2b): h = k share w |v_s|/v_i.
    const double asperity_load = asperity_share_[i] * p.line_load[i];
    wear1.push_back(p.v1[i] > 0.0 ? k_wear * asperity_load * std::abs(vs) / p.v1[i] : 0.0);
    wear2.push_back(p.v2[i] > 0.0 ? k_wear * asperity_load * std::abs(vs) / p.v2[i] : 0.0);
    const lub::OilState local = lub::oil_state(c.lubrication.lubricant, iso_contact_t.back());
    hy.push_back(
        lub::iso_film_hy(p.radius[i], reduced_modulus_, p.hertz_p0[i], p.v1[i] + p.v2[i], oil_at_bulk_, local));
    lambda_gf.push_back(hy.back() / mean_ra_);
    lambda.push_back(film_[i] / composite_rq_);
    bool low = false;
    for (int g = 0; g < 2; ++g) {
      const Material& m = (g == 0 ? c.pinion : c.wheel).material;
      low = low || lub::peclet_number(g == 0 ? p.v1[i] : p.v2[i], p.half_width[i], m.thermal_conductivity, m.density,
                                      m.specific_heat) < lub::kMinBlokPeclet;
    }
    peclet.push_back(low ? 1.0 : 0.0);
  }
  auto& g = r.lubrication;
  g.reserve(32);
  auto add = [&](const char* name, const char* unit, std::vector<double> v) {
    g.push_back({name, unit, std::move(v)});
  };
  add("film_isothermal_m", "m", film_isothermal_);
  add("inlet_heating_factor", "1", heating_factor_);
  add("film_m", "m", film_);
  add("lambda", "1", lambda);
  add("ehl_regime", "1", regime_);
  add("separation_m", "m", separation_);
  add("asperity_load_share", "1", asperity_share_);
  {
    std::vector<double> film_share;
    for (double a : asperity_share_) film_share.push_back(1.0 - a);
    add("film_load_share", "1", std::move(film_share));
  }
  add("friction_coefficient", "1", mu);
  add("film_traction_coefficient", "1", mu_film);
  add("iso_friction_coefficient", "1", std::vector<double>(n, iso_friction_));
  add("power_loss_W", "W", power);
  add("flash_temperature_K", "K", flash);
  add("contact_temperature_K", "K", contact_t);
  add("iso_flash_temperature_K", "K", iso_flash_);
  add("iso_contact_temperature_K", "K", iso_contact_t);
  add("iso_film_hy_m", "m", hy);
  add("iso_lambda_gf", "1", lambda_gf);
  add("wear_depth_pinion_m", "m", wear1);
  add("wear_depth_wheel_m", "m", wear2);
  add("flag_low_peclet", "1", peclet);
  add("flag_gap_from_dry_contact", "1", gap_from_dry_);

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
  sum.mean_power_loss = path_mean(power) * path.length / path.base_pitch;
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
        lub::iso_scuffing_safety(t_s, t_oil, *std::max_element(iso_contact_t.begin(), iso_contact_t.end()));
    sum.scuffing_safety = lub::iso_scuffing_safety(t_s, t_oil, *std::max_element(contact_t.begin(), contact_t.end()));
  }
  const std::pair<const char*, double> named[] = {
      {"A", path.a}, {"AB", 0.5 * (path.a + path.b)}, {"B", path.b}, {"C", path.c},
      {"D", path.d}, {"DE", 0.5 * (path.d + path.e)}, {"E", path.e}};
  for (const auto& [name, s] : named)
    sum.points.push_back({name, s, at(p.s, film_, s), at(p.s, lambda, s), at(p.s, hy, s), at(p.s, lambda_gf, s),
                          at(p.s, asperity_share_, s)});
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
    const double hottest = *std::max_element(iso_contact_t.begin(), iso_contact_t.end());
    if (hottest > l.max_temperature)
      r.warnings.push_back(
          fmt::format("ISO/TS 6336-22 h_Y evaluates the oil at contact temperatures up to {:.1f} degC, "
                      "beyond {}'s data ({:.0f} degC): its sliding parameter S_GF is extrapolated",
                      hottest - kC, l.name, l.max_temperature - kC));
  }
  const auto low = static_cast<int>(std::count(peclet.begin(), peclet.end(), 1.0));
  if (low > 0)
    r.warnings.push_back(
        fmt::format("{} of {} positions with a Peclet number below {:g} (flag_low_peclet): Blok's "
                    "flash temperature assumes fast-moving surfaces and overestimates there",
                    low, n, lub::kMinBlokPeclet));
}

}  // namespace geartrib::contact
