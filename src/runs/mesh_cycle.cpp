#include "runs/mesh_cycle.hpp"

#include "contact/areal/mesh_areal.hpp"

#include "case/asperity_setup.hpp"
#include "case/gear_setup.hpp"
#include "config/case_parameters.hpp"
#include "config/case_records.hpp"
#include "config/input_error.hpp"
#include "config/resource_budget.hpp"
#include "contact/deterministic/mesh_deterministic.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/position_threads.hpp"
#include "contact/run_summary.hpp"
#include "core/fftw_planner.hpp"
#include "core/keyed_error.hpp"
#include "core/stopwatch.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"
#include "runs/case_rating.hpp"
#include "solvers/integrators.hpp"
#include "solvers/kinsol_solver.hpp"
#include "surface/areal_synthesis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

namespace geartrib::runs {

namespace {

// The components' own rules on the Case as it holds them now (the loader checked them; a Case
// changed in code may break one): a refusal at the key of the field it names, before any work.
void check_component_rules(const Case& c) {
  const auto check = [&](const std::string& prefix, const auto& component) {
    try {
      component.validate();
    } catch (const core::KeyedError& e) {
      throw io::refusal_error(c, e, prefix);
    }
  };
  check("lubrication.", c.lubrication);
  check("mesh.", c.mesh);
  check("roughness.", c.roughness);
  check("dynamics.", c.dynamics);
  check("asperity.", c.asperity);
  check("contact.", c.contact);
  check("rating.settings.", c.rating.settings);
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
      roughness += fmt::format("{}{} = {} ({})", roughness.empty() ? "" : ", ", p.key, p.value, p.origin.text());
    if (!flank) continue;
    const std::string leaf = p.key.substr(p.key.find(".flank.") + 7);
    if (leaf != "ra" && leaf != "rq" && leaf != "summit_sigma" && leaf != "summit_density" && leaf != "m0" &&
        leaf != "summit_radius" && leaf != "topography.file")
      continue;
    roughness += fmt::format("{}{} = {} ({})", roughness.empty() ? "" : ", ", p.key, p.value, p.origin.text());
  }
  // The torque as the case gave it: itself, or an FZG load stage (whose row names the table's torque).
  const ResolvedParameter* torque = io::find_record(c, "operating.pinion_torque");
  const bool stage = io::find_record(c, "operating.fzg_load_stage") != nullptr;
  const std::string key = stage ? "operating.fzg_load_stage" : "operating.pinion_torque";
  throw io::located_error(c, key,
                          what +
                              (stage && torque ? ": lower the load stage (its torque " + torque->value + ")"
                                               : std::string(": lower the torque")) +
                              ", or check the flanks' roughness" +
                              (roughness.empty() ? std::string() : " (" + roughness + ")"));
}

// A synthesised flank that leaves out more than this share of its patch's variance is warned about.
constexpr double kRolledOffWarning = 0.5;

std::string um(double metres) { return fmt::format("{:.4g} um", metres * 1e6); }
std::string mm(double metres) { return fmt::format("{:.4g} mm", metres * 1e3); }

// The largest Hertz half-width of one pair over n evenly spaced positions A -> E, as the mesh cycle
// computes them (contact/mesh_contact.cpp, stage 1): from the quasi-static share, or with dynamics
// from the steady cycle's pair force (integrated once, when first asked for).
class PathHalfWidths {
 public:
  PathHalfWidths(const Case& c, const gear::GearMesh& mesh, const OdeIntegrator* dynamics)
      : c_(c), mesh_(mesh), dynamics_(dynamics) {}
  double largest(long n) {
    if (dynamics_ && !cycle_) {
      dyn_ = std::make_unique<gear::MeshDynamics>(mesh_, gear::dynamics_settings(c_));
      cycle_ = std::make_unique<gear::SteadyCycle>(dyn_->steady_cycle(*dynamics_, mesh_.pinion_speed()));
    }
    const auto& path = mesh_.pair().path();
    const auto stiffness = mesh_.analysis().method() == gear::LoadSharing::stiffness
                               ? gear::MeshAnalysis::PairStiffness::computed
                               : gear::MeshAnalysis::PairStiffness::omitted;
    double b = 0.0;
    for (long i = 0; i < n; ++i) {
      const double s = path.a + path.length * static_cast<double>(i) / static_cast<double>(n - 1);
      const double half_width = cycle_
                                    ? mesh_.analysis()
                                          .pair_load(s, dyn_->pair_force(*cycle_, s) / mesh_.pair().spec().face_width)
                                          .hertz_half_width
                                    : mesh_.analysis().at(s, false, stiffness).pair_at(s).hertz_half_width;
      b = std::max(b, half_width);
    }
    return b;
  }

