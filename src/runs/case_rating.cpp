#include "runs/case_rating.hpp"

#include "core/keyed_error.hpp"
#include "lubrication/flank_temperature.hpp"
#include "rating/scuffing.hpp"
#include "surface/rough_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace geartrib::runs {

RatingRequest default_rating_request(const Case& c) {
  RatingRequest r = c.rating;
  if (r.any()) return r;
  const bool lub = c.lubrication.lubricated;
  r.pitting = lub;
  r.bending = true;
  r.scuffing = lub;
  r.micropitting = lub;
  return r;
}

rating::RatingResult rate_case(const Case& c, const gear::GearMesh& mesh, const contact::MeshContactResult& cycle) {
  RatingRequest req = c.rating;
  rating::RatingResult out;
  const bool lub = c.lubrication.lubricated;
  if (!lub && (req.pitting || req.scuffing || req.micropitting)) {
    out.findings.push_back("a dry case: pitting (Z_L, Z_v), scuffing and micropitting need the oil and are not rated");
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
  out.findings = lc.findings;
  out.pitting_safety = lc.pitting_safety;
  out.bending_safety = lc.bending_safety;
  if (req.pitting) out.methods.emplace_back("pitting");
  if (req.bending) out.methods.emplace_back("bending");
  const double k_load = c.rating.settings.application_factor * lc.dynamic_factor *
                        lc.find("K_Hbeta")->value * lc.transverse_factor;  // K_A K_v K_Hbeta K_Halpha

  if (req.scuffing || req.micropitting) {
    if (!cycle.lubrication_summary) throw core::KeyedError("rating.methods", "scuffing and micropitting need the lubricated cycle");
    const contact::LubricationSummary& ls = *cycle.lubrication_summary;
    const lubrication::Lubricant& oil = c.lubrication.lubricant;
    const double x_l = oil.lubricant_factor();
    auto add = [&](std::string symbol, double value, std::string unit, std::string clause, bool assumed = false,
                   std::string note = {}) {
      out.factors.push_back({std::move(symbol), -1, value, std::move(unit), std::move(clause), assumed, std::move(note)});
      return value;
    };
    if (req.scuffing) {
      out.methods.emplace_back("scuffing");
      const rating::MaterialGroup group = c.pinion.material.grade.group;
      const double x_w = rating::structural_factor(group);
      // The scuffing temperature: given, or from the oil's FZG A/8.3/90 failure stage.
      double theta_s = c.lubrication.scuffing_temperature;
      if (theta_s > 0.0) {
        add("theta_S", theta_s, "K", "lubrication.scuffing_temperature (given)");
      } else if (oil.fzg_scuffing_stage > 0) {
        add("S_FZG", oil.fzg_scuffing_stage, "1", "FZG A/8.3/90 failure load stage of the oil", oil.fzg_assumed, oil.fzg_source);
        add("X_W", x_w, "1", "ISO/TS 6336-20 Table 2: through-hardened and case-carburised (average austenite) 1.0");
        add("X_L", x_l, "1", "ISO/TS 6336-20: the base stock's lubricant factor");
        theta_s = add("theta_S", rating::fzg_scuffing_temperature(oil.fzg_scuffing_stage, x_w, x_l), "K",
                      "ISO/TS 6336-20 eq. (99): 80 degC + (0.85 + 1.4 X_W) X_L S_FZG^2", oil.fzg_assumed);
      } else {
        out.findings.push_back(
            "scuffing: no scuffing temperature (lubrication.scuffing_temperature, or the oil's fzg_scuffing_stage): the "
            "contact and integral temperatures are reported without the safeties S_B and S_intS");
      }
      // Flash-temperature method: the path's ISO contact temperature (computed at the nominal load,
      // K factors 1) taken to the rating load: theta_fl ~ mu_m w^0.75 ~ w^0.95 (mu_m ~ w^0.2), the
      // estimated bulk temperature's rise with it.
      const double f = std::pow(k_load, 0.95);
      const double t_oil = ls.oil_temperature;
      const double flash = ls.max_iso_contact_temperature - ls.bulk_temperature;
      const double bulk = ls.bulk_estimated ? t_oil + f * (ls.bulk_temperature - t_oil) : ls.bulk_temperature;
      const double theta_b = bulk + f * flash;
      add("theta_B,max", theta_b, "K",
          "ISO/TS 6336-20 eqs. (1)-(2), A.5: the path's largest contact temperature at w_Bt K_A K_v K_Hbeta K_Halpha "
          "(x (K)^0.95 of /lubrication's)");
      if (theta_s > 0.0)
        out.flash_scuffing_safety = add("S_B", (theta_s - t_oil) / (theta_b - t_oil), "1",
                                        "ISO/TS 6336-20 eq. (100): (theta_S - theta_oil)/(theta_B,max - theta_oil)");
      // Integral-temperature method.
      rating::IntegralTemperatureInputs it;
      it.pair = &pair;
      it.tangential_force = lc.find("F_t")->value;
      it.pitch_line_speed = lc.find("v")->value;
      it.load_factor = k_load;
      it.application_factor = c.rating.settings.application_factor;
      it.single_stiffness = lc.find("c'")->value;
      it.eta_oil = lubrication::oil_state(oil, t_oil).dynamic_viscosity;
      it.viscosity_40 = oil.kinematic_viscosity_40;
      it.oil_temperature = t_oil;
      it.mean_ra = ls.mean_ra;
      it.lubricant_factor = x_l;
      const auto b_m = [](const Material& m) {
        return lubrication::thermal_contact_coefficient(m.thermal_conductivity, m.density, m.specific_heat);
      };
      it.thermo_elastic_factor = lubrication::iso_thermo_elastic_factor(composite_modulus(c.pinion.material, c.wheel.material) * 2.0,
                                                                        b_m(c.pinion.material), b_m(c.wheel.material));
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
        out.findings.push_back("integral temperature: no permissible temperature (the oil has no fzg_scuffing_stage)");
    }
    if (req.micropitting) {
      out.methods.emplace_back("micropitting");
      // lambda_GF along the path (ISO/TS 6336-22 method B at the named points), taken to the rating
      // load: h_Y ~ W^-0.13 ~ p_dyn^-0.26 ~ K^-0.13 (bulk temperature held).
      out.min_lambda = add("lambda_GF,min", ls.min_iso_lambda * std::pow(k_load, -0.13), "1",
                           "ISO/TS 6336-22 eqs. (2), (4), (24): the least of the named points at p_dyn "
                           "(x K^-0.13 of /lubrication's)");
      out.findings.push_back(
          "micropitting: the permissible lambda_GFP (from the oil's GF-C/8.3/90 stage) is not computed: lambda_GF,min is "
          "reported without a safety S_lambda");
    }
  }
  return out;
}

}  // namespace geartrib::runs
