// `geartrib ehl`: one line contact through the mixed-EHL solver (contact/mixed_ehl/line_ehl_run.hpp):
// the inputs dimensional, or as Dowson-Higginson's (W, U, G) or Moes's (M, L) groups realised on a
// radius, modulus and viscosity; smooth, or with a waviness or a ridge moving through the contact.
// Prints the summary; -o writes the last instant's profile (CSV, or HDF5 with the series).
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/progress_bar.hpp"

#include "config/case_file.hpp"
#include "config/units.hpp"
#include "contact/mixed_ehl/line_ehl_run.hpp"
#include "core/keyed_error.hpp"
#include "lubrication/ehl_film.hpp"
#include "lubrication/lubricant.hpp"
#include "material/material.hpp"
#include "output/column_table.hpp"
#include "output/line_ehl_results.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::app {

namespace {

namespace me = contact::mixed_ehl;
using io::Dimension;

struct Options {
  // The operating point.
  std::optional<double> load;  // [N/m]
  std::string radius, speed, speed1, speed2;
  double slide_roll = 0.0;
  std::vector<double> groups, moes;
  // The solids and the oil.
  std::string modulus, hardness, viscosity, alpha, eyring_stress, temperature, lubricant;
  std::vector<std::string> materials;
  std::string viscosity_law = "roelands", flow = "newtonian";
  bool incompressible = false;
  // The solver.
  me::EhlOptions solver;
  std::string film_floor;
  // The roughness and the transient.
  std::vector<std::string> waviness, ridge;
  std::string surfaces = "1";
  bool steady = false;
  double window = 0.0, courant = 1.0;
  bool dry = false;
  // Outputs.
  std::string output, series;
  CsvOption csv;
  bool quiet = false;