 private:
  const Case& c_;
  const gear::GearMesh& mesh_;
  const OdeIntegrator* dynamics_;
  std::unique_ptr<gear::MeshDynamics> dyn_;
  std::unique_ptr<gear::SteadyCycle> cycle_;
};

// The contact point's largest move along a flank between n evenly spaced positions. Along the
// path each flank's radius of curvature rho is linear, and with it sqrt(sigma) = rho/sqrt(2 r_b):
// from a = sqrt(sigma_near) to b = sqrt(sigma_far) the largest move is the last one,
// b^2 - (b - (b - a)/(n - 1))^2 (what run_deterministic samples at the positions it runs).
double largest_flank_step(const contact::FlankSpan& span, long n) {
  double step = 0.0;
  for (int g = 0; g < 2; ++g) {
    const double a = std::sqrt(std::max(0.0, span.active_first[g])), b = std::sqrt(span.active_last[g]);
    const double last = b - (b - a) / static_cast<double>(n - 1);
    step = std::max(step, b * b - last * last);
  }
  return step;
}

// Positions running-in takes, above the case's, or most + 1 when none up to `most` does: the
// largest flank step within the strip's half-length, which is strip_halfwidths times the largest
// Hertz half-width at those positions. That half-width depends on where the positions fall on the
// load (a coarse sampling can miss the single pair's zone), so each number is checked at its own,
// from the first within reach of even the path's largest half-width (sampled finely): the fewest
// that hold. A search past kMaxCandidates numbers (a load peak the positions keep missing) ends
// at the fewest that hold whatever they sample: every number samples A and E (n = 2), so the half-
// width there bounds the strip from below.
long running_in_positions(const Case& c, const contact::FlankSpan& span, PathHalfWidths& half_widths, long most) {
  constexpr long kMaxCandidates = 1000;
  const double k = c.contact.boundary_elements.strip_halfwidths;
  auto fewest_within = [&](double strip, long from) {  // step(n) falls with n
    long n = from;
    while (n <= most && largest_flank_step(span, n) > strip) n = std::min(most + 1, std::max(n + 1, n + n / 20));
    while (n > from && largest_flank_step(span, n - 1) <= strip) --n;  // back from the 5% strides
    return n;
  };
  long n =
      fewest_within(k * std::max(half_widths.largest(std::max<long>(span.positions, 4097)), span.strip_half_length / k),
                    span.positions + 1);
  for (const long last = n + kMaxCandidates; n <= most && n < last; ++n)
    if (largest_flank_step(span, n) <= k * half_widths.largest(n)) return n;
  return n > most ? most + 1 : fewest_within(k * half_widths.largest(2), n);
}

// The spacing of the profile a flank rolls, as rolling_flanks takes it (0: none).
double profile_spacing(const surface::FlankSpec& flank) {
  const surface::TopographySpec* topo = flank.topography ? &*flank.topography : nullptr;
  if (topo && topo->synthesis != surface::SynthesisMethod::none)
    return flank.patch_spectrum ? flank.patch_spectrum->spacing : 0.0;
  if (flank.measured_profile) return flank.measured_profile->spacing;
  if (flank.profile) return flank.profile->spacing;
  return 0.0;
}

// Running-in carries each flank point's deformation from position to position: every point must
// pass through the strip at two positions or more (a step of at most the strip's half-length).
void check_running_in_step(const Case& c, const contact::FlankSpan& span, PathHalfWidths& half_widths) {
  const double step = std::max(span.max_step[0], span.max_step[1]);
  if (!span.running_in || step <= span.strip_half_length) return;
  const long most = static_cast<long>(io::find_parameter("contact.positions").parameter->max);
  const long needed = running_in_positions(c, span, half_widths, most);
  throw io::located_error(
      c, "contact.positions", std::to_string(span.positions),
      fmt::format("running-in needs every flank point in the strip at two positions or more: the "
                  "contact point moves up to {} along a flank between positions, more than the "
                  "strip's half-length {}; {}",
                  mm(step), mm(span.strip_half_length),
                  needed <= most ? fmt::format("use {} positions (checked at the Hertz "
                                               "half-widths they sample: the strip follows the "
                                               "largest, so another number may fall short)",
                                               needed)
                                 : fmt::format("no number of positions within the key's range (up to {}) "
                                               "does: run without running-in (running_in.meshes = "
                                               "0)",
                                               most)));
}

// One gear's flank as a rolling fidelity reads it: the stretch it needs and why.
struct FlankRead {
  const Case& c;
  const contact::FlankSpan& span;
  int g = 0;
  int teeth = 1;
  std::string gear;
  const surface::FlankSpec& flank;
  double needed = 0.0;
  std::string why_needed;
  bool grid() const { return span.reader == contact::FlankSpan::Reader::grid; }
  // What reads the flank, for the messages.
  const char* reader() const { return grid() ? "mixed-EHL contact" : "deterministic contact"; }
};

// The elements average the profile: finer elements than its spacing resolve only the
// interpolation between its points.
// The mixed-EHL grid samples it at its nodes: a grid coarser than its spacing would skip its points
// (0: the automatic grid, which the fidelity keeps at most at the profiles' spacing).
void check_spacing(const FlankRead& f, double spacing, const std::string& where) {
  if (f.grid()) {
    if (f.span.element_size <= spacing * (1.0 + 1e-9)) return;
    throw io::located_error(f.c, "mixed_ehl.grid_spacing", um(f.span.element_size),
                            fmt::format("coarser than the {} spacing of {} ({}): the nodes would skip the profile's "
                                        "points between them; use a spacing of at most {} (or 0: automatic)",
                                        um(spacing), where, f.gear, um(spacing)));
  }
  if (f.span.element_size >= spacing * (1.0 - 1e-9)) return;
  throw io::located_error(f.c, "contact.element_size", um(f.span.element_size),
                          fmt::format("finer than the {} spacing of {} ({}): the elements would resolve the "
                                      "interpolation between its points; use elements of at least {}",
                                      um(spacing), where, f.gear, um(spacing)));
}

// The generated stretch (a module below the base circle to a module beyond the tip) must hold the
// strip's reach.
void check_generated_stretch(const FlankRead& f, const std::string& what) {
  const contact::FlankSpan& span = f.span;
  if (span.first[f.g] >= span.generated_first[f.g] && span.last[f.g] <= span.generated_last[f.g]) return;
  if (f.grid())
    throw io::located_error(
        f.c, "mixed_ehl.window", fmt::format("{:g}", f.c.contact.mixed_ehl.window),
        fmt::format("the grid and the windows reach {} before and {} beyond the {}'s active flank, past the {}'s ends "
                    "(a module below the base circle and beyond the tip): a shorter window, or a shorter domain "
                    "(mixed_ehl.inlet, mixed_ehl.outlet)",
                    mm(span.active_first[f.g] - span.first[f.g]), mm(span.last[f.g] - span.active_last[f.g]), f.gear,
                    what));
  throw io::located_error(f.c, "contact.strip_halfwidths",
                          fmt::format("{:g}", f.c.contact.boundary_elements.strip_halfwidths),
                          fmt::format("the strip reaches {} beyond the {}'s active flank, past the {}'s end a "
                                      "module beyond its tip: narrow the strip",
                                      mm(span.strip_half_length), f.gear, what));
}

// What a synthesis came from, before its teeth are made.
contact::FlankSynthesis synthesis_record(const FlankRead& f) {
  const surface::TopographySpec& topo = *f.flank.topography;
  const surface::ProfileSpectrum& patch = *f.flank.patch_spectrum;
  contact::FlankSynthesis record;
  record.gear = f.gear, record.patch = topo.file, record.method = surface::synthesis_method_name(topo.synthesis);
  record.seed = static_cast<double>(topo.synthesis_seed), record.teeth = f.teeth;
  record.patch_lines = static_cast<double>(patch.lines), record.patch_points = static_cast<double>(patch.points);
  record.patch_spacing = patch.spacing, record.patch_rq = patch.rq();
  record.rolled_off_fraction = patch.rolled_off_fraction();
  return record;
}

// A flank-long profile synthesised from the patch's spectrum: over the generated stretch, or the
// given length centred on the active part.
void synthesised_tracks(const FlankRead& f, std::vector<contact::FlankTrack>& tracks,
                        std::vector<contact::FlankSynthesis>& synthesis) {
  const contact::FlankSpan& span = f.span;
  const int g = f.g;
  const surface::TopographySpec& topo = *f.flank.topography;
  if (!f.flank.patch_spectrum) throw std::logic_error(f.gear + ": a synthesis asked for without the patch's spectrum");
  const std::string t = f.gear + ".flank.topography.";
  check_spacing(f, profile_spacing(f.flank), "the profile synthesised from " + topo.file);
  const bool given = topo.synthesis_length > 0.0;
  const double length = given ? topo.synthesis_length : span.generated_last[g] - span.generated_first[g];
  if (!given) check_generated_stretch(f, "synthesised profile");
  contact::FlankSynthesis record = synthesis_record(f);
  for (int tooth = 0; tooth < f.teeth; ++tooth) {
    surface::SynthesisOptions options;
    options.method = topo.synthesis;
    options.seed = topo.synthesis_seed + static_cast<std::uint64_t>(tooth);
    surface::SynthesisedProfile s;
    try {
      s = surface::synthesise_profile(*f.flank.patch_spectrum, options, length);
    } catch (const std::invalid_argument& e) {
      throw io::located_error(f.c, t + (given ? "synthesis_length" : "synthesis"), e.what());
    }
    const double start = given ? span.centred_start(g, s.profile.length()) : span.generated_first[g];
    if (given && (start > span.first[g] || start + s.profile.length() < span.last[g])) {
      throw io::located_error(f.c, t + "synthesis_length", mm(topo.synthesis_length),
                              fmt::format("the synthesised profile, centred on the {}'s active flank, must cover the "
                                          "{} the {} reads ({}); give at least that, or 0 (a "
                                          "module below the base circle to a module beyond the tip)",
                                          f.gear, mm(f.needed), f.reader(), f.why_needed));
    }
    if (tooth == 0) {
      record.profile_length = s.profile.length();
      record.profile_rq = surface::profile_statistics(s.profile.z, s.profile.spacing).rq;
    }
    record.iterations = std::max(record.iterations, s.iterations);
    record.spectrum_misfit = std::max(record.spectrum_misfit, s.spectrum_misfit);
    if (std::abs(s.curvature_ratio - 1.0) > std::abs(record.curvature_ratio - 1.0))
      record.curvature_ratio = s.curvature_ratio;
    record.converged = record.converged && s.converged;
    tracks.push_back({std::move(s.profile), start});
  }
  synthesis.push_back(std::move(record));
}

// The topography's line along the involute, centred on the active part (a knob that widens the
// strip does not move it); every tooth's.
void measured_tracks(const FlankRead& f, std::vector<contact::FlankTrack>& tracks) {
  const contact::FlankSpan& span = f.span;
  const int g = f.g;
  const surface::FlankProfile& p = *f.flank.measured_profile;
  const std::string key = f.gear + ".flank.topography.file";
  const std::string file = f.flank.topography ? f.flank.topography->file : std::string();
  const char* axis = f.flank.topography && !f.flank.topography->profile_along_x ? "y" : "x";
  check_spacing(f, profile_spacing(f.flank), "the profile of " + file);
  if (p.length() < f.needed) {
    throw io::located_error(f.c, key, file,
                            fmt::format("its profile along {} is {} long; the {} reads {} of it "
                                        "({}): give a trace of the whole flank (profile_axis, resample), "
                                        "synthesise one from its spectrum (synthesis = \"psd\" or \"iaaft\" in "
                                        "[{}.flank.topography]) or give a generated [{}.flank.profile]",
                                        axis, mm(p.length()), f.reader(), mm(f.needed), f.why_needed, f.gear, f.gear));
  }
  const double start = span.centred_start(g, p.length());
  if (start > span.first[g] || start + p.length() < span.last[g]) {
    throw io::located_error(
        f.c, key, file,
        fmt::format("its profile along {} ({} long), centred on the {}'s active flank, does not "
                    "reach {} beyond it either side ({})",
                    axis, mm(p.length()), f.gear, mm(0.5 * (f.needed - (span.active_last[g] - span.active_first[g]))),
                    f.why_needed));
  }
  for (int t = 0; t < f.teeth; ++t) tracks.push_back({p, start});
}

// Generated over a fixed stretch of the involute (a module either side of base circle to tip):
// the same flank whatever the strip, elements or load; tooth t with seed + t.
void generated_tracks(const FlankRead& f, std::vector<contact::FlankTrack>& tracks) {
  const contact::FlankSpan& span = f.span;
  const int g = f.g;
  check_spacing(f, profile_spacing(f.flank), f.gear + ".flank.profile.spacing");
  check_generated_stretch(f, "generated profile");
  for (int t = 0; t < f.teeth; ++t) {
    surface::GeneratedProfileSpec spec = *f.flank.profile;
    spec.seed += static_cast<std::uint64_t>(t);
    try {
      tracks.push_back(
          {surface::generate_profile(spec, span.generated_last[g] - span.generated_first[g]), span.generated_first[g]});
    } catch (const core::KeyedError& e) {
      throw io::located_error(f.c, f.gear + ".flank.profile." + e.key(), e.what());
    } catch (const std::invalid_argument& e) {
      const auto [where, line] = io::location_of(f.c, f.gear + ".flank.profile.kind");
      throw io::InputError(where, line, f.gear + ".flank.profile", "", e.what());
    }
  }
}

// The areal fidelity's patch lay: each tooth's map of the flank from the measured patch, synthesised
// from its areal spectrum (seed + tooth) or tiled, over the span at the elements' spacing along the
// involute and areal.window across the face; its track, the map's middle row.
void patch_maps(const FlankRead& f, std::vector<contact::FlankTrack>& tracks, std::vector<contact::FlankMap>& maps,
                std::vector<contact::FlankSynthesis>& synthesis) {
  const contact::FlankSpan& span = f.span;
  const contact::areal::ArealMeshOptions& o = f.c.contact.areal;
  const surface::TopographySpec& topo = *f.flank.topography;
  const std::string t = f.gear + ".flank.topography.";
  if (!f.flank.patch) throw std::logic_error(f.gear + ": the patch lay asked for without the measured surface");
  // The patch with its axis along the involute as x.
  surface::HeightGrid patch = *f.flank.patch;
  if (!topo.profile_along_x) {
    surface::HeightGrid turned = surface::make_grid(patch.ny, patch.nx, patch.dy, patch.dx);
    for (int j = 0; j < patch.ny; ++j)
      for (int i = 0; i < patch.nx; ++i) {
        turned.at(j, i) = patch.at(i, j);
        turned.valid[static_cast<std::size_t>(i) * patch.ny + j] = patch.ok(i, j) ? 1 : 0;
      }
    patch = std::move(turned);
  }
  if (patch.missing() > 0)
    throw io::located_error(f.c, t + "fill", "false",
                            fmt::format("{} has {} missing points; a patch's areal spectrum or tiling needs every "
                                        "point: fill = true",
                                        topo.file, patch.missing()));
  const double dx = span.element_size, dy = o.spacing();
  const char* along = topo.profile_along_x ? "x" : "y";
  const char* across = topo.profile_along_x ? "y" : "x";
  if (dx < patch.dx * (1.0 - 1e-9))
    throw io::located_error(f.c, "contact.element_size", um(dx),
                            fmt::format("finer than the spacing along {} of {} ({}): the patch holds no detail that "
                                        "fine; use elements of at least {}",
                                        along, topo.file, um(patch.dx), um(patch.dx)));
  if (dy < patch.dy * (1.0 - 1e-9))
    throw io::located_error(f.c, "areal.points", std::to_string(o.points),
                            fmt::format("{} points over {} across the face are {} apart, finer than the spacing along "
                                        "{} of {} ({}): at most {} points",
                                        o.points, um(o.window), um(dy), across, topo.file, um(patch.dy),
                                        static_cast<int>(std::floor(o.window / patch.dy * (1.0 + 1e-9)))));
  surface::ArealSpectrum spectrum;
  try {
    spectrum = surface::areal_spectrum(patch);
  } catch (const std::invalid_argument& e) {
    throw io::located_error(f.c, t + "file", topo.file, e.what());
  }
  // A patch shorter than one of its own hills (the mean spacing of the profile elements, RSm) holds
  // no contact spot whole: nothing to synthesise or tile from.
  for (const bool x : {true, false}) {
    const double rsm = spectrum.element_spacing(x), side = x ? spectrum.length_x() : spectrum.length_y();
    if (side < rsm)
      throw io::located_error(
          f.c, t + "file", topo.file,
          fmt::format("the patch is {} long along {}, shorter than one spot: the mean spacing of its profile "
                      "elements there, RSm = 2 pi sqrt(m0/m2), is {}; measure a larger patch (several RSm each way)",
                      um(side), x == topo.profile_along_x ? "x" : "y", um(rsm)));
  }
  const int g = f.g;
  const double start = span.first[g] - dx;
  const bool tiled = o.patch == contact::areal::ArealPatch::tiled;
  contact::FlankSynthesis record;  // what the maps came from, as a profile synthesis is recorded
  record.gear = f.gear, record.patch = topo.file, record.method = tiled ? "areal-tiled" : "areal-synthesis";
  record.seed = static_cast<double>(topo.synthesis_seed), record.teeth = f.teeth;
  record.patch_lines = patch.ny, record.patch_points = patch.nx, record.patch_spacing = patch.dx;
  record.patch_rq = spectrum.patch_rq;
  const int nx = static_cast<int>(std::ceil(span.length(g) / dx)) + 3, ny = o.points;
  for (int tooth = 0; tooth < f.teeth; ++tooth) {
    contact::FlankMap m;
    m.nx = nx, m.ny = ny, m.start = start, m.dx = dx, m.dy = dy;
    try {
      if (tiled) {
        // Tooth t starts a patch's length further along its mirror images.
        m.z = surface::tile_surface(patch, nx, ny, dx, dy, tooth * spectrum.length_x()).z;
      } else {
        // Periodic along the involute over an FFT-friendly length, cut to the map's.
        const int mx = static_cast<int>(fast_fft_size(static_cast<std::size_t>(nx)));
        const surface::SynthesisedSurface full = surface::synthesise_surface(
            spectrum, mx, ny, dx, dy, topo.synthesis_seed + static_cast<std::uint64_t>(tooth));
        if (tooth == 0) record.rolled_off_fraction = 1.0 - full.resolved_fraction;
        m.z.resize(static_cast<std::size_t>(nx) * ny);
        for (int j = 0; j < ny; ++j)
          std::copy_n(&full.grid.z[static_cast<std::size_t>(j) * mx], nx, &m.z[static_cast<std::size_t>(j) * nx]);
      }
    } catch (const std::invalid_argument& e) {
      throw io::located_error(f.c, "areal.patch",
                              std::string(choice_name(contact::areal::areal_patch_choices(), o.patch)),
                              fmt::format("{}: {}", topo.file, e.what()));
    }
    surface::FlankProfile row{dx, std::vector<double>(&m.z[static_cast<std::size_t>(ny / 2) * nx],
                                                      &m.z[static_cast<std::size_t>(ny / 2) * nx] + nx)};
    tracks.push_back({std::move(row), start});
    if (tooth == 0) {
      double ms = 0.0;
      for (double z : m.z) ms += z * z;
      record.profile_length = (nx - 1) * dx, record.profile_rq = std::sqrt(ms / static_cast<double>(m.z.size()));
    }
    maps.push_back(std::move(m));
  }
  synthesis.push_back(std::move(record));
}

// A rolling fidelity's flanks (deterministic, mixed EHL): each gear's measured profile (its
// topography's line along the involute), one synthesised from the topography's spectrum, or a
// generated one, checked against the stretch of flank the run reads and the element size (the
// mixed-EHL grid's spacing). Hunting order: a generated or synthesised
// profile per tooth (seed + tooth); a measured one is every tooth's. `synthesis`: what each
// synthesised flank came from; `half_widths`: the path's, for the advice on positions.
contact::RollingFlanks rolling_flanks(const Case& c, const contact::FlankSpan& span, const int teeth[2],
                                      std::vector<contact::FlankSynthesis>& synthesis, PathHalfWidths& half_widths) {
  contact::RollingFlanks out;
  check_running_in_step(c, span, half_widths);
  for (int g = 0; g < 2; ++g) {
    const std::string gear = g == 0 ? "pinion" : "wheel";
    const std::string rolls = mm(span.active_last[g] - span.active_first[g]);
    const FlankRead f{
        c,
        span,
        g,
        teeth[g],
        gear,
        (g == 0 ? c.pinion : c.wheel).flank,
        span.length(g),
        span.reader == contact::FlankSpan::Reader::grid
            ? fmt::format(
                  "the contact point rolls {} along the {}'s active flank and the grid and the windows reach {} "
                  "before it and {} beyond",
                  rolls, gear, mm(span.active_first[g] - span.first[g]), mm(span.last[g] - span.active_last[g]))
            : fmt::format("the contact point rolls {} along the {}'s active flank and the strip reaches {} either side",
                          rolls, gear, mm(span.strip_half_length + 2.0 * span.element_size))};
    auto& tracks = g == 0 ? out.pinion : out.wheel;
    const surface::TopographySpec* topo = f.flank.topography ? &*f.flank.topography : nullptr;
    if (span.reader == contact::FlankSpan::Reader::areal && c.contact.areal.lay == contact::areal::ArealLay::patch) {
      if (!topo || !f.flank.patch) {
        const auto [where, line] = io::location_of(c, "areal.lay");
        throw io::InputError(where, line, "areal.lay", "patch",
                             fmt::format("the patch lay makes each flank's map from its measured topography: give "
                                         "[{}.flank.topography] an areal surface (not a profile trace)",
                                         gear));
      }
      patch_maps(f, tracks, g == 0 ? out.pinion_maps : out.wheel_maps, synthesis);
    } else if (topo && topo->synthesis != surface::SynthesisMethod::none) {
      synthesised_tracks(f, tracks, synthesis);
    } else if (f.flank.measured_profile) {
      measured_tracks(f, tracks);
    } else if (f.flank.profile) {
      generated_tracks(f, tracks);
    } else {
      const auto [where, line] = io::location_of(c, "contact.fidelity");
      throw io::InputError(
          where, line, gear + ".flank", "",
          fmt::format("the {} fidelity rolls each flank's profile: give [{}.flank.profile] (generated) "
                      "or [{}.flank.topography] (a measured surface, its line along the involute)",
                      c.contact.fidelity.name(), gear, gear));
    }
  }
  return out;
}

// The points of one flank profile of gear g as rolling_flanks will make or take it.
double flank_points(const Case& c, const contact::FlankSpan& span, int g) {
  const surface::FlankSpec& flank = (g == 0 ? c.pinion : c.wheel).flank;
  const double generated = span.generated_last[g] - span.generated_first[g];
  const surface::TopographySpec* topo = flank.topography ? &*flank.topography : nullptr;
  if (topo && topo->synthesis != surface::SynthesisMethod::none && flank.patch_spectrum)
    return (topo->synthesis_length > 0.0 ? topo->synthesis_length : generated) / flank.patch_spectrum->spacing + 1.0;
  if (flank.measured_profile) return static_cast<double>(flank.measured_profile->z.size());
  if (flank.profile) return generated / flank.profile->spacing + 1.0;
  return 0.0;
}

// A deterministic run's memory and time from its sizes (contact::deterministic_cost) against the
// budget (io::resource_budget), before any flank is made or strip solved: refused at the key that
// sets the largest part, with the estimate and what fits.
// The memory budget exceeded: refused at the key of the largest part.
void refuse_memory(const Case& c, const contact::FlankSpan& span, const int teeth[2],
                   const contact::DeterministicWork& w, const contact::DeterministicCost& cost,
                   const io::ResourceBudget& budget) {
  const std::string what = fmt::format(
      "the run would hold about {} (flanks {}: {} profiles of {:.3g} and {} of {:.3g} points; pressure profiles "
      "{}: {} of {} elements; strip solvers {} on {} threads; per-position results {}), more than the memory "
      "budget of {} ({})",
      io::format_bytes(cost.bytes()), io::format_bytes(cost.flank_bytes), teeth[0], w.flank_points[0], teeth[1],
      w.flank_points[1], io::format_bytes(cost.profile_bytes), w.kept_profiles, span.elements,
      io::format_bytes(cost.solver_bytes), w.threads, io::format_bytes(cost.position_bytes),
      io::format_bytes(budget.bytes), io::kMemoryBudgetVariable);
  const double largest = std::max({cost.flank_bytes, cost.profile_bytes, cost.solver_bytes, cost.position_bytes});
  const std::string raise = ", or raise the budget";
  auto refuse = [&](const std::string& key, const std::string& value, const std::string& rule) {
    throw io::located_error(c, key, value, rule);
  };
  if (largest == cost.profile_bytes)
    refuse("contact.pressure_profiles", io::recorded_value(c, "contact.pressure_profiles", "all"),
           what +
               ": keep the profiles at the named points (\"points\") or none, or fewer positions "
               "(contact.positions)" +
               raise);
  if (largest == cost.solver_bytes)
    refuse("contact.threads", std::to_string(w.threads),
           what + ": fewer threads, or coarser elements (contact.element_size)" + raise);
  if (largest == cost.flank_bytes && (teeth[0] > 1 || teeth[1] > 1))
    refuse("running_in.teeth", io::recorded_value(c, "running_in.teeth", "hunting"),
           what +
               ": the hunting order holds every tooth's flank; run the pair (running_in.teeth = \"pair\") or "
               "give the flanks a coarser profile spacing" +
               raise);
  if (largest == cost.flank_bytes) {  // one pair's flanks: the longer profile's own key
    const int g = w.flank_points[1] > w.flank_points[0] ? 1 : 0;
    const std::string gear = g == 0 ? "pinion" : "wheel";
    const std::string key =
        (g == 0 ? c.pinion : c.wheel).flank.profile ? gear + ".flank.profile.spacing" : gear + ".flank.topography.file";
    refuse(key, io::recorded_value(c, key, ""), what + ": a coarser or shorter flank profile" + raise);
  }
  refuse("contact.positions", std::to_string(span.positions), what + ": fewer positions" + raise);
}

// The time budget exceeded: refused at the key with the largest share, with what fits.
void refuse_time(const Case& c, const contact::FlankSpan& span, const int teeth[2], const contact::DeterministicWork& w,
                 const contact::DeterministicCost& cost, const io::ResourceBudget& budget) {
  const bool hunting = teeth[0] > 1 || teeth[1] > 1;
  const std::string what = fmt::format(
      "the run would take about {} on {} cores ({:.4g} strip solves: {} positions{}{}, each about {} on one core "
      "for {} elements, from measured costs: docs/reference/performance.md#budgets), more than the time budget "
      "of {} ({})",
      io::format_duration(cost.seconds), w.cores, cost.solves, span.positions,
      w.meshes > 1 ? fmt::format(" x {} meshes at most", w.meshes) : std::string(),
      hunting ? fmt::format(" x {} tooth pairs of the hunting order", teeth[0]) : std::string(),
      io::format_duration(cost.solve_seconds), span.elements, io::format_duration(budget.seconds),
      io::kTimeBudgetVariable);
  const std::string raise = ", or raise the budget";
  // The key with the largest share: the meshes, the hunting order's pairs, the elements (against the
  // shipped case's 1280) or the positions (against its 201).
  const double meshes = w.meshes, pairs = teeth[0], elements = cost.solve_seconds / contact::strip_solve_seconds(1280),
               positions = span.positions / 201.0;
  const double largest = std::max({meshes, pairs, elements, positions});
  const double over = cost.seconds / budget.seconds;  // how many times over
  // How many of a count fit the budget (the time is in proportion to it), or that none does.
  auto fits_in = [&](double count, double least, const char* what_fits) {
    const double fits = std::floor(count / over);
    return fits >= least ? fmt::format(": at most {:.0f} {} fit it", fits, what_fits)
                         : fmt::format(": not even {:.0f} {} fit it", least, what_fits);
  };
  auto refuse = [&](const std::string& key, const std::string& value, const std::string& rule) {
    throw io::located_error(c, key, value, rule);
  };
  if (largest == meshes)
    refuse("running_in.meshes", std::to_string(c.running_in.meshes),
           what + fits_in(w.meshes, 1, "meshes") + " (a run stops earlier at shakedown)" + raise);
  if (largest == pairs)
    refuse("running_in.teeth", io::recorded_value(c, "running_in.teeth", "hunting"),
           what + ": the hunting order solves every tooth pair; run the pair (running_in.teeth = \"pair\")" + raise);
  if (largest == elements)
    refuse("contact.element_size", io::recorded_value(c, "contact.element_size", ""),
           what + ": coarser elements, or a shorter strip (contact.strip_halfwidths)" + raise);
  refuse("contact.positions", std::to_string(span.positions), what + fits_in(span.positions, 2, "positions") + raise);
}

void check_budget(const Case& c, const contact::FlankSpan& span, const int teeth[2]) {
  const ContactSettings& cs = c.contact;
  contact::DeterministicWork w;
  for (int g = 0; g < 2; ++g) w.flank_points[g] = flank_points(c, span, g), w.teeth[g] = teeth[g];
  w.meshes = std::max(1, c.running_in.meshes);
  w.kept_profiles = cs.pressure_profiles == PressureProfiles::all      ? span.positions
                    : cs.pressure_profiles == PressureProfiles::points ? std::min(5, span.positions)
                                                                       : 0;
  w.threads = contact::position_threads(cs, span.positions);
  w.cores = std::min(w.threads, std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  const contact::DeterministicCost cost = contact::deterministic_cost(span, w);
  const io::ResourceBudget budget = io::resource_budget();
  if (cost.bytes() > budget.bytes) refuse_memory(c, span, teeth, w, cost, budget);
  if (cost.seconds > budget.seconds) refuse_time(c, span, teeth, w, cost, budget);
}

// The areal fidelity's peak memory (its maps and its window's solve) against the budget: refused at
// areal.points, the knob that grows both.
void check_areal_budget(const Case& c, const contact::FlankSpan& span, const int teeth[2]) {
  const double bytes = contact::areal::areal_run_bytes(span, c.contact.areal, teeth);
  const io::ResourceBudget budget = io::resource_budget();
  if (bytes > budget.bytes)
    throw io::located_error(
        c, "areal.points",
        fmt::format("the areal run would hold about {} (both flanks' maps over {:.4g} and {:.4g} mm of involute, and "
                    "a window of {} x {} elements), more than the memory budget of {} ({}): fewer points across the "
                    "face, a coarser contact.element_size, or raise the budget",
                    io::format_bytes(bytes), span.length(0) * 1e3, span.length(1) * 1e3, span.elements,
                    c.contact.areal.points, io::format_bytes(budget.bytes), io::kMemoryBudgetVariable));
}

}  // namespace

void check_finite_outputs(const contact::MeshContactResult& r) {
  const contact::Series* s = r.find("s_m");
  auto fail = [](const std::string& what, double v, const std::string& where) {
    throw std::runtime_error(fmt::format("{} is {}{}: a model left its range unnoticed; nothing is written", what, v,
                                         where.empty() ? "" : " at " + where));
  };
  auto at_position = [&](std::size_t i, std::size_t n) {
    return s && i < s->values.size()
               ? fmt::format("position {} of {} (0 at A; s = {:.4f} mm)", i, n, s->values[i] * 1e3)
               : fmt::format("entry {} of {}", i, n);
  };
  // One dataset's values, scanned where they are (a flank profile may hold millions).
  auto values = [&](const std::string& dataset, const std::vector<double>& v, bool positions) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        fail(dataset, v[i], positions ? at_position(i, v.size()) : fmt::format("entry {} of {}", i, v.size()));
  };
  auto group = [&](const std::string& path, const std::vector<contact::Series>& series, bool positions) {
    for (const auto& q : series) values(path + q.name, q.values, positions);
  };
  auto scalar = [&](const std::string& what, double v) {
    if (!std::isfinite(v)) fail(what, v, "");
  };
  group("/mesh/", r.mesh, true);
  group("/contact/", r.contact, true);
  group("/contact/validity/", r.validity, true);
  group("/lubrication/", r.lubrication, true);
  group("/statistical/", r.statistical, true);
  group("/mixed_ehl/", r.mixed_ehl, true);
  for (const auto& p : r.ehl_profiles) {
    const std::string at = "/mixed_ehl/profiles/position_" + std::to_string(p.position) + "/";
    values(at + "x_m", p.x, false);
    for (const auto& [name, q] : {std::pair{"peak", &p.peak}, std::pair{"middle", &p.middle}}) {
      values(at + name + "_pressure_Pa", q->pressure, false);
      values(at + name + "_film_m", q->film, false);
      values(at + name + "_shear_Pa", q->shear, false);
    }
  }
  // Every summary's values, named as the file names them (contact/run_summary.hpp).
  auto summary = [&](const std::string& group, const contact::Summary& sum) {
    for (const auto& v : sum.values) scalar(group + " attribute " + v.name, v.value);
  };
  summary("/mesh", contact::path_summary(r.path));
  summary("/mesh", contact::gear_summary(r));
  if (r.tooth_contact) summary("/mesh", contact::tooth_contact_summary(*r.tooth_contact));
  if (r.rating)  // its summary holds NaN for what was not rated; every factor is a number
    for (const auto& f : r.rating->factors) scalar("/rating/value of " + f.symbol, f.value);
  summary("/meta", contact::surface_summary(r));
  summary("/contact/validity", contact::validity_summary(r));
  if (r.mixed_ehl_summary) summary("/mixed_ehl", contact::mixed_ehl_summary(*r.mixed_ehl_summary));
  if (r.lubrication_summary) {
    summary("/lubrication", contact::lubrication_summary(*r.lubrication_summary));
    const auto& points = r.lubrication_summary->points;
    for (const auto& q : contact::named_point_series(*r.lubrication_summary))
      for (std::size_t i = 0; i < q.values.size(); ++i)
        if (!std::isfinite(q.values[i]))
          fail("/lubrication/points/" + q.name, q.values[i], "point " + (i < points.size() ? points[i].name : ""));
  }
  for (const auto& p : r.pressure_profiles) {
    values("/contact/pressure/x_m", p.x, false);
    values("/contact/pressure/position_" + std::to_string(p.position), p.pressure, false);
  }
  if (r.running_in) {
    summary("/running_in", contact::running_in_summary(*r.running_in));
    // Row 0 of the history is the new flanks, before any mesh: its per-mesh values are NaN by
    // design (docs/reference/hdf5-layout.md), the rows after it and the flanks' statistics numbers.
    for (const auto& q : r.running_in->history) {
      const bool per_mesh = q.name == "new_plastic_deformation_m" || q.name == "real_area_ratio_mean" ||
                            q.name == "plastic_area_fraction_mean" || q.name == "max_pressure_Pa";
      for (std::size_t i = 0; i < q.values.size(); ++i)
        if (!std::isfinite(q.values[i]) && !(per_mesh && i == 0 && std::isnan(q.values[i])))
          fail("/running_in/" + q.name, q.values[i], fmt::format("entry {} of {}", i, q.values.size()));
    }
    for (int g = 0; g < 2; ++g) {
      const std::string gear = g == 0 ? "pinion" : "wheel";
      values("/running_in/" + gear + "_profile_initial_m", r.running_in->initial[g], false);
      values("/running_in/" + gear + "_profile_final_m", r.running_in->final[g], false);
    }
  }
  for (const auto& f : r.synthesis) summary("/synthesis/" + f.gear, contact::synthesis_summary(f));
}

