// `geartrib tradeoff`: what each fidelity knob of the mesh cycle costs in time and in accuracy.
// For every knob, each setting is run with the other knobs at the case's own settings, timed,
// and compared with the same knob's highest setting (its reference) on the main outputs: the
// real-area ratio, the plastic area fraction and the highest asperity's von Mises stress along
// A -> E. Then the case as given and the recommended combination (each knob's cheapest setting
// within the tolerance of its reference) are compared with all knobs at their highest settings.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/mesh_contact.hpp"
#include "runs/mesh_cycle.hpp"

#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/units.hpp"
#include "fem/ccx_results.hpp"
#include "output/column_table.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <utility>

namespace geartrib::app {

namespace {

struct Options {
  CaseOptions case_options;
  TableOptions table;
  double tolerance = 0.01;
  double min_time = 0.3;
  std::vector<std::string> knobs;
  bool quiet = false;
};

struct Setting {
  std::string label;
  std::vector<io::CaseChange> changes;
};

// A knob's settings from cheapest to most faithful; the last is its reference. `physics`: the
// settings are different models (or, for the integrator, not used by the case): reported, not
// part of the recommended combination nor of the all-highest reference.
struct Knob {
  std::string name;
  std::vector<Setting> settings;
  bool physics = false;
};

const io::Parameter& row(const std::string& key) { return *io::find_parameter(key).parameter; }

// A resolution's ladder from the parameter table.
Knob ladder(std::string_view name, std::string_view key) {
  Knob k{std::string(name), {}, false};
  for (const auto& v : row(std::string(key)).ladder) k.settings.push_back({v, {{std::string(key), v}}});
  return k;
}

// Elements not finer than the flanks' profile spacing (the case's own rule): the ladder's settings
// that respect it, and the spacing itself as the finest (the reference) when it falls between them.
void limit_to_profile_spacing(const Case& c, Knob& elements) {
  const double finest = runs::finest_element_size(c);
  if (!(finest > 0.0)) return;
  std::erase_if(elements.settings, [&](const Setting& s) {
    return io::parse_quantity(s.label, io::Dimension::length) < finest * (1.0 - 1e-9);
  });
  const bool on_ladder =
      !elements.settings.empty() &&
      io::parse_quantity(elements.settings.back().label, io::Dimension::length) <= finest * (1.0 + 1e-9);
  if (!on_ladder) {
    // Written to 1e-6 um, rounded up: the setting is never finer than the spacing.
    const std::string v = fmt::format("{:.12g} um", std::ceil(finest * 1e12 * (1.0 - 1e-12)) * 1e-6);
    elements.settings.push_back({v, {{"contact.element_size", v}}});
  }
}

// A grid not coarser than the flanks' profile spacing (the mixed-EHL case's rule): the ladder's
// settings that respect it, and the spacing itself as the coarsest when the ladder starts finer.
void limit_to_grid_spacing(const Case& c, Knob& grid) {
  const double coarsest = runs::coarsest_grid_spacing(c);
  if (!(coarsest > 0.0)) return;
  std::erase_if(grid.settings, [&](const Setting& s) {
    return io::parse_quantity(s.label, io::Dimension::length) > coarsest * (1.0 + 1e-9);
  });
  const bool on_ladder = !grid.settings.empty() && io::parse_quantity(grid.settings.front().label,
                                                                      io::Dimension::length) >= coarsest * (1.0 - 1e-9);
  if (!on_ladder) {
    // Written to 1e-6 um, rounded down: the setting is never coarser than the spacing.
    const std::string v = fmt::format("{:.12g} um", std::floor(coarsest * 1e12 * (1.0 + 1e-12)) * 1e-6);
    grid.settings.insert(grid.settings.begin(), {v, {{"mixed_ehl.grid_spacing", v}}});
  }
}

// The fidelities of the case's family (contact/fidelities.hpp), each with its settings.
Knob fidelity_knob(const contact::FidelityEntry& own) {
  Knob fidelity{"fidelity", {}, false};
  for (const contact::FidelityEntry& f : contact::fidelities()) {
    if (f.traits.family != own.traits.family) continue;
    const std::string name(f.name), key(f.traits.setting_key);
    if (key.empty()) fidelity.settings.push_back({name, {{"contact.fidelity", name}}});
    else
      for (const auto& n : row(key).ladder)
        fidelity.settings.push_back({name + " " + n, {{"contact.fidelity", name}, {key, n}}});
  }
  return fidelity;
}

// The dynamic cycle: static load sharing against the steady dynamic cycle (a physics choice,
// reported), and the integrators and their tolerances (recommended when the case asks for dynamics).
Knob dynamics_knob(const Case& c, bool integrators) {
  // The reference of the dynamic cycle: CVODE (BDF) at the finest tolerance of the ladder.
  const std::vector<std::string>& rtols = row("dynamics.relative_tolerance").ladder;
  const std::vector<io::CaseChange> finest = {{"mesh.dynamics", "cvode"},
                                              {"dynamics.relative_tolerance", rtols.back()}};
  if (!integrators)
    return {"dynamics", {{"none (static)", {{"mesh.dynamics", "none"}}}, {"cvode " + rtols.back(), finest}}, true};
  Knob integrator{"integrator", {}, c.dynamics.engine == gear::DynamicsEngine::none};
  std::vector<std::string> engines = row("mesh.dynamics").choices;
  std::erase(engines, "none");
  std::stable_partition(engines.begin(), engines.end(), [](const std::string& e) { return e != "cvode"; });
  for (const auto& engine : engines)
    for (std::size_t i = 0; i + 1 < rtols.size(); ++i)
      integrator.settings.push_back(
          {engine + " " + rtols[i], {{"mesh.dynamics", engine}, {"dynamics.relative_tolerance", rtols[i]}}});
  integrator.settings.push_back({"cvode " + rtols.back(), finest});
  return integrator;
}

// A model choice (a physics knob): the table's choices, the case's own last (the reference).
Knob choice_knob(std::string_view name, const std::string& key, const std::string& own) {
  Knob k{std::string(name), {}, true};
  for (const auto& v : row(key).choices)
    if (v != own) k.settings.push_back({v, {{key, v}}});
  k.settings.push_back({own, {{key, own}}});
  return k;
}

// The knobs of the case's fidelity, as it registers them (contact/fidelity_registry.hpp): each
// resolution's ladder from the parameter table, and the trade tool's own knobs by name.
std::vector<Knob> knobs_of(const Case& c) {
  const contact::FidelityEntry& entry = contact::find_fidelity(c.contact.fidelity);
  std::vector<Knob> out;
  for (const contact::TradeKnob& k : entry.traits.knobs) {
    if (k.key == "contact.stress_table" && !c.contact.asperity_stress) continue;
    if (!k.key.empty()) {
      out.push_back(ladder(k.name, k.key));
      if (k.key == "contact.element_size") limit_to_profile_spacing(c, out.back());
      if (k.key == "mixed_ehl.grid_spacing") limit_to_grid_spacing(c, out.back());
    } else if (k.name == "fidelity") {
      out.push_back(fidelity_knob(entry));
    } else if (k.name == "dynamics" || k.name == "integrator") {
      out.push_back(dynamics_knob(c, k.name == "integrator"));
    } else if (k.name == "asperity_model") {
      out.push_back(choice_knob(k.name, "asperity.model", c.asperity.model));
    } else if (k.name == "film_formula" && c.lubrication.lubricated) {
      // Lubricated: the film formulas and inlet-heating corrections, through the asperities' share
      // of the load they leave.
      out.push_back(choice_knob(k.name, "lubrication.film_formula", row("lubrication.film_formula").get(c, -1).text));
    } else if (k.name == "inlet_heating" && c.lubrication.lubricated) {
      out.push_back(choice_knob(k.name, "lubrication.inlet_heating", row("lubrication.inlet_heating").get(c, -1).text));
    }
  }
  return out;
}

// The outputs compared, as named in the mesh-cycle result: the real-area ratio, the plastic area
// fraction and the fidelity's peak stress (statistical: the highest asperity's von Mises stress;
// deterministic: the von Mises maximum below the strip).
std::array<std::string, 3> outputs_of(const Case& c) {
  return {"real_area_ratio", "plastic_area_fraction",
          std::string(contact::find_fidelity(c.contact.fidelity).traits.peak_stress)};
}

struct Curves {
  std::vector<double> s;
  std::vector<std::vector<double>> outputs;  // per kOutputs
};

struct Timed {
  double seconds = 0.0;
  Curves curves;
};

// One setting on top of the command line's --set changes.
Timed run_timed(const std::filesystem::path& case_file, const std::vector<io::CaseChange>& base,
                const std::vector<io::CaseChange>& setting, double min_time) {
  std::vector<io::CaseChange> changes = base;
  changes.insert(changes.end(), setting.begin(), setting.end());
  const Case c = io::prepare_case(io::load_case(case_file, changes));
  Timed t;
  t.seconds = 1e300;
  double total = 0.0;
  for (int repeat = 0; repeat < 5 && (repeat == 0 || total < min_time); ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    const contact::MeshContactResult r = runs::run_mesh_cycle(c);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.seconds = std::min(t.seconds, dt);  // the least disturbed of the repeats
    total += dt;
    if (repeat == 0) {
      t.curves.s = r.find("s_m")->values;
      for (const std::string& name : outputs_of(c)) {
        const contact::Series* q = r.find(name);
        if (!q)
          throw std::invalid_argument(std::string("tradeoff needs the case's contact outputs to include ") + name);
        t.curves.outputs.push_back(q->values);
      }
    }
  }
  return t;
}

// The error of one output against the reference, relative to the reference's largest magnitude:
// the largest difference of the path's minimum, mean and maximum (what a sweep reports; coarse
// positions miss extremes between samples), and where the positions coincide also the largest
// pointwise difference.
double curve_error(const std::vector<double>& s, const std::vector<double>& v, const std::vector<double>& s_ref,
                   const std::vector<double>& ref) {
  double scale = 0.0;
  for (double x : ref) scale = std::max(scale, std::abs(x));
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  const auto [lo_ref, hi_ref] = std::minmax_element(ref.begin(), ref.end());
  double worst = std::max(
      {std::abs(*lo - *lo_ref), std::abs(*hi - *hi_ref), std::abs(contact::path_mean(v) - contact::path_mean(ref))});
  if (s == s_ref)
    for (std::size_t i = 0; i < v.size(); ++i) worst = std::max(worst, std::abs(v[i] - ref[i]));
  return scale > 0.0 ? worst / scale : worst;
}

struct Row {
  std::string knob, setting;
  double seconds = 0.0;
  double errors[3] = {0.0, 0.0, 0.0};
  bool reference = false, recommended = false;
  double worst() const { return std::max({errors[0], errors[1], errors[2]}); }
};

Row compare(const std::string& knob, const std::string& setting, const Timed& t, const Timed& ref) {
  Row r{knob, setting, t.seconds, {}, false, false};
  for (std::size_t k = 0; k < 3; ++k)
    r.errors[k] = curve_error(t.curves.s, t.curves.outputs[k], ref.curves.s, ref.curves.outputs[k]);
  return r;
}

// With -o FILE.png: the Pareto plot, and the table as CSV beside it unless --csv names a file.
bool png_output(const Options& o) {
  const std::string& output = o.table.output;
  return output.size() > 4 && output.substr(output.size() - 4) == ".png";
}
std::filesystem::path csv_beside_plot(const Options& o) {
  return o.table.csv.to_file() ? std::filesystem::path(o.table.csv.file)
                               : std::filesystem::path(o.table.output.substr(0, o.table.output.size() - 4) + ".csv");
}

void run(const Options& o) {
  const std::filesystem::path case_file = case_path(o.case_options);
  const Case base = load_case_reporting(o.case_options);
  io::OutputSet outputs;  // -o, --csv FILE and a plot's CSV: all or none, checked before the runs
  reserve_table(o.table, outputs);
  if (png_output(o)) outputs.reserve(csv_beside_plot(o));
  const std::vector<io::CaseChange> given = case_changes(o.case_options);
  std::vector<Knob> knobs = knobs_of(base);
  if (!o.knobs.empty()) {
    std::erase_if(knobs,
                  [&](const Knob& k) { return std::find(o.knobs.begin(), o.knobs.end(), k.name) == o.knobs.end(); });
    if (knobs.empty()) throw std::invalid_argument("--knob: none of the names is a knob (see --help)");
  }
  std::vector<Row> rows;
  std::vector<io::CaseChange> recommended, highest;
  for (const Knob& k : knobs) {
    if (!o.quiet) std::cerr << "tradeoff: " << k.name << " (" << k.settings.size() << " settings)\n";
    const Timed ref = run_timed(case_file, given, k.settings.back().changes, o.min_time);
    std::vector<Row> mine;
    for (std::size_t i = 0; i + 1 < k.settings.size(); ++i)
      mine.push_back(
          compare(k.name, k.settings[i].label, run_timed(case_file, given, k.settings[i].changes, o.min_time), ref));
    mine.push_back(compare(k.name, k.settings.back().label, ref, ref));
    mine.back().reference = true;
    // The cheapest setting within the tolerance of the reference; times within 5% of the fastest
    // such setting are ties (timer noise), won by the lower setting of the ladder.
    double fastest = mine.back().seconds;
    for (const Row& r : mine)
      if (r.worst() <= o.tolerance) fastest = std::min(fastest, r.seconds);
    std::size_t best = 0;
    while (!(mine[best].worst() <= o.tolerance && mine[best].seconds <= 1.05 * fastest)) ++best;
    if (!k.physics) mine[best].recommended = true;
    if (!k.physics) {
      recommended.insert(recommended.end(), k.settings[best].changes.begin(), k.settings[best].changes.end());
      highest.insert(highest.end(), k.settings.back().changes.begin(), k.settings.back().changes.end());
    }
    rows.insert(rows.end(), mine.begin(), mine.end());
  }
  // Later knobs' changes win where keys repeat (the coupled fidelity makes strip_points moot).
  if (!o.quiet) std::cerr << "tradeoff: the case as given and the recommended combination against all knobs highest\n";
  const Timed all_highest = run_timed(case_file, given, highest, o.min_time);
  rows.push_back(compare("combined", "case as given", run_timed(case_file, given, {}, o.min_time), all_highest));
  rows.push_back(compare("combined", "recommended", run_timed(case_file, given, recommended, o.min_time), all_highest));
  rows.push_back(compare("combined", "all highest", all_highest, all_highest));
  rows.back().reference = true;

  io::ColumnTable t;
  t.columns = {{"knob", "", true, {}, {}},
               {"setting", "", true, {}, {}},
               {"time_s", "s", false, {}, {}},
               {"error_real_area", "1", false, {}, {}},
               {"error_plastic_fraction", "1", false, {}, {}},
               {"error_peak_stress", "1", false, {}, {}},
               {"note", "", true, {}, {}}};
  for (const Row& r : rows) {
    t.columns[0].texts.push_back(r.knob);
    t.columns[1].texts.push_back(r.setting);
    t.columns[2].numbers.push_back(r.seconds);
    for (int k = 0; k < 3; ++k) t.columns[3 + k].numbers.push_back(r.errors[k]);
    t.columns[6].texts.emplace_back(r.reference ? (r.recommended ? "reference, recommended" : "reference")
                                                : (r.recommended ? "recommended" : ""));
  }
  const std::string& output = o.table.output;
  const bool png = png_output(o);
  const CsvOption& csv_option = o.table.csv;
  const std::filesystem::path csv = png ? csv_beside_plot(o) : std::filesystem::path(csv_option.file);
  std::filesystem::path csv_written;  // its temporary, complete: what the plot reads
  if (csv_option.to_file() || png) csv_written = outputs.add_text(csv, io::format_csv(t));
  if (csv_option.in_place() && !png) {
    const std::string text = io::format_csv(t);
    if (output.empty()) outputs.add_stdout(text);
    else outputs.add_text(output, text);
  } else {
    std::string text = fmt::format("{:<15} {:<16} {:>10} {:>16} {:>22} {:>17}  {}\n", "knob", "setting", "time_s",
                                   "error_real_area", "error_plastic_fraction", "error_peak_stress", "note");
    for (std::size_t i = 0; i < t.rows(); ++i)
      text += fmt::format("{:<15} {:<16} {:>10.4g} {:>16.3g} {:>22.3g} {:>17.3g}  {}\n", t.columns[0].texts[i],
                          t.columns[1].texts[i], t.columns[2].numbers[i], t.columns[3].numbers[i],
                          t.columns[4].numbers[i], t.columns[5].numbers[i], t.columns[6].texts[i]);
    std::string advice = fmt::format(
        "\nRecommended (cheapest within {:g}% of each knob's reference on all three outputs):", 100 * o.tolerance);
    for (const Row& r : rows)
      if (r.recommended && r.knob != "combined") advice += fmt::format(" {} = {};", r.knob, r.setting);
    text += advice + "\n";
    if (png || output.empty()) outputs.add_stdout(text);
    else outputs.add_text(output, text);
  }
  if (png) {
    // The Pareto plot by scripts/plot_tradeoff.py from the CSV table (matplotlib), into the plot's
    // temporary: committed with the table, or neither.
    outputs.add(output, [&](const std::filesystem::path& plot) {
      const std::filesystem::path script = std::filesystem::path(GEARTRIB_SOURCE_DIR) / "scripts/plot_tradeoff.py";
      // Debian's interpreter, where python3-matplotlib installs (a PATH python3 may lack it).
      const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
      const std::string command = python + " " + fem::shell_quoted(script.string()) + " " +
                                  fem::shell_quoted(csv_written.string()) + " " + fem::shell_quoted(plot.string()) +
                                  fmt::format(" {:g}", o.tolerance);
      if (std::system(command.c_str()) != 0)
        throw std::runtime_error(
            "plotting failed (" + command +
            "; needs python3 with matplotlib: apt-get install python3-matplotlib); nothing written "
            "(-o FILE.csv writes the table alone)");
    });
  }
  outputs.commit();
  if (png) fmt::print("wrote {} and {}\n", csv.string(), output);
}

}  // namespace

void add_tradeoff_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "tradeoff",
      "The speed/accuracy trade of the mesh cycle, measured on a case. Knobs: positions along A -> E,\n"
      "height_points (summit-height quadrature), table_points (pressure-separation table per sigma),\n"
      "strip_points (uncoupled quadrature across the Hertz strip), strip_lookup (cubic cells or the exact\n"
      "table inversion), stress_table (intervals of the normalised von Mises table, 0: exact maximisation),\n"
      "fidelity (uncoupled, coupled with N nodes), integrator (odeint/cvode and tolerance of the dynamic cycle; recommended only when the case\n"
      "asks for dynamics); reported as physics choices, not recommended: dynamics (static against the\n"
      "dynamic cycle) and asperity_model. Each setting runs with the other knobs as the case has them and\n"
      "is compared with the knob's highest setting on the real-area ratio, the plastic area fraction and\n"
      "the highest asperity's von Mises stress: the largest difference of the path's minimum, mean and\n"
      "maximum and, where the positions coincide, of any position, relative to the reference's largest\n"
      "value. Time: the fastest of up to 5 runs (at least --min-time in all).\n"
      "Then the case as given and the recommended combination against all knobs at their highest.\n"
      "A deterministic case (contact.fidelity = deterministic) has its own knobs: positions, element_size\n"
      "(boundary-element width) and strip_halfwidths (the strip's reach in Hertz half-widths), compared on\n"
      "the real-area ratio, the plastic area fraction and the von Mises maximum below the strip (set\n"
      "threads=1 for one core's times). A mixed-EHL case (contact.fidelity = mixed_ehl): positions,\n"
      "grid_spacing (not coarser than the flanks' profiles), window, time_step and tolerance, compared on\n"
      "the asperity contact's area ratio and plastic fraction within the film and the von Mises maximum.\n"
      "The multi-asperity study's boundary-element grid: `geartrib_bench\n"
      "--benchmark_filter=multi_asperity` (docs/reference/timings.md).");
  add_case_argument(cmd, o->case_options);
  add_output_option(cmd, o->table.output,
                    "the table (default: standard output); a .png name draws the Pareto plot (time against\n"
                    "error) with scripts/plot_tradeoff.py and writes the table beside it as .csv (or to --csv FILE)");
  add_csv_option(cmd, o->table.csv, "the table as CSV: to FILE, or without one in place of the aligned table");
  cmd->add_option("--tolerance", o->tolerance, "Relative error a recommended setting may have (default 0.01)")
      ->check(CLI::Range(1e-9, 1.0));
  cmd->add_option("--min-time", o->min_time, "Repeat each run until this much time [s] is spent (default 0.3)")
      ->check(CLI::Range(0.0, 1e4));
  cmd->add_option("--knob", o->knobs, "Only these knobs (repeatable)");
  add_quiet_flag(cmd, o->quiet);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
