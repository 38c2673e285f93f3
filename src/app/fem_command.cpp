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
#include <unistd.h>
#include <iostream>
#include <memory>

namespace geartrib::app {

namespace {

struct SingleOptions {
  std::string case_file;
  std::string material = "perfectly-plastic";
  std::vector<double> delta_star{1, 2, 6, 10};
  int refine = 20;
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
  s.delta_star = o.delta_star;
  s.refine = o.refine;
  const fem::SingleAsperityDeck deck = fem::single_asperity_deck(s);
  const std::filesystem::path dir = o.keep_deck.empty() ? std::filesystem::temp_directory_path() / fmt::format("geartrib-fem-{}", getpid())
                                                        : std::filesystem::path(o.keep_deck);
  std::filesystem::create_directories(dir);
  const std::string job = "single_asperity";
  io::write_file_atomically(dir / (job + ".inp"), deck.text);
  const std::filesystem::path ccx = fem::find_ccx();
  if (ccx.empty()) {
    if (o.keep_deck.empty()) std::filesystem::remove_all(dir);
    throw std::runtime_error(o.keep_deck.empty() ? "ccx (CalculiX) not found: install calculix-ccx (bash scripts/setup.sh does), "
                                                   "or give --keep-deck DIR to write the deck only"
                                                 : fmt::format("ccx (CalculiX) not found; the deck is in {}", (dir / (job + ".inp")).string()));
  }
  fmt::print(stderr, "ccx: {} CAX8, tip element a/{} ({:.3g} a_c), levels up to delta* = {}\n", deck.elements, s.refine,
             deck.tip_element / std::sqrt(deck.critical_interference), s.delta_star.back());
  const auto t0 = std::chrono::steady_clock::now();
  fem::run_ccx(ccx, dir, job);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto rows = fem::read_single_asperity(s, deck, dir, job);
  io::Table t;
  t.header = {"delta_star", "load_star", "area_star", "mean_pressure_over_yield", "contact_radius_over_ac", "max_von_mises_over_yield",
              "max_von_mises_depth_over_a", "plastic_depth_over_ac", "plastic_surface_radius_over_ac"};
  for (const auto& r : rows)
    t.rows.push_back({r.delta_star, r.load_star, r.area_star, r.mean_pressure_over_yield, r.contact_radius, r.max_von_mises_over_yield,
                      r.max_von_mises_depth, r.plastic_depth, r.plastic_surface_radius});
  const std::string provenance = fmt::format(
      "# source: geartrib fem single-asperity ({}), axisymmetric paraboloid against a rigid flat, frictionless, penalty contact\n"
      "# material: {}, E' = {:.6g} GPa, nu = {}, S_y = {:.6g} MPa\n"
      "# mesh: {} CAX8, tip element {:.4g} a_c (a_max/{}), body {} contact radii\n"
      "# normalisation: Kogut-Etsion delta_c, F_c, A_c (Hertz at delta_c); {:.1f} s\n",
      fem::ccx_version(ccx), o.material, s.modulus * 1e-9, s.poisson_ratio, s.yield_strength * 1e-6, deck.elements,
      deck.tip_element / std::sqrt(deck.critical_interference), s.refine, s.size, seconds);
  const std::string text = provenance + io::format_csv(t);
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
  single->add_option("--refine", o->refine, "Elements across the final contact radius (default 20)")->check(CLI::Range(4, 400));
  single->add_option("-o,--output", o->output, "Write the table here (atomically) instead of stdout");
  single->add_option("--keep-deck", o->keep_deck, "Keep the deck and ccx's files in this folder (written even without ccx)");
  single->callback([o] { single_asperity(*o); });
}

}  // namespace geartrib::app