contact::MeshContactResult run_mesh_contact(const Case& c, const gear::GearMesh& mesh, const NonlinearSolver* solver,
                                            const std::function<void(int, int)>& progress, int positions,
                                            const OdeIntegrator* dynamics, const contact::FlankSource& flanks_source) {
  const std::unique_ptr<asperity::AsperityModel> model = asperity::make_case_model(c, c.asperity.model);
  contact::StatisticalFlanks flanks;
  flanks.materials = {&c.pinion.material, &c.wheel.material};
  flanks.roughness = {c.pinion.flank.roughness, c.wheel.flank.roughness};
  flanks.distribution = c.roughness.distribution;
  flanks.eta_sigma_beta = c.roughness.eta_sigma_beta;
  flanks.model = model.get();
  flanks.friction = c.friction_coefficient;
  const bool dynamic = c.dynamics.engine != gear::DynamicsEngine::none;
  if (dynamic && !dynamics) throw std::invalid_argument("the case asks for dynamics but no integrator was given");
  contact::MeshCycleInputs in{
      .mesh = mesh,
      .contact = c.contact,
      .running_in = c.running_in,
      .flanks = flanks,
      .lubrication = c.lubrication.lubricated ? &c.lubrication : nullptr,
      .operating = {c.operating.oil_temperature, c.operating.bulk_temperature, c.operating.pinion_torque},
      .dynamics = dynamic ? dynamics : nullptr,
      .dynamics_settings = dynamic ? gear::dynamics_settings(c) : gear::DynamicsSettings{},
      .solver = solver,
      .flank_source = flanks_source,
      .progress = progress,
      .flank_specs = {&c.pinion.flank, &c.wheel.flank}};
  if (positions > 0) in.contact.positions = positions;
  return contact::run_mesh_contact(in);
}

