#include "contact/mixed_ehl/line_ehl_run.hpp"

#include "core/keyed_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace geartrib::contact::mixed_ehl {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr NamedChoice<RoughnessShape> kShapes[] = {
    {RoughnessShape::none, "none"}, {RoughnessShape::waviness, "waviness"}, {RoughnessShape::ridge, "ridge"}};
constexpr NamedChoice<RoughSurfaces> kSurfaces[] = {
    {RoughSurfaces::first, "1"}, {RoughSurfaces::second, "2"}, {RoughSurfaces::both, "both"}};
// The default window: after the roughness has crossed the domain, this many contact widths more.
constexpr double kWindowAfterCrossing = 2.0;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One surface's heights at its displacement d = u_k t since the start.
void add_surface(const LineRoughness& r, const HalfPlaneGrid& grid, double d, bool transient,
                 std::vector<double>& out) {
  const double inlet = grid.start;
  for (int i = 0; i < grid.size; ++i) {
    const double x = grid.x(i);
    double h = 0.0;
    if (r.shape == RoughnessShape::waviness) {
      if (!transient) {
        h = r.amplitude * std::cos(2.0 * kPi * x / r.length);
      } else {
        const double s = inlet + d - x;  // how far behind the front x is
        if (s >= 0.0) h = r.amplitude * std::sin(2.0 * kPi * s / r.length);
      }
    } else if (r.shape == RoughnessShape::ridge) {
      const double centre = transient ? inlet - 0.5 * r.length + d : 0.0;
      const double t = (x - centre) / r.length;
      if (std::abs(t) < 0.5) h = r.amplitude * std::pow(std::cos(kPi * t), 2);
    }
    out[static_cast<std::size_t>(i)] += h;
  }
}

StepRange range_of(const std::vector<LineEhlStep>& series, double LineEhlStep::*member) {
  StepRange r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0.0};
  for (const LineEhlStep& s : series) {
    const double v = s.*member;
    r.min = std::min(r.min, v);
    r.max = std::max(r.max, v);
    r.mean += v;
  }
  r.mean /= static_cast<double>(series.size());
  return r;
}

LineEhlStep step_of(const EhlField& f, double time, double seconds) {
  return {time,
          f.central_film,
          f.min_film,
          f.peak_pressure,
          f.asperity_share,
          f.contact_fraction,
          f.friction_coefficient,
          f.load_error,
          f.iterations,
          seconds};
}

// The spike and the rupture of the last instant (LineEhlResult).
void read_profile(LineEhlResult& r) {
  const EhlField& f = r.field;
  const int n = r.grid.size;
  const auto p = [&](int i) { return f.pressure[static_cast<std::size_t>(i)]; };
  r.spike_x = r.spike_pressure = r.rupture_x = std::numeric_limits<double>::quiet_NaN();
  int peak = 0;
  for (int i = 1; i < n; ++i)
    if (p(i) > p(peak)) peak = i;
  for (int i = 1; i + 1 < n; ++i) {
    const double x = r.grid.x(i) / r.hertz_half_width;
    const double hertz = std::abs(x) < 1.0 ? r.hertz_pressure * std::sqrt(1.0 - x * x) : 0.0;
    if (x > 0.0 && p(i) > p(i - 1) && p(i) >= p(i + 1) && p(i) > std::max(0.1 * f.peak_pressure, hertz)) {
      r.spike_x = r.grid.x(i);
      r.spike_pressure = p(i);
    }
  }
  for (int i = peak + 1; i < n; ++i)
    if (f.state[static_cast<std::size_t>(i)] == NodeState::cavitated) {
      r.rupture_x = r.grid.x(i - 1);
      break;
    }
}
}  // namespace

std::span<const NamedChoice<RoughnessShape>> roughness_shape_choices() { return kShapes; }
std::span<const NamedChoice<RoughSurfaces>> rough_surfaces_choices() { return kSurfaces; }

void LineRoughness::validate() const {
  using core::KeyedError;
  if (shape == RoughnessShape::none) return;
  if (!std::isfinite(amplitude)) throw KeyedError("amplitude", "the roughness' height must be finite");
  if (!(length > 0.0) || !std::isfinite(length))
    throw KeyedError("length", "the wavelength or the ridge's width must be positive");
}

void LineTransient::validate() const {
  using core::KeyedError;
  if (!(window >= 0.0) || !std::isfinite(window))
    throw KeyedError("window", "the window must be >= 0 contact widths (0: the default)");
  if (!(courant > 0.0 && courant <= 100.0)) throw KeyedError("courant", "the time step must lie in (0, 100] nodes");
}

std::vector<double> roughness_heights(const LineRoughness& roughness, const HalfPlaneGrid& grid, double t,
                                      double speed1, double speed2, bool transient) {
  std::vector<double> h(static_cast<std::size_t>(grid.size), 0.0);
  if (roughness.shape == RoughnessShape::none) return h;
  if (roughness.on != RoughSurfaces::second) add_surface(roughness, grid, speed1 * t, transient, h);
  if (roughness.on != RoughSurfaces::first) add_surface(roughness, grid, speed2 * t, transient, h);
  return h;
}

