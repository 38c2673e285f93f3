// `geartrib multi-asperity`: the seed's three parabolic-cylinder asperities (sections 5-7)
// pressed by a rigid flat, by plane-strain boundary elements.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "app/surface_input.hpp"

#include "case/asperity_setup.hpp"
#include "config/units.hpp"
#include "contact/multi_asperity.hpp"
#include "output/table_writer.hpp"
#include "surface/cylinder_reduction.hpp"
#include "surface/surface_statistics.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace geartrib::app {

namespace {

double length_option(const std::string& option, const std::string& text) {
  return quantity_option(option, text, io::Dimension::length);
}

struct Options {
  CaseOptions case_options;
  std::string layout = "HLH";
  double height_step = 0.0;
  std::string spacing = "0.5um";
  double approach = 6.0;
  std::optional<double> load;
  std::string asperity_height = "4um";
  std::string delta_pc;
  int elements = 16384;
  std::string cap = "hardness";
  std::string modulus = "composite";
  std::string reference_depth;
  std::string sweep;
  std::string topography;
  SurfaceInputOptions surface;
  TableOptions table;
};

contact::MultiAsperitySpec make_spec(const Options& o, const Case& c, double delta_pc) {
  const Material& m = asperity::softer_material(c);
  contact::MultiAsperitySpec s;
  s.layout = o.layout;
  s.tip_radius = c.asperity.cylinder_tip_radius;
  s.height_step = o.height_step * delta_pc;
  s.spacing = length_option("--spacing", o.spacing);
  s.asperity_height = length_option("--asperity-height", o.asperity_height);
  s.approach = o.approach * delta_pc;
  s.line_load = o.load;
  // composite: E_t of the two flanks against a rigid flat, the equivalent-surface convention of
  // the seed's sections 4-5 (consistent with delta_pc and the half-widths); single-body:
  // E/(1 - nu^2) of the softer body against a rigid flat, as the CalculiX three-cylinder model.
  s.modulus = o.modulus == "composite" ? composite_modulus(c.pinion.material, c.wheel.material)
                                       : m.youngs_modulus / (1.0 - m.poisson_ratio * m.poisson_ratio);
  s.poisson_ratio = m.poisson_ratio;
  if (o.cap == "hardness") s.pressure_cap = m.hardness;
  else if (o.cap == "yield")
    s.pressure_cap = (2.0 + std::numbers::pi) * m.yield_strength / std::sqrt(3.0);  // Prandtl punch
  else s.pressure_cap = std::numeric_limits<double>::infinity();
  s.elements = o.elements;
  if (!o.reference_depth.empty()) s.reference_length = length_option("--reference-depth", o.reference_depth);
  if (!o.topography.empty()) {
    // A measured profile: its parabolic-cylinder asperities replace the layout (seed section 4 -> 5).
    const io::LoadedSurface in = load_surface_reporting(o.topography, o.surface);
    const surface::CylinderReduction r = about_surface(o.topography, [&] {
      return surface::reduce_to_cylinders(in.grid, surface::surface_statistics(in.grid).lay_angle);
    });
    if (r.asperities.empty())
      throw std::invalid_argument(o.topography + ": no asperity across the lay to reduce to cylinders");
    double top = -std::numeric_limits<double>::infinity(), low = -top;
    for (const auto& a : r.asperities) {
      s.profile.push_back({a.centre, a.height, a.tip_radius});
      top = std::max(top, a.height), low = std::min(low, a.height);
    }
    s.asperity_height = std::max(s.asperity_height, 2.0 * (top - low));  // the base plane below every tip
    // The displacement reference must lie beyond the domain (asperities plus a margin each side).
    const double span = s.profile.back().centre - s.profile.front().centre;
    const double margin = std::max(s.profile.size() > 1 ? span / (s.profile.size() - 1) : 0.0, 2e-6);
    if (o.reference_depth.empty()) s.reference_length = std::max(s.reference_length, 2.0 * (span + 2.0 * margin));
  }
  return s;
}

void run(const Options& o) {
  const Case c = load_case_reporting(o.case_options, io::kGeometryPart | io::kCylinderPart);
  io::OutputSet outputs;  // the tables' files, checked before any solve
  reserve_table(o.table, outputs);
  const double delta_pc = o.delta_pc.empty() ? asperity::seed_critical_interference(asperity::cylinder_asperity(c))
                                             : length_option("--delta-pc", o.delta_pc);
  if (!o.sweep.empty()) {
    // MIN:MAX:COUNT, linearly spaced, units on MIN and MAX.
    // At most 1000 spacings: each is a boundary-element solve.
    const RangeOption range = range_option("--sweep-spacing", o.sweep, io::Dimension::length, 2, 1000);
    const double lo = range.min, hi = range.max;
    const int n = range.count;
    if (!(hi > lo) || lo < 0.0) throw std::invalid_argument("--sweep-spacing needs 0 <= MIN < MAX");
    io::Table t;
    t.header = {"spacing_m",
                "total_contact_area_m2",
                "midpoint_von_mises_Pa",
                "inflection_depth_m",
                "inflection_von_mises_Pa",
                "middle_load_N_per_m",
                "line_load_N_per_m",
                "iterations"};
    for (int i = 0; i < n; ++i) {
      Options oi = o;
      oi.spacing = fmt::format("{} m", lo + (hi - lo) * i / (n - 1));
      const auto r = contact::solve_multi_asperity(make_spec(oi, c, delta_pc));
      t.rows.push_back({lo + (hi - lo) * i / (n - 1), r.total_contact_area,
                        r.midpoint_von_mises.empty() ? 0.0 : r.midpoint_von_mises.front(), r.inflection_depth,
                        r.inflection_von_mises, r.asperities[r.asperities.size() / 2].load, r.line_load,
                        static_cast<double>(r.iterations)});
    }
    emit_table(t, o.table, outputs);
    return;
  }
  const contact::MultiAsperitySpec spec = make_spec(o, c, delta_pc);
  const auto r = contact::solve_multi_asperity(spec);
  io::Table t;
  t.header = {"asperity",          "load_N_per_m", "contact_width_m", "max_pressure_Pa", "max_surface_von_mises_Pa",
              "max_deformation_m", "centre_m"};
  for (std::size_t k = 0; k < r.asperities.size(); ++k) {
    const auto& a = r.asperities[k];
    t.add_row(fmt::format("{}{}", k + 1, a.kind),
              {a.load, a.contact_width, a.max_pressure, a.max_surface_von_mises, a.max_deformation, a.centre});
  }
  io::Table totals;
  totals.header = {"name", "value"};
  totals.add_row("total_contact_area_m2", {r.total_contact_area});
  for (std::size_t k = 0; k < r.midpoint_von_mises.size(); ++k)
    totals.add_row(fmt::format("midpoint_von_mises_{}_{}_Pa", k + 1, k + 2), {r.midpoint_von_mises[k]});
  totals.add_row("inflection_depth_m", {r.inflection_depth});
  totals.add_row("inflection_von_mises_Pa", {r.inflection_von_mises});
  totals.add_row("approach_m", {r.approach});
  totals.add_row("approach_over_delta_pc", {r.approach / delta_pc});
  totals.add_row("line_load_N_per_m", {r.line_load});
  totals.add_row("delta_pc_m", {delta_pc});
  totals.add_row(o.modulus == "composite" ? "modulus_composite_Pa" : "modulus_single_body_Pa", {spec.modulus});
  totals.add_row("elements", {static_cast<double>(r.grid.size)});
  totals.add_row("element_width_m", {r.grid.spacing});
  totals.add_row("iterations", {static_cast<double>(r.iterations)});
  totals.add_row("complementarity_error", {r.complementarity_error});
  // The cost: iterations on the coarser grids that started the solve, its FFTs (count, one
  // transform's mean time, their product) beside the solve's and the whole study's wall time.
  totals.add_row("coarse_iterations", {static_cast<double>(r.coarse_iterations)});
  totals.add_row("fft_transforms", {static_cast<double>(r.transforms)});
  const double one = r.transforms > 0 ? r.transform_seconds / static_cast<double>(r.transforms) : 0.0;
  totals.add_row("fft_transform_time_s", {one});
  totals.add_row("fft_time_s", {one * static_cast<double>(r.transforms)});
  totals.add_row("solve_time_s", {r.solve_seconds});
  totals.add_row("study_time_s", {r.seconds});
  // Two tables, one after the other (a blank line between).
  const bool csv = o.table.csv.in_place();
  auto both = [&](bool as_csv) {
    return (as_csv ? io::format_csv(t) : io::format_text(t)) + "\n" +
           (as_csv ? io::format_csv(totals) : io::format_text(totals));
  };
  if (o.table.csv.to_file()) outputs.add_text(o.table.csv.file, both(true));
  if (o.table.output.empty()) outputs.add_stdout(both(csv));
  else outputs.add_text(o.table.output, both(csv));
  outputs.commit();
}

}  // namespace

