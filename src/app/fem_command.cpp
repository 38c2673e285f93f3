// `geartrib fem`: finite-element reference data with CalculiX (ccx) - decks, runs, tables in the
// fitting format.
#include "app/commands.hpp"

#include "asperity/case_setup.hpp"
#include "asperity/critical.hpp"
#include "fem/asperity_deck.hpp"
#include "fem/ccx_results.hpp"
#include "io/table_writer.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <unistd.h>
#include <iostream>
#include <memory>

namespace geartrib::app {

namespace {

struct SingleOptions {
  std::string case_file;
  std::string material = "perfectly-plastic";
  std::vector<double> delta_star{1, 2, 6, 10};
  int refine = 10;
  bool convergence = false;
  std::string output;
  std::string keep_deck;
};

void single_asperity(const SingleOptions& o) {
  const Case c = load_case_reporting(o.case_file);
  const asperity::ContactPair pair = asperity::contact_pair(c);
  const asperity::Critical crit = asperity::hertz_critical(pair, asperity::ceb_pressure_factor(pair.poisson_ratio) * pair.hardness);
  fem::SingleAsperitySpec s;
  // A deformable asperity with E/(1 - nu^2) = E_t against a rigid flat is the pair (Johnson's E*).
  s.modulus = pair.modulus;
  s.poisson_ratio = pair.poisson_ratio;
  s.yield_strength = pair.yield_strength;
  s.critical_interference_over_radius = crit.interference / pair.radius;  // (pi K H / (2 E_t))^2
  s.material = o.material == "elastic" ? fem::FemMaterial::elastic
               : o.material == "table" ? fem::FemMaterial::table
                                       : fem::FemMaterial::perfectly_plastic;
  const Material& soft = c.pinion.material.hardness <= c.wheel.material.hardness ? c.pinion.material : c.wheel.material;
  s.flow_table.emplace_back(soft.yield_strength, 0.0);
  for (const auto& p : soft.flow_curve)
    if (p.plastic_strain > 0.0) s.flow_table.emplace_back(p.stress, p.plastic_strain);
  const std::filesystem::path dir = o.keep_deck.empty() ? std::filesystem::temp_directory_path() / fmt::format("geartrib-fem-{}", getpid())
                                                        : std::filesystem::path(o.keep_deck);
  std::filesystem::create_directories(dir);
  const std::filesystem::path ccx = fem::find_ccx();
  // Levels in runs whose meshes resolve their first contact (plan_runs); with --convergence each
  // run also at about 1/2 and 1/sqrt2 of the refinement.
  std::vector<int> refinements{o.refine};
  if (o.convergence) refinements = {std::max(4, (o.refine + 1) / 2), std::max(4, static_cast<int>(std::lround(o.refine / std::sqrt(2.0)))), o.refine};
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
      fmt::print(stderr, "ccx run {}: delta* {} to {}, {} CAX8, tip element {:.3g} a_c (first contact / {})\n", job_index, levels.front(),
                 levels.back(), deck.elements, deck.tip_element / std::sqrt(deck.critical_interference), refine);
      const auto t0 = std::chrono::steady_clock::now();
      fem::run_ccx(ccx, dir, job);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      by_refinement.push_back(fem::read_single_asperity(run, deck, dir, job));
      if (refine == o.refine)
        mesh_lines.push_back(fmt::format("# mesh, delta* {}-{}: {} CAX8, tip element {:.4g} a_c (first contact / {}), body {} contact radii",
                                         levels.front(), levels.back(), deck.elements,
                                         deck.tip_element / std::sqrt(deck.critical_interference), refine, run.size));
    }
    if (ccx.empty()) continue;
    const auto& finest = by_refinement.back();
    rows.insert(rows.end(), finest.begin(), finest.end());
    for (std::size_t k = 1; k < by_refinement.size(); ++k)
      for (std::size_t i = 0; i < levels.size(); ++i)
        convergence_lines.push_back(fmt::format(
            "# convergence: delta* {} refine {} -> {}: load* {:+.2f}%, area* {:+.2f}%", levels[i], refinements[k - 1], refinements[k],
            100.0 * (by_refinement[k][i].load_star / by_refinement[k - 1][i].load_star - 1.0),
            100.0 * (by_refinement[k][i].area_star / by_refinement[k - 1][i].area_star - 1.0)));
  }
  if (ccx.empty()) {
    if (o.keep_deck.empty()) std::filesystem::remove_all(dir);
    throw std::runtime_error(o.keep_deck.empty() ? "ccx (CalculiX) not found: install calculix-ccx (bash scripts/setup.sh does), "
                                                   "or give --keep-deck DIR to write the decks only"
                                                 : fmt::format("ccx (CalculiX) not found; the decks are in {}", dir.string()));
  }
  for (const auto& l : convergence_lines) fmt::print(stderr, "{}\n", l.substr(2));
  io::Table t;
  t.header = {"delta_star", "load_star", "area_star", "mean_pressure_over_yield", "contact_radius_over_ac", "max_von_mises_over_yield",
              "max_von_mises_depth_over_a", "plastic_depth_over_ac", "plastic_surface_radius_over_ac"};
  for (const auto& r : rows)
    t.rows.push_back({r.delta_star, r.load_star, r.area_star, r.mean_pressure_over_yield, r.contact_radius, r.max_von_mises_over_yield,
                      r.max_von_mises_depth, r.plastic_depth, r.plastic_surface_radius});
  std::string text = fmt::format(
      "# source: geartrib {} fem single-asperity ({}), axisymmetric paraboloid against a rigid flat, frictionless, penalty contact\n"
      "# material: {}, E/(1-nu^2) = {:.6g} GPa, nu = {}, S_y = {:.6g} MPa{}\n"
      "# normalisation: Kogut-Etsion delta_c = (pi K H/(2 E_t))^2 R, F_c and A_c = Hertz at delta_c; "
      "contact radius from the opening gap of the surface nodes\n",
      GEARTRIB_VERSION, fem::ccx_version(ccx), o.material, s.modulus * 1e-9, s.poisson_ratio, s.yield_strength * 1e-6,
      o.material == "table" ? fmt::format(", flow table of {} points", s.flow_table.size()) : std::string());
  for (const auto& l : mesh_lines) text += l + "\n";
  for (const auto& l : convergence_lines) text += l + "\n";
  text += fmt::format("# ccx time: {:.1f} s\n", seconds);
  text += io::format_csv(t);
  if (o.output.empty()) std::cout << text;
  else io::write_file_atomically(o.output, text);
  if (o.keep_deck.empty()) std::filesystem::remove_all(dir);
}

}  // namespace

