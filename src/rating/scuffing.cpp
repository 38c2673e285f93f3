#include "rating/scuffing.hpp"

#include "lubrication/flank_temperature.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geartrib::rating {

namespace {
constexpr double kCelsius = 273.15;
}

double fzg_scuffing_temperature(int stage, double x_w, double x_l) {
  return kCelsius + 80.0 + (0.85 + 1.4 * x_w) * x_l * stage * stage;
}

double fzg_a_torque(int stage) { return 3.726 * stage * stage; }

double structural_factor(MaterialGroup) { return 1.0; }

double micropitting_material_factor(MaterialGroup g) { return g == MaterialGroup::case_hardened ? 1.0 : 0.5; }

IntegralTemperature iso_integral_temperature(const IntegralTemperatureInputs& in) {
  IntegralTemperature out;
  auto add = [&](std::string symbol, double value, std::string unit, std::string clause, bool assumed = false,
                 std::string note = {}) {
    out.factors.push_back({std::move(symbol), -1, value, std::move(unit), std::move(clause), assumed, std::move(note)});
    return value;
  };
  const gear::SpurPair& pair = *in.pair;
  const gear::GearPairSpec& spec = pair.spec();
  const gear::PathOfContact& p = pair.path();
  const double u = static_cast<double>(spec.teeth[1]) / spec.teeth[0];
  const double alpha_w = pair.operating_pressure_angle(), alpha = spec.pressure_angle;
  const double b = spec.face_width;
  const double eps = p.contact_ratio;
  if (eps < 1.0 || eps > 2.5)
    out.findings.emplace_back(fmt::format("integral temperature: eps_alpha = {:.3f} outside [1, 2.5]", eps));
  if (alpha < 15.0 * std::numbers::pi / 180.0 || alpha > 25.0 * std::numbers::pi / 180.0)
    out.findings.emplace_back("integral temperature: pressure angle outside [15, 25] deg");
  if (in.pitch_line_speed > kMaxScuffingSpeed)
    out.findings.emplace_back(
        fmt::format("scuffing: v = {:.3g} m/s beyond the methods' tests (v < 80 m/s)", in.pitch_line_speed));

  // Eqs. (1)-(7): mu_mC at C with w_Bt = K F_t/b (K_Bgamma = 1 for eps_gamma <= 2).
  const double w_bt = in.load_factor * in.tangential_force / b;
  const double rho_c = p.c * (p.line_length - p.c) / p.line_length;
  lubrication::PitchPointLoad c;
  c.tangential_load = w_bt;
  c.normal_load = w_bt / std::cos(alpha);
  c.pitch_line_speed = in.pitch_line_speed;
  c.sum_speed = 2.0 * in.pitch_line_speed * std::tan(alpha_w) * std::cos(alpha);  // eq. (2)
  c.radius = rho_c;
  c.eta_oil = in.eta_oil;
  c.mean_ra = in.mean_ra;
  c.lubricant_factor = in.lubricant_factor;
  const lubrication::MeanFriction mu =
      lubrication::mean_friction(lubrication::MeanFrictionLaw::iso, c, lubrication::BaseOil::mineral);
  add("mu_mC", mu.coefficient, "1", "ISO/TS 6336-21 eq. (1) (lubrication.mean_friction = iso)");
  if (mu.load_raised)
    out.findings.emplace_back("integral temperature: w_Bt below 150 N/mm, mu_mC evaluated at 150 N/mm (clause 5.1)");
  if (mu.speed_capped)
    out.findings.emplace_back("integral temperature: v above 50 m/s, mu_mC evaluated at 50 m/s (clause 5.1)");
  if (mu.below_speed_range)
    out.findings.emplace_back(
        "integral temperature: v below 1 m/s, where the friction exceeds mu_mC's formula (clause 5.1)");

  // Eq. (22)-(24): geometry factor at the pinion tip E.
  const double rho_e1 = p.e * 1e3, rho_e2 = (p.line_length - p.e) * 1e3;  // mm
  const double x_be =
      0.51 * std::sqrt(u + 1.0) * (std::sqrt(rho_e1) - std::sqrt(rho_e2 / u)) / std::pow(rho_e1 * rho_e2, 0.25);
  add("X_BE", x_be, "1", "ISO/TS 6336-21 eq. (22)");
  const double x_ab = lubrication::iso_angle_factor(alpha_w, alpha);
  add("X_alphabeta", x_ab, "1", "ISO/TS 6336-21 eq. (13)");
  add("X_M", in.thermo_elastic_factor, "K N^-3/4 s^1/2 m^-1/2 mm", "ISO/TS 6336-21 eq. (11) from the materials' B_M");
  add("X_E", 1.0, "1", "ISO/TS 6336-21 eq. (8): run in (phi_E = 1)", true, "run-in flanks assumed");
  // Addendum contact ratios (eqs. 30-31): the recess eps_1 (pinion tip), the approach eps_2.
  const double eps1 = (p.e - p.c) / p.base_pitch, eps2 = (p.c - p.a) / p.base_pitch;
  add("eps_1", eps1, "1", "ISO/TS 6336-21 eq. (30)");
  add("eps_2", eps2, "1", "ISO/TS 6336-21 eq. (31)");
  // Approach factor (eqs. 25-29), pinion driving: eps_f = eps_2, eps_a = eps_1.
  const double ratio = eps2 / eps1;
  const double x_q = ratio <= 1.5 ? 1.0 : (ratio < 3.0 ? 1.40 - 4.0 / 15.0 * ratio : 0.60);
  add("X_Q", x_q, "1", "ISO/TS 6336-21 eqs. (25)-(29), pinion driving");
  // Tip relief factor (eqs. 32-38): C_a of the gear whose tip enters in the dominant addendum,
  // credited for Q <= 6, at most C_eff = K_A F_t/(b c').
  const double c_eff = in.application_factor * in.tangential_force / (b * in.single_stiffness);
  double c_a = eps1 > 1.5 * eps2 ? in.tip_relief[0] : in.tip_relief[1];
  if (in.accuracy_grade > 6) c_a = 0.0;
  c_a = std::min(c_a, c_eff);
  const double e_max = std::max(eps1, eps2), cr = c_a / c_eff;
  const double x_ca = 1.0 + (0.06 + 0.18 * cr) * e_max + (0.02 + 0.69 * cr) * e_max * e_max;
  add("C_eff", c_eff, "m", "ISO/TS 6336-21 eq. (38): K_A F_t/(b c')");
  add("X_Ca", x_ca, "1", "ISO/TS 6336-21 eq. (32)");
  // Eq. (19): flash temperature at E (w in N/mm, v in m/s, a in mm).
  const double theta_fla_e = mu.coefficient * in.thermo_elastic_factor * x_be * x_ab * std::pow(w_bt * 1e-3, 0.75) *
                             std::sqrt(in.pitch_line_speed) / std::pow(pair.center_distance() * 1e3, 0.25) /
                             (x_q * x_ca);
  add("theta_flaE", theta_fla_e, "K", "ISO/TS 6336-21 eq. (19): flash temperature at the pinion tip");
  // Contact ratio factor (eqs. 39-44).
  const double k = 1.0 / (2.0 * eps * eps1);
  double x_eps = 0.0;
  if (eps < 1.0) x_eps = k * (eps1 * eps1 + eps2 * eps2);
  else if (eps < 2.0) {
    if (eps1 < 1.0 && eps2 < 1.0)
      x_eps = k * (0.70 * (eps1 * eps1 + eps2 * eps2) - 0.22 * eps + 0.52 - 0.60 * eps1 * eps2);
    else if (eps1 >= 1.0)
      x_eps = k * (0.18 * eps1 * eps1 + 0.70 * eps2 * eps2 + 0.82 * eps1 - 0.52 * eps2 - 0.30 * eps1 * eps2);
    else x_eps = k * (0.70 * eps1 * eps1 + 0.18 * eps2 * eps2 - 0.52 * eps1 + 0.82 * eps2 - 0.30 * eps1 * eps2);
  } else if (eps1 >= eps2)
    x_eps = k * (0.44 * eps1 * eps1 + 0.59 * eps2 * eps2 + 0.30 * eps1 - 0.30 * eps2 - 0.15 * eps1 * eps2);
  else x_eps = k * (0.59 * eps1 * eps1 + 0.44 * eps2 * eps2 - 0.30 * eps1 + 0.30 * eps2 - 0.15 * eps1 * eps2);
  add("X_eps", x_eps, "1", "ISO/TS 6336-21 eqs. (39)-(44)");
  const double theta_flaint = theta_fla_e * x_eps;
  add("theta_flaint", theta_flaint, "K", "ISO/TS 6336-21 eq. (18): mean flash temperature");
  const double theta_m = in.oil_temperature + 0.7 * in.oil_supply_factor * theta_flaint;  // eqs. (20)-(21)
  add("X_S", in.oil_supply_factor, "1", "ISO/TS 6336-21 (rating.oil_supply)");
  add("theta_M", theta_m, "K", "ISO/TS 6336-21 eq. (20): theta_oil + 0.7 X_S theta_flaint");
  out.integral_temperature =
      add("theta_int", theta_m + 1.5 * theta_flaint, "K", "ISO/TS 6336-21 eq. (17): theta_M + 1.5 theta_flaint");
  if (in.fzg_stage > 0) {
    const double t_1t = fzg_a_torque(in.fzg_stage);
    add("T_1T", t_1t, "N m", "ISO/TS 6336-21 eq. (97): 3.726 S_FZG^2 (FZG A/8.3/90)");
    const double theta_mt = 80.0 + 0.23 * t_1t * in.lubricant_factor;  // degC, eq. (95)
    const double theta_flat =
        0.2 * t_1t * std::pow(100.0 / (in.viscosity_40 * 1e6), 0.02) * in.lubricant_factor;  // eq. (96)
    add("X_WrelT", in.structural_factor, "1", "ISO/TS 6336-21 eq. (102): X_W/X_WT, X_WT = 1");
    out.permissible_temperature = add("theta_intS", kCelsius + theta_mt + in.structural_factor * 1.5 * theta_flat, "K",
                                      "ISO/TS 6336-21 eqs. (94)-(96)");
    // Eq. (14): the ratio of the temperatures in degC, as the standard writes it.
    out.safety = add("S_intS", (out.permissible_temperature - kCelsius) / (out.integral_temperature - kCelsius), "1",
                     "ISO/TS 6336-21 eq. (14): theta_intS/theta_int (degC)");
  }
  return out;
}

}  // namespace geartrib::rating
