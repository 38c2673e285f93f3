#include "runs/case_rating.hpp"

#include "config/fzg_load_stages.hpp"
#include "contact/mesh_lubrication.hpp"
#include "core/keyed_error.hpp"
#include "lubrication/flank_temperature.hpp"
#include "rating/scuffing.hpp"
#include "runs/mesh_cycle.hpp"
#include "surface/rough_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geartrib::runs {

namespace {

constexpr double kCelsius = 273.15;

// The FZG micropitting test GF-C/8.3/90 on its type C gear (FVA 54/7; io::fzg_c_gear_pair): 8.3 m/s (2175 1/min), 90
// degC oil, both flanks ground to Ra 0.5 um, case-carburised 16MnCr5 (io::fzg_c_test_material), the load of
// failure stage `stage` on the 0.35 m arm; the oil and the lubrication models of the rated case `c`.
Case fzg_c_test(const Case& c, int stage) {
  Case t;
  t.title = fmt::format("FZG GF-C/8.3/90 test gear at failure load stage {}", stage);
  t.gear_pair = io::fzg_c_gear_pair();
  for (GearSpec* gs : {&t.pinion, &t.wheel}) {
    gs->material = io::fzg_c_test_material();
    gs->flank.roughness.form = surface::FlankRoughness::Form::ra;
    gs->flank.roughness.ra = 0.5e-6;
    gs->flank.roughness.summit_radius = 75e-6;
  }
  t.roughness.eta_sigma_beta = 0.05;
  t.contact.positions = 21;
  t.contact.real_area = t.contact.plastic_fraction = t.contact.asperity_stress = false;
  t.asperity = c.asperity;
  t.friction_coefficient = c.friction_coefficient;
  t.lubrication = c.lubrication;
  t.lubrication.scuffing_temperature = 0.0;
  t.operating.pinion_torque = io::fzg_pinion_torque("GF-C/8.3/90", stage).torque;
  t.operating.pinion_speed = 2175.0 * 2.0 * std::numbers::pi / 60.0;
  t.operating.oil_temperature = kCelsius + 90.0;
  t.directory = c.directory;
  return t;
}

}  // namespace

RatingRequest default_rating_request(const Case& c) {
  RatingRequest r = c.rating;
  if (r.any()) return r;
  // All four: rate_case leaves out, with a finding, what a dry case cannot rate.
  r.pitting = r.bending = r.scuffing = r.micropitting = true;
  return r;
}

