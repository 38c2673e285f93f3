#include "contact/run_summary.hpp"

#include "contact/series_columns.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geartrib::contact {

namespace {

double flag(bool b) { return b ? 1.0 : 0.0; }

}  // namespace

Summary path_summary(const gear::PathOfContact& p) {
  return {{},
          {{"s_A_m", "m", p.a},
           {"s_B_m", "m", p.b},
           {"s_C_m", "m", p.c},
           {"s_D_m", "m", p.d},
           {"s_E_m", "m", p.e},
           {"base_pitch_m", "m", p.base_pitch},
           {"contact_ratio", "1", p.contact_ratio}}};
}

Summary gear_summary(const MeshContactResult& r) {
  const gear::PathOfContact& p = r.path;
  Summary s{{}, {{"line_of_action_m", "m", p.line_length}}};
  const std::pair<const char*, double> points[] = {{"A", p.a}, {"B", p.b}, {"C", p.c}, {"D", p.d}, {"E", p.e}};
  for (int g = 0; g < 2; ++g) {
    const gear::GearBody& b = r.gears[static_cast<std::size_t>(g)];
    const std::string n = g == 0 ? "pinion" : "wheel";
    // The diameter through the contact point at s: the pinion's roll length is s, the wheel's T1T2 - s.
    auto diameter = [&](double s) { return 2.0 * std::hypot(b.base_radius, g == 0 ? s : p.line_length - s); };
    s.values.insert(s.values.end(), {{n + "_reference_diameter_m", "m", 2.0 * b.pitch_radius},
                                     {n + "_base_diameter_m", "m", 2.0 * b.base_radius},
                                     {n + "_tip_diameter_m", "m", 2.0 * b.tip_radius},
                                     {n + "_root_diameter_m", "m", 2.0 * b.root_radius}});
    for (const auto& [name, at] : points) s.values.push_back({n + "_diameter_at_" + name + "_m", "m", diameter(at)});
    s.values.push_back({n + "_sap_diameter_m", "m", diameter(g == 0 ? p.a : p.e)});
    s.values.push_back({n + "_eap_diameter_m", "m", diameter(g == 0 ? p.e : p.a)});
  }
  return s;
}

Summary tooth_contact_summary(const gear::TransmissionErrorStats& t) {
  return {{},
          {{"transmission_error_mean_m", "m", t.mean},
           {"transmission_error_peak_to_peak_m", "m", t.peak_to_peak},
           {"transmission_error_min_m", "m", t.min},
           {"transmission_error_max_m", "m", t.max},
           {"effective_mesh_stiffness_mean_N_per_m", "N/m", t.stiffness_mean},
           {"effective_mesh_stiffness_min_N_per_m", "N/m", t.stiffness_min},
           {"effective_mesh_stiffness_max_N_per_m", "N/m", t.stiffness_max},
           {"loaded_start_m", "m", t.loaded_start},
           {"loaded_end_m", "m", t.loaded_end},
           {"effective_contact_ratio", "1", t.effective_contact_ratio},
           {"contact_lost", "1", flag(t.contact_lost)},
           {"hertz_approach_in_range", "1", flag(t.hertz_in_range)}}};
}

Summary rating_summary(const rating::RatingResult& r) {
  std::string methods;
  for (const auto& m : r.methods) methods += (methods.empty() ? "" : ",") + m;
  // The same names in the same order whatever was rated (a sweep's columns line up over its
  // points): NaN where a method did not run or found nothing to rate against.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto rated = [&](double v) { return v > 0.0 ? v : nan; };
  const double s_b = rated(r.flash_scuffing_safety), s_int = rated(r.integral_scuffing_safety);
  return {{{"methods", methods}},
          {{"S_H_min", "1", rated(std::min(r.pitting_safety[0], r.pitting_safety[1]))},
           {"S_H_pinion", "1", rated(r.pitting_safety[0])},
           {"S_H_wheel", "1", rated(r.pitting_safety[1])},
           {"S_F_min", "1", rated(std::min(r.bending_safety[0], r.bending_safety[1]))},
           {"S_F_pinion", "1", rated(r.bending_safety[0])},
           {"S_F_wheel", "1", rated(r.bending_safety[1])},
           {"S_S_min", "1", std::fmin(s_b, s_int)},  // fmin: the other where one is NaN
           {"S_B", "1", s_b},
           {"S_intS", "1", s_int},
           {"lambda_GF_min", "1", rated(r.min_lambda)},
           {"S_lambda", "1", rated(r.micropitting_safety)},
           {"assumed_inputs", "1", flag(r.assumed_any())},
           {"findings_count", "1", static_cast<double>(r.findings.size())}}};
}

