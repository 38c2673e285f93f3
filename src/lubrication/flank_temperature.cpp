#include "lubrication/flank_temperature.hpp"

#include "core/named_choices.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace geartrib::lubrication {

double thermal_contact_coefficient(double k, double rho, double c) { return std::sqrt(k * rho * c); }

double blok_flash_temperature(double mu, double w, double b, double v1, double v2, double b1, double b2) {
  if (!(b > 0.0) || mu == 0.0 || w == 0.0 || v1 == v2) return 0.0;
  return kBlokConstant * std::abs(mu) * w * std::abs(v1 - v2) /
         (std::sqrt(2.0 * b) * (b1 * std::sqrt(std::max(v1, 0.0)) + b2 * std::sqrt(std::max(v2, 0.0))));
}

double peclet_number(double v, double b, double k, double rho, double c) { return v * b * rho * c / (2.0 * k); }

namespace {
constexpr NamedChoice<MeanFrictionLaw> kLawNames[] = {{MeanFrictionLaw::iso, "iso"},
                                                      {MeanFrictionLaw::iso_flash, "iso-flash"},
                                                      {MeanFrictionLaw::schlenk, "schlenk"},
                                                      {MeanFrictionLaw::fernandes, "fernandes"}};
}  // namespace

std::span<const NamedChoice<MeanFrictionLaw>> mean_friction_law_choices() { return kLawNames; }
const char* mean_friction_law_name(MeanFrictionLaw law) { return choice_name(mean_friction_law_choices(), law); }

double fernandes_lubricant_factor(BaseOil b, double iso_factor) {
  switch (b) {
    case BaseOil::mineral:
      return 0.846;
    case BaseOil::pao:
    case BaseOil::ester:
      return 0.65;
    case BaseOil::polyglycol_insoluble:
    case BaseOil::polyglycol_water_soluble:
      return 0.585;
    default:
      return iso_factor;
  }
}

MeanFriction mean_friction(MeanFrictionLaw law, const PitchPointLoad& c, BaseOil base_oil) {
  MeanFriction f;
  if (!(c.sum_speed > 0.0) || !(c.radius > 0.0) || !(c.eta_oil > 0.0)) return f;  // no rolling: no formula
  f.below_speed_range = c.pitch_line_speed < kIsoMinSpeed;
  // Beyond 50 m/s the standards evaluate at 50 m/s: v_SigmaC scales with v_t.
  const double speed_scale = c.pitch_line_speed > kIsoMaxSpeed ? kIsoMaxSpeed / c.pitch_line_speed : 1.0;
  f.speed_capped = speed_scale < 1.0;
  const double v_sum = c.sum_speed * speed_scale;
  const double rho_mm = c.radius * 1e3, eta_mpas = c.eta_oil * 1e3, ra_um = c.mean_ra * 1e6;
  switch (law) {
    case MeanFrictionLaw::iso: {
      double w = c.tangential_load;
      if (w < kIsoMinTangentialLoad) {
        w = kIsoMinTangentialLoad;
        f.load_raised = true;
      }
      const double x_r = 2.2 * std::pow(ra_um / rho_mm, 0.25);
      f.coefficient =
          0.045 * std::pow(w * 1e-3 / (v_sum * rho_mm), 0.2) * std::pow(eta_mpas, -0.05) * x_r * c.lubricant_factor;
      break;
    }
    case MeanFrictionLaw::iso_flash:
      f.coefficient = 0.060 * std::pow(c.tangential_load * 1e-3 / (v_sum * rho_mm), 0.2) * c.lubricant_factor *
                      std::pow(eta_mpas, -0.05) * std::pow(ra_um, 0.25);
      break;
    case MeanFrictionLaw::schlenk:
    case MeanFrictionLaw::fernandes: {
      const double x_l = law == MeanFrictionLaw::schlenk ? c.lubricant_factor
                                                         : fernandes_lubricant_factor(base_oil, c.lubricant_factor);
      f.coefficient = 0.048 * std::pow(c.normal_load * 1e-3 / (v_sum * rho_mm), 0.2) * std::pow(eta_mpas, -0.05) *
                      std::pow(ra_um, 0.25) * x_l;
      break;
    }
  }
  return f;
}

