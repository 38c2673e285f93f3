// `geartrib contact SURFACE`: a measured or generated height map pressed by a rigid flat (the
// composite surface of two bodies on their composite modulus), by areal FFT boundary elements
// (contact/areal/areal_bem.hpp): its area-load curve, spots, plastic area, gaps and subsurface
// stress, with Persson's theory beside it.
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/surface_input.hpp"

#include "config/case_file.hpp"
#include "config/input_error.hpp"
#include "config/resource_budget.hpp"
#include "contact/areal/areal_bem.hpp"
#include "contact/persson_contact.hpp"
#include "output/areal_contact_results.hpp"
#include "surface/surface_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace geartrib::app {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Fewer spots than this in the window at a load: its area's statistics rest on too few spots (flagged).
constexpr int kFewSpots = 10;

struct Options {
  std::string file;
  SurfaceInputOptions input;
  std::string pressure, approach;
  std::string material, counter = "same";
  std::string modulus, hardness, poisson;
  std::string periodic = "both";
  std::string depths;
  double tolerance = 1e-8;
  std::string output;
  TableOptions table;
};

// A refusal of an option's value, as the other options' are: "--option 'text': rule" (exit 2).
std::invalid_argument option_error(const std::string& option, const std::string& text, const std::string& rule) {
  return std::invalid_argument(fmt::format("{} '{}': {}", option, text, rule));
}

// The loads: one value, a comma-separated list, or MIN:MAX:COUNT (pressures spaced geometrically: an
// area-load curve spans decades; approaches linearly).
std::vector<double> loads(const std::string& option, const std::string& text, io::Dimension d, bool geometric) {
  if (text.find(':') == std::string::npos) {
    std::vector<double> out;
    std::stringstream in(text);
    for (std::string v; std::getline(in, v, ',');) out.push_back(quantity_option(option, v, d));
    if (out.empty() || out.size() > 200) throw option_error(option, text, "one to 200 values");
    return out;
  }
  const RangeOption r = range_option(option, text, d, 2, 200);
  if (!(r.min > 0.0 && r.max > r.min)) throw option_error(option, text, "a range needs 0 < MIN < MAX");
  std::vector<double> out;
  for (int k = 0; k < r.count; ++k) {
    const double t = static_cast<double>(k) / (r.count - 1);
    out.push_back(geometric ? r.min * std::pow(r.max / r.min, t) : r.min + (r.max - r.min) * t);
  }
  return out;
}

struct Elastic {
  double e_star = 0.0, hardness = kInf, poisson = 0.3;
  std::string source;
};

