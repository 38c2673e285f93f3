// `geartrib dynamics`: the mesh's single-degree-of-freedom dynamics at one speed (the steady
// cycle) or over a speed sweep (the dynamic factor against speed).
#include "app/case_loading.hpp"
#include "app/commands.hpp"

#include "case/gear_setup.hpp"
#include "config/units.hpp"
#include "output/table_writer.hpp"
#include "solvers/integrators.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>

namespace geartrib::app {

namespace {

double speed_option(const std::string& option, const std::string& text) {
  return quantity_option(option, text, io::Dimension::angular_speed);
}

constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;

// A speed inside the model's range, or an error naming where it came from, in rpm.
void check_speed(const std::string& source, double w, const gear::MeshDynamics& dyn) {
  const auto [slowest, fastest] = dyn.speed_range();
  if (!(w >= slowest && w <= fastest))
    throw std::invalid_argument(fmt::format(
        "{} = {:.6g} rpm: outside the dynamics model's range {:.4g} to {:.4g} rpm (mesh frequency 1e-5 to 1e3 times "
        "the natural frequency; below it the cycle is quasi-static: see dynamic_factor_quasi_static)",
        source, w / kRpm, slowest / kRpm, fastest / kRpm));
}

struct Options {
  CaseOptions case_options;
  std::string integrator;
  std::string rtol;
  std::string speed;
  std::string sweep;
  TableOptions table;
};

void run(const Options& o) {
  // --integrator and --rtol are shorthands for --set mesh.dynamics and dynamics.relative_tolerance.
  CaseOptions co = o.case_options;
  if (!o.integrator.empty()) co.changes.push_back("mesh.dynamics=" + o.integrator);
  if (!o.rtol.empty()) co.changes.push_back("dynamics.relative_tolerance=" + o.rtol);
  const Case c = load_case_reporting(co, io::kGeometryPart);
  io::OutputSet outputs;  // the table's files, checked before any work
  reserve_table(o.table, outputs);
  const gear::GearMesh mesh = gear::case_mesh(c);
  // The dynamics rest on the mesh stiffness: warned when it leaves ISO's band.
  if (const std::string w = gear::iso_stiffness_warning(mesh, mesh.iso_comparison(c.mesh.positions)); !w.empty())
    std::cerr << "warning: " << w << '\n';
  const gear::DynamicsSettings settings = gear::dynamics_settings(c);
  const gear::DynamicsEngine engine =
      c.dynamics.engine == gear::DynamicsEngine::none ? gear::DynamicsEngine::cvode : c.dynamics.engine;
  const auto integrator = solvers::make_integrator(engine);
  const gear::MeshDynamics dyn(mesh, settings);
  const int z1 = mesh.pair().pinion().teeth;
  std::cerr << fmt::format(
      "equivalent mass {:.4g} kg, mean mesh stiffness {:.4g} N/m, damping {:.4g} N s/m (zeta {}), natural frequency "
      "{:.1f} Hz (resonance at {:.0f} rpm), quasi-static peak {:.4g} x F; integrator {} rtol {:g}\n",
      dyn.equivalent_mass(), dyn.mean_stiffness(), dyn.damping(), settings.damping_ratio, dyn.natural_frequency(),
      60.0 * dyn.natural_frequency() / z1, dyn.quasi_static_peak() / mesh.normal_force(), integrator->name(),
      settings.tolerances.relative);
  io::Table t;
  if (!o.sweep.empty()) {
    // At most 10^4 speeds: each integrates its cycles to a steady state (~ms apiece).
    const RangeOption range = range_option("--speed-sweep", o.sweep, io::Dimension::angular_speed, 2, 10000);
    const double lo = range.min, hi = range.max;
    const int n = range.count;
    if (!(lo > 0.0 && hi > lo)) throw std::invalid_argument("--speed-sweep needs 0 < MIN < MAX");
    check_speed("--speed-sweep", lo, dyn);
    check_speed("--speed-sweep", hi, dyn);
    t.header = {"speed_rpm",    "mesh_frequency_Hz", "dynamic_factor", "dynamic_factor_quasi_static",
                "contact_lost", "periodic",          "cycles"};
    double best = 0.0, best_f = 0.0;
    for (int i = 0; i < n; ++i) {
      const double w = lo + (hi - lo) * i / (n - 1);
      const gear::SteadyCycle s = dyn.steady_cycle(*integrator, w);
      t.rows.push_back({w / kRpm, s.mesh_frequency, s.dynamic_factor, s.dynamic_factor_quasi_static,
                        s.contact_lost ? 1.0 : 0.0, s.periodic ? 1.0 : 0.0, static_cast<double>(s.cycles)});
      if (s.dynamic_factor > best) best = s.dynamic_factor, best_f = s.mesh_frequency;
    }
    std::cerr << fmt::format(
        "largest dynamic factor {:.4g} at a mesh frequency of {:.1f} Hz ({:+.1f}% from the natural frequency)\n", best,
        best_f, 100.0 * (best_f / dyn.natural_frequency() - 1.0));
  } else {
    const double w = o.speed.empty() ? c.operating.pinion_speed : speed_option("--speed", o.speed);
    check_speed(o.speed.empty() ? "operating.pinion_speed" : "--speed", w, dyn);
    const gear::SteadyCycle s = dyn.steady_cycle(*integrator, w);
    const auto& p = mesh.pair().path();
    t.header = {"time_s",
                "s_m",
                "mesh_stiffness_N_per_m",
                "deflection_m",
                "static_deflection_m",
                "mesh_force_N",
                "force_over_static",
                "pair1_force_N",
                "pair2_force_N"};
    for (std::size_t i = 0; i < s.time.size(); ++i) {
      const double s1 = s.position[i], s2 = s1 + p.base_pitch;
      t.rows.push_back({s.time[i], s1, s.stiffness[i], s.deflection[i], s.static_deflection[i], s.force[i],
                        s.force[i] / s.static_force, dyn.pair_force(s, s1), s2 <= p.e ? dyn.pair_force(s, s2) : 0.0});
    }
    std::cerr << fmt::format(
        "{:.0f} rpm: mesh frequency {:.1f} Hz, dynamic factor {:.4g} ({:.4g} of the quasi-static peak), "
        "contact {}, {} after {} cycles, {} steps\n",
        w / kRpm, s.mesh_frequency, s.dynamic_factor, s.dynamic_factor_quasi_static, s.contact_lost ? "lost" : "kept",
        s.periodic ? "periodic" : "NOT periodic", s.cycles, s.steps);
  }
  emit_table(t, o.table, outputs);
}

}  // namespace

void add_dynamics_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "dynamics",
      "Single-degree-of-freedom mesh dynamics along the line of action: m_e x'' + c x' + k(t) g(x) = F with the\n"
      "potential-energy mesh stiffness (steps at B and D integrated explicitly), damping ratio zeta, contact\n"
      "loss (and back-flank contact with a backlash). At one speed: the periodic steady cycle (deflection,\n"
      "static transmission error, mesh force, each pair's dynamic load). Over a sweep: the dynamic factor\n"
      "(peak mesh force over F, and over the model's quasi-static peak) against speed; plot it with\n"
      "scripts/plot_speed_sweep.py.");
  add_case_argument(cmd, o->case_options);
  cmd->add_option("--integrator", o->integrator,
                  "cvode (SUNDIALS BDF) or odeint (Boost Dormand-Prince 5(4)): shorthand for --set mesh.dynamics=...\n"
                  "(default: the case's, cvode when it asks for none)")
      ->check(CLI::IsMember({"cvode", "odeint"}));
  cmd->add_option("--rtol", o->rtol,
                  "Relative tolerance: shorthand for --set dynamics.relative_tolerance=... (default 1e-8)");
  auto* sp = cmd->add_option("--speed", o->speed, "Pinion speed, e.g. 1000rpm (default: the case's)");
  auto* sw = cmd->add_option("--speed-sweep", o->sweep, "MIN:MAX:COUNT pinion speeds, e.g. 100rpm:9000rpm:200");
  sp->excludes(sw);
  add_table_options(cmd, o->table);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