Summary surface_summary(const MeshContactResult& r) {
  return {{{"asperity_model", r.asperity_model}, {"fidelity", r.fidelity}},
          {{"summit_density_per_m2", "1/m^2", r.surface.summit_density},
           {"summit_radius_m", "m", r.surface.summit_radius},
           {"summit_sigma_m", "m", r.surface.summit_sigma},
           {"surface_sigma_m", "m", r.surface.surface_sigma},
           {"summit_mean_height_m", "m", r.surface.summit_mean_height},
           {"plasticity_index", "1", r.plasticity_index}}};
}

Summary validity_summary(const MeshContactResult& r) {
  Summary s{{{"regime", r.regime}, {"verdict", r.verdict}}, {}};
  for (const auto& f : r.flag_counts)
    s.values.push_back({"positions_" + f.name, "1", static_cast<double>(f.positions)});
  return s;
}

Summary running_in_summary(const RunningInResult& ri) {
  return {{{"teeth", ri.teeth}},
          {{"meshes", "1", static_cast<double>(ri.meshes)},
           {"shakedown_mesh", "1", static_cast<double>(ri.shakedown_mesh)},
           {"tolerance_m", "m", ri.tolerance},
           {"pinion_profile_spacing_m", "m", ri.spacing[0]},
           {"wheel_profile_spacing_m", "m", ri.spacing[1]}}};
}

Summary synthesis_summary(const FlankSynthesis& f) {
  Summary s{{{"patch", f.patch}, {"method", f.method}},
            {{"seed", "1", f.seed},
             {"teeth", "1", static_cast<double>(f.teeth)},
             {"patch_lines", "1", f.patch_lines},
             {"patch_points", "1", f.patch_points},
             {"patch_spacing_m", "m", f.patch_spacing},
             {"patch_rq_m", "m", f.patch_rq},
             {"rolled_off_fraction", "1", f.rolled_off_fraction},
             {"profile_length_m", "m", f.profile_length},
             {"profile_rq_m", "m", f.profile_rq}}};
  if (f.method == "iaaft") {
    const std::vector<SummaryValue> iaaft = {{"iaaft_iterations", "1", static_cast<double>(f.iterations)},
                                             {"iaaft_spectrum_misfit", "1", f.spectrum_misfit},
                                             {"iaaft_curvature_ratio", "1", f.curvature_ratio},
                                             {"iaaft_converged", "1", flag(f.converged)}};
    s.values.insert(s.values.end(), iaaft.begin(), iaaft.end());
  }
  return s;
}

Summary lubrication_summary(const LubricationSummary& l) {
  Summary s;
  s.texts = {
      {"lubricant", l.lubricant},
      {"film_formula", l.film_formula},
      {"inlet_heating", l.inlet_heating},
      {"film_gap", l.film_gap},
      {"asperity_pressure", l.asperity_pressure},
      {"traction", l.traction},
      {"bulk_friction_law", l.bulk_friction_law},
      {"roughness_source", l.roughness_source},
      {"ehl_regime_codes", "0 rigid-isoviscous, 1 rigid-piezoviscous, 2 elastic-isoviscous, 3 elastic-piezoviscous"}};
  s.values = {{"oil_temperature_K", "K", l.oil_temperature},
              {"bulk_temperature_K", "K", l.bulk_temperature},
              {"bulk_temperature_estimated", "1", flag(l.bulk_estimated)},
              {"dynamic_viscosity_at_bulk_Pa_s", "Pa s", l.dynamic_viscosity},
              {"pressure_viscosity_at_bulk_per_Pa", "1/Pa", l.pressure_viscosity},
              {"composite_rq_m", "m", l.composite_rq},
              {"mean_ra_m", "m", l.mean_ra},
              {"summit_model_sigma_m", "m", l.summit_model_sigma},
              {"bearing_area_weight", "1", l.bearing_area_weight}};
  for (const auto& m : l.mean_friction) {
    std::string name = "mean_friction_" + m.law;
    std::replace(name.begin(), name.end(), '-', '_');
    s.values.push_back({name, "1", m.coefficient});
  }
  const std::vector<SummaryValue> rest = {
      {"mesh_mean_friction", "1", l.mesh_mean_friction},
      {"mesh_power_loss_W", "W", l.mesh_power_loss},
      {"input_power_W", "W", l.input_power},
      {"tooth_friction_efficiency", "1", l.efficiency},
      {"gear_loss_factor_path", "1", l.loss_factor_path},
      {"gear_loss_factor_ohlendorf", "1", l.loss_factor_ohlendorf},
      {"max_contact_temperature_K", "K", l.max_contact_temperature},
      {"max_iso_contact_temperature_K", "K", l.max_iso_contact_temperature},
      {"min_iso_lambda_gf", "1", l.min_iso_lambda},
      {"min_lambda_smooth_film", "1", l.min_lambda_film},
      {"max_asperity_share_closure_spread", "1", l.max_share_spread},
      {"positions_share_depends_on_closure", "1", static_cast<double>(l.closure_dependent_positions)},
      {"positions_oil_temperature_clamped", "1", static_cast<double>(l.oil_clamped_positions)},
      {"iso_effective_tip_relief_m", "m", l.iso_effective_relief}};
  s.values.insert(s.values.end(), rest.begin(), rest.end());
  if (!l.persson_spectrum.empty()) {
    s.texts.push_back({"persson_spectrum", l.persson_spectrum});
    s.values.push_back({"persson_spectrum_rq_m", "m", l.persson_rms_height});
    s.values.push_back({"persson_spectrum_rms_gradient", "1", l.persson_rms_gradient});
  }
  if (l.iso_scuffing_safety > 0.0) {
    s.values.push_back({"iso_scuffing_safety", "1", l.iso_scuffing_safety});
    s.values.push_back({"scuffing_safety", "1", l.scuffing_safety});
  }
  return s;
}