double finest_element_size(const Case& c) {
  return std::max(profile_spacing(c.pinion.flank), profile_spacing(c.wheel.flank));
}

double coarsest_grid_spacing(const Case& c) {
  const double a = profile_spacing(c.pinion.flank), b = profile_spacing(c.wheel.flank);
  return a > 0.0 && b > 0.0 ? std::min(a, b) : std::max(a, b);
}

contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress) {
  check_component_rules(c);
  // A fidelity that needs a lubricant, on a dry case (the loader refuses it; a Case changed in code).
  if (const std::string rule = contact::dry_case_rule(contact::find_fidelity(c.contact.fidelity));
      !rule.empty() && !c.lubrication.lubricated)
    throw io::located_error(c, "contact.fidelity", rule);
  const gear::GearMesh mesh = gear::case_mesh(c);
  const solvers::KinsolSolver kinsol;
  const std::unique_ptr<OdeIntegrator> integrator =
      c.dynamics.engine != gear::DynamicsEngine::none ? solvers::make_integrator(c.dynamics.engine) : nullptr;
  contact::MeshContactResult r;
  std::vector<contact::FlankSynthesis> synthesis;
  PathHalfWidths half_widths(c, mesh, integrator.get());
  try {
    const contact::FidelityNeeds needs = contact::find_fidelity(c.contact.fidelity).traits.needs;
    r = run_mesh_contact(c, mesh, needs.nonlinear_solver ? &kinsol : nullptr, progress, 0, integrator.get(),
                         [&](const contact::FlankSpan& span, const int teeth[2]) {
                           // The strip solves' estimate (the mixed-EHL windows have none yet).
                           if (span.reader == contact::FlankSpan::Reader::strip) check_budget(c, span, teeth);
                           if (span.reader == contact::FlankSpan::Reader::areal) check_areal_budget(c, span, teeth);
                           return rolling_flanks(c, span, teeth, synthesis, half_widths);
                         });
  } catch (const contact::RoughSurfaceOverload& e) {
    throw_overload(c, e.what());  // at the torque, naming the roughness and where each came from
  } catch (const core::KeyedError& e) {
    // A refusal the physics pins on one key: located where that key's value came from.
    throw io::refusal_error(c, e);
  } catch (const std::invalid_argument& e) {
    // A refusal about no one option field (a combination of them, a state of the physics: a
    // coupled strip without its solver, more solves than a run counts): the case file, unkeyed.
    throw io::InputError(io::case_file(c), 0, "", "", e.what());
  }
  for (const auto& f : synthesis) {
    if (!f.converged)
      r.warnings.push_back(fmt::format(
          "the {} flank's IAAFT synthesis stopped after {} iterations with its Fourier amplitudes {:.2g}% rms from "
          "the spectrum's and its curvature moment m4 {:+.1f}% (the patch's height distribution exact; the rank "
          "step's roughness at the sampling scale raises m4): consider synthesis = \"psd\"",
          f.gear, f.iterations, 100.0 * f.spectrum_misfit, 100.0 * (f.curvature_ratio - 1.0)));
    if (f.rolled_off_fraction > kRolledOffWarning)
      r.warnings.push_back(fmt::format(
          "{:.0f}% of the {} patch's height variance ({}) lies at wavelengths near or beyond its length, which the "
          "synthesis leaves out: the synthesised flank's Rq is {} against the patch's {}; measure a longer patch",
          100.0 * f.rolled_off_fraction, f.gear, f.patch, um(f.profile_rq), um(f.patch_rq)));
  }
  r.synthesis = std::move(synthesis);
  if (c.rating.any()) {
    try {
      Stopwatch clock;
      r.rating = rate_case(c, mesh, r);
      r.stages.push_back({"rating", clock.lap()});
    } catch (const core::KeyedError& e) {
      throw io::refusal_error(c, e);
    }
  }
  check_finite_outputs(r);
  // A run whose outputs rest on the mesh stiffness is warned, first, when it leaves ISO's band.
  const bool uses_stiffness = c.contact.mesh_stiffness || mesh.analysis().method() == gear::LoadSharing::stiffness ||
                              c.dynamics.engine != gear::DynamicsEngine::none;
  if (uses_stiffness)
    if (std::string w = gear::iso_stiffness_warning(mesh, mesh.iso_comparison(c.mesh.positions)); !w.empty())
      r.warnings.insert(r.warnings.begin(), std::move(w));
  return r;
}

}  // namespace geartrib::runs
