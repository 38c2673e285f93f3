// `geartrib asperity`: single-asperity contact of the case's equivalent asperity pair, by model,
// in normal or side contact; the case summary; comparison with a reference table.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "runs/asperity_columns.hpp"

#include "asperity/side_contact.hpp"
#include "case/asperity_setup.hpp"
#include "config/case_file.hpp"
#include "config/input_error.hpp"
#include "config/reference_table.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace geartrib::app {

namespace {

using asperity::AsperityState;

using runs::asperity_column;
using runs::kAsperityColumns;

struct Options {
  std::string model;
  CaseOptions case_options;
  std::string contact = "normal";
  std::string mu;
  std::vector<double> delta_star;
  std::string range;
  TableOptions table;
  bool summary = false;
  bool list_constants = false;
  std::string compare;
};

std::vector<double> parse_range(const std::string& text) {
  auto fail = [&](const std::string& rule) {
    throw std::invalid_argument("--range '" + text + "': " + rule + " (expected MIN:MAX:COUNT, log-spaced)");
  };
  std::vector<double> parts;
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const auto end = i < 2 ? text.find(':', start) : text.size();
    if (end == std::string::npos) fail("needs three fields");
    double v = 0.0;
    const auto [p, ec] = std::from_chars(text.data() + start, text.data() + end, v);
    if (ec != std::errc{} || p != text.data() + end) fail("field " + std::to_string(i + 1) + " is not a number");
    parts.push_back(v);
    start = end + 1;
  }
  const double lo = parts[0], hi = parts[1], count = parts[2];
  if (!(lo > 0.0 && std::isfinite(hi) && hi >= lo)) fail("need 0 < MIN <= MAX");
  if (!(count >= 1.0 && count <= 1e6 && count == std::floor(count))) fail("COUNT must be a whole number in [1, 1e6]");
  if (count == 1.0 && hi != lo) fail("COUNT = 1 needs MIN = MAX");
  std::vector<double> out;
  const int n = static_cast<int>(count);
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) out.push_back(n == 1 ? lo : lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1)));
  out.back() = hi;  // both ends exactly
  return out;
}