namespace {

// What the lubricated methods read: the case, its pair and cycle, the load capacity's factors, the
// rating load's factor K = K_A K_v K_Hbeta K_Halpha, and the result they add to.
struct LubricatedRating {
  const Case& c;
  const gear::SpurPair& pair;
  const contact::LubricationSummary& ls;
  const contact::MeshContactResult& cycle;
  const rating::LoadCapacity& lc;
  double k_load;
  rating::RatingResult& out;
  // A pair factor into the table; returns its value.
  double add(std::string symbol, double value, std::string unit, std::string clause, bool assumed = false,
             std::string note = {}) {
    out.factors.push_back({std::move(symbol), -1, value, std::move(unit), std::move(clause), assumed, std::move(note)});
    return value;
  }
};

// Scuffing: the scuffing temperature (given, or from the oil's A/8.3/90 stage), the flash method on
// the path at the rating load, the integral method.
void rate_scuffing(LubricatedRating& x) {
  const Case& c = x.c;
  const gear::SpurPair& pair = x.pair;
  const contact::LubricationSummary& ls = x.ls;
  const lubrication::Lubricant& oil = c.lubrication.lubricant;
  rating::RatingResult& out = x.out;
  const double x_l = oil.lubricant_factor();
  out.methods.emplace_back("scuffing");
  const double x_w = rating::structural_factor(c.pinion.material.grade.group);
  double theta_s = c.lubrication.scuffing_temperature;
  if (theta_s > 0.0) {
    x.add("theta_S", theta_s, "K", "lubrication.scuffing_temperature (given)");
  } else if (oil.fzg_scuffing_stage > 0) {
    x.add("S_FZG", oil.fzg_scuffing_stage, "1", "FZG A/8.3/90 failure load stage of the oil", oil.fzg_assumed,
          oil.fzg_source);
    x.add("X_W", x_w, "1", "ISO/TS 6336-20 Table 2: through-hardened and case-carburised (average austenite) 1.0");
    x.add("X_L", x_l, "1", "ISO/TS 6336-20: the base stock's lubricant factor");
    theta_s = x.add("theta_S", rating::fzg_scuffing_temperature(oil.fzg_scuffing_stage, x_w, x_l), "K",
                    "ISO/TS 6336-20 eq. (99): 80 degC + (0.85 + 1.4 X_W) X_L S_FZG^2", oil.fzg_assumed);
  } else {
    out.findings.emplace_back(
        "scuffing: no scuffing temperature (lubrication.scuffing_temperature, or the oil's fzg_scuffing_stage): the "
        "contact and integral temperatures are reported without the safeties S_B and S_intS");
  }
  // Flash-temperature method: the path's ISO flash temperature (computed at the nominal load, K
  // factors 1) taken to the rating load w_Bt K: theta_fl ~ mu_m X_J w^0.75 with mu_m ~ w^0.2
  // (ISO/TS 6336-20 eq. 25) and X_J's C_eff ~ w (annex A), position by position; the estimated
  // bulk temperature's rise with the path mean (eq. 22).
  const double f = std::pow(x.k_load, 0.95);
  const double t_oil = ls.oil_temperature;
  const contact::Series* s_m = x.cycle.find("s_m");
  const contact::Series* flash = x.cycle.find("iso_flash_temperature_K");
  const lubrication::IsoFlashGeometry geo = contact::iso_flash_geometry(pair);
  const double c_eff = ls.iso_effective_relief, c_a = c.mesh.modification[1].tip.amount;
  std::vector<double> scaled(flash->values.size());
  for (std::size_t i = 0; i < scaled.size(); ++i) {
    const double gamma = pair.flank(s_m->values[i]).roll_parameter;
    scaled[i] = flash->values[i] * f * lubrication::iso_approach_factor(geo, gamma, x.k_load * c_eff, c_a) /
                lubrication::iso_approach_factor(geo, gamma, c_eff, c_a);
  }
  if (ls.bulk_estimated && c.lubrication.mean_friction == lubrication::MeanFrictionLaw::iso &&
      pair.tangential_line_load(c.operating.pinion_torque) < lubrication::kIsoMinTangentialLoad)
    out.findings.emplace_back(
        "scuffing: the bulk estimate's friction law (iso) is floored at 150 N/mm at the nominal load: its rise taken "
        "to the rating load with the flash temperatures is approximate");
  const double bulk = ls.bulk_estimated ? t_oil + (ls.bulk_temperature - t_oil) * contact::path_mean(scaled) /
                                                      contact::path_mean(flash->values)
                                        : ls.bulk_temperature;
  const double theta_b = bulk + *std::max_element(scaled.begin(), scaled.end());
  x.add("theta_B,max", theta_b, "K",
        "ISO/TS 6336-20 eqs. (1)-(2), A.5: the path's largest contact temperature at w_Bt K_A K_v K_Hbeta K_Halpha "
        "(/lubrication's flash x K^0.95 X_J(K C_eff)/X_J(C_eff))");
  if (theta_s > 0.0)
    out.flash_scuffing_safety = x.add("S_B", (theta_s - t_oil) / (theta_b - t_oil), "1",
                                      "ISO/TS 6336-20 eq. (100): (theta_S - theta_oil)/(theta_B,max - theta_oil)");
  // Integral-temperature method.
  rating::IntegralTemperatureInputs it;
  it.pair = &pair;
  it.tangential_force = x.lc.find("F_t")->value;
  it.pitch_line_speed = x.lc.find("v")->value;
  it.load_factor = x.k_load;
  it.application_factor = c.rating.settings.application_factor;
  it.single_stiffness = x.lc.find("c'")->value;
  it.eta_oil = lubrication::oil_state(oil, t_oil).dynamic_viscosity;
  it.viscosity_40 = oil.kinematic_viscosity_40;
  it.oil_temperature = t_oil;
  it.mean_ra = ls.mean_ra;
  it.lubricant_factor = x_l;
  const auto b_m = [](const Material& m) {
    return lubrication::thermal_contact_coefficient(m.thermal_conductivity, m.density, m.specific_heat);
  };
  it.thermo_elastic_factor = lubrication::iso_thermo_elastic_factor(
      composite_modulus(c.pinion.material, c.wheel.material) * 2.0, b_m(c.pinion.material), b_m(c.wheel.material));
  it.oil_supply_factor = c.rating.settings.oil_supply == rating::RatingSettings::OilSupply::spray ? 1.2 : 1.0;
  it.tip_relief[0] = c.mesh.modification[0].tip.amount;
  it.tip_relief[1] = c.mesh.modification[1].tip.amount;
  it.accuracy_grade = c.rating.settings.accuracy_grade;
  it.structural_factor = x_w;
  it.fzg_stage = oil.fzg_scuffing_stage;
  const rating::IntegralTemperature ti = rating::iso_integral_temperature(it);
  out.factors.insert(out.factors.end(), ti.factors.begin(), ti.factors.end());
  out.findings.insert(out.findings.end(), ti.findings.begin(), ti.findings.end());
  out.integral_scuffing_safety = ti.safety;
  if (!(ti.safety > 0.0) && theta_s > 0.0)
    out.findings.emplace_back("integral temperature: no permissible temperature (the oil has no fzg_scuffing_stage)");
}

// Micropitting: lambda_GF,min at the rating load and the permissible film (given, or from the oil's
// GF-C/8.3/90 stage on the test gear).
void rate_micropitting(LubricatedRating& x) {
  const Case& c = x.c;
  const lubrication::Lubricant& oil = c.lubrication.lubricant;
  rating::RatingResult& out = x.out;
  out.methods.emplace_back("micropitting");
  // lambda_GF along the path (ISO/TS 6336-22 method B at the named points), taken to the rating
  // load: h_Y ~ W^-0.13 ~ p_dyn^-0.26 ~ K^-0.13 (bulk temperature held).
  out.min_lambda = x.add("lambda_GF,min", x.ls.min_iso_lambda * std::pow(x.k_load, -0.13), "1",
                         "ISO/TS 6336-22 eqs. (2), (4), (24): the least of the named points at p_dyn "
                         "(x K^-0.13 of /lubrication's)");
  // Method B's development range (ISO/TS 6336-22 scope): modules 3..11 mm, 8..60 m/s, applicable above 2 m/s.
  const double v = x.lc.find("v")->value, m = c.gear_pair.module;
  if (v < 2.0 || v > 60.0 || m < 3e-3 || m > 11e-3)
    out.findings.emplace_back(fmt::format(
        "micropitting: v = {:.3g} m/s, m = {:.3g} mm outside method B's development range (3..11 mm, 8..60 m/s; "
        "applicable above 2 m/s)",
        v, m * 1e3));
  double lambda_p = 0.0;
  if (oil.permissible_lambda > 0.0) {
    lambda_p = x.add("lambda_GFP", oil.permissible_lambda, "1", "ISO/TS 6336-22 5.4: given for the oil", false,
                     oil.permissible_lambda_source);
  } else if (oil.fzg_micropitting_stage > 0) {
    // The test gear's own lambda_GF: method B on the test at that stage (K factors 1).
    x.add("S_GF", oil.fzg_micropitting_stage, "1", "FZG GF-C/8.3/90 failure load stage of the oil", oil.fzg_assumed,
          oil.fzg_source);
    const contact::MeshContactResult test = run_mesh_cycle(fzg_c_test(c, oil.fzg_micropitting_stage));
    const double lambda_t = x.add("lambda_GFT", test.lubrication_summary->min_iso_lambda, "1",
                                  "ISO/TS 6336-22: method B on the C-GF test gear at the failure stage (8.3 m/s, "
                                  "90 degC oil, Ra 0.5 um, this oil)",
                                  oil.fzg_assumed);
    // The softer gear's (the lower W_W of the two).
    const double w_w = x.add("W_W",
                             std::min(rating::micropitting_material_factor(c.pinion.material.grade.group),
                                      rating::micropitting_material_factor(c.wheel.material.grade.group)),
                             "1",
                             "ISO/TR 15144-1 material factor, the lower of the two gears' (recollected: "
                             "case-carburised 1.0, through-hardened 0.5)",
                             true, "unconfirmed: the standard's text was not available");
    lambda_p = x.add("lambda_GFP", rating::kMicropittingTestFactor * w_w * lambda_t, "1",
                     "ISO/TR 15144-1: 1.4 W_W lambda_GFT (recollected)", true,
                     "unconfirmed: the standard's text was not available");
  } else {
    out.findings.emplace_back(
        "micropitting: no permissible film (the oil's permissible_lambda or fzg_micropitting_stage): lambda_GF,min "
        "is reported without the safety S_lambda");
  }
  if (lambda_p > 0.0)
    out.micropitting_safety = x.add("S_lambda", out.min_lambda / lambda_p, "1",
                                    "ISO/TS 6336-22 eq. (1): lambda_GF,min/lambda_GFP (no minimum recommended)");
}

}  // namespace

