#include "contact/mixed_ehl/mesh_mixed_ehl.hpp"

#include "contact/mesh_lubrication.hpp"
#include "contact/position_threads.hpp"
#include "contact/series_columns.hpp"
#include "contact/stage_clock.hpp"
#include "core/keyed_error.hpp"
#include "core/stopwatch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geartrib::contact::mixed_ehl {

void MixedEhlOptions::validate() const {
  using core::KeyedError;
  if (!(grid_spacing >= 0.0 && grid_spacing <= 1e-3))
    throw KeyedError("grid_spacing", "the grid spacing must lie in [0, 1 mm] (0: automatic)");
  if (!(window >= kMinWindow && window <= kMaxWindow))
    throw KeyedError("window", fmt::format("the window must be {:g} to {:g} contact widths: a shorter one does not let "
                                           "the slower surface's roughness cross the contact",
                                           kMinWindow, kMaxWindow));
  if (!(lead_in >= 0.0 && lead_in <= kMaxLeadIn))
    throw KeyedError("lead_in",
                     fmt::format("the lead-in must lie in [0, {:g}] Hertz half-widths (0: none)", kMaxLeadIn));
  if (!(time_step > 0.0 && time_step <= 100.0))
    throw KeyedError("time_step", "the Courant number must lie in (0, 100]");
  core::validate_member("solver", solver);
}

namespace {

// The subsurface stress below every loaded node, in two scans in depth: to 1.5 b (the Hertzian
// maximum lies at 0.70-0.78 b, nearer with traction) in 48 steps of 0.031 b (the von Mises curve's
// flat top: its maximum within ~1e-3), and to 16 node spacings in steps of one (the asperities'
// stresses lie within a few contact spots' widths); each depth one convolution of the loads
// (subsurface_maximum).
constexpr int kDeepDepths = 48, kShallowDepths = 16;
constexpr double kDeepDepth = 1.5;

double state_code(NodeState s) { return static_cast<double>(static_cast<int>(s)); }

// The nodes [first, last] of `grid` as a grid of their own.
HalfPlaneGrid sub_grid(const HalfPlaneGrid& g, int first, int last) {
  return {g.start + first * g.spacing, g.spacing, last - first + 1};
}

// The peak over x of the flash temperature of one instant, and the peak heat flux.
std::pair<double, double> flash_peak(const HalfPlaneGrid& grid, const EhlField& f, const ContactInstant& c,
                                     const double coefficient[2], std::vector<double>& q) {
  const double slide = std::abs(c.speed1 - c.speed2);
  q.resize(f.shear.size());
  double q_max = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) q_max = std::max(q_max, q[i] = std::abs(f.shear[i]) * slide);
  if (!(q_max > 0.0)) return {0.0, 0.0};
  const std::vector<double> theta = flash_temperature(grid, q, c.speed1, c.speed2, coefficient[0], coefficient[1]);
  return {*std::max_element(theta.begin(), theta.end()), q_max};
}

// The von Mises maximum below the softer flank under the pressure and its traction, over the
// loaded nodes.
StressMaximum stress_maximum(const HalfPlaneGrid& grid, const std::vector<double>& pressure,
                             const std::vector<double>& traction, double nu, double half_width) {
  int first = grid.size, last = -1;
  for (int i = 0; i < grid.size; ++i)
    if (pressure[static_cast<std::size_t>(i)] > 0.0) first = std::min(first, i), last = i;
  if (last < 0) return {};
  const HalfPlaneGrid g = sub_grid(grid, first, last);
  const auto m = static_cast<std::size_t>(g.size);
  const std::span<const double> p(pressure.data() + first, m), q(traction.data() + first, m);
  const StressMaximum deep = subsurface_maximum(g, p, q, nu, kDeepDepth * half_width, kDeepDepths);
  const StressMaximum shallow = subsurface_maximum(g, p, q, nu, kShallowDepths * grid.spacing, kShallowDepths);
  return shallow.von_mises > deep.von_mises ? shallow : deep;
}

EhlProfile::Instant snapshot(const EhlField& f, double time) {
  EhlProfile::Instant s;
  s.time = time;
  s.pressure = f.pressure;
  s.film = f.film;
  s.shear = f.shear;
  s.state.reserve(f.state.size());
  for (NodeState k : f.state) s.state.push_back(state_code(k));
  return s;
}

}  // namespace