void print_summary(const Case& c, const asperity::AsperityModel& model, double mu) {
  using namespace asperity;
  const ContactPair p = contact_pair(c);
  const double k = ceb_pressure_factor(p.poisson_ratio);
  const Critical crit = hertz_critical(p, k * p.hardness);
  const HertzYieldPoint y = hertz_yield_point(p.poisson_ratio);
  const double a_c = hertz_contact_radius(crit.interference, p.radius);
  fmt::print("Case: {}\n", c.title);
  fmt::print("Equivalent asperity (the two flanks' mean summits against a rigid flat)\n");
  fmt::print("  E_t      composite modulus           {:.5g} GPa\n", p.modulus / 1e9);
  fmt::print("  R        equivalent tip radius       {:.5g} um\n", p.radius * 1e6);
  fmt::print("  k        CEB pressure factor         {:.4g}\n", k);
  fmt::print("  H        hardness                    {:.5g} GPa\n", p.hardness / 1e9);
  fmt::print("  delta_c  critical interference (CEB) {:.4g} nm\n", crit.interference * 1e9);
  fmt::print("  F_c      critical load               {:.4g} uN\n", crit.load * 1e6);
  fmt::print("  a_c      contact radius at delta_c   {:.4g} nm\n", a_c * 1e9);
  fmt::print("  p_y      Hertz peak at delta_c (kH)  {:.4g} GPa\n", crit.peak_pressure / 1e9);
  fmt::print("  yield depth (von Mises max on axis) {:.4f} a = {:.4g} nm at delta_c, sigma_vm = {:.4f} p0\n",
             y.depth_over_radius, y.depth_over_radius * a_c * 1e9, y.von_mises_over_peak);
  fmt::print("Critical values of each model (its own delta_c normalises its starred outputs)\n");
  for (auto name : asperity_model_names()) {
    const auto m = make_case_model(c, name);
    const Critical mc = m->critical(p);
    fmt::print("  {:<14} delta_c {:.5g} nm  F_c {:.5g} uN  A_c {:.5g} nm^2\n", name, mc.interference * 1e9,
               mc.load * 1e6, mc.area * 1e18);
  }
  const SideContactGeometry g =
      side_contact_geometry(c.pinion.flank.roughness.summit_radius, c.wheel.flank.roughness.summit_radius, mu);
  const ContactPair p0 = with_radius(p, g.radius_0);
  fmt::print("Side contact of sliding summits, mu = {:.4g} (model {})\n", mu, model.name());
  fmt::print("  theta    contact-normal tilt atan(mu) {:.4f} deg\n", g.theta * 180.0 / std::numbers::pi);
  fmt::print("  d        axis offset (R1+R2) mu       {:.4g} um; tip gap at touch {:.4g} um\n", g.axis_offset * 1e6,
             g.tip_gap * 1e6);
  fmt::print("  R0       R/cos^3(theta)               {:.5g} um  (across: R/cos(theta) = {:.5g} um)\n",
             g.radius_0 * 1e6, g.radius_y * 1e6);
  fmt::print("  delta_cn (pi k H/(2 E_t))^2 R0         {:.5g} nm  (model {}: {:.5g} nm)\n",
             hertz_critical(p0, k * p.hardness).interference * 1e9, model.name(),
             model.critical(p0).interference * 1e9);
  if (c.asperity.measured_axis_offset > 0.0) {
    const double r12 = c.pinion.flank.roughness.summit_radius + c.wheel.flank.roughness.summit_radius;
    const double d0 = c.asperity.measured_axis_offset;
    fmt::print(
        "  measured d0 = {:.4g} um, y0 = {:.4g} um: touching tips need y0 = d0^2/(2(R1+R2)) = {:.4g} um;\n"
        "  their normal tilt is atan(d0/(R1+R2)) = {:.4f} deg, i.e. tan(theta) = {:.4g}, not mu\n",
        d0 * 1e6, c.asperity.measured_tip_gap * 1e6, d0 * d0 / (2.0 * r12) * 1e6,
        normal_tilt_from_offset(c.pinion.flank.roughness.summit_radius, c.wheel.flank.roughness.summit_radius, d0) *
            180.0 / std::numbers::pi,
        d0 / r12);
  }
  const CylinderAsperity cyl = cylinder_asperity(c);
  const LineCritical lc = line_critical(cyl);
  CylinderAsperity seed_c = cyl;
  seed_c.yield_constant = 1.64;
  fmt::print("Cylinder asperity (the multi-asperity and FEM studies), R_m = {:.4g} um\n", cyl.tip_radius * 1e6);
  fmt::print("  delta_pc (2 R_m s/E_t)[ln(2 E_t/s) - 1] C, C = {:.4g}: {:.4g} um (the thesis prints 0.38 um",
             cyl.yield_constant, seed_critical_interference(cyl) * 1e6);
  if (cyl.yield_constant != 1.64)
    fmt::print("; its C = 1.64 gives {:.4g} um", seed_critical_interference(seed_c) * 1e6);
  fmt::print(")\n");
  fmt::print("  Green (2005) plane-strain C_L(nu = {:.3g}) = {:.4g}\n", cyl.poisson_ratio,
             green_cylinder_yield_factor(cyl.poisson_ratio));
  fmt::print("  first yield of the line contact: b_c = {:.4g} nm, F'_c = {:.4g} N/m, p0 = {:.4g} MPa\n",
             lc.half_width * 1e9, lc.load_per_length, lc.peak_pressure / 1e6);
}

