// A gear flank's surface as a case gives it: its roughness in one of the forms of FlankRoughness,
// or a measured topography (the file and how it is read and cleaned), or a generated profile
// along the involute; and the rough-surface settings both flanks share.
#pragma once

#include "surface/flank_profile.hpp"
#include "surface/height_grid.hpp"
#include "surface/profile_synthesis.hpp"
#include "surface/rough_surface.hpp"
#include "surface/surface_statistics.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace geartrib::surface {

// A measured flank: the topography file and how it is read and cleaned.
struct TopographySpec {
  std::string file;       // as written in the case file (relative to it)
  double unit = 1e-6;     // length unit of a file that does not state one [m]
  double spacing = 0.0;   // grid spacing of files without one [m]; 0: from the file
  double resample = 0.0;  // regrid spacing [m]; 0: as measured
  CleanupOptions clean;
  // The deterministic fidelity's profile: the grid line along x (or y) at this fraction of the
  // other axis, taken along the involute from root to tip.
  bool profile_along_x = true;
  double profile_at = 0.5;
  // Or a flank-long profile synthesised from the surface's profile spectrum along that axis (every
  // line; surface/profile_synthesis.hpp): psd or iaaft, the phases' seed (tooth t of the hunting
  // order: seed + t), the length centred on the active flank (0: a generated profile's stretch).
  SynthesisMethod synthesis = SynthesisMethod::none;
  std::uint64_t synthesis_seed = 1;
  double synthesis_length = 0.0;  // [m]
  void validate() const;          // throws core::KeyedError naming the field
};

// The rough flank of one gear: its roughness in one of the forms of FlankRoughness (Ra, Rq,
// summit statistics or spectral moments; roughness.summit_radius is the flank's summit radius,
// the only place it is kept).
struct FlankSpec {
  FlankRoughness roughness;
  // When the flank is measured ([*.flank.topography]): where it came from, and the statistics
  // of the cleaned surface the roughness above was taken from.
  std::optional<TopographySpec> topography;
  std::optional<SurfaceStatistics> measured;
  std::optional<FlankProfile> measured_profile;   // the topography's line for the deterministic fidelity
  std::optional<ProfileSpectrum> patch_spectrum;  // its profile spectrum, when a synthesis is asked for
  std::optional<HeightGrid> patch;                // the cleaned surface itself, for the areal fidelity's patch lay
  // A generated profile along the involute ([*.flank.profile]): the deterministic fidelity's flank,
  // and (its statistics) the roughness of the others.
  std::optional<GeneratedProfileSpec> profile;
};

// Rough-surface settings shared by both flanks.
struct RoughnessSettings {
  HeightDistribution distribution = HeightDistribution::gaussian;
  double eta_sigma_beta = kTypicalEtaSigmaBeta;  // for flanks given by Ra or Rq
  void validate() const;                         // throws core::KeyedError naming the field
};

}  // namespace geartrib::surface