// E*, H and nu: from the material files (the counter-body's too: "same" for two flanks of one
// steel, "rigid" for a rigid flat) or given; a given value overrides the material's.
Elastic elastic(const Options& o) {
  Elastic e;
  if (!o.material.empty()) {
    const Material m = io::load_material(o.material);
    e.poisson = m.poisson_ratio;
    const double body = (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
    double counter = body, counter_hardness = m.hardness;
    if (o.counter == "rigid") {
      counter = 0.0, counter_hardness = kInf;
    } else if (o.counter != "same") {
      const Material c = io::load_material(o.counter);
      counter = (1.0 - c.poisson_ratio * c.poisson_ratio) / c.youngs_modulus;
      counter_hardness = c.hardness;
    }
    e.e_star = 1.0 / (body + counter);
    e.hardness = std::min(m.hardness, counter_hardness);  // the softer body yields
    e.source = o.material + (o.counter == "same" ? " on itself" : " on " + o.counter);
  }
  if (!o.modulus.empty()) e.e_star = quantity_option("--modulus", o.modulus, io::Dimension::pressure);
  if (!o.poisson.empty()) e.poisson = quantity_option("--poisson", o.poisson, io::Dimension::dimensionless);
  if (!o.hardness.empty())
    e.hardness = o.hardness == "none" ? kInf : quantity_option("--hardness", o.hardness, io::Dimension::pressure);
  if (!(e.e_star > 0.0))
    throw option_error("--modulus", o.modulus, "give the composite modulus E* (or --material) above 0");
  if (!(e.hardness > 0.0))
    throw option_error("--hardness", o.hardness, "the hardness must be positive (or none: elastic)");
  if (!(e.poisson >= 0.0 && e.poisson < 0.5))
    throw option_error("--poisson", o.poisson, "Poisson's ratio must lie in [0, 0.5)");
  if (e.source.empty()) e.source = "given";
  return e;
}

void run(const Options& o) {
  io::OutputSet outputs;
  reserve_table(o.table, outputs);
  if (!o.output.empty()) outputs.reserve(o.output);
  const Elastic el = elastic(o);
  const bool by_pressure = !o.pressure.empty();
  if (by_pressure == !o.approach.empty())
    throw option_error("--pressure", o.pressure, "give either --pressure or --approach");
  const std::vector<double> values = by_pressure ? loads("--pressure", o.pressure, io::Dimension::pressure, true)
                                                 : loads("--approach", o.approach, io::Dimension::length, false);
  std::vector<double> depths;
  if (!o.depths.empty()) {
    std::stringstream in(o.depths);
    for (std::string d; std::getline(in, d, ',');) {
      const double z = quantity_option("--depths", d, io::Dimension::length);
      if (!(z > 0.0)) throw option_error("--depths", d, "a depth must be positive");
      depths.push_back(z);
    }
  }

  const io::LoadedSurface in = load_surface_reporting(o.file, o.input);
  const surface::HeightGrid& hg = in.grid;
  if (hg.missing() > 0)
    throw io::InputError(
        o.file, 0, "", "",
        fmt::format("{} points are missing after the clean-up: the contact needs every height (--fill)", hg.missing()));
  contact::areal::ArealGrid g;
  g.nx = hg.nx, g.ny = hg.ny, g.dx = hg.dx, g.dy = hg.dy;
  g.periodic_x = o.periodic == "both" || o.periodic == "x";
  g.periodic_y = o.periodic == "both" || o.periodic == "y";
  const double bytes = contact::areal::areal_solve_bytes(g), budget = io::resource_budget().bytes;
  if (bytes > budget)
    throw io::InputError(o.file, 0, "", "",
                         fmt::format("a {} x {} grid ({}) needs {} to solve, beyond the memory budget {} "
                                     "(GEARTRIB_MEMORY_BUDGET): resample it (--resample) or raise the budget",
                                     g.nx, g.ny, o.periodic == "both" ? "periodic" : "zero-padded",
                                     io::format_bytes(bytes), io::format_bytes(budget)));
  // The surface's rms gradient for Persson's theory: spectral on a periodic window (what the
  // spectral kernel sees), by differences otherwise.
  const surface::SurfaceStatistics stats = about_surface(o.file, [&] { return surface::surface_statistics(hg); });
  const double rms_gradient =
      g.periodic_x && g.periodic_y ? surface::spectral_rms_gradient(hg) : std::sqrt(stats.m2_along + stats.m2_across);

  contact::areal::ArealOptions opt;
  opt.composite_modulus = el.e_star;
  opt.hardness = el.hardness;
  opt.poisson_ratio = el.poisson;
  opt.tolerance = o.tolerance;
  const contact::areal::ElasticKernel kernel(g, el.e_star);
  const auto control = by_pressure ? contact::areal::Control::mean_pressure : contact::areal::Control::approach;

  io::ColumnTable curve;
  auto column = [&](const std::string& name, const std::string& unit) -> std::vector<double>& {
    curve.columns.push_back({name, unit, false, {}, {}});
    return curve.columns.back().numbers;
  };
  const std::vector<std::pair<std::string, std::string>> names = {{"mean_pressure_Pa", "Pa"},
                                                                  {"approach_m", "m"},
                                                                  {"contact_fraction", "1"},
                                                                  {"plastic_fraction", "1"},
                                                                  {"peak_pressure_Pa", "Pa"},
                                                                  {"mean_contact_pressure_Pa", "Pa"},
                                                                  {"spots", "1"},
                                                                  {"largest_spot_m2", "m^2"},
                                                                  {"mean_spot_m2", "m^2"},
                                                                  {"mean_gap_m", "m"},
                                                                  {"max_von_mises_Pa", "Pa"},
                                                                  {"max_von_mises_depth_m", "m"},
                                                                  {"persson_contact_fraction", "1"},
                                                                  {"persson_plastic_fraction", "1"},
                                                                  {"iterations", "1"},
                                                                  {"residual", "1"},
                                                                  {"flag_not_converged", "1"},
                                                                  {"flag_few_spots", "1"}};
  for (const auto& [name, unit] : names) column(name, unit);
  auto col = [&](std::size_t k) -> std::vector<double>& { return curve.columns[k].numbers; };

  std::vector<double> start;
  contact::areal::ArealSolution last;
  contact::areal::ContactSpots last_spots;
  std::vector<contact::areal::SubsurfacePlane> last_planes;
  int not_converged = 0, few = 0;
  for (double v : values) {
    contact::areal::ArealSolution s;
    try {
      s = contact::areal::solve_contact(kernel, hg.z, control, v, opt, start);
    } catch (const core::KeyedError& e) {
      throw option_error(by_pressure ? "--pressure" : "--approach", by_pressure ? o.pressure : o.approach, e.what());
    }
    start = s.pressure;
    const contact::areal::ContactSpots spots = contact::areal::contact_spots(g, s.pressure);
    const std::vector<contact::areal::SubsurfacePlane> planes =
        depths.empty() ? std::vector<contact::areal::SubsurfacePlane>{}
                       : contact::areal::subsurface_von_mises(kernel, s.pressure, el.poisson, depths);
    const auto deepest = std::max_element(
        planes.begin(), planes.end(), [](const auto& a, const auto& b) { return a.max_von_mises < b.max_von_mises; });
    double gap_sum = 0.0;
    for (double x : s.gap) gap_sum += std::max(x, 0.0);
    const double contact_area = s.contact_fraction * g.area();
    const contact::PerssonAreas persson =
        s.mean_pressure < el.hardness
            ? contact::persson_elastic_plastic(s.mean_pressure, el.e_star, rms_gradient, el.hardness)
            : contact::PerssonAreas{0.0, 1.0};
    const bool few_spots = !spots.area.empty() && static_cast<int>(spots.area.size()) < kFewSpots;
    not_converged += !s.converged, few += few_spots;
    const std::vector<double> row = {
        s.mean_pressure,
        // undefined on a half-periodic window: its datum is arbitrary
        g.periodic_x == g.periodic_y ? s.approach : std::nan(""), s.contact_fraction, s.plastic_fraction,
        s.peak_pressure, s.contact_fraction > 0.0 ? s.mean_pressure / s.contact_fraction : 0.0,
        static_cast<double>(spots.area.size()), spots.area.empty() ? 0.0 : spots.area.front(),
        spots.area.empty() ? 0.0 : contact_area / static_cast<double>(spots.area.size()),
        gap_sum / static_cast<double>(g.size()), planes.empty() ? std::nan("") : deepest->max_von_mises,
        planes.empty() ? std::nan("") : deepest->depth, persson.contact(), persson.plastic,
        static_cast<double>(s.iterations), s.residual, s.converged ? 0.0 : 1.0, few_spots ? 1.0 : 0.0};
    for (std::size_t k = 0; k < row.size(); ++k) col(k).push_back(row[k]);
    last = std::move(s), last_spots = spots, last_planes = planes;
  }
  if (not_converged > 0)
    fmt::print(stderr, "warning: at {} loads the iteration stopped before its tolerance {:g} (flag_not_converged)\n",
               not_converged, o.tolerance);
  if (few > 0)
    fmt::print(stderr,
               "warning: at {} loads the window holds fewer than {} contact spots: its area and spot statistics rest "
               "on too few (flag_few_spots); take a larger window\n",
               few, kFewSpots);

  io::Table t;
  for (const auto& [name, unit] : names) t.header.push_back(name);
  for (std::size_t r = 0; r < values.size(); ++r) {
    std::vector<double> row;
    for (std::size_t k = 0; k < names.size(); ++k) row.push_back(col(k)[r]);
    t.rows.push_back(std::move(row));
  }
  if (!o.output.empty()) {
    io::ArealContactFile f;
    f.curve = curve;
    f.nx = g.nx, f.ny = g.ny, f.dx = g.dx, f.dy = g.dy, f.periodic_x = g.periodic_x, f.periodic_y = g.periodic_y;
    f.heights = hg.z;
    f.pressure = last.pressure;
    f.gap = last.gap;
    f.spot.assign(last_spots.label.begin(), last_spots.label.end());
    f.spots.columns = {{"area_m2", "m^2", false, last_spots.area, {}}, {"load_N", "N", false, last_spots.load, {}}};
    io::Column depth{"depth_m", "m", false, {}, {}}, vm{"max_von_mises_Pa", "Pa", false, {}, {}},
        x{"x_m", "m", false, {}, {}}, y{"y_m", "m", false, {}, {}};
    for (const auto& p : last_planes)
      depth.numbers.push_back(p.depth), vm.numbers.push_back(p.max_von_mises), x.numbers.push_back(p.x),
          y.numbers.push_back(p.y);
    f.stress.columns = {depth, vm, x, y};
    f.numbers = {{"composite_modulus_Pa", el.e_star}, {"hardness_Pa", el.hardness},   {"poisson_ratio", el.poisson},
                 {"rms_height_m", stats.rq},          {"rms_gradient", rms_gradient}, {"tolerance", o.tolerance}};
    f.texts = {{"surface", o.file},
               {"elastic_data", el.source},
               {"periodic", o.periodic},
               {"control", by_pressure ? "mean_pressure" : "approach"},
               {"model", "areal FFT boundary elements (Polonsky-Keer CG, pressure capped at the hardness)"}};
    f.scene = fmt::format(
        "geartrib contact {}\n--{} {}\n--periodic {}\nE* = {:.6g} Pa, H = {:.6g} Pa, nu = {:g} ({})\ntolerance {:g}\n",
        o.file, by_pressure ? "pressure" : "approach", by_pressure ? o.pressure : o.approach, o.periodic, el.e_star,
        el.hardness, el.poisson, el.source, o.tolerance);
    outputs.add(o.output, [&](const std::filesystem::path& p) { io::write_areal_contact_hdf5(p, f); });
  }
  emit_table(t, o.table, outputs);
}

}  // namespace