void rolled_heights(const FlankTrack& pinion, const FlankTrack& wheel, const HalfPlaneGrid& grid, double sigma_pinion,
                    double sigma_wheel, std::vector<double>& heights) {
  heights.resize(static_cast<std::size_t>(grid.size));
  const double e = grid.spacing;
  for (int j = 0; j < grid.size; ++j) {
    const double x = grid.x(j);
    // As StripSolver::gap: the pinion's point at x is sigma1c - x, the wheel's sigma2c + x.
    heights[static_cast<std::size_t>(j)] = track_mean(pinion, sigma_pinion - x - 0.5 * e, sigma_pinion - x + 0.5 * e) +
                                           track_mean(wheel, sigma_wheel + x - 0.5 * e, sigma_wheel + x + 0.5 * e);
  }
}

WindowResult solve_window(const FlankTrack& pinion, const FlankTrack& wheel, const WindowSetup& w) {
  Stopwatch watch;
  const ContactInstant& c = w.instant;
  const double u_slow = std::min(c.speed1, c.speed2), u_fast = std::max(c.speed1, c.speed2);
  if (!(u_slow > 0.0))  // a flank standing still at the contact (the base circle): no window ends
    throw std::invalid_argument(
        fmt::format("mixed EHL: a surface speed of {:.3g} m/s: the window needs both moving", u_slow));
  LineEhlSolver solver(w.fluid, w.composite_modulus, c, w.solver);
  const HalfPlaneGrid grid = solver.grid();
  WindowResult r;
  r.nodes = grid.size;
  r.spacing = grid.spacing;
  r.half_width = solver.hertz_half_width();
  r.duration = w.window * 2.0 * r.half_width / u_slow;
  r.steps = std::max(1, static_cast<int>(std::ceil(r.duration * u_fast / (w.time_step * grid.spacing))));
  r.dt = r.duration / r.steps;
  const double p_h = solver.hertz_pressure();
  const std::size_t n = static_cast<std::size_t>(grid.size);
  // The softer flank's traction: the field's shear is the slower surface's (in +x for u1 > u2).
  const bool wheel_slower = c.speed1 > c.speed2;
  const double traction_sign = (w.pinion_softer != wheel_slower) ? 1.0 : -1.0;

  std::vector<double> heights, q;
  std::vector<double> central, min_film, contact, share, peak, friction, film_friction, boundary, heat, flash, area,
      plastic, yielding_band, iterations, linear, transforms;
  EhlProfile::Instant at_peak, at_middle;
  double best_peak = -1.0;
  auto heights_at = [&](double t) {
    rolled_heights(pinion, wheel, grid, w.sigma_pinion + c.speed1 * t, w.sigma_wheel - c.speed2 * t, heights);
  };
  // The window's start. By default a lead-in: the smooth contact's steady solution, then time steps
  // from t = -T_lead, T_lead = lead_in b/u, over whose first half the heights grow linearly from
  // zero to their amplitude, so that the window starts from the state the moving surfaces leave.
  // (The steady rough contact at t = 0, lead_in = 0, locks oil in the valleys: on the shipped case
  // its windows' mean central films were up to 20 % thinner than from a lead-in, and where a lead-in
  // of 4 and of 8 b/u gave the same means within 2 %.) Without a lead-in the solver retries the
  // steady rough start at first order and by homotopy in the roughness.
  try {
    if (w.lead_in > 0.0) {
      r.lead_in_steps = static_cast<int>(std::ceil(w.lead_in * r.half_width / (c.entrainment() * r.dt)));
      solver.solve_steady(c, std::vector<double>(n, 0.0));
      const int ramp = std::max(1, r.lead_in_steps / 2);
      for (int j = r.lead_in_steps - 1; j >= 0; --j) {
        heights_at(-j * r.dt);
        const double grow = std::min(1.0, static_cast<double>(r.lead_in_steps - j) / ramp);
        for (double& h : heights) h *= grow;
        solver.step(c, heights, r.dt);
      }
    } else {
      heights_at(0.0);
      solver.solve_steady(c, heights);
    }
  } catch (const std::runtime_error& e) {
    throw WindowFailure(e.what(), true, 0, r.steps, 0.0, r.duration);
  }
  for (int k = 0; k <= r.steps; ++k) {
    const double t = k * r.dt;
    const EhlField* f = nullptr;
    if (k == 0) {
      f = &solver.field();
    } else {
      heights_at(t);
      try {
        f = &solver.step(c, heights, r.dt);
      } catch (const std::runtime_error& e) {
        throw WindowFailure(e.what(), false, k, r.steps, t, r.duration);
      }
    }
    central.push_back(f->central_film);
    min_film.push_back(f->min_film);
    contact.push_back(f->contact_fraction);
    share.push_back(f->asperity_share);
    peak.push_back(f->peak_pressure);
    friction.push_back(f->friction_coefficient);
    film_friction.push_back(f->film_friction);
    boundary.push_back(f->boundary_friction);
    iterations.push_back(f->iterations);
    const auto [theta, q_max] = flash_peak(grid, *f, c, w.thermal_coefficient, q);
    flash.push_back(theta);
    heat.push_back(q_max);
    // The contact nodes, and those of them where the flanks yield (the pressure held at the
    // softer flank's hardness).
    int touching = 0, yielding = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (f->state[i] == NodeState::contact) ++touching, yielding += f->yields[i];
    area.push_back(touching * grid.spacing / (2.0 * r.half_width));
    plastic.push_back(touching > 0 ? static_cast<double>(yielding) / touching : 0.0);
    yielding_band.push_back(f->yield_fraction);
    linear.push_back(f->linear_iterations);
    transforms.push_back(static_cast<double>(f->transforms));
    r.transform_seconds += f->transform_seconds;
    // Load balance, computed here from the pressures (not the solver's own figure).
    double load = 0.0;
    for (double p : f->pressure) load += p * grid.spacing;
    r.load_error_max = std::max(r.load_error_max, std::abs(load - c.line_load) / c.line_load);
    r.edge_pressure_max = std::max({r.edge_pressure_max, f->pressure.front() / p_h, f->pressure.back() / p_h});
    if (f->peak_pressure > best_peak) {
      best_peak = f->peak_pressure;
      if (w.keep_profile || w.subsurface) at_peak = snapshot(*f, t);
    }
    if (w.keep_profile && k == r.steps / 2) at_middle = snapshot(*f, t);
  }
  auto extreme = [](const std::vector<double>& v, bool largest) {
    return largest ? *std::max_element(v.begin(), v.end()) : *std::min_element(v.begin(), v.end());
  };
  r.central_film_mean = path_mean(central), r.central_film_min = extreme(central, false);
  r.min_film_mean = path_mean(min_film), r.min_film_min = extreme(min_film, false);
  r.contact_fraction_mean = path_mean(contact), r.contact_fraction_max = extreme(contact, true);
  r.asperity_share_mean = path_mean(share), r.asperity_share_max = extreme(share, true);
  r.peak_pressure_mean = path_mean(peak), r.peak_pressure_max = extreme(peak, true);
  r.friction_mean = path_mean(friction), r.friction_max = extreme(friction, true);
  r.film_friction_mean = path_mean(film_friction), r.boundary_friction_mean = path_mean(boundary);
  r.heat_flux_mean = path_mean(heat), r.heat_flux_max = extreme(heat, true);
  r.flash_mean = path_mean(flash), r.flash_max = extreme(flash, true);
  r.real_area_ratio_mean = path_mean(area), r.real_area_ratio_max = extreme(area, true);
  r.plastic_fraction_mean = path_mean(plastic);
  r.yield_fraction_max = extreme(yielding_band, true);
  r.iterations_mean = path_mean(iterations);
  r.linear_iterations_mean = path_mean(linear);
  r.transforms_mean = path_mean(transforms);
  if (w.subsurface) {
    std::vector<double> traction(n);
    for (std::size_t i = 0; i < n; ++i) traction[i] = traction_sign * at_peak.shear[i];
    r.stress = stress_maximum(grid, at_peak.pressure, traction, w.poisson_ratio, r.half_width);
  }
  if (w.keep_profile) {
    EhlProfile p;
    p.x.resize(n);
    for (std::size_t i = 0; i < n; ++i) p.x[i] = grid.x(static_cast<int>(i));
    p.peak = std::move(at_peak);
    p.middle = std::move(at_middle);
    r.profile = std::move(p);
  }
  r.seconds = watch.lap();
  return r;
}