  bool rough() const { return !waviness.empty() || !ridge.empty(); }
  // The roughness's option (--waviness and --ridge exclude each other) and its two lengths.
  std::string roughness_option() const { return ridge.empty() ? "--waviness" : "--ridge"; }
  const std::vector<std::string>& roughness() const { return ridge.empty() ? waviness : ridge; }
};

// The run's texts (name, value: the inputs' files, the models chosen), as the result file holds them.
using Texts = decltype(io::LineEhlFile::texts);

double positive(const std::string& option, const std::string& text, Dimension d) {
  const double v = quantity_option(option, text, d);
  if (!(v > 0.0)) throw std::invalid_argument(fmt::format("{} '{}': must be positive", option, text));
  return v;
}
[[noreturn]] void missing(const std::string& what) { throw std::invalid_argument(what); }

// The option each field of the physics' structs comes from (a core::KeyedError's key).
std::string option_of(const std::string& key, const Options& o) {
  static const std::map<std::string, std::string> kFields = {{"viscosity", "--viscosity"},
                                                             {"pressure_viscosity", "--alpha"},
                                                             {"eyring_stress", "--eyring-stress"},
                                                             {"limiting_shear_coefficient", "--lubricant"},
                                                             {"inlet", "--inlet"},
                                                             {"outlet", "--outlet"},
                                                             {"nodes", "--nodes"},
                                                             {"tolerance", "--tolerance"},
                                                             {"max_iterations", "--max-iterations"},
                                                             {"film_floor", "--film-floor"},
                                                             {"hardness", "--hardness"},
                                                             {"boundary_friction", "--boundary-friction"},
                                                             {"amplitude", o.roughness_option()},
                                                             {"length", o.roughness_option()},
                                                             {"window", "--window"},
                                                             {"courant", "--time-step"}};
  const auto it = kFields.find(key);
  if (it == kFields.end()) return key;
  if (key == "viscosity" && !o.lubricant.empty()) return "--lubricant/--oil-temperature";
  return it->second;
}

// The solids: E* and the softer surface's hardness (infinite: none given).
void solids(const Options& o, me::LineEhlSpec& s, Texts& texts) {
  if (!o.materials.empty()) {
    if (o.materials.size() > 2) missing("--materials takes one file (both bodies) or two");
    const Material m1 = io::load_material(o.materials.front());
    const Material m2 = o.materials.size() == 2 ? io::load_material(o.materials.back()) : m1;
    s.modulus = composite_modulus(m1, m2);
    s.options.hardness = std::min(m1.hardness, m2.hardness);
    texts.emplace_back("materials", o.materials.front() + (o.materials.size() == 2 ? "," + o.materials.back() : ""));
  } else if (!o.modulus.empty()) {
    s.modulus = positive("--modulus", o.modulus, Dimension::pressure);
  } else {
    missing("the solids: --modulus E* or --materials FILE[,FILE]");
  }
  if (!o.hardness.empty()) s.options.hardness = positive("--hardness", o.hardness, Dimension::pressure);
}

// The oil at its inlet: eta_0 and alpha given, or a lubricant file at a temperature.
void oil(const Options& o, me::Fluid& f, bool needs_alpha, Texts& texts) {
  f.viscosity_law = choice_from_name(me::viscosity_law_choices(), o.viscosity_law, "viscosity law");
  f.flow = choice_from_name(me::flow_model_choices(), o.flow, "flow model");
  f.compressible = !o.incompressible;
  if (!o.lubricant.empty()) {
    if (o.temperature.empty()) missing("--lubricant needs --oil-temperature");
    const lubrication::Lubricant l = io::load_lubricant(o.lubricant);
    const double t = quantity_option("--oil-temperature", o.temperature, Dimension::temperature);
    const lubrication::TemperatureRange range = lubrication::operating_range(l);
    if (!range.contains(t))
      throw std::invalid_argument(
          fmt::format("--oil-temperature '{}': {:.2f} degC is outside {}'s range {:.1f} to "
                      "{:.1f} degC (its data widened as a run allows)",
                      o.temperature, t - 273.15, o.lubricant, range.lo - 273.15, range.hi - 273.15));
    f.set_oil_state(lubrication::oil_state(l, t));
    texts.emplace_back("lubricant", o.lubricant);
  } else {
    if (o.viscosity.empty()) missing("the oil: --viscosity ETA (and --alpha) or --lubricant FILE --oil-temperature T");
    f.viscosity = positive("--viscosity", o.viscosity, Dimension::dynamic_viscosity);
    if (needs_alpha) {
      if (o.alpha.empty()) missing("--viscosity needs --alpha (the pressure-viscosity coefficient; 0 for none)");
      f.pressure_viscosity = quantity_option("--alpha", o.alpha, Dimension::inverse_pressure);
    }
  }
  if (!o.eyring_stress.empty()) f.eyring_stress = positive("--eyring-stress", o.eyring_stress, Dimension::pressure);
}

// The surfaces' speeds of an entrainment u and the slide-to-roll ratio S = (u1 - u2)/u.
void set_speeds(me::ContactInstant& c, double u, double slide_roll) {
  c.speed1 = u * (1.0 + 0.5 * slide_roll);
  c.speed2 = u * (1.0 - 0.5 * slide_roll);
}

// The contact: dimensional, or the groups realised on R, E* and eta_0 (E' = 2 E*).
me::LineEhlSpec make_spec(const Options& o, Texts& texts) {
  me::LineEhlSpec s;
  s.options = o.solver;
  if (!o.film_floor.empty()) s.options.film_floor = positive("--film-floor", o.film_floor, Dimension::length);
  solids(o, s, texts);
  if (o.radius.empty()) missing("--radius R (the reduced radius of curvature) is needed");
  me::ContactInstant& c = s.instant;
  c.radius = positive("--radius", o.radius, Dimension::length);
  const double e_prime = 2.0 * s.modulus;
  if (!o.groups.empty() || !o.moes.empty()) {
    oil(o, s.fluid, false, texts);
    lubrication::EhlGroups g;
    if (!o.groups.empty()) {
      g = {o.groups[1], o.groups[2], o.groups[0]};
      if (!(g.load > 0.0 && g.speed > 0.0 && g.material >= 0.0))
        throw std::invalid_argument("--groups W,U,G: W and U must be positive, G >= 0");
    } else {
      if (!o.load) missing("--moes M,L needs --load (the line load: W = w/(E' R))");
      if (!(o.moes[0] > 0.0 && o.moes[1] >= 0.0)) throw std::invalid_argument("--moes M,L: M must be positive, L >= 0");
      g = lubrication::groups_from_moes({o.moes[0], o.moes[1]}, *o.load / (e_prime * c.radius));
    }
    c.line_load = g.load * e_prime * c.radius;
    s.fluid.pressure_viscosity = g.material / e_prime;
    set_speeds(c, g.speed * e_prime * c.radius / s.fluid.viscosity, o.slide_roll);
  } else {
    oil(o, s.fluid, true, texts);
    if (!o.load) missing("the contact: --load W (N/m), or --groups W,U,G, or --moes M,L with --load");
    c.line_load = *o.load;
    if (!o.speed.empty()) {
      set_speeds(c, quantity_option("--speed", o.speed, Dimension::speed), o.slide_roll);
    } else if (!o.speed1.empty() && !o.speed2.empty()) {
      c.speed1 = quantity_option("--speed1", o.speed1, Dimension::speed);
      c.speed2 = quantity_option("--speed2", o.speed2, Dimension::speed);
    } else {
      missing("the speeds: --speed U (the mean of the surfaces') [--slide-roll S] or --speed1 and --speed2");
    }
  }
  if (!(c.line_load > 0.0) || !std::isfinite(c.line_load))
    throw std::invalid_argument(fmt::format("--load {:g}: the line load must be positive", c.line_load));
  if (!(c.speed1 >= 0.0) || !(c.speed2 >= 0.0) || !(c.entrainment() > 0.0))
    throw std::invalid_argument(
        fmt::format("the surfaces' speeds {:g} and {:g} m/s: both must be >= 0 (x runs the way they roll), their mean "
                    "positive (--speed, --slide-roll, --speed1, --speed2)",
                    c.speed1, c.speed2));
  // The roughness.
  if (o.rough()) {
    const std::vector<std::string>& r = o.roughness();
    const std::string option = o.roughness_option();
    const bool ridge = !o.ridge.empty();
    if (r.size() != 2) missing(option + " takes two lengths: " + (ridge ? "HEIGHT,WIDTH" : "AMPLITUDE,WAVELENGTH"));
    s.roughness.shape = ridge ? me::RoughnessShape::ridge : me::RoughnessShape::waviness;
    s.roughness.amplitude = quantity_option(option, r[0], Dimension::length);
    s.roughness.length = positive(option, r[1], Dimension::length);
    s.roughness.on = choice_from_name(me::rough_surfaces_choices(), o.surfaces, "surface");
    texts.emplace_back("roughness", choice_name(me::roughness_shape_choices(), s.roughness.shape));
    texts.emplace_back("rough_surface", o.surfaces);
  } else {
    texts.emplace_back("roughness", "none");
  }
  s.transient.enabled = !o.steady;
  s.transient.window = o.window;
  s.transient.courant = o.courant;
  s.dry_reference = o.dry;
  texts.emplace_back("viscosity_law", o.viscosity_law);
  texts.emplace_back("flow", o.flow);
  texts.emplace_back("density", o.incompressible ? "constant" : "dowson-higginson");
  return s;
}

io::Table summary_table(const me::LineEhlSpec& s, const me::LineEhlResult& r) {
  const me::ContactInstant& c = s.instant;
  const me::EhlField& f = r.field;
  const double e_prime = 2.0 * s.modulus, b = r.hertz_half_width;
  const lubrication::EhlGroups g = lubrication::ehl_groups(s.fluid.viscosity, s.fluid.pressure_viscosity,
                                                           c.entrainment(), c.line_load, c.radius, e_prime);
  const lubrication::MoesGroups m = lubrication::moes_groups(g);
  const double dowson_higginson = lubrication::smooth_film(lubrication::FilmFormula::dowson_higginson, g, c.radius);
  io::Table t;
  t.header = {"name", "value"};
  const auto add = [&](const char* name, double v) { t.add_row(name, {v}); };
  add("line_load_N_per_m", c.line_load);
  add("radius_m", c.radius);
  add("speed1_m_per_s", c.speed1);
  add("speed2_m_per_s", c.speed2);
  add("composite_modulus_Pa", s.modulus);
  add("viscosity_Pa_s", s.fluid.viscosity);
  add("pressure_viscosity_per_Pa", s.fluid.pressure_viscosity);
  add("load_W", g.load);
  add("speed_U", g.speed);
  add("material_G", g.material);
  add("moes_M", m.load);
  add("moes_L", m.material);
  add("hertz_half_width_m", b);
  add("hertz_pressure_Pa", r.hertz_pressure);
  add("nodes", r.grid.size);
  add("node_spacing_m", r.grid.spacing);
  add("central_film_m", f.central_film);
  add("min_film_m", f.min_film);
  add("min_film_over_dowson_higginson", f.min_film / dowson_higginson);
  add("peak_pressure_Pa", f.peak_pressure);
  add("peak_pressure_over_hertz", f.peak_pressure / r.hertz_pressure);
  add("spike_x_m", r.spike_x);
  add("spike_x_over_b", r.spike_x / b);
  add("spike_pressure_Pa", r.spike_pressure);
  add("rupture_x_m", r.rupture_x);
  add("load_error", f.load_error);
  add("asperity_share", f.asperity_share);
  add("contact_fraction", f.contact_fraction);
  add("yield_fraction", f.yield_fraction);
  add("friction_coefficient", f.friction_coefficient);
  add("film_friction_N_per_m", f.film_friction);
  add("boundary_friction_N_per_m", f.boundary_friction);
  add("iterations", f.iterations);
  add("steady_solve_s", r.steady_seconds);
  if (!r.series.empty()) {
    const auto steps = static_cast<double>(r.series.size() - 1);
    add("time_step_s", r.time_step);
    add("steps", steps);
    add("window_s", r.time_step * steps);
    add("transient_s", r.transient_seconds);
    add("time_per_step_s", r.transient_seconds / steps);
    const auto range = [&](const std::string& name, const std::string& unit, const me::StepRange& v) {
      t.add_row(name + "_min" + unit, {v.min});
      t.add_row(name + "_max" + unit, {v.max});
      t.add_row(name + "_mean" + unit, {v.mean});
    };
    range("central_film", "_m", r.central_film);
    range("min_film", "_m", r.min_film);
    range("peak_pressure", "_Pa", r.peak_pressure);
    range("asperity_share", "", r.asperity_share);
    range("friction_coefficient", "", r.friction_coefficient);
  }
  if (!r.dry_pressure.empty()) {
    double peak = 0.0;
    for (double p : r.dry_pressure) peak = std::max(peak, p);
    add("dry_peak_pressure_Pa", peak);
    add("dry_pressure_difference_over_hertz", r.dry_difference);
    add("dry_iterations", r.dry_iterations);
  }
  return t;
}

io::Column numeric_column(const char* name, const char* unit) {
  io::Column c;
  c.name = name;
  c.unit = unit;
  return c;
}

io::ColumnTable profile_table(const me::LineEhlResult& r) {
  const int n = r.grid.size;
  io::Column x = numeric_column("x_m", "m"), p = numeric_column("pressure_Pa", "Pa"), h = numeric_column("film_m", "m"),
             tau = numeric_column("shear_Pa", "Pa"), z = numeric_column("heights_m", "m"),
             state = numeric_column("state", "");
  state.text = true;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    x.numbers.push_back(r.grid.x(i));
    p.numbers.push_back(r.field.pressure[k]);
    h.numbers.push_back(r.field.film[k]);
    tau.numbers.push_back(r.field.shear[k]);
    z.numbers.push_back(r.heights[k]);
    const me::NodeState s = r.field.state[k];
    state.texts.emplace_back(s == me::NodeState::fluid       ? "fluid"
                             : s == me::NodeState::cavitated ? "cavitated"
                                                             : "contact");
  }
  io::ColumnTable t;
  t.columns = {x, p, h, tau, z, state};
  if (!r.dry_pressure.empty()) {
    t.columns.push_back(numeric_column("dry_pressure_Pa", "Pa"));
    t.columns.back().numbers = r.dry_pressure;
  }
  return t;
}

