// `geartrib fem`: finite-element reference data with CalculiX (ccx) - decks, runs, tables in the
// fitting format.
#include "app/case_loading.hpp"
#include "app/commands.hpp"

#include "asperity/critical.hpp"
#include "asperity/cylinder.hpp"
#include "case/asperity_setup.hpp"
#include "fem/asperity_deck.hpp"
#include "fem/ccx_results.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

namespace geartrib::app {

namespace {

// Where a run's decks and ccx's files go: --keep-deck DIR, else a temporary folder removed when
// the run completes (left in place when ccx fails, for the deck and ccx's log its message names).
struct FemFolder {
  std::filesystem::path dir;
  bool temporary = false;
  explicit FemFolder(const std::string& keep_deck)
      : dir(keep_deck.empty() ? std::filesystem::temp_directory_path() / fmt::format("geartrib-fem-{}", getpid())
                              : std::filesystem::path(keep_deck)),
        temporary(keep_deck.empty()) {
    std::filesystem::create_directories(dir);
  }
  void done() const {
    if (temporary) std::filesystem::remove_all(dir);
  }
  // Without ccx: the decks stay only when the user asked to keep them.
  [[noreturn]] void missing_ccx() const {
    done();
    throw std::runtime_error(temporary ? "ccx (CalculiX) not found: install calculix-ccx (bash scripts/setup.sh does), "
                                         "or give --keep-deck DIR to write the decks only"
                                       : fmt::format("ccx (CalculiX) not found; the decks are in {}", dir.string()));
  }
};

struct SingleOptions {
  CaseOptions case_options;
  std::string material = "perfectly-plastic";
  std::vector<double> delta_star{1, 2, 6, 10};
  int refine = 10;
  bool convergence = false;
  bool reuse = false;
  std::string output;
  std::string details;
  std::string keep_deck;
};

void single_asperity(const SingleOptions& o) {
  const Case c = load_case_reporting(o.case_options, io::kGeometryPart | io::kRoughnessPart);
  io::OutputSet outputs;  // -o and --details: both or neither, checked before ccx runs
  if (!o.output.empty()) outputs.reserve(o.output);
  if (!o.details.empty()) outputs.reserve(o.details);
  const asperity::ContactPair pair = asperity::contact_pair(c);
  const asperity::Critical crit =
      asperity::hertz_critical(pair, asperity::ceb_pressure_factor(pair.poisson_ratio) * pair.hardness);
  fem::SingleAsperitySpec s;
  // A deformable asperity with E/(1 - nu^2) = E_t against a rigid flat is the pair (Johnson's E*).
  s.modulus = pair.modulus;
  s.poisson_ratio = pair.poisson_ratio;
  s.yield_strength = pair.yield_strength;
  s.critical_interference_over_radius = crit.interference / pair.radius;  // (pi K H / (2 E_t))^2
  s.material = o.material == "elastic" ? fem::FemMaterial::elastic
               : o.material == "table" ? fem::FemMaterial::table
                                       : fem::FemMaterial::perfectly_plastic;
  const Material& soft = asperity::softer_material(c);
  s.flow_table.emplace_back(soft.yield_strength, 0.0);
  for (const auto& p : soft.flow_curve)
    if (p.plastic_strain > 0.0) s.flow_table.emplace_back(p.stress, p.plastic_strain);
  const FemFolder folder(o.keep_deck);
  const std::filesystem::path& dir = folder.dir;
  const std::filesystem::path ccx = fem::find_ccx();
  // Levels in runs whose meshes resolve their first contact (plan_runs); with --convergence each
  // run also at about 1/2 and 1/sqrt2 of the refinement.
  std::vector<int> refinements{o.refine};
  if (o.convergence)
    refinements = {std::max(4, (o.refine + 1) / 2),
                   std::max(4, static_cast<int>(std::lround(o.refine / std::sqrt(2.0)))), o.refine};
  std::vector<std::string> mesh_lines, convergence_lines;
  std::vector<fem::SingleAsperityResult> rows;
  double seconds = 0.0;
  int job_index = 0;
  for (const auto& levels : fem::plan_runs(o.delta_star)) {
    std::vector<std::vector<fem::SingleAsperityResult>> by_refinement;
    for (int refine : refinements) {
      fem::SingleAsperitySpec run = s;
      run.delta_star = levels;
      run.refine = refine;
      const fem::SingleAsperityDeck deck = fem::single_asperity_deck(run);
      const std::string job = fmt::format("single_asperity_{}", ++job_index);
      io::write_file_atomically(dir / (job + ".inp"), deck.text);
      if (ccx.empty()) continue;
      fmt::print(stderr, "ccx run {}: delta* {} to {}, {} CAX8, tip element {:.3g} a_c (first contact / {})\n",
                 job_index, levels.front(), levels.back(), deck.elements,
                 deck.tip_element / std::sqrt(deck.critical_interference), refine);
      const auto t0 = std::chrono::steady_clock::now();
      // --reuse: results of an identical deck already in --keep-deck DIR are read, not rerun.
      const bool reused =
          o.reuse && std::filesystem::exists(dir / (job + ".frd")) && std::filesystem::exists(dir / (job + ".dat"));
      if (!reused) fem::run_ccx(ccx, dir, job);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      by_refinement.push_back(fem::read_single_asperity(run, deck, dir, job));
      if (refine == o.refine)
        mesh_lines.push_back(fmt::format(
            "# mesh, delta* {}-{}: {} CAX8, tip element {:.4g} a_c (first contact / {}), body {} contact radii",
            levels.front(), levels.back(), deck.elements, deck.tip_element / std::sqrt(deck.critical_interference),
            refine, run.size));
    }
    if (ccx.empty()) continue;
    const auto& finest = by_refinement.back();
    rows.insert(rows.end(), finest.begin(), finest.end());
    for (std::size_t k = 1; k < by_refinement.size(); ++k)
      for (std::size_t i = 0; i < levels.size(); ++i)
        convergence_lines.push_back(fmt::format(
            "# convergence: delta* {} refine {} -> {}: load* {:+.2f}%, area* {:+.2f}%", levels[i], refinements[k - 1],
            refinements[k], 100.0 * (by_refinement[k][i].load_star / by_refinement[k - 1][i].load_star - 1.0),
            100.0 * (by_refinement[k][i].area_star / by_refinement[k - 1][i].area_star - 1.0)));
  }
  if (ccx.empty()) folder.missing_ccx();
  for (const auto& l : convergence_lines) fmt::print(stderr, "{}\n", l.substr(2));
  // The reference table in `geartrib fit`'s format; the other figures go to --details.
  io::Table t, details;
  t.header = {"delta_star",
              "load_star",
              "area_star",
              "mean_pressure_over_yield",
              "plastic_area_fraction",
              "sd_plastic_area_fraction"};
  details.header = {"delta_star",
                    "contact_radius_over_ac",
                    "max_pressure_over_yield",
                    "max_von_mises_over_yield",
                    "max_von_mises_depth_over_a",
                    "plastic_depth_over_ac",
                    "plastic_surface_radius_over_ac",
                    "plastic_surface_area_fraction",
                    "plastic_surface_inner_radius_over_ac"};
  for (const auto& r : rows) {
    t.rows.push_back({r.delta_star, r.load_star, r.area_star, r.mean_pressure_over_yield,
                      r.plastic_surface_area_fraction, r.plastic_surface_area_fraction_sd});
    details.rows.push_back({r.delta_star, r.contact_radius, r.max_pressure_over_yield, r.max_von_mises_over_yield,
                            r.max_von_mises_depth, r.plastic_depth, r.plastic_surface_radius,
                            r.plastic_surface_area_fraction, r.plastic_surface_inner_radius});
  }
  std::string text = fmt::format(
      "# source: geartrib {} fem single-asperity ({}), axisymmetric paraboloid against a rigid flat, frictionless, penalty contact\n"
      "# material: {}, E/(1-nu^2) = {:.6g} GPa, nu = {}, S_y = {:.6g} MPa{}\n"
      "# normalisation: Kogut-Etsion delta_c = (pi K H/(2 E_t))^2 R, F_c and A_c = Hertz at delta_c; "
      "contact radius from the opening gap of the surface nodes\n"
      "# plastic_area_fraction: the yielded share of the contact disc at the surface, integral over r <= a of (a deformed surface node "
      "has yielded: the median of its and its neighbours' nodal PEEQ > {:g}; each node stands for the ring between the midpoints to "
      "its neighbours) 2 pi r dr / (pi a^2); sd_plastic_area_fraction = half the share of the surface element containing r = a, "
      "at least 0.02\n",
      GEARTRIB_VERSION, fem::ccx_version(ccx), o.material, s.modulus * 1e-9, s.poisson_ratio, s.yield_strength * 1e-6,
      o.material == "table" ? fmt::format(", flow table of {} points", s.flow_table.size()) : std::string(),
      fem::surface_yield_threshold);
  for (const auto& l : mesh_lines) text += l + "\n";
  for (const auto& l : convergence_lines) text += l + "\n";
  text += fmt::format("# ccx time: {:.1f} s\n", seconds);
  if (!o.output.empty()) outputs.add_text(o.output, text + io::format_csv(t));
  else outputs.add_stdout(text + io::format_csv(t));
  if (!o.details.empty()) outputs.add_text(o.details, text + io::format_csv(details));
  outputs.commit();
  folder.done();
}

struct CylinderOptions {
  CaseOptions case_options;
  std::string layout = "HLH";
  double height_step = 0.0;
  std::string spacing = "0.5um";
  std::vector<double> approach{6.0};
  std::string delta_pc;
  std::string asperity_height = "4um";
  std::string depth = "50um";
  std::string material = "perfectly-plastic";
  int refine = 10;
  std::string output;
  std::string keep_deck;
};

void three_cylinders(const CylinderOptions& o) {
  const Case c = load_case_reporting(o.case_options, io::kGeometryPart | io::kCylinderPart);
  io::OutputSet outputs;  // -o, checked before ccx runs
  if (!o.output.empty()) outputs.reserve(o.output);
  const double delta_pc = o.delta_pc.empty() ? asperity::seed_critical_interference(asperity::cylinder_asperity(c))
                                             : quantity_option("--delta-pc", o.delta_pc, io::Dimension::length);
  const Material& m = asperity::softer_material(c);
  if (o.layout.empty() || o.layout.find_first_not_of("HL") != std::string::npos ||
      o.layout.find('H') == std::string::npos)
    throw std::invalid_argument("--layout must be letters H and L with at least one H (e.g. HLH, H)");
  fem::CylindersSpec s;
  const double spacing = quantity_option("--spacing", o.spacing, io::Dimension::length);
  const int n = static_cast<int>(o.layout.size());
  for (int k = 0; k < n; ++k)
    s.cylinders.push_back({(k - 0.5 * (n - 1)) * spacing,
                           o.layout[static_cast<std::size_t>(k)] == 'H' ? 0.0 : -o.height_step * delta_pc,
                           c.asperity.cylinder_tip_radius});
  s.asperity_height = quantity_option("--asperity-height", o.asperity_height, io::Dimension::length);
  s.depth = quantity_option("--depth", o.depth, io::Dimension::length);
  s.youngs_modulus = m.youngs_modulus;
  s.poisson_ratio = m.poisson_ratio;
  s.yield_strength = m.yield_strength;
  s.material = o.material == "elastic" ? fem::FemMaterial::elastic
               : o.material == "table" ? fem::FemMaterial::table
                                       : fem::FemMaterial::perfectly_plastic;
  s.flow_table.emplace_back(m.yield_strength, 0.0);
  for (const auto& p : m.flow_curve)
    if (p.plastic_strain > 0.0) s.flow_table.emplace_back(p.stress, p.plastic_strain);
  s.unit = delta_pc;
  s.levels = o.approach;
  s.refine = o.refine;
  const fem::CylindersDeck deck = fem::cylinders_deck(s);
  const FemFolder folder(o.keep_deck);
  const std::filesystem::path& dir = folder.dir;
  const std::string job = "cylinders";
  io::write_file_atomically(dir / (job + ".inp"), deck.text);
  const std::filesystem::path ccx = fem::find_ccx();
  if (ccx.empty()) folder.missing_ccx();
  fmt::print(stderr, "ccx: {} CPE8, tip element {:.3g} nm, approach to {} x {:.4g} nm\n", deck.elements,
             deck.tip_element * 1e6, s.levels.back(), delta_pc * 1e9);
  const auto t0 = std::chrono::steady_clock::now();
  fem::run_ccx(ccx, dir, job);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto results = fem::read_cylinders(s, deck, dir, job);
  io::Table t;
  t.header = {"asperity",         "approach_over_delta_pc",   "load_N_per_m",
              "contact_width_m",  "max_surface_von_mises_Pa", "max_plastic_strain",
              "line_load_N_per_m"};
  for (const auto& r : results)
    for (std::size_t k = 0; k < r.asperities.size(); ++k) {
      const auto& a = r.asperities[k];
      t.add_row(fmt::format("{}{}", k + 1, o.layout[k]),
                {r.level, a.load, a.contact_width, a.max_von_mises, a.max_plastic_strain, r.line_load});
    }
  const std::string text =
      fmt::format(
          "# source: geartrib {} fem three-cylinders ({}), plane strain CPE8, rigid flat, frictionless, penalty contact\n"
          "# geometry: layout {}, h_m = {} delta_pc, spacing {:.6g} m, R_m = {:.6g} m, asperity height {:.6g} m, depth {:.6g} m (bottom fixed)\n"
          "# material: {}, E = {:.6g} GPa, nu = {}, S_y = {:.6g} MPa; delta_pc = {:.6g} m\n"
          "# mesh: {} CPE8, tip element {:.4g} m; ccx time {:.1f} s\n",
          GEARTRIB_VERSION, fem::ccx_version(ccx), o.layout, o.height_step, spacing, c.asperity.cylinder_tip_radius,
          s.asperity_height, s.depth, o.material, m.youngs_modulus * 1e-9, m.poisson_ratio, m.yield_strength * 1e-6,
          delta_pc, deck.elements, deck.tip_element * 1e-3, seconds) +
      io::format_csv(t);
  if (o.output.empty()) outputs.add_stdout(text);
  else outputs.add_text(o.output, text);
  outputs.commit();
  folder.done();
}

}  // namespace

void add_fem_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "fem", "Finite-element reference data with CalculiX (ccx): decks, runs and tables for `geartrib fit`");
  cmd->require_subcommand(1);
  auto o = std::make_shared<SingleOptions>();
  auto* single = cmd->add_subcommand(
      "single-asperity",
      "Axisymmetric paraboloid of the case's equivalent radius pressed by a rigid flat, frictionless, displacement-controlled\n"
      "to the delta* levels; prints load*, area* and mean pressure / S_y with provenance lines, in the reference-table\n"
      "format of `geartrib fit`, with the yielded share of the contact area at the surface (--details: contact radius,\n"
      "largest von Mises stress and its depth, plastic zone).");
  add_case_option(single, o->case_options);
  single->add_option("--material", o->material, "elastic, perfectly-plastic (default) or table (the case's flow curve)")
      ->check(CLI::IsMember({"elastic", "perfectly-plastic", "table"}));
  single
      ->add_option("--delta-star", o->delta_star,
                   "Comma-separated interference levels delta/delta_c (default 1,2,6,10)")
      ->delimiter(',');
  single
      ->add_option("--refine", o->refine,
                   "Elements across each run's first contact radius (default 10); levels more than 4x apart\n"
                   "run on separate meshes")
      ->check(CLI::Range(4, 400));
  single->add_flag("--convergence", o->convergence,
                   "Also run each mesh at about 1/2 and 1/sqrt2 of the refinement and report the\n"
                   "changes in load* and area* (stderr and provenance lines)");
  add_output_option(single, o->output,
                    "the table (CSV with # provenance lines), written atomically (default: standard output)");
  single->add_option(
      "--details", o->details,
      "Also write the contact radius, the largest von Mises stress and its depth, and the\n"
      "plastic zone's depth, surface radius, surface yielded share and inner radius per level to this CSV");
  auto* keep = single->add_option("--keep-deck", o->keep_deck,
                                  "Keep the deck and ccx's files in this folder (written even without ccx)");
  single
      ->add_flag("--reuse", o->reuse,
                 "Read the results already in the --keep-deck folder instead of rerunning ccx (same decks)")
      ->needs(keep);
  single->callback([o] { single_asperity(*o); });

  auto c = std::make_shared<CylinderOptions>();
  auto* cyl = cmd->add_subcommand(
      "three-cylinders",
      "The thesis's finite-element model of a hobbed flank: parabolic cylinders (R_m from the case) on a base\n"
      "in plane strain, pressed by a rigid flat to the approaches (in delta_pc); per asperity its load, contact\n"
      "width, surface von Mises and plastic strain, for comparison with `geartrib multi-asperity`.");
  add_case_option(cyl, c->case_options);
  cyl->add_option("--layout", c->layout, "H (high) and L (low) letters, e.g. HLH, LHL, or H alone (default HLH)");
  cyl->add_option("--height-step", c->height_step,
                  "Height difference h_m of the low asperities, in delta_pc (default 0)")
      ->check(CLI::Range(0.0, 9.0));
  cyl->add_option("--spacing", c->spacing, "Distance d_m between neighbouring asperity axes (default 0.5um)");
  cyl->add_option("--approach", c->approach,
                  "Comma-separated approaches of the flat after touching the high tips, in delta_pc (default 6)")
      ->delimiter(',');
  cyl->add_option("--delta-pc", c->delta_pc,
                  "The unit of --height-step and --approach (default: the cylinder's critical interference by the\n"
                  "thesis's formula, geartrib asperity --summary; the thesis's tables imply 0.5797nm)");
  cyl->add_option("--asperity-height", c->asperity_height, "High tips above the base plane (default 4um, assumed)");
  cyl->add_option("--depth", c->depth,
                  "Body depth below the high tips; its bottom is fixed (default 50um, the BEM's L_ref)");
  cyl->add_option("--material", c->material, "elastic, perfectly-plastic (default) or table (the case's flow curve)")
      ->check(CLI::IsMember({"elastic", "perfectly-plastic", "table"}));
  cyl->add_option("--refine", c->refine,
                  "Elements across the estimated contact half-width sqrt(2 R_m delta) (default 10)")
      ->check(CLI::Range(4, 200));
  add_output_option(cyl, c->output,
                    "the table (CSV with # provenance lines), written atomically (default: standard output)");
  cyl->add_option("--keep-deck", c->keep_deck,
                  "Keep the deck and ccx's files in this folder (written even without ccx)");
  cyl->callback([c] { three_cylinders(*c); });
}

}  // namespace geartrib::app