namespace {

// The grid's nodes over a contact of half-width b: its domain [-inlet b, outlet b] in elements
// of at most `spacing`.
int nodes_for(const EhlOptions& o, double b, double spacing) {
  return static_cast<int>(std::ceil((o.inlet + o.outlet) * b / spacing * (1.0 - 1e-12)));
}

// The oil as the line solver takes it: the lubricated stage's, at the flanks' bulk temperature.
Fluid fluid_of(const FidelityInputs& in) {
  if (!in.film) throw std::logic_error("mixed EHL: solve() without the lubricated stage");
  const MixedEhlOptions& o = in.contact.mixed_ehl;
  Fluid f;
  f.set_oil_state(in.film->bulk_oil());
  f.viscosity_law = o.viscosity_law;
  f.compressible = o.compressible;
  f.flow = o.flow;
  return f;
}

ContactInstant instant_at(const PathState& p, std::size_t k) { return {p.line_load[k], p.radius[k], p.v1[k], p.v2[k]}; }

// A window that did not converge, at its position: where, and the key that changes what it asks.
core::KeyedError window_refusal(const WindowFailure& e, const PathState& p, std::size_t k, const std::string& point) {
  const std::string where = fmt::format(
      "at position {} of {} (s = {:.6g} mm{}, line load {:.6g} N/m, R {:.4g} mm, u1 {:.4g} m/s, u2 {:.4g} m/s)", k + 1,
      p.size(), p.s[k] * 1e3, point.empty() ? "" : ", point " + point, p.line_load[k], p.radius[k] * 1e3, p.v1[k],
      p.v2[k]);
  if (e.steady)
    return core::KeyedError(
        "mixed_ehl.tolerance",
        fmt::format(
            "{}: the start of its window (the steady contact and the lead-in): {}; a looser tolerance "
            "(mixed_ehl.tolerance), a finer grid (mixed_ehl.grid_spacing), a larger film floor "
            "(mixed_ehl.film_floor) or a lead-in from the smooth contact (mixed_ehl.lead_in > 0) ask less of it",
            where, e.what()));
  return core::KeyedError(
      "mixed_ehl.time_step",
      fmt::format("{}: time step {} of {} (t = {:.4g} of {:.4g} us into its window): {}; a smaller time step "
                  "(mixed_ehl.time_step, a Courant number) or a looser tolerance (mixed_ehl.tolerance) ask less of it",
                  where, e.step, e.steps, e.time * 1e6, e.duration * 1e6, e.what()));
}

// The whole path A -> E in one transient solve on the largest contact's grid.
WholePath solve_whole_path(const FidelityInputs& in, const MixedEhl::State& st, const WindowSetup& base) {
  Stopwatch watch;
  const PathState& p = in.path;
  const gear::SpurPair& pair = in.mesh.pair();
  const std::size_t n = p.size();
  const std::size_t k_ref =
      static_cast<std::size_t>(std::max_element(p.half_width.begin(), p.half_width.end()) - p.half_width.begin());
  EhlOptions o = base.solver;
  o.nodes = st.nodes_max;
  LineEhlSolver solver(base.fluid, base.composite_modulus, instant_at(p, k_ref), o);
  const HalfPlaneGrid& grid = solver.grid();
  // The contact point moves along the line of action at the base speed omega1 r_b1.
  const double v_base = in.mesh.pinion_speed() * pair.pinion().base_radius;
  const double duration = (p.s.back() - p.s.front()) / v_base;
  double u_fast = 0.0;
  for (std::size_t k = 0; k < n; ++k) u_fast = std::max({u_fast, p.v1[k], p.v2[k]});
  WholePath r;
  r.nodes = grid.size;
  r.steps = std::max(1, static_cast<int>(std::ceil(duration * u_fast / (base.time_step * grid.spacing))));
  const double dt = duration / r.steps, ds = n > 1 ? p.s[1] - p.s[0] : 1.0;
  const double rb[2] = {pair.pinion().base_radius, pair.wheel().base_radius};
  // The instant at s: linear between positions (the radii of curvature and the speeds are linear
  // in s, so exact; the load's jumps at B and D are spread over one interval), R from the radii.
  auto at = [&](double s, double& sigma1, double& sigma2) {
    const double f = std::clamp((s - p.s.front()) / ds, 0.0, static_cast<double>(n - 1));
    const std::size_t i = std::min(static_cast<std::size_t>(f), n - 2);
    const double a = f - static_cast<double>(i);
    auto lerp = [&](const std::vector<double>& v) { return (1.0 - a) * v[i] + a * v[i + 1]; };
    const double rho1 = lerp(p.rho1), rho2 = lerp(p.rho2);
    sigma1 = rho1 * rho1 / (2.0 * rb[0]);
    sigma2 = rho2 * rho2 / (2.0 * rb[1]);
    return ContactInstant{lerp(p.line_load), rho1 * rho2 / (rho1 + rho2), lerp(p.v1), lerp(p.v2)};
  };
  std::vector<double> sums[4], peaks(n, 0.0), counts(n, 0.0), heights;
  for (auto& v : sums) v.assign(n, 0.0);
  for (int k = 0; k <= r.steps; ++k) {
    const double s = p.s.front() + v_base * k * dt;
    double sigma1 = 0.0, sigma2 = 0.0;
    const ContactInstant c = at(s, sigma1, sigma2);
    rolled_heights(st.flanks.pinion.front(), st.flanks.wheel.front(), grid, sigma1, sigma2, heights);
    const EhlField& f = k == 0 ? solver.solve_steady(c, heights) : solver.step(c, heights, dt);
    double load = 0.0;
    for (double q : f.pressure) load += q * grid.spacing;
    r.load_error_max = std::max(r.load_error_max, std::abs(load - c.line_load) / c.line_load);
    const auto bin = static_cast<std::size_t>(std::clamp(std::lround((s - p.s.front()) / ds), 0L, long(n - 1)));
    sums[0][bin] += f.central_film, sums[1][bin] += f.min_film, sums[2][bin] += f.asperity_share;
    sums[3][bin] += f.friction_coefficient;
    peaks[bin] = std::max(peaks[bin], f.peak_pressure);
    counts[bin] += 1.0;
  }
  auto mean = [&](const std::vector<double>& sum) {
    std::vector<double> out(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) out[k] = counts[k] > 0.0 ? sum[k] / counts[k] : 0.0;
    return out;
  };
  r.central_film = mean(sums[0]), r.min_film = mean(sums[1]), r.asperity_share = mean(sums[2]);
  r.friction = mean(sums[3]), r.peak_pressure = peaks;
  r.seconds = watch.lap();
  return r;
}

}  // namespace