void print_constants(const asperity::AsperityModel& m) {
  fmt::print("{}: {}\n", m.name(), m.citation());
  const auto specs = m.constant_specs();
  if (specs.empty()) fmt::print("  (no adjustable constants)\n");
  for (std::size_t i = 0; i < specs.size(); ++i)
    fmt::print("  {:<22} = {:<8.6g} [{:g}, {:g}]  {}\n", specs[i].name, m.constants()[i], specs[i].lower,
               specs[i].upper, specs[i].meaning);
  const asperity::LawRange r = m.range();
  fmt::print("range: delta* <= {:g}, contact radius <= {:g} x the summit radius; past it: {}\n",
             r.fitted_delta_star_max, r.contact_radius_over_radius_max, r.past_range);
}

// The model's difference from a reference value [%]: 100 (model - reference)/reference; where the
// reference is 0, the symmetric 200 (model - reference)/(|model| + |reference|) (+-200 % for a
// nonzero model, 0 for both 0), so that a zero in the table gives a number, never inf or NaN.
double percent_difference(double model, double reference) {
  if (reference != 0.0) return 100.0 * (model - reference) / reference;
  const double scale = std::abs(model) + std::abs(reference);
  return scale > 0.0 ? 200.0 * (model - reference) / scale : 0.0;
}

void run_compare(const Options& o, const asperity::AsperityModel& m, const asperity::ContactPair& p,
                 io::OutputSet& outputs) {
  const io::ReferenceTable ref =
      io::read_reference_table(o.compare, [](const std::string& q) { return asperity_column(q).dimension; });
  if (ref.input_name != "delta_star")
    throw io::InputError(ref.file, 0, ref.input_name, "", "the input column must be delta_star");
  fmt::print("Reference: {}\n", ref.file);
  for (const auto& [k, v] : ref.provenance) fmt::print("  {}: {}\n", k, v);
  fmt::print("Model: {} ({}); differences are (model - reference)/reference\n", m.name(), m.citation());
  io::Table t;
  t.header.emplace_back("delta_star");
  for (const auto& col : ref.columns) {
    const std::string name = col.quantity + "@" + col.label + "[" + col.unit + "]";
    t.header.push_back(name);
    t.header.push_back("model[" + col.unit + "]");
    t.header.emplace_back("diff_%");
  }
  const auto crit = m.critical(p);
  for (std::size_t r = 0; r < ref.inputs.size(); ++r) {
    const AsperityState s = m.evaluate(p, ref.inputs[r] * crit.interference);
    std::vector<double> row{ref.inputs[r]};
    for (const auto& col : ref.columns) {
      const double factor = col.unit.empty() ? 1.0 : io::unit_factor(col.unit, asperity_column(col.quantity).dimension);
      const double model_value = asperity_column(col.quantity).get(s);
      row.push_back(col.values[r] / factor);
      row.push_back(model_value / factor);
      row.push_back(percent_difference(model_value, col.values[r]));
    }
    t.rows.push_back(std::move(row));
  }
  emit_table(t, o.table, outputs);
}