void add_contact_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "contact",
      "A rough surface pressed by a rigid flat, by areal FFT boundary elements: the surface's heights are the\n"
      "composite roughness of two bodies, on their composite modulus E* (1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2),\n"
      "elastic-perfectly-plastic with the pressure capped at the softer body's hardness. For each mean pressure\n"
      "(or approach): the real contact area, the plastic area, the peak and mean contact pressure, the contact\n"
      "spots (connected elements), the mean gap, the largest von Mises stress on the planes --depths names, and\n"
      "Persson's theory's areas on the surface's rms gradient beside them. A pressure range gives the area-load\n"
      "curve. -o writes HDF5: the curve, the last load's fields (pressure, gap, spots), spots and stress.\n"
      "Formats as `geartrib surface`; a generated surface: `geartrib surface generate self-affine -o FILE`.");
  cmd->add_option("surface", o->file, "Surface file (the composite roughness)")->required();
  cmd->add_option("--pressure", o->pressure,
                  "Mean pressure over the window: a value, a list (10MPa,20MPa) or MIN:MAX:COUNT geometrically\n"
                  "spaced (1MPa:1GPa:13)");
  cmd->add_option("--approach", o->approach,
                  "The flat's approach below the highest point: a value, a list or MIN:MAX:COUNT linearly spaced\n"
                  "(a periodic or an open window)");
  cmd->add_option("--material", o->material, "Material file (E, nu, hardness), e.g. materials/16MnCr5.toml");
  cmd->add_option("--counter", o->counter,
                  "The other body: same (default: two bodies of the material), rigid, or a material file");
  cmd->add_option("--modulus", o->modulus, "Composite modulus E* (e.g. \"115 GPa\"; overrides the materials')");
  cmd->add_option("--hardness", o->hardness, "Pressure cap H (e.g. \"6 GPa\"), or none: elastic");
  cmd->add_option("--poisson", o->poisson, "Poisson's ratio for the subsurface stress (default the material's, 0.3)");
  cmd->add_option("--periodic", o->periodic,
                  "Which directions repeat: both (default), x, y or none (zero-padded: DC-FFT)")
      ->check(CLI::IsMember({"both", "x", "y", "none"}));
  cmd->add_option("--depths", o->depths, "Depths of the subsurface stress planes, comma-separated (e.g. 1um,2um,5um)");
  cmd->add_option("--tolerance", o->tolerance,
                  "The contact conditions' rms residual over the heights' rms at which to stop (default 1e-8)")
      ->check(CLI::Range(1e-14, 0.1));
  add_output_option(cmd, o->output, "HDF5 results (the curve, the last load's fields, spots and stress)");
  add_surface_input_options(cmd, o->input);
  add_csv_option(cmd, o->table.csv,
                 "the curve as CSV (header, full precision): to FILE, or without one to standard output in\n"
                 "place of the aligned table");
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