MixedEhl::State MixedEhl::prepare(const FidelityInputs& in, StageClock& clock) {
  // The caller's inputs, no option field: unkeyed.
  if (!in.flank_source) throw std::invalid_argument("the mixed-EHL fidelity needs the flanks' profiles");
  if (!in.lubricated) throw core::KeyedError("contact.fidelity", dry_case_rule(find_fidelity(name)));
  const MixedEhlOptions& o = in.contact.mixed_ehl;
  const PathState& p = in.path;
  const gear::SpurPair& pair = in.mesh.pair();
  State st;
  st.sigma = contact_arcs(pair, p);
  const double b_max = *std::max_element(p.half_width.begin(), p.half_width.end());
  const double domain = (o.solver.inlet + o.solver.outlet) * b_max;
  // The spacing at most (the automatic one may come out finer, at a profile's spacing).
  const double spacing = o.grid_spacing > 0.0 ? o.grid_spacing : domain / MixedEhlOptions::kAutomaticNodes;
  // Each flank as the windows read it: the pinion's point at x is sigma1c + u1 t - x, x over
  // [-inlet b, outlet b] and t over the window T = window 2b / min(u1, u2); the wheel's
  // sigma2c - u2 t + x. Two nodes more either side; the whole path's domain lies within these.
  double before[2] = {0.0, 0.0}, after[2] = {0.0, 0.0};
  for (std::size_t k = 0; k < p.size(); ++k) {
    const double b = p.half_width[k], u_slow = std::min(p.v1[k], p.v2[k]);
    if (!(u_slow > 0.0) || !(b > 0.0)) continue;  // refused at the solve, at its position
    const double t = o.window * 2.0 * b / u_slow;
    before[0] = std::max(before[0], o.solver.outlet * b);
    after[0] = std::max(after[0], p.v1[k] * t + o.solver.inlet * b);
    before[1] = std::max(before[1], p.v2[k] * t + o.solver.inlet * b);
    after[1] = std::max(after[1], o.solver.outlet * b);
  }
  for (int g = 0; g < 2; ++g) before[g] += 2.0 * spacing, after[g] += 2.0 * spacing;
  FlankSpan& span = st.span;
  span.reader = FlankSpan::Reader::grid;
  span.element_size = o.grid_spacing;  // 0: automatic, never coarser than a profile (below)
  span.strip_half_length = std::max(o.solver.inlet, o.solver.outlet) * b_max;
  span.elements = nodes_for(o.solver, b_max, spacing);
  set_span_ranges(span, pair, st.sigma, before, after);
  const int teeth[2] = {1, 1};
  st.flanks = in.flank_source(span, teeth);
  if (st.flanks.pinion.size() != 1 || st.flanks.wheel.size() != 1)
    throw std::logic_error("mixed-EHL run: the flank source gave the wrong number of teeth");
  clock.lap("flank_profiles");
  // The grid as run: the automatic one not coarser than either profile.
  st.grid_spacing =
      o.grid_spacing > 0.0
          ? o.grid_spacing
          : std::min({spacing, st.flanks.pinion.front().profile.spacing, st.flanks.wheel.front().profile.spacing});
  st.nodes_max = nodes_for(o.solver, b_max, st.grid_spacing);
  if (st.nodes_max > MixedEhlOptions::kMaxNodes)
    throw core::KeyedError(
        "mixed_ehl.grid_spacing",
        fmt::format("the largest contact's domain ({:.4g} mm) would need {} nodes of {:.4g} um, more than {}: a "
                    "coarser grid (not coarser than the flank profiles' spacing), or coarser profiles",
                    domain * 1e3, st.nodes_max, st.grid_spacing * 1e6, MixedEhlOptions::kMaxNodes));
  // The statistical model on the same flanks (both rough): the lubricated cycle beside it.
  build_rolled_flanks_model(in, st.span, st.flanks, name, clock, st.model);
  return st;
}