void run(const Options& o) {
  // --model and --mu are shorthands for --set asperity.model and friction.mu.
  CaseOptions co = o.case_options;
  if (!o.model.empty()) co.changes.push_back("asperity.model=" + o.model);
  if (!o.mu.empty()) co.changes.push_back("friction.mu=" + o.mu);
  unsigned parts = io::kGeometryPart | io::kRoughnessPart;
  if (o.contact == "side" || o.summary) parts |= io::kFrictionPart;
  if (o.summary) parts |= io::kCylinderPart;
  const Case c = load_case_reporting(co, parts);
  const auto model = asperity::make_case_model(c, c.asperity.model);
  const double mu = c.friction_coefficient;
  const asperity::ContactPair pair = asperity::contact_pair(c);

  if (o.list_constants) return print_constants(*model);
  if (o.summary) return print_summary(c, *model, mu);
  io::OutputSet outputs;  // the table's files, checked before any work
  reserve_table(o.table, outputs);
  if (!o.compare.empty()) return run_compare(o, *model, pair, outputs);

  std::vector<double> levels = o.delta_star;
  if (!o.range.empty()) levels = parse_range(o.range);
  if (levels.empty()) levels = {1.0, 2.0, 6.0, 7.0, 10.0};  // the seed's section 3 levels
  // Interference from 0 to 10^6 critical interferences: the range every model is tested over
  // (tests/test_extremes.cpp); past it the contact radius exceeds the summit a thousandfold.
  constexpr double kMaxDeltaStar = 1e6;
  for (double d : levels)
    if (!(d >= 0.0 && d <= kMaxDeltaStar))
      throw std::invalid_argument(fmt::format("{} {:g}: delta* must be from 0 to {:g}",
                                              o.range.empty() ? "--delta-star" : "--range", d, kMaxDeltaStar));

  io::Table t;
  for (const auto& col : kAsperityColumns) t.header.push_back(std::string(col.quantity) + std::string(col.suffix));
  if (o.contact == "normal") {
    const double dc = model->critical(pair).interference;
    for (double d : levels) {
      const AsperityState s = model->evaluate(pair, d * dc);
      std::vector<double> row;
      for (const auto& col : kAsperityColumns) row.push_back(col.get(s));
      t.rows.push_back(std::move(row));
    }
  } else {
    const auto g = asperity::side_contact_geometry(c.pinion.flank.roughness.summit_radius,
                                                   c.wheel.flank.roughness.summit_radius, mu);
    for (auto h :
         {"applied_delta_m", "theta_deg", "vertical_load_N", "tangential_load_N", "semi_major_m", "semi_minor_m"})
      t.header.emplace_back(h);
    const double dcn = model->critical(asperity::with_radius(pair, g.radius_0)).interference;
    for (double d : levels) {
      const auto s = asperity::evaluate_side_contact(*model, pair, g, d * dcn / std::cos(g.theta));
      std::vector<double> row;
      for (const auto& col : kAsperityColumns) row.push_back(col.get(s.normal));
      for (double v : {s.applied_delta, s.theta * 180.0 / std::numbers::pi, s.vertical_load, s.tangential_load,
                       s.semi_major, s.semi_minor})
        row.push_back(v);
      t.rows.push_back(std::move(row));
    }
  }
  emit_table(t, o.table, outputs);
}

// The registry's model names, for the help text.
std::string model_list() {
  std::string s;
  for (auto n : asperity::asperity_model_names()) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

}  // namespace

void add_asperity_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "asperity",
      "Single-asperity elastic-plastic contact (sphere on flat) of the case's equivalent asperity.\n"
      "Prints, for each interference delta* = delta/delta_c (the model's own delta_c), the load, contact\n"
      "area and radius, plastic-core radius, mean and peak pressure, plastic share of the area, and the\n"
      "largest von Mises stress of the elastic field on the axis with its depth. Models: " +
          model_list() + ".");
  cmd->add_option("--model", o->model, "Asperity model: shorthand for --set asperity.model=... (default: the case's)");
  add_case_option(cmd, o->case_options);
  cmd->add_option("--contact", o->contact, "normal (frictionless, coaxial) or side (frictional, tilted by atan(mu))")
      ->check(CLI::IsMember({"normal", "side"}));
  cmd->add_option("--mu", o->mu, "Friction coefficient of side contact: shorthand for --set friction.mu=...");
  auto* ds = cmd->add_option("--delta-star", o->delta_star, "Comma-separated delta* values (default 1,2,6,7,10)")
                 ->delimiter(',');
  auto* rg = cmd->add_option("--range", o->range, "MIN:MAX:COUNT, log-spaced delta* with both ends included");
  ds->excludes(rg);
  add_table_options(cmd, o->table);
  cmd->add_flag("--summary", o->summary,
                "Print E_t, R, k, H, delta_c, F_c, the yield depth, side-contact and cylinder values");
  cmd->add_flag("--constants", o->list_constants, "List the model's named constants with values, ranges and meaning");
  cmd->add_option("--compare", o->compare, "Reference table (validation/*/...csv) to print the model beside");
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