io::ColumnTable series_table(const me::LineEhlResult& r) {
  io::ColumnTable t;
  if (r.series.empty()) return t;
  const auto column = [&](const char* name, const char* unit, auto get) {
    io::Column c = numeric_column(name, unit);
    for (const me::LineEhlStep& s : r.series) c.numbers.push_back(get(s));
    t.columns.push_back(std::move(c));
  };
  column("time_s", "s", [](const auto& s) { return s.time; });
  column("central_film_m", "m", [](const auto& s) { return s.central_film; });
  column("min_film_m", "m", [](const auto& s) { return s.min_film; });
  column("peak_pressure_Pa", "Pa", [](const auto& s) { return s.peak_pressure; });
  column("asperity_share", "1", [](const auto& s) { return s.asperity_share; });
  column("contact_fraction", "1", [](const auto& s) { return s.contact_fraction; });
  column("friction_coefficient", "1", [](const auto& s) { return s.friction_coefficient; });
  column("load_error", "1", [](const auto& s) { return s.load_error; });
  column("iterations", "1", [](const auto& s) { return static_cast<double>(s.iterations); });
  column("solve_s", "s", [](const auto& s) { return s.seconds; });
  return t;
}

bool is_hdf5(const std::string& file) {
  const auto dot = file.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : file.substr(dot);
  return ext == ".h5" || ext == ".hdf5";
}

