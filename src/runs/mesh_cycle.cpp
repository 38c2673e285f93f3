#include "runs/mesh_cycle.hpp"

#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/mesh_deterministic.hpp"
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
  // The torque as the case gave it: itself, or an FZG load stage (whose row names the table's torque).
  const ResolvedParameter* torque = recorded(c, "operating.pinion_torque");
  const bool stage = recorded(c, "operating.fzg_load_stage") != nullptr;
  const std::string key = stage ? "operating.fzg_load_stage" : "operating.pinion_torque";
  const auto [file, line] = location_of(c, key);
  const ResolvedParameter* given = recorded(c, key);
  throw io::InputError(file, line, key, given ? given->value : "",
                       what +
                           (stage && torque ? ": lower the load stage (its torque " + torque->value + ")"
                                            : std::string(": lower the torque")) +
                           ", or check the flanks' roughness" +
                           (roughness.empty() ? std::string() : " (" + roughness + ")"));
}

std::string um(double metres) { return fmt::format("{:.4g} um", metres * 1e6); }
std::string mm(double metres) { return fmt::format("{:.4g} mm", metres * 1e3); }

// The deterministic fidelity's flanks: each gear's measured profile (its topography's line along
// the involute) or generated one, checked against the stretch of flank the run reads and the
// element size. Hunting order: a generated profile per tooth (seed + tooth); a measured one is
// every tooth's.
contact::RollingFlanks rolling_flanks(const Case& c, const contact::FlankSpan& span, const int teeth[2]) {
  contact::RollingFlanks out;
  // Running-in carries each flank point's deformation from position to position: every point must
  // pass through the strip at two positions or more (a step of at most the strip's half-length).
  const double step = std::max(span.max_step[0], span.max_step[1]);
  if (span.running_in && step > span.strip_half_length) {
    const auto [file, line] = location_of(c, "contact.positions");
    const int needed = static_cast<int>(std::ceil((span.positions - 1) * step / span.strip_half_length)) + 1;
    throw io::InputError(file, line, "contact.positions", std::to_string(span.positions),
                         fmt::format("running-in needs every flank point in the strip at two positions or more: the "
                                     "contact point moves up to {} along a flank between positions, more than the "
                                     "strip's half-length {}; use at least {} positions",
                                     mm(step), mm(span.strip_half_length), needed));
  }
  for (int g = 0; g < 2; ++g) {
    const std::string gear = g == 0 ? "pinion" : "wheel";
    const FlankSpec& flank = (g == 0 ? c.pinion : c.wheel).flank;
    auto& tracks = g == 0 ? out.pinion : out.wheel;
    const double needed = span.length(g);
    const std::string why_needed = fmt::format(
        "the contact point rolls {} along the {}'s active flank and the strip reaches {} either side",
        mm(span.active_last[g] - span.active_first[g]), gear, mm(span.strip_half_length + 2.0 * span.element_size));
    // The elements average the profile: finer elements than its spacing resolve only the
    // interpolation between its points.
    auto check_spacing = [&](double spacing, const std::string& where) {
      if (span.element_size < spacing * (1.0 - 1e-9)) {
        const auto [file, line] = location_of(c, "contact.element_size");
        throw io::InputError(file, line, "contact.element_size", um(span.element_size),
                             fmt::format("finer than the {} spacing of {} ({}): the elements would resolve the "
                                         "interpolation between its points; use elements of at least {}",
                                         um(spacing), where, gear, um(spacing)));
      }
    };
    if (flank.measured_profile) {
      const surface::FlankProfile& p = *flank.measured_profile;
      const std::string key = gear + ".flank.topography.file";
      const std::string file = flank.topography ? flank.topography->file : std::string();
      check_spacing(p.spacing, "the profile of " + file);
      if (p.length() < needed) {
        const auto [where, line] = location_of(c, key);
        throw io::InputError(where, line, key, file,
                             fmt::format("its profile along {} is {} long; the deterministic contact reads {} of it "
                                         "({}): give a trace of the whole flank (profile_axis, resample) or a "
                                         "generated [{}.flank.profile]",
                                         flank.topography && !flank.topography->profile_along_x ? "y" : "x",
                                         mm(p.length()), mm(needed), why_needed, gear));
      }
      // The trace centred on the active part (a knob that widens the strip does not move it).
      const double start = span.centred_start(g, p.length());
      if (start > span.first[g] || start + p.length() < span.last[g]) {
        const auto [where, line] = location_of(c, key);
        throw io::InputError(
            where, line, key, file,
            fmt::format("its profile along {} ({} long), centred on the {}'s active flank, does not "
                        "reach {} beyond it either side ({})",
                        flank.topography && !flank.topography->profile_along_x ? "y" : "x", mm(p.length()), gear,
                        mm(0.5 * (needed - (span.active_last[g] - span.active_first[g]))), why_needed));
      }
      for (int t = 0; t < teeth[g]; ++t) tracks.push_back({p, start});
    } else if (flank.profile) {
      check_spacing(flank.profile->spacing, gear + ".flank.profile.spacing");
      // Generated over a fixed stretch of the involute (a module either side of base circle to
      // tip): the same flank whatever the strip, elements or load.
      if (span.first[g] < span.generated_first[g] || span.last[g] > span.generated_last[g]) {
        const auto [where, line] = location_of(c, "contact.strip_halfwidths");
        throw io::InputError(where, line, "contact.strip_halfwidths", fmt::format("{:g}", c.contact.strip_halfwidths),
                             fmt::format("the strip reaches {} beyond the {}'s active flank, past the generated "
                                         "profile's end a module beyond its tip: narrow the strip",
                                         mm(span.strip_half_length), gear));
      }
      for (int t = 0; t < teeth[g]; ++t) {
        surface::GeneratedProfileSpec spec = *flank.profile;
        spec.seed += static_cast<std::uint64_t>(t);
        try {
          tracks.push_back({surface::generate_profile(spec, span.generated_last[g] - span.generated_first[g]),
                            span.generated_first[g]});
        } catch (const std::invalid_argument& e) {
          const auto [where, line] = location_of(c, gear + ".flank.profile.kind");
          throw io::InputError(where, line, gear + ".flank.profile", "", e.what());
        }
      }
    } else {
      const auto [where, line] = location_of(c, "contact.fidelity");
      throw io::InputError(where, line, gear + ".flank", "",
                           "the deterministic fidelity rolls each flank's profile: give [" + gear +
                               ".flank.profile] (generated) or [" + gear +
                               ".flank.topography] (a measured surface, its line along the involute)");
    }
  }
  return out;
}

}  // namespace

contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress) {
  const gear::GearMesh mesh(c);
  const solvers::KinsolSolver kinsol;
  const std::unique_ptr<OdeIntegrator> integrator =
      c.dynamics.engine != "none" ? solvers::make_integrator(c.dynamics.engine) : nullptr;
  contact::MeshContactResult r;
  try {
    r = contact::run_mesh_contact(
        c, mesh, c.contact.coupled() ? &kinsol : nullptr, progress, 0, integrator.get(),
        [&c](const contact::FlankSpan& span, const int teeth[2]) { return rolling_flanks(c, span, teeth); });
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
  // A run whose outputs rest on the mesh stiffness is warned, first, when it leaves ISO's band.
  const bool uses_stiffness = c.contact.mesh_stiffness || mesh.analysis().method() == gear::LoadSharing::stiffness ||
                              c.dynamics.engine != "none";
  if (uses_stiffness)
    if (std::string w = gear::iso_stiffness_warning(mesh, mesh.iso_comparison(c.mesh.positions)); !w.empty())
      r.warnings.insert(r.warnings.begin(), std::move(w));
  return r;
}

}  // namespace geartrib::runs
