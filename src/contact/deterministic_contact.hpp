// Deterministic rough line contact along the path of contact: at each position the gap across a
// strip of the contact is the Hertz geometry x^2/(2 R) less both flanks' profiles, each read at
// the flank points that have rolled into the strip (the flanks slide past each other at their own
// speeds), solved with the plane-strain boundary elements of half_plane_bem.hpp under the
// position's line load, elastic-perfectly-plastic with the softer flank's hardness as the cap.
// Running-in: the plastic deformation of each flank point is kept on its flank and carried to the
// next mesh of the same teeth, until no new plastic deformation (shakedown).
//
// Frame (docs/theory/deterministic-contact.md): x along the common tangent in the direction the
// surfaces roll (both flanks move in +x relative to the contact). A flank point's coordinate is its
// involute arc length from the base circle, sigma = rho^2/(2 r_b) (Litvin); the contact point's
// moves at d(sigma1)/dt = rho1 omega1 = v1 on the pinion and -v2 on the wheel, so the point at x is
// sigma1 = sigma1c - x on the pinion and sigma2 = sigma2c + x on the wheel.
#pragma once

#include "contact/half_plane_bem.hpp"
#include "surface/flank_profile.hpp"

#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace geartrib::contact {

// One flank as the strip reads it: its profile along the involute (root to tip) and the arc
// coordinate of its first point. Running-in lowers the profile in place.
struct FlankTrack {
  surface::FlankProfile profile;
  double start = 0.0;  // sigma of profile.z[0] [m]
  double end() const { return start + profile.length(); }
};

struct DeterministicOptions {
  static constexpr double kMinStripHalfwidths = 1.05, kMaxStripHalfwidths = 20.0;
  static constexpr int kMaxElements = 1 << 20;
  double element_size = 0.5e-6;  // boundary-element width [m]
  // The strip spans +- strip_halfwidths times the path's largest Hertz half-width (one grid for
  // every position).
  double strip_halfwidths = 2.0;
  double pressure_cap = std::numeric_limits<double>::infinity();  // H of the softer flank [Pa]
  double poisson_ratio = 0.3;                                     // of the softer flank, for the von Mises stress
  // Share of a plastic deformation taken by the pinion's flank (the softer one takes it all; equal
  // hardness: half each); the wheel's takes the rest.
  double pinion_plastic_share = 0.5;
  bool subsurface_stress = true;  // the von Mises maximum below the strip and its depth
  double tolerance = 1e-8;        // the boundary elements' complementarity tolerance (relative)
  // An element is plastic where its overlap beyond the elastic answer exceeds this: the solves
  // leave ~1e-14 m of a micrometre relief, and a flank flattened to the cap in an earlier mesh
  // touches again at the cap with overlaps far below a nanometre without yielding anew [m].
  double plastic_overlap = 1e-9;
  void validate() const;  // throws core::KeyedError naming the field
};

// Where the strip is at one position of the path.
struct StripPosition {
  double line_load = 0.0;         // [N/m]
  double radius = 0.0;            // equivalent radius R [m]
  double hertz_half_width = 0.0;  // b [m] (the nominal width 2b of the ratios)
  double sigma_pinion = 0.0;      // arc coordinate of the contact point on the pinion's flank [m]
  double sigma_wheel = 0.0;       // ... on the wheel's [m]
  double path = 0.0;              // the position's coordinate s along the path of contact [m] (for messages)
};

// One position's answer, per unit face width.
struct DeterministicStrip {
  double real_area_per_width = 0.0;      // contact elements x element size [m]
  double real_area_ratio = 0.0;          // real_area_per_width / 2b
  int contact_spots = 0;                 // runs of neighbouring contact elements
  double peak_pressure = 0.0;            // [Pa]
  double mean_real_pressure = 0.0;       // line load / real area [Pa]
  double plastic_area_per_width = 0.0;   // capped elements x element size [m]
  double plastic_area_fraction = 0.0;    // capped / contact elements
  double contact_half_width = 0.0;       // half the distance between the outermost contact elements [m]
  double max_plastic_deformation = 0.0;  // largest overlap beyond the elastic answer (where capped) [m]
  double max_von_mises = 0.0;            // largest von Mises stress below the strip [Pa]
  double max_von_mises_depth = 0.0;      // its depth [m]
  double max_von_mises_x = 0.0;          // its position across the strip [m]
  bool edge_loaded = false;              // pressure in the strip's outermost elements: the strip is too short
  int iterations = 0;                    // conjugate-gradient iterations of the solve
  std::vector<double> pressure;          // per element [Pa] (kept when asked)
  std::vector<double> plastic;           // plastic overlap per element [m] (kept when asked)
};

// The strip's grid: [-L', L'] in elements of options.element_size, L' the least whole number of
// them not below L (at least 4 either side): element edges at whole multiples of the element
// size from the contact point.
HalfPlaneGrid strip_grid(double half_length, const DeterministicOptions& options);

// The strip's boundary elements and its gap; one per thread (the solver keeps work buffers).
class StripSolver {
 public:
  // composite_modulus: the plane-strain E* of the pair, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
  StripSolver(double composite_modulus, double strip_half_length, const DeterministicOptions& options);
  const HalfPlaneGrid& grid() const { return grid_; }
  // The undeformed gap per element: x^2/(2R) less both flanks' element-averaged heights.
  std::vector<double> gap(const FlankTrack& pinion, const FlankTrack& wheel, const StripPosition& p) const;
  DeterministicStrip solve(const FlankTrack& pinion, const FlankTrack& wheel, const StripPosition& p,
                           bool keep_profiles) const;

 private:
  HalfPlaneGrid grid_;
  DeterministicOptions options_;
  HalfPlaneBem bem_;
  std::unique_ptr<HalfPlaneBem> elastic_;  // without the cap: the lightest loads (solve())
};

// The mean height of a profile over [a, b] (arc coordinates, a < b, inside the track): the exact
// integral of its piecewise-linear interpolation over the interval's length.
double track_mean(const FlankTrack& t, double a, double b);

// One mesh of the two flanks: every position solved (on `threads` threads, each with its own
// StripSolver), and the plastic deformation each flank point took (its largest over the positions,
// at the profile's points). keep[i]: keep position i's pressure. progress(done, total) from the
// calling thread.
struct MeshPass {
  std::vector<DeterministicStrip> strips;
  std::vector<double> plastic_pinion, plastic_wheel;  // per profile point [m]
  double max_new_plastic = 0.0;                       // [m]
};
MeshPass mesh_pass(const FlankTrack& pinion, const FlankTrack& wheel, const std::vector<StripPosition>& positions,
                   double composite_modulus, double strip_half_length, const DeterministicOptions& options,
                   const std::vector<bool>& keep, int threads, const std::function<void(int, int)>& progress = {});

// A flank's roughness over its active part (the arc range [a, b] the contact point passes).
surface::ProfileStatistics active_statistics(const FlankTrack& t, double a, double b);

}  // namespace geartrib::contact