rating::RatingResult rate_case(const Case& c, const gear::GearMesh& mesh, const contact::MeshContactResult& cycle) {
  RatingRequest req = c.rating;
  rating::RatingResult out;
  const bool lub = c.lubrication.lubricated;
  if (!lub && (req.pitting || req.scuffing || req.micropitting)) {
    out.findings.emplace_back(
        "a dry case: pitting (Z_L, Z_v), scuffing and micropitting need the oil and are not rated");
    req.pitting = req.scuffing = req.micropitting = false;
  }
  const gear::SpurPair& pair = mesh.pair();
  rating::LoadCapacityInputs in;
  in.pair = &pair;
  in.material = {&c.pinion.material, &c.wheel.material};
  in.grade = {c.pinion.material.grade, c.wheel.material.grade};
  in.settings = req.settings;
  in.pinion_torque = c.operating.pinion_torque;
  in.pinion_speed = c.operating.pinion_speed;
  if (lub) in.viscosity_40 = c.lubrication.lubricant.kinematic_viscosity_40;
  for (int g = 0; g < 2; ++g) {
    const surface::HeightRoughness h = surface::height_roughness((g == 0 ? c.pinion : c.wheel).flank.roughness);
    in.flank_ra[static_cast<std::size_t>(g)] = h.known ? h.ra : 0.0;
    in.tip_relief[static_cast<std::size_t>(g)] = c.mesh.modification[g].tip.amount;
    if (req.pitting && !h.known && !(req.settings.flank_rz[static_cast<std::size_t>(g)] > 0.0))
      throw core::KeyedError(g == 0 ? "pinion.flank_rz" : "wheel.flank_rz",
                             "the flank's roughness is given by summit statistics alone: give its Rz for Z_R");
  }
  const rating::LoadCapacity lc = rating::iso6336_load_capacity(in, req.pitting, req.bending);
  out.factors = lc.factors;
  out.findings.insert(out.findings.end(), lc.findings.begin(), lc.findings.end());
  out.pitting_safety = lc.pitting_safety;
  out.bending_safety = lc.bending_safety;
  if (req.pitting) out.methods.emplace_back("pitting");
  if (req.bending) out.methods.emplace_back("bending");
  if (!(req.scuffing || req.micropitting)) return out;
  if (!cycle.lubrication_summary)
    throw core::KeyedError("rating.methods", "scuffing and micropitting need the lubricated cycle");
  LubricatedRating x{
      c,
      pair,
      *cycle.lubrication_summary,
      cycle,
      lc,
      c.rating.settings.application_factor * lc.dynamic_factor * lc.find("K_Hbeta")->value * lc.transverse_factor,
      out};
  if (req.scuffing) rate_scuffing(x);
  if (req.micropitting) rate_micropitting(x);
  return out;
}

}  // namespace geartrib::runs
