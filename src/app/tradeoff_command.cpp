// `geartrib tradeoff`: what each fidelity knob of the mesh cycle costs in time and in accuracy.
// For every knob, each setting is run with the other knobs at the case's own settings, timed,
// and compared with the same knob's highest setting (its reference) on the main outputs: the
// real-area ratio, the plastic area fraction and the highest asperity's von Mises stress along
// A -> E. Then the case as given and the recommended combination (each knob's cheapest setting
// within the tolerance of its reference) are compared with all knobs at their highest settings.
// An areal case has also the ladder: the models that answer the same question on the same flanks
// (GW and Persson beside it, the profile fidelity, the areal fidelity at its knobs' settings)
// against the areal fidelity at the finest settings the case allows, and where each one holds.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/mesh_contact.hpp"
#include "runs/mesh_cycle.hpp"

#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/case_records.hpp"
#include "config/input_error.hpp"
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
#include <exception>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace geartrib::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Options {
  CaseOptions case_options;
  TableOptions table;
  double tolerance = 0.01;
  double ladder_tolerance = 0.1;
  double min_time = 0.3;
  std::vector<std::string> knobs;
  bool quiet = false;
};

// The model a ladder's rung reads (the verdict says why each one departs where it does).
enum class Rung { none, gw, persson, profile, areal };

struct Setting {
  Setting(std::string label_, std::vector<io::CaseChange> changes_, Rung rung_ = Rung::none,
          std::optional<std::array<std::string, 3>> series_ = std::nullopt, std::vector<std::string> laps_ = {})
      : label(std::move(label_)),
        changes(std::move(changes_)),
        rung(rung_),
        series(std::move(series_)),
        laps(std::move(laps_)) {}
  std::string label;
  std::vector<io::CaseChange> changes;
  // A ladder's rung: its model; the three series it reads where that is not the run's fidelity (an
  // empty name: the model has no such output); the stage laps that are its time (none: the run's).
  Rung rung;
  std::optional<std::array<std::string, 3>> series;
  std::vector<std::string> laps;
};

// A knob's settings from cheapest to most faithful; the last is its reference. `physics`: the
// settings are different models (or, for the integrator, not used by the case): reported, not
// part of the recommended combination nor of the all-highest reference. `key`: the case key whose
// ladder it runs (empty: one of the trade tool's own knobs). `ladder`: the areal ladder, whose
// rungs are made once the case's allowed resolution settings are known (ladder_rungs).
struct Knob {
  Knob(std::string name_, std::vector<Setting> settings_, bool physics_, std::string key_ = "", bool ladder_ = false)
      : name(std::move(name_)),
        settings(std::move(settings_)),
        physics(physics_),
        key(std::move(key_)),
        ladder(ladder_) {}
  std::string name;
  std::vector<Setting> settings;
  bool physics;
  std::string key;
  bool ladder;
};

const io::Parameter& row(const std::string& key) { return *io::find_parameter(key).parameter; }

