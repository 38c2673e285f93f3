#include "app/case_loading.hpp"

#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "io/case_file.hpp"
#include "solvers/integrators.hpp"
#include "solvers/kinsol_solver.hpp"

#include <cmath>
#include <iostream>
#include <memory>

namespace geartrib::app {

std::filesystem::path default_case_file() {
  std::filesystem::path local = "gears/m6z30.toml";  // not const: returned by move
  if (std::filesystem::exists(local)) return local;
  // An installed tool: <prefix>/bin/geartrib with its data in <prefix>/share/geartrib.
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    std::filesystem::path installed = exe.parent_path().parent_path() / "share/geartrib" / local;
    if (std::filesystem::exists(installed)) return installed;
  }
  return std::filesystem::path(GEARTRIB_SOURCE_DIR) / local;
}

std::filesystem::path case_path(const CaseOptions& o) {
  return o.file.empty() ? default_case_file() : std::filesystem::path(o.file);
}

std::vector<io::CaseChange> case_changes(const CaseOptions& o) {
  std::vector<io::CaseChange> parsed;
  parsed.reserve(o.changes.size());
  for (const auto& text : o.changes) parsed.push_back(io::parse_case_change(text));
  return parsed;
}

Case load_case_reporting(const CaseOptions& o, unsigned parts) {
  Case c = io::load_case(case_path(o), case_changes(o), parts);
  for (const auto& w : c.warnings) std::cerr << w << '\n';
  return c;
}

contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress) {
  const gear::GearMesh mesh(c);
  const solvers::KinsolSolver kinsol;
  const std::unique_ptr<OdeIntegrator> integrator =
      c.dynamics.engine != "none" ? solvers::make_integrator(c.dynamics.engine) : nullptr;
  contact::MeshContactResult r =
      contact::run_mesh_contact(c, mesh, c.contact.coupled ? &kinsol : nullptr, progress, 0, integrator.get());
  for (const auto* group : {&r.mesh, &r.contact})
    for (const auto& q : *group)
      for (double v : q.values)
        if (!std::isfinite(v)) throw std::runtime_error("non-finite value in " + q.name);
  return r;
}

}  // namespace geartrib::app
