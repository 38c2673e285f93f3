#include "lubrication/flank_temperature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace geartrib::lubrication {

double thermal_contact_coefficient(double k, double rho, double c) { return std::sqrt(k * rho * c); }

double blok_flash_temperature(double mu, double w, double b, double v1, double v2, double b1, double b2) {
  if (!(b > 0.0) || mu == 0.0 || w == 0.0 || v1 == v2) return 0.0;
  return 1.11 * std::abs(mu) * w * std::abs(v1 - v2) /
         (2.0 * std::sqrt(b) * (b1 * std::sqrt(std::max(v1, 0.0)) + b2 * std::sqrt(std::max(v2, 0.0))));
}

double peclet_number(double v, double b, double k, double rho, double c) { return v * b * rho * c / (2.0 * k); }

double iso_mean_friction(double w_bt, double v_sum, double rho, double eta, double ra, double x_l) {
  const double w_n_per_mm = w_bt * 1e-3, rho_mm = rho * 1e3, eta_mpas = eta * 1e3, ra_um = ra * 1e6;
  const double x_r = 2.2 * std::pow(ra_um / rho_mm, 0.25);
  return 0.045 * std::pow(w_n_per_mm / (v_sum * rho_mm), 0.2) * std::pow(eta_mpas, -0.05) * x_r * x_l;
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