void add_fem_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("fem", "Finite-element reference data with CalculiX (ccx): decks, runs and tables for `geartrib fit`");
  cmd->require_subcommand(1);
  auto o = std::make_shared<SingleOptions>();
  auto* single = cmd->add_subcommand(
      "single-asperity",
      "Axisymmetric paraboloid of the case's equivalent radius pressed by a rigid flat, frictionless, displacement-controlled\n"
      "to the delta* levels; prints load*, area*, mean pressure / S_y, the largest von Mises stress and its depth, and the\n"
      "plastic zone, with provenance lines, in the reference-table format of `geartrib fit`.");
  single->add_option("--case", o->case_file, "Case file for the material and radius (default: gears/m6z30.toml)");
  single->add_option("--material", o->material, "elastic, perfectly-plastic (default) or table (the case's flow curve)")
      ->check(CLI::IsMember({"elastic", "perfectly-plastic", "table"}));
  single->add_option("--delta-star", o->delta_star, "Comma-separated interference levels delta/delta_c (default 1,2,6,10)")->delimiter(',');
  single->add_option("--refine", o->refine, "Elements across each run's first contact radius (default 10); levels more than 4x apart\n"
                                             "run on separate meshes")->check(CLI::Range(4, 400));
  single->add_flag("--convergence", o->convergence, "Also run each mesh at about 1/2 and 1/sqrt2 of the refinement and report the\n"
                                                    "changes in load* and area* (stderr and provenance lines)");
  single->add_option("-o,--output", o->output, "Write the table here (atomically) instead of stdout");
  single->add_option("--keep-deck", o->keep_deck, "Keep the deck and ccx's files in this folder (written even without ccx)");
  single->callback([o] { single_asperity(*o); });
}

}  // namespace geartrib::app