void add_multi_asperity_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "multi-asperity",
      "Parallel parabolic-cylinder asperities y = -x^2/(2 R_m) (the case's asperity.cylinder R_m) on a base\n"
      "plane, pressed by a rigid flat (the thesis's multi-asperity model of a hobbed flank), by plane-strain\n"
      "boundary elements with an elastic-perfectly-plastic pressure cap and the composite modulus E_t (--modulus).\n"
      "Height step and approach in units of the cylinder's critical interference delta_pc (--delta-pc).\n"
      "Prints per asperity its load, contact width, peak pressure, surface von Mises stress and\n"
      "largest deformation, then the total contact area (10 um long cylinders), the von Mises stress at the\n"
      "surface midway between neighbours and the inflection point of the von Mises profile below the middle\n"
      "asperity.");
  add_case_option(cmd, o->case_options);
  cmd->add_option("--layout", o->layout,
                  "H (high) and L (low) letters, e.g. LLH, LHL, LHH, HLH, or H alone (default HLH)");
  cmd->add_option("--height-step", o->height_step,
                  "Height difference h_m of the low asperities, in delta_pc (default 0)")
      ->check(CLI::Range(0.0, 9.0));
  cmd->add_option("--spacing", o->spacing, "Distance d_m between neighbouring asperity axes (default 0.5um)");
  auto* ap = cmd->add_option("--approach", o->approach,
                             "Approach of the flat after touching the high tips, in delta_pc (default 6)");
  auto* ld = cmd->add_option("--load", o->load, "Line load [N/m] instead of an approach (load control)");
  ap->excludes(ld);
  cmd->add_option("--asperity-height", o->asperity_height,
                  "High asperities' height above the base plane (default 4um, assumed)");
  cmd->add_option(
      "--delta-pc", o->delta_pc,
      "The unit of --height-step and --approach (default: the cylinder's critical interference by the thesis's "
      "formula, geartrib asperity --summary: 0.423 um for the default case; the thesis's deformation table implies "
      "0.58nm)");
  cmd->add_option("--elements", o->elements, "Boundary elements over the domain (default 16384)")
      ->check(CLI::Range(64, 1 << 22));
  cmd->add_option("--pressure-cap", o->cap, "hardness (H), yield (Prandtl punch (2+pi) S_y/sqrt3) or none (elastic)")
      ->check(CLI::IsMember({"hardness", "yield", "none"}));
  cmd->add_option(
         "--modulus", o->modulus,
         "composite (default: E_t of both flanks on a rigid flat, the equivalent rough surface's, consistent\n"
         "with delta_pc) or single-body (E/(1 - nu^2) of the softer body, as the CalculiX three-cylinder model)")
      ->check(CLI::IsMember({"composite", "single-body"}));
  cmd->add_option("--reference-depth", o->reference_depth,
                  "Displacement reference L_ref: a rigid base ~L_ref deep (default 50um, assumed)");
  auto* topo =
      cmd->add_option("--topography", o->topography,
                      "Surface file: its profile across the lay, cut into parabolic cylinders (`geartrib surface\n"
                      "asperities --cylinders`), replaces --layout, --height-step, --spacing and R_m");
  add_surface_input_options(cmd, o->surface);
  auto* sweep =
      cmd->add_option("--sweep-spacing", o->sweep, "MIN:MAX:COUNT spacings (e.g. 0.25um:2um:8): one row per spacing");
  topo->excludes(sweep);
  for (const char* geometry : {"--layout", "--height-step", "--spacing"}) topo->excludes(geometry);
  add_table_options(cmd, o->table);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