void run(const Options& o) {
  if (o.steady && !o.rough()) missing("--steady needs a roughness (--waviness or --ridge)");
  if ((o.window > 0.0 || o.courant != 1.0) && !o.rough())
    missing("--window and --time-step need a roughness (--waviness or --ridge) to move");
  if (!o.series.empty() && (o.steady || !o.rough()))
    missing("--series needs a transient: a roughness (--waviness or --ridge) without --steady");
  Texts texts;
  me::LineEhlSpec spec = make_spec(o, texts);
  // Every target checked before any work; written all or none.
  io::OutputSet outputs;
  if (!o.output.empty()) outputs.reserve(o.output);
  if (!o.series.empty()) outputs.reserve(o.series);
  if (o.csv.to_file()) outputs.reserve(o.csv.file);
  ProgressBar bar(!o.quiet, "time steps");
  me::LineEhlResult r;
  try {
    r = me::run_line_ehl(spec, [&](int done, int total) { bar(done, total); });
  } catch (const core::KeyedError& e) {
    throw std::invalid_argument(option_of(e.key(), o) + ": " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) +
                             "; more --nodes, a smaller --time-step or more --max-iterations may converge");
  }
  const io::Table summary = summary_table(spec, r);
  if (!o.output.empty()) {
    io::ColumnTable profile = profile_table(r);
    if (is_hdf5(o.output)) {
      io::LineEhlFile file{std::move(profile), series_table(r), summary, texts};
      outputs.add(o.output, [&](const std::filesystem::path& p) { io::write_line_ehl_hdf5(p, file); });
    } else {
      outputs.add_text(o.output, io::format_csv(profile));
    }
  }
  if (!o.series.empty()) outputs.add_text(o.series, io::format_csv(series_table(r)));
  std::string head;
  for (const auto& [name, value] : texts) head += fmt::format("# {}: {}\n", name, value);
  const std::string csv = head + io::format_csv(summary);
  if (o.csv.to_file()) outputs.add_text(o.csv.file, csv);
  if (!o.quiet) outputs.add_stdout(o.csv.in_place() ? csv : head + io::format_text(summary));
  outputs.commit();
}