// A resolution's ladder from the parameter table.
Knob ladder(std::string_view name, std::string_view key) {
  Knob k{std::string(name), {}, false, std::string(key)};
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
  integrator.settings.emplace_back("cvode " + rtols.back(), finest);
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
    } else if (k.name == "ladder") {
      out.push_back({"ladder", {}, true, "", true});
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

// One case's mesh cycle: the fastest of its repeats, that repeat's result and the case's fidelity
// outputs.
struct Timed {
  double seconds = 0.0;
  contact::MeshContactResult result;
  std::array<std::string, 3> outputs;
};

Timed time_cycle(const Case& c, double min_time) {
  Timed t;
  t.seconds = 1e300;
  t.outputs = outputs_of(c);
  double total = 0.0;
  for (int repeat = 0; repeat < 5 && (repeat == 0 || total < min_time); ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    contact::MeshContactResult r = runs::run_mesh_cycle(c);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The tradeoff reads the per-position series and the stages: the profiles kept are dropped.
    r.pressure_profiles.clear(), r.ehl_profiles.clear(), r.synthesis.clear(), r.running_in.reset();
    if (dt < t.seconds) t.seconds = dt, t.result = std::move(r);  // the least disturbed of the repeats
    total += dt;
  }
  return t;
}

// The tradeoff's runs, each case once: settings whose cases hold the same parameters (a knob's
// own setting and the case as given) share a run. A case refused as input (io::InputError: a
// height map beyond the grid's limit, a budget) is remembered with its refusal.
class Runs {
 public:
  struct Outcome {
    std::optional<Timed> timed;
    std::exception_ptr refusal;
    std::string why;
  };
  Runs(std::filesystem::path case_file, std::vector<io::CaseChange> given, double min_time)
      : case_file_(std::move(case_file)), given_(std::move(given)), min_time_(min_time) {}

  // The case with the command line's --set changes and then the setting's.
  const Outcome& run(const std::vector<io::CaseChange>& setting) {
    std::vector<io::CaseChange> changes = given_;
    changes.insert(changes.end(), setting.begin(), setting.end());
    std::optional<Case> c;
    std::string key;
    try {
      c = io::prepare_case(io::load_case(case_file_, changes));
      for (const ResolvedParameter& p : io::current_parameters(*c)) key += p.key + '=' + p.value + '\n';
    } catch (const io::InputError& e) {
      key = "refused at loading:";
      for (const auto& ch : changes) key += ' ' + ch.key + '=' + ch.value;
      return done_.try_emplace(key, Outcome{std::nullopt, std::current_exception(), e.what()}).first->second;
    }
    if (const auto found = done_.find(key); found != done_.end()) return found->second;
    Outcome o;
    try {
      o.timed = time_cycle(*c, min_time_);
    } catch (const io::InputError& e) {
      o.refusal = std::current_exception();
      o.why = e.what();
    }
    return done_.emplace(key, std::move(o)).first->second;
  }

 private:
  std::filesystem::path case_file_;
  std::vector<io::CaseChange> given_;
  double min_time_;
  std::map<std::string, Outcome> done_;
};

// A knob's settings the case allows, each with its run, in the knob's order: a setting the case
// refuses is left out and said in `left_out`; when it refuses all, its first refusal is thrown.
std::vector<std::pair<Setting, const Timed*>> allowed(const Knob& k, Runs& runs, std::vector<std::string>& left_out) {
  std::vector<std::pair<Setting, const Timed*>> out;
  std::exception_ptr first;
  for (const Setting& s : k.settings) {
    const Runs::Outcome& o = runs.run(s.changes);
    if (o.timed) {
      out.emplace_back(s, &*o.timed);
      continue;
    }
    if (!first) first = o.refusal;
    const std::string note = k.name + " " + s.label + ": " + o.why;
    if (std::find(left_out.begin(), left_out.end(), note) == left_out.end()) left_out.push_back(note);
  }
  if (out.empty() && first) std::rethrow_exception(first);
  return out;
}

// The ladder on an areal case's flanks (contact.fidelity = areal), each rung with its model:
// GW and Persson beside the case as given (their time: their stage laps), the profile fidelity on
// the same flanks (on one thread, as the areal fidelity solves its positions), the areal fidelity
// as given and at each setting of its resolution knobs the case allows (one run each: a setting
// that is the case as given is not repeated), and the reference: every resolution knob at its
// finest allowed setting. The reference's settings are named in `reference`.
std::vector<Setting> ladder_rungs(const std::vector<Knob>& resolution, Runs& runs, std::vector<std::string>& left_out,
                                  std::string& reference) {
  std::vector<Setting> rungs = {
      {"GW (statistical)",
       {},
       Rung::gw,
       std::array<std::string, 3>{"statistical_real_area_ratio", "statistical_plastic_area_fraction",
                                  "statistical_max_asperity_von_mises_Pa"},
       {"statistical_surface_table", "statistical_model"}},
      {"Persson",
       {},
       Rung::persson,
       std::array<std::string, 3>{"statistical_persson_real_area_ratio", "statistical_persson_plastic_area_fraction",
                                  ""},
       {"persson_beside"}},
      {"profile BEM", {{"contact.fidelity", "deterministic"}, {"contact.threads", "1"}}, Rung::profile},
      {"areal (case)", {}, Rung::areal}};
  // The case as given and the reference, each refused only as the case is: thrown.
  auto required = [&](const std::vector<io::CaseChange>& changes) -> const Timed* {
    const Runs::Outcome& r = runs.run(changes);
    if (!r.timed) std::rethrow_exception(r.refusal);
    return &*r.timed;
  };
  std::set<const Timed*> areal_runs = {required({})};
  std::vector<io::CaseChange> finest;
  for (const Knob& k : resolution) {
    const auto settings = allowed(k, runs, left_out);
    for (const auto& [s, t] : settings)
      if (areal_runs.insert(t).second) rungs.emplace_back("areal " + k.name + " " + s.label, s.changes, Rung::areal);
    const Setting& last = settings.back().first;
    finest.insert(finest.end(), last.changes.begin(), last.changes.end());
    reference += (reference.empty() ? "" : ", ") + k.name + " " + last.label;
  }
  required(finest);
  rungs.emplace_back("areal finest", finest, Rung::areal);
  return rungs;
}

// A model's outputs along the path, as a setting reads them from its run, and its time.
struct Curves {
  double seconds = 0.0;
  std::vector<double> s;
  std::array<std::vector<double>, 3> outputs;  // empty: the model has none
};

// The run's fidelity outputs and its time, or a rung's series and laps; none when the run holds no
// such model (a rung's real area absent: no statistical model beside a flat flank).
std::optional<Curves> read(const Setting& setting, const Timed& t) {
  Curves c;
  c.s = t.result.find("s_m")->values;
  const std::array<std::string, 3>& names = setting.series ? *setting.series : t.outputs;
  for (std::size_t k = 0; k < 3; ++k) {
    if (names[k].empty()) continue;
    const contact::Series* q = t.result.find(names[k]);
    if (!q && !setting.series)
      throw std::invalid_argument(std::string("tradeoff needs the case's contact outputs to include ") + names[k]);
    if (!q && k == 0) return std::nullopt;
    if (q) c.outputs[k] = q->values;
  }
  c.seconds = setting.laps.empty() ? t.seconds : 0.0;
  for (const contact::StageTiming& st : t.result.stages)
    if (std::find(setting.laps.begin(), setting.laps.end(), st.name) != setting.laps.end()) c.seconds += st.seconds;
  return c;
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
  double errors[3] = {0.0, 0.0, 0.0};  // NaN: the model has no such output
  bool reference = false, recommended = false;
  std::string verdict;  // a ladder's rung: where it holds (rung_verdict)
  // The largest error of the outputs the model has.
  double worst() const {
    double w = 0.0;
    for (double e : errors)
      if (!std::isnan(e)) w = std::max(w, e);
    return w;
  }
};

Row compare(const std::string& knob, const std::string& setting, const Curves& c, const Curves& ref) {
  Row r{knob, setting, c.seconds, {}, false, false, {}};
  for (std::size_t k = 0; k < 3; ++k)
    r.errors[k] =
        c.outputs[k].empty() || ref.outputs[k].empty() ? kNaN : curve_error(c.s, c.outputs[k], ref.s, ref.outputs[k]);
  return r;
}

// A setting's value of a resolution key: its own change, else the case's.
double value_of(const Setting& s, const std::string& key, const Case& base) {
  const io::Parameter& p = row(key);
  double v = p.get(base, -1).number;
  for (const io::CaseChange& ch : s.changes)
    if (ch.key == key) v = io::parse_quantity(ch.value, p.dimension);
  return v;
}

// Where a ladder's rung holds on this case: within `tolerance` of the reference on every output it
// has; where not, why the physics says it departs there, output by output. In brief before its
// first " (": "holds", or "does not hold on" the outputs. `t`: the rung's run; `finest`: the
// reference's setting.
std::string rung_verdict(const Setting& s, const Row& r, const Curves& c, const Curves& ref, const Timed& t,
                         const Setting& finest, const Case& base, double tolerance) {
  static constexpr std::array<const char*, 3> kNames = {"real area", "plastic fraction", "peak stress"};
  // A relative error in percent: two digits, whole percent from 100 % on.
  auto percent = [](double x, bool sign = false) {
    const std::string digits =
        std::abs(x) < 0.995 ? fmt::format("{:.2g}", 100.0 * std::abs(x)) : fmt::format("{:.0f}", 100.0 * std::abs(x));
    return (x < 0.0 ? "-" : sign ? "+" : "") + digits + " %";
  };

  std::string within, beyond, names;
  std::array<bool, 3> off{};
  for (std::size_t k = 0; k < 3; ++k) {
    if (std::isnan(r.errors[k])) continue;
    off[k] = r.errors[k] > tolerance;
    std::string& list = off[k] ? beyond : within;
    list += fmt::format("{}{} {}", list.empty() ? "" : ", ", kNames[k], percent(r.errors[k]));
    if (off[k]) names += (names.empty() ? "" : ", ") + std::string(kNames[k]);
  }
  if (beyond.empty()) return fmt::format("holds ({})", within);
  // The real area's path mean against the reference's: which way the model reads.
  const double bias = contact::path_mean(c.outputs[0]) / contact::path_mean(ref.outputs[0]) - 1.0;
  // The flanks' lay: extruded, the profile fidelity's own flanks; any other, maps drawn on each grid.
  const std::string lay = row("areal.lay").get(base, -1).text;
  const bool extruded = lay == "extruded";
  std::vector<std::string> why;
  auto add = [&](bool when, const std::string& reason) {
    if (when && std::find(why.begin(), why.end(), reason) == why.end()) why.push_back(reason);
  };
  switch (s.rung) {
    case Rung::gw: {
      int flagged = 0;
      if (const contact::Series* f = t.result.find("statistical_flag_summits_interact"))
        for (double x : f->values) flagged += x > 0.5;
      add(off[0] && flagged > 0,
          fmt::format("GW takes the summits as independent, and at this contact (real-area ratio up to {:.2g}) they "
                      "interact (its own flag at {} of {} positions)",
                      *std::max_element(ref.outputs[0].begin(), ref.outputs[0].end()), flagged, c.s.size()));
      add(off[0] && flagged == 0,
          "GW's summits (McCool's, from the profiles' spectral moments) are not the maps' spots");
      add(off[1],
          "its plastic fraction is the yielded share of each summit's contact (the asperity model's law), the "
          "reference's the share at the hardness cap");
      add(off[2], "its peak stress is the highest summit's von Mises (one asperity), not the maximum below the window");
      break;
    }
    case Rung::persson:
      add(bias < 0.0,
          "Persson's theory underestimates the real area at light load (kappa 1.60 against about 2.2 from boundary "
          "elements), and this contact is partly elastic");
      add(bias >= 0.0, "Persson's theory reads high here");
      break;
    case Rung::profile:
      add(!extruded, fmt::format("the profile fidelity extrudes each flank's profile across the face: line contacts "
                                 "as wide as the face, where these flanks (areal.lay = {}) touch in {}",
                                 lay, lay == "isotropic" ? "round spots" : "spots of finite length across it"));
      add(extruded, "on the same extruded flanks: its strip's elements and stress planes differ from the window's");
      break;
    case Rung::areal: {
      auto coarser = [&](const std::string& key, bool finer_is_smaller) {
        const double mine = value_of(s, key, base), theirs = value_of(finest, key, base);
        return finer_is_smaller ? mine > theirs * (1.0 + 1e-9) : mine < theirs * (1.0 - 1e-9);
      };
      const bool elements = coarser("contact.element_size", true), grid = elements || coarser("areal.points", false);
      // The rung's own looser stop (the case's own is the rows' common part).
      const bool stop = std::any_of(s.changes.begin(), s.changes.end(),
                                    [](const io::CaseChange& ch) { return ch.key == "areal.tolerance"; }) &&
                        value_of(s, "areal.tolerance", base) > value_of(finest, "areal.tolerance", base);
      add((off[0] || off[1]) && grid,
          std::string("a coarser grid than the reference's") +
              (extruded ? "" : "; each grid draws its own realisation of the maps, whose scatter this holds too"));
      add((off[0] || off[1]) && grid && stop, "and a looser stop (areal.tolerance)");
      add(off[2] && elements,
          "the von Mises maximum is sought on planes 1 to 32 element sizes deep (and at 0.786 b): coarser elements "
          "than the reference's put the shallowest plane deeper");
      add(why.empty(), "the solver's stop (areal.tolerance)");
      break;
    }
    case Rung::none:
      break;
  }
  std::string reasons;
  for (const std::string& w : why) reasons += (reasons.empty() ? "" : "; ") + w;
  return fmt::format("does not hold on {} ({}{}{}; the real area's path mean {}): {}", names, beyond,
                     within.empty() ? "" : "; within: ", within, percent(bias, true), reasons);
}

// The reference's regime, for the verdict: its real-area range and how much of it yielded.
std::string reference_line(const Curves& ref) {
  const auto [lo, hi] = std::minmax_element(ref.outputs[0].begin(), ref.outputs[0].end());
  const double plastic = contact::path_mean(ref.outputs[1]);
  return fmt::format("real-area ratio {:.3g} to {:.3g} of the Hertz band, {:.0f} % of it yielded (path mean){}", *lo,
                     *hi, 100.0 * plastic,
                     plastic > 0.9 ? ": nearly fully plastic, where the real area is about the load over the hardness "
                                     "whatever the model"
                                   : "");
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
  Runs runs(case_file, case_changes(o.case_options), o.min_time);
  std::vector<Knob> knobs = knobs_of(base);
  std::vector<Knob> resolution;  // the fidelity's keyed knobs, whatever --knob selects: the ladder's rungs
  std::copy_if(knobs.begin(), knobs.end(), std::back_inserter(resolution),
               [](const Knob& k) { return !k.key.empty(); });
  if (!o.knobs.empty()) {
    std::erase_if(knobs,
                  [&](const Knob& k) { return std::find(o.knobs.begin(), o.knobs.end(), k.name) == o.knobs.end(); });
    if (knobs.empty()) throw std::invalid_argument("--knob: none of the names is a knob (see --help)");
  }
  std::vector<Row> rows;
  std::vector<io::CaseChange> recommended, highest;
  std::vector<std::string> left_out, verdict;  // settings the case refuses; where each rung holds
  std::string ladder_reference;
  for (Knob& k : knobs) {
    if (k.ladder) k.settings = ladder_rungs(resolution, runs, left_out, ladder_reference);
    if (!o.quiet) std::cerr << "tradeoff: " << k.name << " (" << k.settings.size() << " settings)\n";
    const auto settings = allowed(k, runs, left_out);
    const auto& [ref_setting, ref_run] = settings.back();
    const Curves ref = *read(ref_setting, *ref_run);
    std::vector<Row> mine;
    std::vector<const Setting*> kept;
    for (const auto& [s, t] : settings) {
      const std::optional<Curves> c = read(s, *t);
      if (!c) {
        left_out.push_back(k.name + " " + s.label + ": the run has no such model (a flank is flat)");
        continue;
      }
      mine.push_back(compare(k.name, s.label, *c, ref));
      kept.push_back(&s);
      if (k.ladder && &s != &ref_setting)
        mine.back().verdict = rung_verdict(s, mine.back(), *c, ref, *t, ref_setting, base, o.ladder_tolerance);
    }
    mine.back().reference = true;
    if (k.ladder) {
      verdict.push_back("the reference: " + reference_line(ref));
      for (const Row& r : mine)
        if (!r.reference) verdict.push_back(r.setting + ": " + r.verdict);
    }
    // The cheapest setting within the tolerance of the reference; times within 5% of the fastest
    // such setting are ties (timer noise), won by the lower setting of the ladder.
    double fastest = mine.back().seconds;
    for (const Row& r : mine)
      if (r.worst() <= o.tolerance) fastest = std::min(fastest, r.seconds);
    std::size_t best = 0;
    while (!(mine[best].worst() <= o.tolerance && mine[best].seconds <= 1.05 * fastest)) ++best;
    if (!k.physics) {
      mine[best].recommended = true;
      recommended.insert(recommended.end(), kept[best]->changes.begin(), kept[best]->changes.end());
      highest.insert(highest.end(), ref_setting.changes.begin(), ref_setting.changes.end());
    }
    rows.insert(rows.end(), mine.begin(), mine.end());
  }
  // Later knobs' changes win where keys repeat (the coupled fidelity makes strip_points moot).
  if (!o.quiet) std::cerr << "tradeoff: the case as given and the recommended combination against all knobs highest\n";
  const std::vector<Setting> combined = {{"case as given", {}}, {"recommended", recommended}, {"all highest", highest}};
  std::vector<std::pair<Setting, const Timed*>> combined_runs;
  for (const Setting& s : combined) {
    const Runs::Outcome& r = runs.run(s.changes);
    if (!r.timed) std::rethrow_exception(r.refusal);
    combined_runs.emplace_back(s, &*r.timed);
  }
  const Curves all_highest = *read(combined_runs.back().first, *combined_runs.back().second);
  for (const auto& [s, t] : combined_runs) rows.push_back(compare("combined", s.label, *read(s, *t), all_highest));
  rows.back().reference = true;

  io::ColumnTable t;
  t.columns = {{"knob", "", true, {}, {}},
               {"setting", "", true, {}, {}},
               {"time_s", "s", false, {}, {}},
               {"error_real_area", "1", false, {}, {}},
               {"error_plastic_fraction", "1", false, {}, {}},
               {"error_peak_stress", "1", false, {}, {}},
               {"note", "", true, {}, {}}};
  // The note: reference and recommended; a rung's verdict (the aligned table: in brief).
  auto note = [](const Row& r, bool whole) -> std::string {
    if (!r.verdict.empty()) return whole ? r.verdict : r.verdict.substr(0, r.verdict.find(" ("));
    return r.reference ? (r.recommended ? "reference, recommended" : "reference")
                       : (r.recommended ? "recommended" : "");
  };
  for (const Row& r : rows) {
    t.columns[0].texts.push_back(r.knob);
    t.columns[1].texts.push_back(r.setting);
    t.columns[2].numbers.push_back(r.seconds);
    for (int k = 0; k < 3; ++k) t.columns[3 + k].numbers.push_back(r.errors[k]);
    t.columns[6].texts.push_back(note(r, true));
  }
  const std::string& output = o.table.output;
  const bool png = png_output(o);
  const CsvOption& csv_option = o.table.csv;
  const std::filesystem::path csv = png ? csv_beside_plot(o) : std::filesystem::path(csv_option.file);
  std::filesystem::path csv_written;  // its temporary, complete: what the plot reads
  if (csv_option.to_file() || png) csv_written = outputs.add_text(csv, io::format_csv(t));
  if (!o.quiet)
    for (const std::string& l : left_out) std::cerr << "tradeoff: left out: " << l << '\n';
  if (csv_option.in_place() && !png) {
    const std::string text = io::format_csv(t);
    if (output.empty()) outputs.add_stdout(text);
    else outputs.add_text(output, text);
  } else {
    // The setting's column as wide as its longest (a ladder's rungs), at least 16.
    std::size_t width = 16;
    for (const Row& r : rows) width = std::max(width, r.setting.size());
    // An error the model does not have: "-".
    auto error = [](double e, int w) {
      return std::isnan(e) ? fmt::format("{:>{}}", "-", w) : fmt::format("{:>{}.3g}", e, w);
    };
    std::string text = fmt::format("{:<15} {:<{}} {:>10} {:>16} {:>22} {:>17}  {}\n", "knob", "setting", width,
                                   "time_s", "error_real_area", "error_plastic_fraction", "error_peak_stress", "note");
    for (const Row& r : rows)
      text += fmt::format("{:<15} {:<{}} {:>10.4g} {} {} {}  {}\n", r.knob, r.setting, width, r.seconds,
                          error(r.errors[0], 16), error(r.errors[1], 22), error(r.errors[2], 17), note(r, false));
    std::string advice = fmt::format(
        "\nRecommended (cheapest within {:g}% of each knob's reference on all three outputs):", 100 * o.tolerance);
    for (const Row& r : rows)
      if (r.recommended && r.knob != "combined") advice += fmt::format(" {} = {};", r.knob, r.setting);
    text += advice + "\n";
    if (!verdict.empty()) {
      text += fmt::format(
          "\nWhere each holds on this case (the ladder: within {:g}% of the areal fidelity at {} on every output "
          "the model has; GW's and Persson's times are their stage laps beside the case as given):\n",
          100 * o.ladder_tolerance, ladder_reference);
      for (const std::string& l : verdict) text += "  " + l + "\n";
    }
    if (!left_out.empty()) {
      text += "\nLeft out:\n";
      for (const std::string& l : left_out) text += "  " + l + "\n";
    }
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
      "fidelity (uncoupled, coupled with N nodes), integrator (odeint/cvode and tolerance of the dynamic\n"
      "cycle; recommended only when the case asks for dynamics); reported as physics choices, not\n"
      "recommended: dynamics (static against the dynamic cycle), asperity_model and, on a lubricated case,\n"
      "film_formula and inlet_heating. Each setting runs with the other knobs as the case has them and\n"
      "is compared with the knob's highest setting on the real-area ratio, the plastic area fraction and\n"
      "the highest asperity's von Mises stress: the largest difference of the path's minimum, mean and\n"
      "maximum and, where the positions coincide, of any position, relative to the reference's largest\n"
      "value. Time: the fastest of up to 5 runs (at least --min-time in all). A setting the case refuses\n"
      "(a height map beyond the grid's limit, a budget) is left out and said; the next is the reference.\n"
      "Then the case as given and the recommended combination against all knobs at their highest.\n"
      "A deterministic case (contact.fidelity = deterministic) has its own knobs: positions, element_size\n"
      "(boundary-element width) and strip_halfwidths (the strip's reach in Hertz half-widths), compared on\n"
      "the real-area ratio, the plastic area fraction and the von Mises maximum below the strip (set\n"
      "threads=1 for one core's times). A mixed-EHL case (contact.fidelity = mixed_ehl): positions,\n"
      "grid_spacing (not coarser than the flanks' profiles), window, lead_in, time_step and tolerance,\n"
      "compared on the asperity contact's area ratio and plastic fraction within the film and the von\n"
      "Mises maximum. An areal case (contact.fidelity = areal): element_size (along the involute), points\n"
      "(across the face) and tolerance (the solver's stop), compared also on the von Mises maximum below\n"
      "the window; and the ladder (a physics choice): GW and Persson beside it on the same flanks (their time:\n"
      "their stage laps), the profile fidelity on the same flanks (one thread), the areal fidelity as given\n"
      "and at its knobs' settings, each against the areal fidelity at the finest settings the case allows\n"
      "(a peak stress a model has not: \"-\"), and where each holds: within --ladder-tolerance on every\n"
      "output it has, and why the physics says it departs where it does.\n"
      "The multi-asperity study's boundary-element grid: `geartrib_bench\n"
      "--benchmark_filter=multi_asperity` (docs/reference/timings.md).");
  add_case_argument(cmd, o->case_options);
  add_output_option(cmd, o->table.output,
                    "the table (default: standard output); a .png name draws the Pareto plot (time against\n"
                    "error) with scripts/plot_tradeoff.py and writes the table beside it as .csv (or to --csv FILE)");
  add_csv_option(cmd, o->table.csv, "the table as CSV: to FILE, or without one in place of the aligned table");
  cmd->add_option("--tolerance", o->tolerance, "Relative error a recommended setting may have (default 0.01)")
      ->check(CLI::Range(1e-9, 1.0));
  cmd->add_option("--ladder-tolerance", o->ladder_tolerance,
                  "Relative error within which a ladder's rung holds (an areal case; default 0.1: the isotropic\n"
                  "maps' realisation scatter between grids is a few percent)")
      ->check(CLI::Range(1e-9, 1.0));
  cmd->add_option("--min-time", o->min_time, "Repeat each run until this much time [s] is spent (default 0.3)")
      ->check(CLI::Range(0.0, 1e4));
  cmd->add_option("--knob", o->knobs, "Only these knobs (repeatable)");
  add_quiet_flag(cmd, o->quiet);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
