// One line contact through the mixed-EHL solver (line_ehl.hpp), as `geartrib ehl` runs it: smooth
// and steady, or with a roughness on one surface or both (a harmonic waviness or a single
// transverse ridge) that moves with its surface's speed, solved transiently over a window; the
// per-step series, the last instant's profile and the quantities read off it (the pressure spike,
// the film's rupture). Optionally the dry contact of the same gap by boundary elements
// (half_plane_bem.hpp), the limit the solver must reach as the viscosity vanishes.
//
// Heights r (towards the other surface, closing the gap) on a surface moving at u_k, at time t, in
// the frame of the contact (x from the inlet to the outlet, the solver's nodes):
//  - waviness, steady: r = A cos(2 pi x/lambda) (a crest at x = 0);
//  - waviness, transient: the waviness enters the domain at its inlet x_s at t = 0, as a surface
//    smooth ahead of that point would carry it: r = A sin(2 pi s/lambda) for s = x_s + u_k t - x >= 0,
//    0 ahead of the front (s < 0), so the first instant is the smooth contact's steady solution;
//  - ridge, steady: r = A cos^2(pi x/w) for |x| < w/2 (its top at x = 0, base width w);
//  - ridge, transient: the same ridge with its top at c(t) = x_s - w/2 + u_k t, entering at the inlet.
// On both surfaces the two heights add.
#pragma once

#include "contact/half_plane_bem.hpp"
#include "contact/mixed_ehl/line_ehl.hpp"
#include "core/named_choices.hpp"

#include <functional>
#include <span>
#include <vector>

namespace geartrib::contact::mixed_ehl {

enum class RoughnessShape { none, waviness, ridge };
std::span<const NamedChoice<RoughnessShape>> roughness_shape_choices();
enum class RoughSurfaces { first, second, both };
std::span<const NamedChoice<RoughSurfaces>> rough_surfaces_choices();  // "1", "2", "both"

struct LineRoughness {
  RoughnessShape shape = RoughnessShape::none;
  double amplitude = 0.0;  // the waviness' amplitude or the ridge's height, towards the other surface [m]
  double length = 0.0;     // the waviness' wavelength or the ridge's base width [m]
  RoughSurfaces on = RoughSurfaces::first;
  void validate() const;  // throws core::KeyedError naming the field
};

// The transient: `window` contact widths 2b travelled by the slower rough surface; the time step
// dt = courant dx/u_fast (the faster rough surface's roughness moves `courant` nodes a step).
struct LineTransient {
  bool enabled = true;  // false: one steady solve with the roughness in place (its steady form)
  double window = 0.0;  // [contact widths]; 0: the roughness crosses the whole domain, then 2 more
  double courant = 1.0;
  static constexpr int kMaxSteps = 1000000;
  void validate() const;  // throws core::KeyedError naming the field
};

struct LineEhlSpec {
  Fluid fluid;
  double modulus = 0.0;  // E* [Pa]
  ContactInstant instant;
  EhlOptions options;
  LineRoughness roughness;
  LineTransient transient;
  bool dry_reference = false;  // also the dry contact of the last instant's gap by boundary elements
};

// One instant of the transient.
struct LineEhlStep {
  double time = 0.0;  // [s]
  double central_film = 0.0, min_film = 0.0, peak_pressure = 0.0;
  double asperity_share = 0.0, contact_fraction = 0.0, friction_coefficient = 0.0;
  double load_error = 0.0;
  int iterations = 0;
  double seconds = 0.0;  // the solve's wall time
};

// Extremes and mean of one quantity over the transient's steps.
struct StepRange {
  double min = 0.0, max = 0.0, mean = 0.0;
};

struct LineEhlResult {
  HalfPlaneGrid grid;
  double hertz_half_width = 0.0, hertz_pressure = 0.0;  // b [m], p_H [Pa] of the instant
  EhlField field;                                       // the last instant's
  std::vector<double> heights;                          // the last instant's r per node [m]
  // The spike: the last local maximum of the pressure downstream of x = 0 that stands above
  // Hertz's pressure there (the instant's) and above a tenth of the peak (NaN: none); the rupture:
  // the last node with pressure before the cavitated zone that follows the pressure's maximum
  // (NaN: the film does not rupture in the domain).
  double spike_x = 0.0, spike_pressure = 0.0, rupture_x = 0.0;
  // Transient: the step (dt), every instant from t = 0 (the steady start) to the window's end.
  double time_step = 0.0;
  std::vector<LineEhlStep> series;
  StepRange central_film, min_film, peak_pressure, asperity_share, friction_coefficient;
  double steady_seconds = 0.0;     // the first (steady) solve
  double transient_seconds = 0.0;  // every time step
  // The dry contact of the same gap (dry_reference): pressure per node [Pa], its largest difference
  // from the solver's over p_H, and the boundary-element solve's iterations.
  std::vector<double> dry_pressure;
  double dry_difference = 0.0;
  int dry_iterations = 0;
};

// The heights of `roughness` on `grid` at time t (transient: entering at the inlet; steady: in
// place) with the surfaces' speeds u1, u2.
std::vector<double> roughness_heights(const LineRoughness& roughness, const HalfPlaneGrid& grid, double t,
                                      double speed1, double speed2, bool transient);

// Solves it; `progress(done, total)` after each step. Throws core::KeyedError for a refused
// field (the spec's validate()s', the roughness' and the transient's), std::runtime_error when the
// solver does not converge (the message gives the instant).
LineEhlResult run_line_ehl(const LineEhlSpec& spec, const std::function<void(int, int)>& progress = {});

}  // namespace geartrib::contact::mixed_ehl