std::string default_text(double v) { return fmt::format("{:g}", v); }

}  // namespace

void add_ehl_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  const me::EhlOptions defaults;
  const me::Fluid fluid;
  auto* cmd = app.add_subcommand(
      "ehl",
      "One line contact by the mixed elastohydrodynamic solver (isothermal Reynolds with wedge and squeeze, the\n"
      "half-plane's deflection, Roelands or Barus viscosity, Dowson-Higginson density, Newtonian or Ree-Eyring flow,\n"
      "asperity contact where the film vanishes; docs/guide/ehl.md). Inputs: the line load, reduced radius and the\n"
      "two surfaces' speeds, E* (or two material files) and the oil (eta_0 and alpha, or a lubricant file at a\n"
      "temperature); or the groups (W, U, G) or Moes's (M, L) realised on --radius, E* and --viscosity. Optionally\n"
      "a harmonic waviness or a single transverse ridge on surface 1, 2 or both, moving with its surface through\n"
      "the contact over a window of time steps (--steady: in place). Prints the central and minimum film, the\n"
      "peak pressure and the spike, the load error, the asperity share, friction, iterations and times (a\n"
      "transient: the last instant's, then the window's extremes and means); -o writes the profile (x, pressure,\n"
      "film, shear, heights, state) as CSV, or as HDF5 (.h5) with the summary and the transient's series.");
  // The operating point.
  auto* load = cmd->add_option("--load", o->load, "W: line load [N/m]")->check(CLI::PositiveNumber);
  cmd->add_option("--radius", o->radius, "R: reduced radius of curvature R1 R2/(R1 + R2) (e.g. 10mm)");
  auto* speed = cmd->add_option("--speed", o->speed, "U: entrainment speed, the mean of the surfaces' (e.g. 2m/s)");
  cmd->add_option("--slide-roll", o->slide_roll,
                  "S = (u1 - u2)/U with --speed, --groups or --moes: u1 = U (1 + S/2), u2 = U (1 - S/2) (default 0)")
      ->check(CLI::Range(-2.0, 2.0));
  auto* speed1 = cmd->add_option("--speed1", o->speed1, "u1: surface 1's speed, in the rolling direction");
  auto* speed2 = cmd->add_option("--speed2", o->speed2, "u2: surface 2's speed");
  speed->excludes(speed1)->excludes(speed2);
  speed1->needs(speed2);
  speed2->needs(speed1);
  auto* groups = cmd->add_option("--groups", o->groups,
                                 "W,U,G: Dowson-Higginson's groups W = w/(E'R), U = eta_0 U/(E'R), G = alpha E' (E' = "
                                 "2E*), realised on --radius, E* and --viscosity")
                     ->delimiter(',')
                     ->expected(3);
  auto* moes = cmd->add_option("--moes", o->moes,
                               "M,L: Moes's groups M = W (2U)^-1/2, L = G (2U)^1/4, with W from --load, realised on "
                               "--radius, E* and --viscosity")
                   ->delimiter(',')
                   ->expected(2);
  groups->excludes(moes)->excludes(load);
  for (auto* dimensional : {speed, speed1, speed2}) groups->excludes(dimensional), moes->excludes(dimensional);
  // The solids and the oil.
  auto* modulus = cmd->add_option("--modulus", o->modulus,
                                  "E*: composite modulus, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (e.g. 113.19GPa)");
  auto* materials = cmd->add_option("--materials", o->materials,
                                    "FILE[,FILE]: material files (materials/*.toml) of the two bodies (one: both): E* "
                                    "and the softer one's hardness")
                        ->delimiter(',');
  modulus->excludes(materials);
  cmd->add_option(
      "--hardness", o->hardness,
      "H: the surfaces yield at this pressure, which holds there (elastic-perfectly-plastic; yield_fraction; "
      "default: the softer material's, else elastic)");
  auto* viscosity =
      cmd->add_option("--viscosity", o->viscosity, "eta_0: the oil's viscosity at the inlet (e.g. 0.05Pa s)");
  auto* alpha = cmd->add_option("--alpha", o->alpha, "alpha: pressure-viscosity coefficient (e.g. 2e-8 1/Pa)");
  auto* lubricant = cmd->add_option("--lubricant", o->lubricant,
                                    "FILE: a lubricant file (lubricants/*.toml), with --oil-temperature");
  auto* temperature = cmd->add_option("--oil-temperature", o->temperature,
                                      "T: the oil's inlet temperature for --lubricant (e.g. 80degC)");
  lubricant->excludes(viscosity)->excludes(alpha);
  temperature->needs(lubricant);
  groups->excludes(alpha)->excludes(lubricant);
  moes->excludes(alpha)->excludes(lubricant);
  cmd->add_option("--viscosity-law", o->viscosity_law,
                  "roelands (default; Z from alpha, Roelands 1966) or barus (exp(alpha p))")
      ->check(CLI::IsMember(choice_names(me::viscosity_law_choices())));
  cmd->add_flag("--incompressible", o->incompressible, "Constant density (default: Dowson-Higginson's)");
  cmd->add_option("--flow", o->flow,
                  "newtonian (default) or eyring: the Ree-Eyring Poiseuille flow factor (Conry, Wang & Cusano 1987)")
      ->check(CLI::IsMember(choice_names(me::flow_model_choices())));
  cmd->add_option("--eyring-stress", o->eyring_stress,
                  "tau_0 of the Eyring flow and the film's shear (default: the lubricant's, else " +
                      default_text(fluid.eyring_stress / 1e6) + " MPa)");
  // The solver.
  cmd->add_option("--nodes", o->solver.nodes, "Nodes over the domain (default " + std::to_string(defaults.nodes) + ")");
  cmd->add_option(
      "--inlet", o->solver.inlet,
      "The domain's start, Hertz half-widths b ahead of x = 0 (default " + default_text(defaults.inlet) + ")");
  cmd->add_option("--outlet", o->solver.outlet,
                  "The domain's end, half-widths behind x = 0 (default " + default_text(defaults.outlet) + ")");
  cmd->add_option("--tolerance", o->solver.tolerance,
                  "Converged when the Newton update is below this times p_H and the load error below it (default " +
                      default_text(defaults.tolerance) + ")");
  cmd->add_option("--max-iterations", o->solver.max_iterations,
                  "Newton iterations per solve (default " + std::to_string(defaults.max_iterations) + ")");
  cmd->add_option("--film-floor", o->film_floor,
                  "The film below which a node is in asperity contact (default " +
                      default_text(defaults.film_floor * 1e9) + " nm)");
  cmd->add_option(
      "--boundary-friction", o->solver.boundary_friction,
      "Friction coefficient in the asperity contacts (default " + default_text(defaults.boundary_friction) + ")");
  // The roughness and the transient.
  auto* waviness = cmd->add_option("--waviness", o->waviness,
                                   "AMPLITUDE,WAVELENGTH: a harmonic waviness (e.g. 0.05um,100um); moving, it enters "
                                   "at the inlet")
                       ->delimiter(',');
  auto* ridge = cmd->add_option("--ridge", o->ridge,
                                "HEIGHT,WIDTH: one transverse ridge A cos^2(pi x/w) of base width w (e.g. 0.2um,50um); "
                                "moving, it enters at the inlet")
                    ->delimiter(',');
  waviness->excludes(ridge);
  cmd->add_option("--rough-surface", o->surfaces,
                  "1 (default), 2 or both: the surface carrying the roughness, which moves at that surface's speed")
      ->check(CLI::IsMember(choice_names(me::rough_surfaces_choices())));
  auto* steady = cmd->add_flag("--steady", o->steady, "The roughness in place (a crest at x = 0), one steady solve");
  auto* window =
      cmd->add_option("--window", o->window,
                      "The transient's length in contact widths 2b travelled by the slower rough surface (default: the "
                      "roughness crosses the domain, then 2 more)")
          ->check(CLI::NonNegativeNumber);
  auto* time_step =
      cmd->add_option("--time-step", o->courant,
                      "The time step in nodes travelled by the faster rough surface: dt = this dx/u (default 1)");
  steady->excludes(window)->excludes(time_step);
  cmd->add_flag("--dry", o->dry,
                "Also the dry contact of the same gap and load by boundary elements: its pressure beside the "
                "solver's (the limit of a vanishing viscosity)");
  // Outputs.
  add_output_option(cmd, o->output,
                    "the last instant's profile: CSV (x, pressure, film, shear, heights, state), or HDF5 (.h5, .hdf5) "
                    "with /profile, /series and /summary");
  cmd->add_option("--series", o->series,
                  "FILE: the transient's instants as CSV (time, films, pressure, shares, friction)");
  add_csv_option(cmd, o->csv, "the summary as CSV: to FILE, or without one in place of the aligned table");
  add_quiet_flag(cmd, o->quiet);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