LineEhlResult run_line_ehl(const LineEhlSpec& spec, const std::function<void(int, int)>& progress) {
  spec.roughness.validate();
  spec.transient.validate();
  const auto start = std::chrono::steady_clock::now();
  LineEhlSolver solver(spec.fluid, spec.modulus, spec.instant, spec.options);
  LineEhlResult r;
  r.grid = solver.grid();
  r.hertz_half_width = solver.hertz_half_width();
  r.hertz_pressure = solver.hertz_pressure();
  const ContactInstant& c = spec.instant;
  const bool rough = spec.roughness.shape != RoughnessShape::none;
  const bool transient = rough && spec.transient.enabled;

  // The transient's length and step (both before any solve: a refusal costs nothing).
  int steps = 0;
  double dt = 0.0;
  if (transient) {
    const double u_slow = spec.roughness.on == RoughSurfaces::first    ? c.speed1
                          : spec.roughness.on == RoughSurfaces::second ? c.speed2
                                                                       : std::min(c.speed1, c.speed2);
    const double u_fast = spec.roughness.on == RoughSurfaces::first    ? c.speed1
                          : spec.roughness.on == RoughSurfaces::second ? c.speed2
                                                                       : std::max(c.speed1, c.speed2);
    if (!(u_slow > 0.0))
      throw core::KeyedError("window",
                             "the rough surface does not move (speed 0): its roughness stays where it is; solve it "
                             "steady");
    const double width = 2.0 * r.hertz_half_width;
    const double domain =
        r.grid.spacing * r.grid.size + (spec.roughness.shape == RoughnessShape::ridge ? spec.roughness.length : 0.0);
    const double window = spec.transient.window > 0.0 ? spec.transient.window : domain / width + kWindowAfterCrossing;
    const double duration = window * width / u_slow;
    const double dt0 = spec.transient.courant * r.grid.spacing / u_fast;
    const double count = std::ceil(duration / dt0 - 1e-9);
    if (!(count <= LineTransient::kMaxSteps))
      throw core::KeyedError(
          "courant", fmt::format("{:.3g} time steps (window {:.4g} contact widths at a step of {:.3g} nodes): at most "
                                 "{}; a larger step or a shorter window",
                                 count, window, spec.transient.courant, LineTransient::kMaxSteps));
    steps = std::max(1, static_cast<int>(count));
    dt = duration / steps;
  }

  std::vector<double> heights = roughness_heights(spec.roughness, r.grid, 0.0, c.speed1, c.speed2, transient);
  solver.solve_steady(c, heights);
  r.steady_seconds = seconds_since(start);
  if (transient) {
    r.time_step = dt;
    r.series.reserve(static_cast<std::size_t>(steps) + 1);
    r.series.push_back(step_of(solver.field(), 0.0, r.steady_seconds));
    const auto transient_start = std::chrono::steady_clock::now();
    for (int k = 1; k <= steps; ++k) {
      const double t = k * dt;
      heights = roughness_heights(spec.roughness, r.grid, t, c.speed1, c.speed2, true);
      const auto step_start = std::chrono::steady_clock::now();
      try {
        solver.step(c, heights, dt);
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("{} (time step {} of {}, t = {:.6g} s)", e.what(), k, steps, t));
      }
      r.series.push_back(step_of(solver.field(), t, seconds_since(step_start)));
      if (progress) progress(k, steps);
    }
    r.transient_seconds = seconds_since(transient_start);
    r.central_film = range_of(r.series, &LineEhlStep::central_film);
    r.min_film = range_of(r.series, &LineEhlStep::min_film);
    r.peak_pressure = range_of(r.series, &LineEhlStep::peak_pressure);
    r.asperity_share = range_of(r.series, &LineEhlStep::asperity_share);
    r.friction_coefficient = range_of(r.series, &LineEhlStep::friction_coefficient);
  }
  r.field = solver.field();
  r.heights = std::move(heights);
  read_profile(r);

  if (spec.dry_reference) {
    // The dry contact of the same undeformed gap x^2/(2R) - r(x) under the same line load.
    std::vector<double> gap(static_cast<std::size_t>(r.grid.size));
    for (int i = 0; i < r.grid.size; ++i) {
      const double x = r.grid.x(i);
      gap[static_cast<std::size_t>(i)] = x * x / (2.0 * c.radius) - r.heights[static_cast<std::size_t>(i)];
    }
    // Under load control the pressure does not depend on the displacements' reference length; it
    // must only lie beyond the domain (half_plane_bem.hpp).
    BemOptions bem_options;
    bem_options.reference_length = 2.0 * r.grid.spacing * r.grid.size;
    const HalfPlaneBem bem(r.grid, spec.modulus, bem_options);
    const BemSolution dry = bem.solve_load(gap, c.line_load);
    r.dry_pressure = dry.pressure;
    r.dry_iterations = dry.iterations;
    for (std::size_t i = 0; i < gap.size(); ++i)
      r.dry_difference = std::max(r.dry_difference, std::abs(r.field.pressure[i] - dry.pressure[i]) / r.hertz_pressure);
  }
  return r;
}

}  // namespace geartrib::contact::mixed_ehl
