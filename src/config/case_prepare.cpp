#include "config/case_prepare.hpp"

#include "config/case_parameters.hpp"
#include "config/case_records.hpp"
#include "contact/areal/mesh_areal.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/surface_model.hpp"
#include "core/keyed_error.hpp"
#include "gear/iso6336_stiffness.hpp"
#include "gear/spur_pair.hpp"
#include "gear/tooth_contact.hpp"
#include "surface/flank_profile.hpp"
#include "surface/profile_synthesis.hpp"
#include "surface/rough_surface.hpp"
#include "surface/surface_statistics.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace geartrib::io {

namespace {

// A finding of the preparation, once: preparing a Case again (after changing it in code) does not
// repeat the warnings it already holds.
void add_warning(Case& c, std::string w) {
  if (std::find(c.warnings.begin(), c.warnings.end(), w) == c.warnings.end()) c.warnings.push_back(std::move(w));
}

constexpr std::size_t kFewSummits = 100;           // below this a summit statistic scatters by more than 10%
constexpr double kReferenceProfilePoints = 65536;  // a generated profile's sample for its statistics

// A given key (read from the file or a --set, not a default).
bool given(const Case& c, const std::string& key) {
  const ResolvedParameter* p = find_record(c, key);
  return p && p->origin.kind != Origin::Kind::default_value;
}

// Persson's closure on the flanks' own spectra (lubrication.persson_spectrum = flanks): a measured
// areal flank's cleaned patch is kept for its spectrum (contact::flank_spectrum).
bool persson_takes_patches(const Case& c) {
  const auto& l = c.lubrication;
  return l.lubricated && l.asperity_pressure == lubrication::AsperityPressureModel::persson &&
         l.persson_spectrum == lubrication::PerssonSpectrum::flanks;
}

// A measured flank: the cleaned surface's summits give density, height sigma and radius
// (summit_radius, if given, overrides the measured radius: grid sampling biases it); a profile
// trace (fewer than 3 lines) its spectral moments.
void prepare_measured(Case& c, int gear) {
  GearSpec& g = gear == 0 ? c.pinion : c.wheel;
  const std::string f = std::string(gear == 0 ? "pinion" : "wheel") + ".flank.";
  const std::string t = f + "topography.";
  auto& rough = g.flank.roughness;
  const surface::TopographySpec& spec = *g.flank.topography;
  const auto path = std::filesystem::path(c.directory) / spec.file;
  TopographyReadOptions read;
  read.unit = spec.unit;
  read.spacing = spec.spacing / spec.unit;
  read.resample = spec.resample;
  const double given_radius = rough.summit_radius;
  const LoadedSurface loaded = load_surface(path, read, spec.clean);
  for (const auto& w : loaded.warnings) add_warning(c, w);  // units implausible for a flank
  const surface::HeightGrid& grid = loaded.grid;
  const bool trace = grid.nx < 3 || grid.ny < 3;
  auto refuse = [&](const std::string& key, const std::string& rule) { throw located_error_as_written(c, key, rule); };
  // The line along the involute: what the deterministic fidelity rolls, and a profile trace's
  // roughness. A statistical run of an areal surface takes its summits only, not this line.
  if (trace || contact::rolls_flank_profiles(c.contact.fidelity)) {
    try {
      g.flank.measured_profile = surface::profile_from_grid(grid, spec.profile_along_x, spec.profile_at);
    } catch (const std::invalid_argument& e) {
      refuse(t + "file", fmt::format("{}: {} along {}: {}{}", path.string(),
                                     trace ? "the profile trace" : "the line the deterministic fidelity rolls",
                                     spec.profile_along_x ? "x" : "y", e.what(),
                                     trace ? ""
                                           : " (" + t + "fill = true fills missing points; " + t + "profile_axis and " +
                                                 t + "profile_at choose the line)"));
    }
  }
  if (spec.synthesis != surface::SynthesisMethod::none) {
    try {  // the spectrum a flank-long profile is synthesised from (every line along the involute)
      g.flank.patch_spectrum = surface::profile_spectrum(grid, spec.profile_along_x);
    } catch (const std::invalid_argument& e) {
      refuse(t + "synthesis", path.string() + ": " + e.what());
    }
  }
  const bool patch_lay = c.contact.fidelity.name() == contact::areal::Areal::name &&
                         c.contact.areal.lay == contact::areal::ArealLay::patch;
  if (!trace && persson_takes_patches(c) && grid.missing() > 0)
    refuse(t + "fill", fmt::format("{} has {} missing points; Persson's closure takes the patch's own spectrum "
                                   "(lubrication.persson_spectrum = flanks), which needs every point: fill = true, "
                                   "or take \"moments\"",
                                   path.string(), grid.missing()));
  // Synthesised or tiled into the areal fidelity's maps (runs/mesh_cycle.cpp); Persson's spectrum.
  if (!trace && (patch_lay || persson_takes_patches(c))) g.flank.patch = grid;
  if (trace) {
    // A profile trace (a stylus's line along the involute): its spectral moments give the
    // roughness (McCool's summits), as for a generated profile.
    if (given(c, f + "summit_radius"))
      refuse(f + "summit_radius", "a profile trace gives the summit radius (its spectral moments); remove it");
    try {
      const surface::FlankProfile& line = *g.flank.measured_profile;
      rough = surface::spectral_roughness(surface::profile_statistics(line.z, line.spacing));
    } catch (const std::invalid_argument& e) {
      refuse(t + "file", path.string() + ": " + e.what());
    }
    return;
  }
  try {
    g.flank.measured = surface::surface_statistics(grid);
    rough = surface::measured_roughness(*g.flank.measured);
  } catch (const std::invalid_argument& e) {
    refuse(t + "file", path.string() + ": " + e.what());
  }
  if (given(c, f + "summit_radius")) rough.summit_radius = given_radius;
  if (g.flank.measured->summits < kFewSummits)
    add_warning(c, fmt::format("{}: warning: key '{}': only {} summits on the measured surface (statistics "
                               "scatter by ~1/sqrt(n)); measure a larger area",
                               location_of(c, t + "file").text(), t + "file", g.flank.measured->summits));
}

// A generated rough profile: its spectral moments from a sample of kReferenceProfilePoints points.
void prepare_generated(Case& c, int gear) {
  GearSpec& g = gear == 0 ? c.pinion : c.wheel;
  const std::string f = std::string(gear == 0 ? "pinion" : "wheel") + ".flank.";
  const surface::GeneratedProfileSpec& spec = *g.flank.profile;
  if (spec.kind == surface::ProfileKind::smooth) return;  // no statistics (the loader zeroed them)
  try {
    const surface::FlankProfile sample = surface::generate_profile(spec, kReferenceProfilePoints * spec.spacing);
    g.flank.roughness = surface::spectral_roughness(surface::profile_statistics(sample.z, sample.spacing));
  } catch (const core::KeyedError& e) {
    throw located_error_as_written(c, f + "profile." + e.key(), e.what());
  } catch (const std::invalid_argument& e) {
    throw located_error_as_written(c, f + "profile.kind", e.what());
  }
}

// The pair must exist: an impossible geometry is an error at the key to change; findings such as
// undercut are kept as located warnings. A pair built from an implausible value (a "4.5 m" module)
// is refused at that value first: it is the likely cause.
void prepare_gear_pair(Case& c) {
  try {
    const gear::SpurPair pair(c.gear_pair);
    for (const auto& w : pair.warnings())
      add_warning(c, fmt::format("{}: warning: key '{}': {}", location_of(c, w.key).text(), w.key, w.message));
    // The profile modifications must lie on the flanks (a relief off the flank or across it).
    if (c.mesh.load_sharing == gear::LoadSharing::compatibility) {
      const double design = gear::iso_effective_relief(pair, pair.tangential_line_load(c.operating.pinion_torque));
      for (int g = 0; g < 2; ++g) gear::FlankModification(pair, g, c.mesh.modification[g], design);
    }
  } catch (const gear::GeometryError& e) {
    if (e.key().find("_relief.") != std::string::npos) throw located_error_as_written(c, e.key(), e.what());
    for (const Parameter& p : case_parameters()) {
      if (p.key.rfind("gear_pair.", 0) != 0 || !given(c, p.key)) continue;
      const double v = p.get(c, -1).number;
      if (!p.plausible(v))
        throw located_error_as_written(
            c, p.key,
            fmt::format("{} the plausible band {} of a spur gear, and the pair it gives cannot exist: {} (key '{}')",
                        v < p.plausible_min ? "below" : "above", p.plausible_text(), e.what(), e.key()));
    }
    throw located_error_as_written(c, e.key(), e.what());
  }
}

}  // namespace