MixedEhl::Solution MixedEhl::solve(const FidelityInputs& in, State& st, const std::vector<double>& share,
                                   StageClock& clock) {
  Solution out;
  if (st.model) {
    out.statistical = solve_statistical(in, *st.model, StripFidelity::uncoupled, share, nullptr, {});
    clock.lap("statistical_model");
  }
  const ContactSettings& cs = in.contact;
  const MixedEhlOptions& o = cs.mixed_ehl;
  const PathState& p = in.path;
  const Material& m1 = *in.flanks.materials[0];
  const Material& m2 = *in.flanks.materials[1];
  const DeterministicOptions softer = deterministic_options(cs, m1, m2);  // the softer flank's hardness and nu
  out.fluid = fluid_of(in);
  out.hardness = softer.pressure_cap;
  WindowSetup base;
  base.fluid = out.fluid;
  base.composite_modulus = in.mesh.composite_modulus();
  base.solver = o.solver;
  base.solver.hardness = softer.pressure_cap;
  base.window = o.window;
  base.time_step = o.time_step;
  base.lead_in = o.lead_in;
  for (int g = 0; g < 2; ++g) base.thermal_coefficient[g] = in.film->thermal_contact_coefficient(g);
  base.poisson_ratio = softer.poisson_ratio;
  base.pinion_softer = m1.hardness <= m2.hardness;
  base.subsurface = cs.asperity_stress;
  const std::vector<bool> keep = kept_profiles(cs, p);
  const std::vector<std::string> names = path_point_names(p);
  const int n = static_cast<int>(p.size());
  for (int k = 0; k < n; ++k)
    if (!(p.line_load[static_cast<std::size_t>(k)] > 0.0))
      throw core::KeyedError(
          "mesh.dynamics",
          fmt::format("at position {} of {} (s = {:.6g} mm) the pair carries no load (the dynamic cycle's teeth part): "
                      "the mixed-EHL film has no load to carry there; run the static load sharing",
                      k + 1, n, p.s[static_cast<std::size_t>(k)] * 1e3));
  out.windows.resize(p.size());
  run_in_threads(
      position_threads(cs, n), n,
      [&](ThreadItems& items) {
        for (int i = items.take(); i >= 0; i = items.take()) {
          const auto k = static_cast<std::size_t>(i);
          WindowSetup w = base;
          w.instant = instant_at(p, k);
          w.solver.nodes = nodes_for(o.solver, p.half_width[k], st.grid_spacing);
          w.sigma_pinion = st.sigma[0][k];
          w.sigma_wheel = st.sigma[1][k];
          w.keep_profile = keep[k];
          try {
            out.windows[k] = solve_window(st.flanks.pinion.front(), st.flanks.wheel.front(), w);
          } catch (const WindowFailure& e) {
            throw window_refusal(e, p, k, names[k]);
          }
          if (out.windows[k].profile) {
            out.windows[k].profile->position = i;
            out.windows[k].profile->point = names[k];
            out.windows[k].profile->s = p.s[k];
          }
          items.finished();
        }
      },
      in.progress);
  clock.lap("mixed_ehl_windows");
  if (o.whole_path) {
    try {
      out.whole_path = solve_whole_path(in, st, base);
    } catch (const std::runtime_error& e) {
      throw core::KeyedError(
          "mixed_ehl.whole_path",
          fmt::format("the transient solve of the whole path A -> E did not converge: {}; a smaller time step "
                      "(mixed_ehl.time_step) or a looser tolerance (mixed_ehl.tolerance), or the positions' windows "
                      "alone (whole_path = false)",
                      e.what()));
    }
    clock.lap("mixed_ehl_whole_path");
  }
  return out;
}