Summary mixed_ehl_summary(const MixedEhlSummary& m) {
  Summary s{{{"viscosity_law", m.viscosity_law}, {"flow", m.flow}},
            {{"compressible", "1", m.compressible},
             {"grid_spacing_m", "m", m.grid_spacing},
             {"nodes_max", "1", m.nodes_max},
             {"inlet_halfwidths", "1", m.inlet},
             {"outlet_halfwidths", "1", m.outlet},
             {"window_contact_widths", "1", m.window},
             {"lead_in_halfwidths", "1", m.lead_in},
             {"time_step_courant", "1", m.time_step},
             {"tolerance", "1", m.tolerance},
             {"film_floor_m", "m", m.film_floor},
             {"boundary_friction", "1", m.boundary_friction},
             {"hardness_Pa", "Pa", m.hardness},
             {"dynamic_viscosity_Pa_s", "Pa s", m.eta},
             {"pressure_viscosity_per_Pa", "1/Pa", m.alpha},
             {"eyring_stress_Pa", "Pa", m.eyring_stress},
             {"limiting_shear_coefficient", "1", m.limiting_shear_coefficient},
             {"time_steps", "1", m.steps},
             {"windows_seconds", "s", m.window_seconds},
             {"windows_transform_seconds", "s", m.transform_seconds},
             {"min_film_m", "m", m.min_film},
             {"max_asperity_share", "1", m.max_asperity_share},
             {"mean_asperity_share", "1", m.mean_asperity_share},
             {"max_peak_pressure_Pa", "Pa", m.max_peak_pressure},
             {"mean_friction_coefficient", "1", m.mean_friction},
             {"max_flash_temperature_K", "K", m.max_flash_temperature},
             {"max_von_mises_Pa", "Pa", m.max_von_mises},
             {"max_load_error", "1", m.max_load_error},
             {"whole_path", "1", m.whole_path}}};
  if (m.whole_path > 0.0) {
    s.values.push_back({"whole_path_time_steps", "1", m.whole_path_steps});
    s.values.push_back({"whole_path_seconds", "s", m.whole_path_seconds});
  }
  return s;
}

std::vector<Series> named_point_series(const LubricationSummary& l) {
  using P = LubricationSummary::NamedPoint;
  std::vector<Series> out;
  add_columns<P>(out, l.points,
                 {{"s_m", "m", [](const P& q) { return q.s; }},
                  {"line_load_N_per_m", "N/m", [](const P& q) { return q.line_load; }},
                  {"film_m", "m", [](const P& q) { return q.film; }},
                  {"lambda_smooth_film", "1", [](const P& q) { return q.lambda_film; }},
                  {"mean_gap_m", "m", [](const P& q) { return q.mean_gap; }},
                  {"lambda_mean_gap", "1", [](const P& q) { return q.lambda_gap; }},
                  {"iso_film_hy_m", "m", [](const P& q) { return q.iso_film; }},
                  {"iso_lambda_gf", "1", [](const P& q) { return q.iso_lambda; }},
                  {"asperity_load_share", "1", [](const P& q) { return q.asperity_share; }},
                  {"asperity_share_closure_spread", "1", [](const P& q) { return q.share_spread; }},
                  {"friction_coefficient", "1", [](const P& q) { return q.friction; }},
                  {"flash_temperature_K", "K", [](const P& q) { return q.flash; }},
                  {"iso_flash_temperature_K", "K", [](const P& q) { return q.iso_flash; }},
                  {"contact_temperature_K", "K", [](const P& q) { return q.contact_temperature; }},
                  {"iso_contact_temperature_K", "K", [](const P& q) { return q.iso_contact_temperature; }}});
  return out;
}

}  // namespace geartrib::contact