void prepare_case(Case& c) {
  for (int gear = 0; gear < 2; ++gear) {
    const surface::FlankSpec& flank = (gear == 0 ? c.pinion : c.wheel).flank;
    if (flank.topography) prepare_measured(c, gear);
    else if (flank.profile) prepare_generated(c, gear);
  }
  surface::FlankRoughness& r1 = c.pinion.flank.roughness;
  surface::FlankRoughness& r2 = c.wheel.flank.roughness;
  if ((c.pinion.flank.topography || c.wheel.flank.topography) && r1.form != r2.form) {
    // Located at the wheel's flank: the first of its keys the case gave (its form's).
    std::string_view wheel_key = "wheel.flank.topography.file";
    for (const auto& p : c.parameters)
      if (p.key.rfind("wheel.flank.", 0) == 0 && p.origin.kind != Origin::Kind::default_value) {
        wheel_key = p.key;
        break;
      }
    const Location at = location_of(c, wheel_key);
    throw InputError(at.file, at.line, "wheel.flank", "",
                     "give both flanks' roughness in the same form as the pinion's");
  }
  // One radius per run: the flanks' radii consistent with the equivalent surface (spectral:
  // McCool's). A smooth generated profile has none: the deterministic run alone takes it.
  if (r1.form != surface::FlankRoughness::Form::spectral || (r1.m4 > 0.0 && r2.m4 > 0.0)) {
    const auto [radius1, radius2] = surface::flank_summit_radii(r1, r2);
    r1.summit_radius = radius1;
    r2.summit_radius = radius2;
  }
  prepare_gear_pair(c);
  // Persson's spectrum from the flanks themselves, asked for in so many words: both must have one.
  const std::string spectrum_key = "lubrication.persson_spectrum";
  if (persson_takes_patches(c) && given(c, spectrum_key))
    for (int gear = 0; gear < 2; ++gear) {
      const surface::FlankSpec& f = (gear == 0 ? c.pinion : c.wheel).flank;
      if (!contact::has_own_spectrum(f))
        throw located_error_as_written(
            c, spectrum_key,
            fmt::format("the {} flank has no spectrum of its own (a measured areal topography or a generated ground "
                        "profile; {}): take \"moments\", the statistical model's fit",
                        gear == 0 ? "pinion" : "wheel",
                        f.topography ? "its topography is a profile trace"
                        : f.profile  ? "its generated profile is not a ground one"
                                     : "it is given by its statistics"));
    }
}

Case prepare_case(Case&& c) {
  prepare_case(c);
  return std::move(c);
}

}  // namespace geartrib::io
