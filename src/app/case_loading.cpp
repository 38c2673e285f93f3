#include "app/commands.hpp"

#include "gear/gear_mesh.hpp"
#include "io/case_file.hpp"
#include "solvers/integrators.hpp"
#include "solvers/kinsol_solver.hpp"

#include <cmath>
#include <memory>

#include <iostream>

namespace geartrib::app {

void add_table_options(CLI::App* cmd, bool& csv, std::string& output) {
  cmd->add_flag("--csv", csv, "CSV with a header instead of aligned columns");
  cmd->add_option("-o,--output", output, "Write the table to this file (atomically) instead of stdout");
}

double quantity_option(const std::string& option, const std::string& text, io::Dimension d) {
  try {
    return io::parse_quantity(text, d);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(option + " '" + text + "': " + e.what());
  }
}

std::filesystem::path default_case_file() {
  const std::filesystem::path local = "gears/m6z30.toml";
  if (std::filesystem::exists(local)) return local;
  return std::filesystem::path(GEARTRIB_SOURCE_DIR) / local;
}

Case load_case_reporting(const std::string& file, const std::vector<std::string>& changes) {
  std::vector<io::CaseChange> parsed;
  for (const auto& text : changes) parsed.push_back(io::parse_case_change(text));
  Case c = io::load_case(file.empty() ? default_case_file() : std::filesystem::path(file), parsed);
  for (const auto& w : c.warnings) std::cerr << w << '\n';
  return c;
}

contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress, int positions) {
  const gear::GearMesh mesh(c);
  const solvers::KinsolSolver kinsol;
  const std::unique_ptr<OdeIntegrator> integrator =
      c.dynamics.engine != "none" ? solvers::make_integrator(c.dynamics.engine) : nullptr;
  contact::MeshContactResult r =
      contact::run_mesh_contact(c, mesh, c.contact.coupled ? &kinsol : nullptr, progress, positions, integrator.get());
  for (const auto* group : {&r.mesh, &r.contact})
    for (const auto& q : *group)
      for (double v : q.values)
        if (!std::isfinite(v)) throw std::runtime_error("non-finite value in " + q.name);
  return r;
}

}  // namespace geartrib::app