namespace {

// The run's regime and verdict, and where its answer holds (/contact/validity).
void add_validity(const MixedEhlOptions& o, const MixedEhl::State& st, const std::vector<WindowResult>& w,
                  MeshContactResult& r) {
  // A pressure above this share of p_H at the domain's first or last node: the inlet or the outlet
  // cuts the film's pressure short (a fully flooded inlet builds from zero well ahead of the contact).
  constexpr double kEdgePressure = 1e-3;
  Series edge{"flag_domain_edge_loaded", "1", {}}, hard{"flag_flanks_yield", "1", {}};
  int n_edge = 0, n_hard = 0, touching = 0;
  double share_max = 0.0;
  for (const WindowResult& q : w) {
    const bool e = q.edge_pressure_max > kEdgePressure, h = q.yield_fraction_max > 0.0;
    edge.values.push_back(e ? 1.0 : 0.0);
    hard.values.push_back(h ? 1.0 : 0.0);
    n_edge += e, n_hard += h;
    touching += q.asperity_share_max > 0.0;
    share_max = std::max(share_max, q.asperity_share_max);
  }
  r.validity.push_back(std::move(edge));
  r.validity.push_back(std::move(hard));
  r.regime = touching == 0 ? "full film" : "mixed";
  r.verdict = fmt::format(
      "Mixed EHL of the flanks' profiles (nodes of {:.3g} um over -{:g} to {:g} Hertz half-widths, windows of {:g} "
      "contact widths at Courant number {:g}): {}; the asperities touch at {} of {} positions (their share of the "
      "load up to {:.3g}).",
      st.grid_spacing * 1e6, o.solver.inlet, o.solver.outlet, o.window, o.time_step,
      touching == 0 ? "the film separates the flanks everywhere" : "mixed lubrication", touching, w.size(), share_max);
  if (n_hard > 0)
    r.verdict += fmt::format(
        " At {} positions the flanks yield somewhere in the contact: the pressure is held at the softer flank's "
        "hardness there and the flanks flatten plastically (flag_flanks_yield).",
        n_hard);
  if (n_edge > 0)
    r.verdict += fmt::format(
        " At {} positions the pressure reaches the domain's ends: raise mixed_ehl.inlet or mixed_ehl.outlet.", n_edge);
  r.flag_counts = {{"domain_edge_loaded", n_edge}, {"flanks_yield", n_hard}};
}

MixedEhlSummary summary_of(const FidelityInputs& in, const MixedEhl::State& st, const MixedEhl::Solution& s) {
  const MixedEhlOptions& o = in.contact.mixed_ehl;
  MixedEhlSummary m;
  m.viscosity_law = choice_name(viscosity_law_choices(), o.viscosity_law);
  m.flow = choice_name(flow_model_choices(), o.flow);
  m.compressible = o.compressible ? 1.0 : 0.0;
  m.grid_spacing = st.grid_spacing;
  m.nodes_max = st.nodes_max;
  m.window = o.window, m.time_step = o.time_step, m.tolerance = o.solver.tolerance;
  m.lead_in = o.lead_in;
  m.inlet = o.solver.inlet, m.outlet = o.solver.outlet;
  m.film_floor = o.solver.film_floor, m.boundary_friction = o.solver.boundary_friction;
  m.hardness = s.hardness;
  m.eta = s.fluid.viscosity, m.alpha = s.fluid.pressure_viscosity;
  m.eyring_stress = s.fluid.eyring_stress, m.limiting_shear_coefficient = s.fluid.limiting_shear_coefficient;
  m.min_film = std::numeric_limits<double>::infinity();
  std::vector<double> share, friction;
  for (const WindowResult& w : s.windows) {
    m.steps += w.steps;
    m.window_seconds += w.seconds;
    m.transform_seconds += w.transform_seconds;
    m.min_film = std::min(m.min_film, w.min_film_min);
    m.max_asperity_share = std::max(m.max_asperity_share, w.asperity_share_max);
    m.max_peak_pressure = std::max(m.max_peak_pressure, w.peak_pressure_max);
    m.max_flash_temperature = std::max(m.max_flash_temperature, w.flash_max);
    m.max_von_mises = std::max(m.max_von_mises, w.stress.von_mises);
    m.max_load_error = std::max(m.max_load_error, w.load_error_max);
    share.push_back(w.asperity_share_mean);
    friction.push_back(w.friction_mean);
  }
  m.mean_asperity_share = path_mean(share);
  m.mean_friction = path_mean(friction);
  if (s.whole_path) {
    m.whole_path = 1.0;
    m.whole_path_steps = s.whole_path->steps;
    m.whole_path_seconds = s.whole_path->seconds;
    m.max_load_error = std::max(m.max_load_error, s.whole_path->load_error_max);
  }
  return m;
}

}  // namespace

