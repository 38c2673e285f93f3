// `geartrib run`: the main job. Rough-surface contact at every position of one tooth pair's
// path A -> E, written to HDF5 (and CSV), with a summary of each quantity's extremes.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "app/progress_bar.hpp"
#include "runs/mesh_cycle.hpp"

#include "contact/fidelity_registry.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/run_summary.hpp"
#include "output/hdf5_results.hpp"
#include "output/html_report.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace geartrib::app {

namespace {

struct Options {
  CaseOptions case_options;
  std::string output;
  CsvOption csv;
  CsvOption report;  // --report [FILE]: the HTML calculation report (output/html_report.hpp)
  std::optional<int> positions;
  std::string fidelity;
  bool quiet = false;
};

// The named point within half a step of s, or "".
std::string point_at(const gear::PathOfContact& p, double s, double step) {
  const std::pair<const char*, double> named[] = {{"A", p.a}, {"B", p.b}, {"C", p.c}, {"D", p.d}, {"E", p.e}};
  for (const auto& [name, at] : named)
    if (std::abs(s - at) <= 0.5 * step) return name;
  return "";
}

void print_summary(const contact::MeshContactResult& r) {
  const auto& s = r.find("s_m")->values;
  const double step = s.size() > 1 ? s[1] - s[0] : 0.0;
  fmt::print(
      "Equivalent surface: summit density {:.4g} /um^2, summit radius {:.4g} um, summit sigma {:.4g} um, "
      "plasticity index {:.3g}; model {}, {} strip\n",
      r.surface.summit_density * 1e-12, r.surface.summit_radius * 1e6, r.surface.summit_sigma * 1e6, r.plasticity_index,
      r.asperity_model, r.fidelity);
  fmt::print("{:<30} {:>6} {:>12} {:>9} {:>3} {:>12} {:>9} {:>3}\n", "quantity", "unit", "min", "at s mm", "", "max",
             "at s mm", "");
  for (const auto* group : {&r.mesh, &r.contact, &r.lubrication, &r.statistical, &r.mixed_ehl})
    for (const auto& q : *group) {
      if (q.name == "s_m" || q.name == "ehl_regime" || q.name.rfind("flag_", 0) == 0) continue;
      std::size_t lo = 0, hi = 0;
      for (std::size_t i = 1; i < q.values.size(); ++i) {
        if (q.values[i] < q.values[lo]) lo = i;
        if (q.values[i] > q.values[hi]) hi = i;
      }
      fmt::print("{:<30} {:>6} {:>12.5g} {:>9.3f} {:>3} {:>12.5g} {:>9.3f} {:>3}\n", q.name, q.unit, q.values[lo],
                 s[lo] * 1e3, point_at(r.path, s[lo], step), q.values[hi], s[hi] * 1e3, point_at(r.path, s[hi], step));
    }
  if (r.lubrication_summary) {
    const auto& l = *r.lubrication_summary;
    constexpr double kC = 273.15;
    fmt::print(
        "Lubricated: {}; oil {:.1f} degC, bulk {:.1f} degC{}; eta {:.4g} mPa s, alpha {:.4g} 1/GPa at bulk; film {} "
        "with {} inlet heating; the film fills the {} (asperity pressure {}), {} traction\n",
        l.lubricant, l.oil_temperature - kC, l.bulk_temperature - kC,
        l.bulk_estimated ? " (ISO/TS 6336-20 estimate)" : "", l.dynamic_viscosity * 1e3, l.pressure_viscosity * 1e9,
        l.film_formula, l.inlet_heating, l.film_gap, l.asperity_pressure, l.traction);
    fmt::print("Roughness: Rq {:.4g} um (composite), Ra {:.4g} um (mean) from {}; the summit model's sigma {:.4g} um\n",
               l.composite_rq * 1e6, l.mean_ra * 1e6, l.roughness_source, l.summit_model_sigma * 1e6);
    if (!l.persson_spectrum.empty())
      fmt::print("Persson's spectrum: {} (rq {:.4g} um, full rms gradient h'_rms {:.4g})\n", l.persson_spectrum,
                 l.persson_rms_height * 1e6, l.persson_rms_gradient);
    fmt::print("{:<4} {:>8} {:>9} {:>8} {:>9} {:>7} {:>9} {:>7} {:>8} {:>7} {:>8} {:>8} {:>8}\n", "pt", "s mm",
               "film um", "lam_film", "gap um", "lam_gap", "ISO h_Y", "lam_GF", "asp shr", "mu", "flash K", "ISO fl K",
               "T_B degC");
    for (const auto& p : l.points)
      fmt::print(
          "{:<4} {:>8.3f} {:>9.4f} {:>8.3f} {:>9.4f} {:>7.3f} {:>9.4f} {:>7.3f} {:>8.3f} {:>7.4f} {:>8.2f} "
          "{:>8.2f} {:>8.1f}\n",
          p.name, p.s * 1e3, p.film * 1e6, p.lambda_film, p.mean_gap * 1e6, p.lambda_gap, p.iso_film * 1e6,
          p.iso_lambda, p.asperity_share, p.friction, p.flash, p.iso_flash, p.iso_contact_temperature - kC);
    std::string laws;
    for (const auto& m : l.mean_friction)
      laws += fmt::format("{}{} {:.4f}", laws.empty() ? "" : ", ", m.law, m.coefficient);
    fmt::print("Friction: model's gear-mean {:.4f} (power loss / (input x H_V)); gear-mean laws at C: {}\n",
               l.mesh_mean_friction, laws);
    fmt::print(
        "Mesh: power loss {:.4g} W of {:.4g} W input (tooth-friction efficiency {:.3f}%); gear loss factor H_V "
        "{:.4f} (path), {:.4f} (Ohlendorf)\n",
        l.mesh_power_loss, l.input_power, 100.0 * l.efficiency, l.loss_factor_path, l.loss_factor_ohlendorf);
    if (l.iso_scuffing_safety > 0.0)
      fmt::print(
          "Scuffing (flash-temperature method): safety S_B {:.3g} (ISO/TS 6336-20), {:.3g} (Blok, local friction)\n",
          l.iso_scuffing_safety, l.scuffing_safety);
  }
  if (r.rating) {
    // The ratings' verdict (/rating; the factors: geartrib rate), what was not rated left out.
    std::string rated;
    for (const auto& v : contact::rating_summary(*r.rating).values)
      if (std::isfinite(v.value) && v.name != "assumed_inputs" && v.name != "findings_count" && v.name != "S_H_min" &&
          v.name != "S_F_min" && v.name != "S_S_min")
        rated += fmt::format("{}{} {:.3g}", rated.empty() ? "" : ", ", v.name, v.value);
    fmt::print("Ratings (ISO 6336-2/-3, ISO/TS 6336-20/-21/-22 at K_A {:g}{}): {}\n",
               r.rating->find("K_A") ? r.rating->find("K_A")->value : 1.0,
               r.rating->assumed_any() ? ", some inputs assumed" : "", rated);
    for (const auto& f : r.rating->findings) fmt::print("  rating: {}\n", f);
  }
  if (r.mixed_ehl_summary) {
    const auto& m = *r.mixed_ehl_summary;
    fmt::print(
        "Mixed EHL: nodes of {:.4g} um (up to {:.0f}), windows of {:g} contact widths at Courant {:g}, {} viscosity, {} "
        "flow; {:.0f} time steps in {:.3g} s of windows (summed over threads){}\n",
        m.grid_spacing * 1e6, m.nodes_max, m.window, m.time_step, m.viscosity_law, m.flow, m.steps, m.window_seconds,
        m.whole_path > 0.0
            ? fmt::format("; the whole path: {:.0f} time steps in {:.3g} s", m.whole_path_steps, m.whole_path_seconds)
            : std::string());
    fmt::print(
        "Mixed EHL along the path: least film {:.4g} um, asperity share up to {:.3g} (path mean {:.3g}), peak pressure "
        "up to {:.4g} GPa, friction (path mean) {:.4f}, flash temperature up to {:.4g} K, load error at most {:.2g}\n",
        m.min_film * 1e6, m.max_asperity_share, m.mean_asperity_share, m.max_peak_pressure * 1e-9, m.mean_friction,
        m.max_flash_temperature, m.max_load_error);
  }
  if (r.running_in) {
    const auto& ri = *r.running_in;
    fmt::print("Running-in ({} order): {} meshes{}, {}\n", ri.teeth, ri.meshes,
               ri.teeth == "hunting" ? " of each pinion tooth (a row per pinion revolution, the teeth's means)" : "",
               ri.shakedown_mesh > 0
                   ? fmt::format("shakedown at mesh {} (no flank point deformed by more than {:.3g} nm)",
                                 ri.shakedown_mesh, ri.tolerance * 1e9)
                   : fmt::format("no shakedown within them (tolerance {:.3g} nm)", ri.tolerance * 1e9));
    fmt::print("{:>5} {:>12} {:>10} {:>10} {:>10} {:>8} {:>10} {:>10} {:>8} {:>10}\n", "mesh", "new plast nm", "A_r/2b",
               "plastic", "pin Rq um", "pin Rsk", "pin R um", "whl Rq um", "whl Rsk", "whl R um");
    auto col = [&](const char* name) -> const std::vector<double>& {
      for (const auto& q : ri.history)
        if (q.name == name) return q.values;
      throw std::logic_error(name);
    };
    for (std::size_t i = 0; i < col("mesh").size(); ++i)
      fmt::print("{:>5.0f} {:>12.4g} {:>10.4g} {:>10.4g} {:>10.4g} {:>8.3f} {:>10.4g} {:>10.4g} {:>8.3f} {:>10.4g}\n",
                 col("mesh")[i], col("new_plastic_deformation_m")[i] * 1e9, col("real_area_ratio_mean")[i],
                 col("plastic_area_fraction_mean")[i], col("pinion_rq_m")[i] * 1e6, col("pinion_rsk")[i],
                 col("pinion_summit_radius_m")[i] * 1e6, col("wheel_rq_m")[i] * 1e6, col("wheel_rsk")[i],
                 col("wheel_summit_radius_m")[i] * 1e6);
  }
  fmt::print("stages:");
  for (const auto& st : r.stages) fmt::print(" {} {:.3f} s;", st.name, st.seconds);
  fmt::print("\n");
}

void run(const Options& o) {
  // --positions and --fidelity are shorthands for --set: what ran is what the case records.
  CaseOptions co = o.case_options;
  if (o.positions) co.changes.push_back(fmt::format("contact.positions={}", *o.positions));
  if (!o.fidelity.empty()) co.changes.push_back("contact.fidelity=" + o.fidelity);
  const Case c = load_case_reporting(co);
  const std::string case_file = case_path(co).string();
  const std::filesystem::path out =
      o.output.empty() ? std::filesystem::path(std::filesystem::path(case_file).stem().string() + ".h5")
                       : std::filesystem::path(o.output);
  // The HDF5 file and the CSV, both or neither; their folders checked before the cycle runs.
  io::OutputSet outputs;
  outputs.reserve(out);
  if (o.csv.to_file()) outputs.reserve(o.csv.file);
  const std::filesystem::path report =
      o.report.to_file() ? std::filesystem::path(o.report.file) : std::filesystem::path(out).replace_extension(".html");
  if (o.report.given()) outputs.reserve(report);
  ProgressBar bar(!o.quiet, "positions");
  const contact::MeshContactResult r = runs::run_mesh_cycle(c, [&](int done, int total) { bar(done, total); });

  const std::filesystem::path written =
      outputs.add(out, [&](const std::filesystem::path& tmp) { io::write_mesh_contact_hdf5(tmp, r, case_file, c); });
  if (o.report.given())
    outputs.add_text(report,
                     io::html_report(written, out.filename().string()));  // read back: one report, from the file
  io::Table t;
  if (o.csv.given()) {
    for (const auto* group : r.groups())
      for (const auto& q : *group) t.header.push_back(q.name);
    for (std::size_t i = 0; i < r.mesh.front().values.size(); ++i) {
      std::vector<double> row;
      for (const auto* group : r.groups())
        for (const auto& q : *group) row.push_back(q.values[i]);
      t.rows.push_back(std::move(row));
    }
    if (o.csv.to_file()) outputs.add_text(o.csv.file, io::format_csv(t));
    if (o.csv.in_place()) outputs.add_stdout(io::format_csv(t));  // standard output holds the table only
  }
  outputs.commit();
  if (o.csv.in_place()) return;
  for (const auto& w : r.warnings) std::cerr << "warning: " << w << '\n';
  if (!r.verdict.empty()) fmt::print("Validity: {}\n", r.verdict);
  if (!o.quiet) {
    for (const auto& [name, g] : {std::pair{"pinion", &c.pinion}, std::pair{"wheel", &c.wheel}})
      if (g->flank.measured)
        fmt::print(
            "{} flank measured ({}): Ra {:.4g} um, Rq {:.4g} um, {} summits, density {:.4g} /um^2, radius {:.4g} um, "
            "sigma {:.4g} um\n",
            name, g->flank.topography->file, g->flank.measured->ra * 1e6, g->flank.measured->rq * 1e6,
            g->flank.measured->summits, g->flank.roughness.summit_density * 1e-12,
            g->flank.roughness.summit_radius * 1e6, g->flank.roughness.summit_sigma * 1e6);
    for (const auto& f : r.synthesis) {
      const bool map = f.method.starts_with("areal");
      fmt::print(
          "{} flank {} ({}, seed {:.0f}{}) from {}: {:.0f} lines of {:.4g} um; Rq {:.4g} um along them, {:.4g} um "
          "over {:.4g} mm ({})\n",
          f.gear, map ? "map made" : "synthesised", f.method, f.seed, f.teeth > 1 ? " + tooth" : "", f.patch,
          f.patch_lines, f.patch_points * f.patch_spacing * 1e6, f.patch_rq * 1e6, f.profile_rq * 1e6,
          f.profile_length * 1e3,
          map ? fmt::format("its variance {:.1f}% of the patch's: no wave longer than the patch, and across the "
                            "face only those the window holds",
                            100.0 * (1.0 - f.rolled_off_fraction))
              : fmt::format("{:.1f}% of the patch's variance, at wavelengths near or beyond its length, left out",
                            100.0 * f.rolled_off_fraction));
    }
    print_summary(r);
  }
  fmt::print("wrote {}{}{}\n", out.string(), o.csv.to_file() ? " and " + o.csv.file : "",
             o.report.given() ? " and " + report.string() : "");
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "run",
      "The main job: rough-surface contact at every position of one tooth pair's path of contact A -> E.\n"
      "For each position: the kinematics and load (share, line load, Hertz strip, speeds) and the rough\n"
      "contact across the strip: real-area ratio, real area per face width, mean real pressure, contacts,\n"
      "plastic share of the real area and of the contacts, and the highest asperity's peak pressure and\n"
      "von Mises stress. Computes only the outputs the case asks for ([contact] outputs).\n"
      "A case with [lubricant] runs lubricated: the EHL film (with inlet heating), lambda, the load the\n"
      "film leaves to the asperities (the /contact outputs are then the asperities' share), friction,\n"
      "power loss, flash and contact temperature, wear per engagement, and the ISO/TS 6336-20/22 values\n"
      "beside them (docs/theory/lubrication.md: each model's range). Writes HDF5 (/mesh, /contact,\n"
      "/lubrication with units, /scene and /parameters: the case as it ran, /meta with the stages and\n"
      "their times) and prints each quantity's extremes and where on the path they occur.\n"
      "contact.fidelity = \"deterministic\" rolls the flanks' profiles (measured or generated) through the\n"
      "contact at every position, solved by boundary elements (pressure profiles in /contact/pressure), with\n"
      "the statistical model on the same flanks beside it (/statistical) and, with [running_in] meshes,\n"
      "the flanks' plastic deformation carried from mesh to mesh until shakedown (/running_in).");
  add_case_argument(cmd, o->case_options);
  add_output_option(cmd, o->output, "the HDF5 results (default: <case name>.h5 in the working directory)");
  add_csv_option(cmd, o->csv,
                 "the per-position table as CSV besides the HDF5: to FILE, or without one to\n"
                 "standard output in place of the summary");
  o->report.option =
      cmd->add_option("--report", o->report.file,
                      "[FILE]: the HTML calculation report beside the HDF5 (default: the HDF5's name with "
                      ".html; geartrib report)")
          ->expected(0, 1);
  cmd->add_option("--positions", o->positions, "N: shorthand for --set contact.positions=N (default 201)")
      ->check(CLI::Range(2, 100000));
  const std::vector<std::string> fidelities = contact::fidelity_names();
  std::string names;  // "a, b or c"
  for (std::size_t i = 0; i < fidelities.size(); ++i)
    names += (i == 0 ? "" : i + 1 == fidelities.size() ? " or " : ", ") + fidelities[i];
  cmd->add_option("--fidelity", o->fidelity, names + ": shorthand for --set contact.fidelity=...")
      ->check(CLI::IsMember(fidelities));
  add_quiet_flag(cmd, o->quiet);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