double iso_angle_factor(double alpha_wt, double alpha_t) {
  return 1.22 * std::pow(std::sin(alpha_wt), 0.25) * std::pow(std::cos(alpha_t), 0.25) /
         (std::sqrt(std::cos(alpha_wt)) * std::sqrt(std::cos(alpha_t)));
}

double iso_geometry_factor(const IsoFlashGeometry& g, double gamma) {
  const double u = g.gear_ratio;
  if (!(gamma > -1.0 && gamma < u)) return 0.0;  // at an interference point the radius vanishes
  const double x_ab = iso_angle_factor(g.operating_angle, g.reference_angle);
  return 0.51 * x_ab * std::sqrt(u + 1.0) * std::abs(std::sqrt(1.0 + gamma) - std::sqrt(1.0 - gamma / u)) /
         (std::pow(1.0 + gamma, 0.25) * std::pow(u - gamma, 0.25));
}

double iso_thermo_elastic_factor(double e_r, double b1, double b2) {
  // X_M = E_r^0.25/B_M in the standard's units: E_r in N/mm^2, B_M in N/(mm^0.5 m^0.5 s^0.5 K),
  // x 1000 for its mixed metre-millimetre units. SI B_M [W s^0.5/(m^2 K) = N/(m s^0.5 K)] is
  // 1000^0.5 x that (steel: 13 795 SI, i.e. 13.8 N/(mm s^0.5 K), is 436 in those units: X_M = 50).
  const double b_iso = 0.5 * (b1 + b2) / std::sqrt(1000.0);
  return std::pow(e_r * 1e-6, 0.25) / b_iso * 1000.0;
}

double iso_approach_factor(const IsoFlashGeometry& g, double gamma, double c_eff, double c_a) {
  if (!(gamma < 0.0)) return 1.0;  // the recess and the pitch point (pinion driving)
  const double span = g.gamma_e - g.gamma_a;
  if (!(span > 0.0)) return 1.0;
  return std::max(1.0, 1.0 + (c_eff - c_a) * 1e6 / 50.0 * std::pow(-gamma / span, 3.0));
}

double iso_flash_temperature(double mu_m, double x_m, double x_j, double x_g, double x_gamma, double w_bt, double v_t,
                             double a) {
  if (!(w_bt > 0.0) || !(a > 0.0) || mu_m == 0.0 || x_g == 0.0) return 0.0;
  return mu_m * x_m * x_j * x_g * std::pow(x_gamma * w_bt * 1e-3, 0.75) * std::sqrt(v_t) / std::pow(a * 1e3, 0.25);
}

double iso_bulk_temperature(double oil, double mean_flash) { return oil + 0.47 * 1.0 * 1.0 * mean_flash; }

double iso_scuffing_safety(double scuffing, double oil, double contact_max) {
  return contact_max > oil ? (scuffing - oil) / (contact_max - oil) : std::numeric_limits<double>::infinity();
}

double iso_film_hy(double rho, double e, double p_h, double v_sum, const OilState& bulk, const OilState& contact) {
  if (!(v_sum > 0.0) || !(p_h > 0.0)) return 0.0;
  const double g = bulk.pressure_viscosity * e;
  const double u = bulk.dynamic_viscosity * v_sum / (2.0 * e * rho);
  const double w = 2.0 * std::numbers::pi * p_h * p_h / (e * e);
  const double s_gf =
      contact.pressure_viscosity * contact.dynamic_viscosity / (bulk.pressure_viscosity * bulk.dynamic_viscosity);
  return 1.6 * rho * std::pow(g, 0.6) * std::pow(u, 0.7) * std::pow(w, -0.13) * std::pow(s_gf, 0.22);
}

}  // namespace geartrib::lubrication