void MixedEhl::write(const FidelityInputs& in, State& st, Solution& s, MeshContactResult& r) {
  if (s.statistical) write_statistical_beside(in, *st.model, *s.statistical, r);
  const ContactSettings& cs = in.contact;
  using W = WindowResult;
  using C = Column<W>;
  // /contact: the asperity contact within the film, as the deterministic fidelity names it.
  if (cs.real_area)
    add_columns<W>(r.contact, s.windows,
                   {C{"real_area_ratio", "1", [](const W& w) { return w.real_area_ratio_mean; }},
                    C{"max_pressure_Pa", "Pa", [](const W& w) { return w.peak_pressure_max; }}});
  if (cs.plastic_fraction)
    add_columns<W>(r.contact, s.windows,
                   {C{"plastic_area_fraction", "1", [](const W& w) { return w.plastic_fraction_mean; }}});
  if (cs.asperity_stress)
    add_columns<W>(r.contact, s.windows,
                   {C{"max_von_mises_Pa", "Pa", [](const W& w) { return w.stress.von_mises; }},
                    C{"max_von_mises_depth_m", "m", [](const W& w) { return w.stress.depth; }},
                    C{"max_von_mises_x_m", "m", [](const W& w) { return w.stress.x; }}});
  // /mixed_ehl: the windows' time means and extremes.
  add_columns<W>(r.mixed_ehl, s.windows,
                 {C{"ehl_central_film_mean_m", "m", [](const W& w) { return w.central_film_mean; }},
                  C{"ehl_central_film_min_m", "m", [](const W& w) { return w.central_film_min; }},
                  C{"ehl_min_film_mean_m", "m", [](const W& w) { return w.min_film_mean; }},
                  C{"ehl_min_film_min_m", "m", [](const W& w) { return w.min_film_min; }},
                  C{"ehl_contact_fraction_mean", "1", [](const W& w) { return w.contact_fraction_mean; }},
                  C{"ehl_contact_fraction_max", "1", [](const W& w) { return w.contact_fraction_max; }},
                  C{"ehl_asperity_share_mean", "1", [](const W& w) { return w.asperity_share_mean; }},
                  C{"ehl_asperity_share_max", "1", [](const W& w) { return w.asperity_share_max; }},
                  C{"ehl_peak_pressure_mean_Pa", "Pa", [](const W& w) { return w.peak_pressure_mean; }},
                  C{"ehl_peak_pressure_max_Pa", "Pa", [](const W& w) { return w.peak_pressure_max; }},
                  C{"ehl_friction_coefficient_mean", "1", [](const W& w) { return w.friction_mean; }},
                  C{"ehl_friction_coefficient_max", "1", [](const W& w) { return w.friction_max; }},
                  C{"ehl_film_friction_mean_N_per_m", "N/m", [](const W& w) { return w.film_friction_mean; }},
                  C{"ehl_boundary_friction_mean_N_per_m", "N/m", [](const W& w) { return w.boundary_friction_mean; }},
                  C{"ehl_heat_flux_peak_mean_W_per_m2", "W/m^2", [](const W& w) { return w.heat_flux_mean; }},
                  C{"ehl_heat_flux_peak_max_W_per_m2", "W/m^2", [](const W& w) { return w.heat_flux_max; }},
                  C{"ehl_flash_temperature_mean_K", "K", [](const W& w) { return w.flash_mean; }},
                  C{"ehl_flash_temperature_max_K", "K", [](const W& w) { return w.flash_max; }},
                  C{"ehl_real_area_ratio_max", "1", [](const W& w) { return w.real_area_ratio_max; }},
                  C{"ehl_load_error_max", "1", [](const W& w) { return w.load_error_max; }},
                  C{"ehl_nodes", "1", [](const W& w) { return static_cast<double>(w.nodes); }},
                  C{"ehl_time_steps", "1", [](const W& w) { return static_cast<double>(w.steps); }},
                  C{"ehl_window_s", "s", [](const W& w) { return w.duration; }},
                  C{"ehl_lead_in_steps", "1", [](const W& w) { return static_cast<double>(w.lead_in_steps); }},
                  C{"ehl_yield_fraction_max", "1", [](const W& w) { return w.yield_fraction_max; }},
                  C{"ehl_newton_iterations_mean", "1", [](const W& w) { return w.iterations_mean; }},
                  C{"ehl_gmres_iterations_mean", "1", [](const W& w) { return w.linear_iterations_mean; }},
                  C{"ehl_transforms_mean", "1", [](const W& w) { return w.transforms_mean; }}});
  if (s.whole_path) {
    const WholePath& wp = *s.whole_path;
    r.mixed_ehl.push_back({"ehl_path_central_film_m", "m", wp.central_film});
    r.mixed_ehl.push_back({"ehl_path_min_film_m", "m", wp.min_film});
    r.mixed_ehl.push_back({"ehl_path_asperity_share", "1", wp.asperity_share});
    r.mixed_ehl.push_back({"ehl_path_peak_pressure_Pa", "Pa", wp.peak_pressure});
    r.mixed_ehl.push_back({"ehl_path_friction_coefficient", "1", wp.friction});
  }
  add_validity(cs.mixed_ehl, st, s.windows, r);
  r.mixed_ehl_summary = summary_of(in, st, s);
  for (WindowResult& w : s.windows)
    if (w.profile) r.ehl_profiles.push_back(std::move(*w.profile));
}

}  // namespace geartrib::contact::mixed_ehl
