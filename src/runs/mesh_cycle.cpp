#include "runs/mesh_cycle.hpp"

#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "io/input_error.hpp"
#include "solvers/integrators.hpp"
#include "solvers/kinsol_solver.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace geartrib::runs {

namespace {

const ResolvedParameter* recorded(const Case& c, const std::string& key) {
  for (const auto& p : c.parameters)
    if (p.key == key) return &p;
  return nullptr;
}

// "file:line" into its parts; {origin, 0} for anything else ("--set", "default").
std::pair<std::string, int> split_origin(const std::string& origin) {
  const auto colon = origin.rfind(':');
  if (colon == std::string::npos || colon + 1 == origin.size()) return {origin, 0};
  int line = 0;
  for (std::size_t i = colon + 1; i < origin.size(); ++i) {
    if (origin[i] < '0' || origin[i] > '9') return {origin, 0};
    line = line * 10 + (origin[i] - '0');
  }
  return {origin.substr(0, colon), line};
}

// The case file, from the origin of its required title (or any key read from a file).
std::string case_file_of(const Case& c) {
  if (const auto* t = recorded(c, "title"); t && split_origin(t->origin).second > 0)
    return split_origin(t->origin).first;
  for (const auto& p : c.parameters)
    if (split_origin(p.origin).second > 0) return split_origin(p.origin).first;
  return "the case";
}

// Where a key's value came from, for a located error: its file and line, or the case file and the --set.
std::pair<std::string, int> location_of(const Case& c, const std::string& key) {
  const ResolvedParameter* p = recorded(c, key);
  if (!p) return {case_file_of(c), 0};
  const auto [file, line] = split_origin(p->origin);
  if (line > 0) return {file, line};
  return {case_file_of(c) + " (" + p->origin + " " + key + "=" + p->value + ")", 0};
}

// The load the flanks cannot carry at any separation (the rough-surface table's search gives up):
// an input error at the torque, naming the flanks' roughness and where each came from.
[[noreturn]] void throw_overload(const Case& c, const std::string& what) {
  std::string roughness;
  for (const auto& p : c.parameters) {
    const bool flank = p.key.rfind("pinion.flank.", 0) == 0 || p.key.rfind("wheel.flank.", 0) == 0;
    const bool ra_or_rq = c.pinion.flank.roughness.form == surface::FlankRoughness::Form::ra ||
                          c.pinion.flank.roughness.form == surface::FlankRoughness::Form::rq;
    if (p.key == "roughness.eta_sigma_beta" && ra_or_rq)
      roughness += fmt::format("{}{} = {} ({})", roughness.empty() ? "" : ", ", p.key, p.value, p.origin);
    if (!flank) continue;
    const std::string leaf = p.key.substr(p.key.find(".flank.") + 7);
    if (leaf != "ra" && leaf != "rq" && leaf != "summit_sigma" && leaf != "summit_density" && leaf != "m0" &&
        leaf != "summit_radius" && leaf != "topography.file")
      continue;
    roughness += fmt::format("{}{} = {} ({})", roughness.empty() ? "" : ", ", p.key, p.value, p.origin);
  }
  const std::string key = "operating.pinion_torque";
  const auto [file, line] = location_of(c, key);
  const ResolvedParameter* torque = recorded(c, key);
  throw io::InputError(file, line, key, torque ? torque->value : "",
                       what + ": lower the torque, or check the flanks' roughness" +
                           (roughness.empty() ? std::string() : " (" + roughness + ")"));
}

}  // namespace

contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress) {
  const gear::GearMesh mesh(c);
  const solvers::KinsolSolver kinsol;
  const std::unique_ptr<OdeIntegrator> integrator =
      c.dynamics.engine != "none" ? solvers::make_integrator(c.dynamics.engine) : nullptr;
  contact::MeshContactResult r;
  try {
    r = contact::run_mesh_contact(c, mesh, c.contact.coupled ? &kinsol : nullptr, progress, 0, integrator.get());
  } catch (const contact::RoughSurfaceOverload& e) {
    throw_overload(c, e.what());  // at the torque, naming the roughness and where each came from
  } catch (const std::invalid_argument& e) {
    // The case's values are what the physics refused: name the case file rather than leave the
    // message without a place.
    throw io::InputError(case_file_of(c), 0, "", "", e.what());
  }
  for (const auto* group : {&r.mesh, &r.contact})
    for (const auto& q : *group)
      for (double v : q.values)
        if (!std::isfinite(v)) throw std::runtime_error("non-finite value in " + q.name);
  return r;
}

}  // namespace geartrib::runs
