// `geartrib kinematics`: the spur pair along its line of action: geometry, load sharing,
// curvature, Hertz line contact, rolling and sliding, mesh stiffness.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "contact/run_summary.hpp"
#include "runs/kinematics_table.hpp"

#include "case/gear_setup.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace geartrib::app {

namespace {

struct Options {
  CaseOptions case_options;
  std::vector<std::string> points;
  std::optional<int> positions;
  std::string load_sharing;
  TableOptions table;
  bool summary = false;
};

void run_summary(const Options& o, const Case& c, const gear::GearMesh& mesh, io::OutputSet& outputs) {
  const auto& pair = mesh.pair();
  const auto& p = pair.path();
  const gear::IsoStiffnessComparison comparison = mesh.iso_comparison(c.mesh.positions);
  const gear::MeshStiffnessStats& k = comparison.model;
  const gear::IsoMeshStiffness& iso = comparison.iso;
  const double b = pair.spec().face_width;
  if (const std::string w = gear::iso_stiffness_warning(mesh, comparison); !w.empty())
    std::cerr << "warning: " << w << '\n';
  const double to_n_per_m_um = 1e-6;  // N/m per m width -> N/(m um)
  io::Table t;
  t.header = {"name", "value"};
  t.add_row("reference_center_distance_m", {pair.reference_center_distance()});
  t.add_row("center_distance_m", {pair.center_distance()});
  t.add_row("operating_pressure_angle_rad", {pair.operating_pressure_angle()});
  t.add_row("operating_pressure_angle_deg", {pair.operating_pressure_angle() * 180.0 / std::numbers::pi});
  for (int i = 0; i < 2; ++i) {
    const auto& g = pair.gear(i);
    const std::string n = i == 0 ? "pinion" : "wheel";
    t.add_row(n + "_base_radius_m", {g.base_radius});
    t.add_row(n + "_tip_radius_m", {g.tip_radius});
    t.add_row(n + "_root_radius_m", {g.root_radius});
    t.add_row(n + "_operating_pitch_radius_m", {g.operating_pitch_radius});
    t.add_row(n + "_fillet_foundation_in_fit_range", {gear::fillet_foundation_in_range(g) ? 1.0 : 0.0});
  }
  t.add_row("line_of_action_T1T2_m", {p.line_length});
  t.add_row("s_A_m", {p.a});
  t.add_row("s_B_m", {p.b});
  t.add_row("s_C_m", {p.c});
  t.add_row("s_D_m", {p.d});
  t.add_row("s_E_m", {p.e});
  t.add_row("base_pitch_m", {p.base_pitch});
  t.add_row("length_of_contact_m", {p.length});
  t.add_row("contact_ratio", {p.contact_ratio});
  t.add_row("normal_force_N", {mesh.normal_force()});
  t.add_row("pinion_speed_rad_per_s", {mesh.pinion_speed()});
  t.add_row("mean_mesh_stiffness_N_per_m", {k.mean});
  t.add_row("min_mesh_stiffness_N_per_m", {k.min});
  t.add_row("max_mesh_stiffness_N_per_m", {k.max});
  t.add_row("mean_mesh_stiffness_per_width_N_per_m_um", {k.mean / b * to_n_per_m_um});
  t.add_row("iso_c_prime_N_per_m_um", {iso.single * to_n_per_m_um});
  t.add_row("iso_c_gamma_alpha_N_per_m_um", {iso.mesh * to_n_per_m_um});
  t.add_row("mean_mesh_stiffness_over_iso_c_gamma_alpha", {comparison.ratio});
  if (mesh.tooth_contact()) {
    // The loaded tooth contact over one base pitch: the same names as the run's /mesh attributes.
    t.add_row("iso_effective_tip_relief_m", {gear::iso_effective_relief(pair, mesh.tangential_line_load())});
    for (int i = 0; i < 2; ++i)
      t.add_row(std::string(i == 0 ? "pinion" : "wheel") + "_tip_relief_m",
                {mesh.tooth_contact()->flank(i).tip_amount()});
    for (const auto& v :
         contact::tooth_contact_summary(mesh.analysis().transmission_error_stats(mesh.cycle_positions())).values)
      t.add_row(v.name, {v.value});
  }
  emit_table(t, o.table, outputs);
}

void run(const Options& o) {
  // --load-sharing is a shorthand for --set mesh.load_sharing; the kinematics need only the geometry.
  CaseOptions co = o.case_options;
  if (!o.load_sharing.empty()) co.changes.push_back("mesh.load_sharing=" + o.load_sharing);
  const Case c = load_case_reporting(co, io::kGeometryPart);
  io::OutputSet outputs;  // the table's files, checked before any work
  reserve_table(o.table, outputs);
  const gear::GearMesh mesh = gear::case_mesh(c);
  if (o.summary) return run_summary(o, c, mesh, outputs);

  emit_table(o.positions ? runs::kinematics_table(mesh, *o.positions) : runs::kinematics_table(mesh, o.points), o.table,
             outputs);
}

}  // namespace

void add_kinematics_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "kinematics",
      "The spur pair along its line of action. For the points A (start of contact), B (lowest single-tooth\n"
      "point), C (pitch point), D (highest single-tooth point), E (end), or N positions from A to E of one\n"
      "tooth pair: curvature radii, ISO roll parameter gamma, load share and line load, Hertz line-contact\n"
      "peak pressure and half-width (shared and if the pair carried the whole load), rolling, entrainment\n"
      "and sliding speeds, slide-to-roll ratio (sliding over mean rolling speed), specific sliding, and the\n"
      "tooth-pair and mesh stiffness. At B and D a named point reports the single-tooth side of the jump.\n"
      "--summary prints the geometry, contact ratio, mesh stiffness and ISO 6336-1 c' and c_gamma_alpha.");
  add_case_argument(cmd, o->case_options);
  auto* pts =
      cmd->add_option("--points", o->points, "Comma-separated named points (default A,B,C,D,E)")->delimiter(',');
  auto* pos =
      cmd->add_option("--positions", o->positions, "N equally spaced positions from A to E instead of named points")
          ->check(CLI::Range(2, 100000));
  pts->excludes(pos);
  cmd->add_option("--load-sharing", o->load_sharing,
                  "iso, stiffness or compatibility: shorthand for --set mesh.load_sharing=...")
      ->check(CLI::IsMember({"iso", "stiffness", "compatibility"}));
  add_table_options(cmd, o->table);
  cmd->add_flag("--summary", o->summary, "name,value rows: geometry, contact ratio, mesh stiffness, ISO stiffness");
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
