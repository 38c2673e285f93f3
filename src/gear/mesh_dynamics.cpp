#include "gear/mesh_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace geartrib::gear {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr NamedChoice<DynamicsEngine> kEngineNames[] = {
    {DynamicsEngine::none, "none"}, {DynamicsEngine::cvode, "cvode"}, {DynamicsEngine::odeint, "odeint"}};
}  // namespace

std::span<const NamedChoice<DynamicsEngine>> dynamics_engine_choices() { return kEngineNames; }
const char* dynamics_engine_name(DynamicsEngine engine) { return choice_name(dynamics_engine_choices(), engine); }

void DynamicsSettings::validate() const {
  using core::KeyedError;
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0))
    throw KeyedError("damping_ratio", "damping ratio must lie in [0, 1)");
  if (!(backlash >= 0.0)) throw KeyedError("backlash", "backlash must not be negative (0: no back-flank contact)");
  if (!(pinion_inertia >= 0.0)) throw KeyedError("pinion_inertia", "inertias must not be negative");
  if (!(wheel_inertia >= 0.0)) throw KeyedError("wheel_inertia", "inertias must not be negative");
  if (!(density > 0.0)) throw KeyedError("density", "density must be positive");
  if (!(tolerances.relative > 0.0)) throw KeyedError("tolerances.relative", "relative tolerance must be positive");
  if (!(steady_tolerance >= 0.0)) throw KeyedError("steady_tolerance", "steady-state tolerance must not be negative");
  if (max_cycles < 1) throw KeyedError("max_cycles", "max_cycles >= 1 and samples_per_cycle >= 8");
  if (samples_per_cycle < 8) throw KeyedError("samples_per_cycle", "max_cycles >= 1 and samples_per_cycle >= 8");
}

MeshDynamics::MeshDynamics(const GearMesh& mesh, const DynamicsSettings& settings) : mesh_(mesh), settings_(settings) {
  settings_.validate();
  const SpurPair& pair = mesh.pair();
  const double b = pair.spec().face_width;
  auto disc = [&](const GearBody& g, double given) {
    if (given > 0.0) return given;
    const double r = g.pitch_radius, ri = g.bore_radius;
    return 0.5 * settings_.density * kPi * b * (std::pow(r, 4) - std::pow(ri, 4));
  };
  const double i1 = disc(pair.pinion(), settings_.pinion_inertia), i2 = disc(pair.wheel(), settings_.wheel_inertia);
  const double rb1 = pair.pinion().base_radius, rb2 = pair.wheel().base_radius;
  mass_ = i1 * i2 / (i1 * rb2 * rb2 + i2 * rb1 * rb1);
  // Stiffness over one cycle, u = s0 - A in [0, p_b): two smooth segments split where the
  // leading pair leaves at E (u = B - A), each tabulated and interpolated by a cubic B-spline.
  const PathOfContact& p = pair.path();
  split_ = std::max(0.0, p.b - p.a);
  const std::vector<std::pair<double, double>> parts =
      split_ > 0.0 ? std::vector<std::pair<double, double>>{{0.0, split_}, {split_, p.base_pitch}}
                   : std::vector<std::pair<double, double>>{{0.0, p.base_pitch}};
  double integral = 0.0;
  for (auto [lo, hi] : parts) {
    const int n = 129;
    std::vector<double> k(n);
    const double h = (hi - lo) / (n - 1);
    for (int i = 0; i < n; ++i) {
      // Inside the segment (the jump sits at its ends): one-sided evaluation at the ends.
      const double u = std::clamp(lo + i * h, lo + 1e-9 * p.base_pitch, hi - 1e-9 * p.base_pitch);
      double ks = 0.0;
      for (double s = p.a + u; s <= p.e + 1e-12; s += p.base_pitch) ks += mesh.stiffness().pair(s).stiffness;
      k[static_cast<std::size_t>(i)] = ks;
    }
    segments_.emplace_back(k.begin(), k.end(), lo, h);
    segment_start_.push_back(lo);
    segment_end_.push_back(hi);
    for (int i = 0; i + 1 < n; ++i)
      integral += 0.5 * (k[static_cast<std::size_t>(i)] + k[static_cast<std::size_t>(i + 1)]) * h;
  }
  mean_stiffness_ = integral / p.base_pitch;
  damping_ = 2.0 * settings_.damping_ratio * std::sqrt(mean_stiffness_ * mass_);
  backlash_ = settings_.backlash > 0.0 ? settings_.backlash : std::numeric_limits<double>::infinity();
  contact_ = mesh.tooth_contact();
}

std::vector<double> MeshDynamics::positions(double u) const {
  const PathOfContact& p = mesh_.pair().path();
  std::vector<double> out;
  for (double s = p.a + u; s <= p.e + 1e-12 * p.line_length; s += p.base_pitch) out.push_back(s);
  return out;
}

CompatibilitySolution MeshDynamics::linear_solve(const std::vector<double>& at, std::size_t first) const {
  std::vector<PairContact> pairs = contact_->pairs(at);
  pairs.erase(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(first));
  for (PairContact& c : pairs) c.hertz.model = HertzApproach::linear;  // the stiffness model's pairs
  return solve_compatibility(pairs, mesh_.normal_force());
}

double MeshDynamics::elastic_force(double x, double u) const {
  if (!contact_) {
    const double g = x > 0.0 ? x : (x <= -backlash_ ? x + backlash_ : 0.0);
    return stiffness(u) * g;
  }
  const PathOfContact& p = mesh_.pair().path();
  double f = 0.0;
  int j = 0;
  for (double s = p.a + u; s <= p.e + 1e-12 * p.line_length; s += p.base_pitch, ++j)
    f += contact_->linear_stiffness(s) * std::max(0.0, x - contact_->separation(s, j));
  if (x <= -backlash_) f += stiffness(u) * (x + backlash_);  // the back flanks: unmodified
  return f;
}

double MeshDynamics::static_deflection(double u) const {
  if (!contact_) return mesh_.normal_force() / stiffness(u);
  return linear_solve(positions(u), 0).approach;
}

double MeshDynamics::natural_frequency() const { return std::sqrt(mean_stiffness_ / mass_) / (2.0 * kPi); }

double MeshDynamics::quasi_static_peak() const {
  const double force = mesh_.normal_force();
  const double zeta = settings_.damping_ratio;
  const double overshoot = std::exp(-zeta * kPi / std::sqrt(1.0 - zeta * zeta));
  if (contact_) {
    double at_d = force, at_b = force;
    // Entry at A (u = 0): the pairs ahead carry F at x0; the entering pair adds k_A (x0 - e_A)+.
    const std::vector<double> entry = positions(0.0);
    if (entry.size() >= 2) {
      const double x0 = linear_solve(entry, 1).approach;
      at_d = force + contact_->linear_stiffness(entry[0]) * std::max(0.0, x0 - contact_->separation(entry[0], 0));
    }
    // Exit at E (u = B - A): the leaving pair's static load returns with the overshoot.
    const PathOfContact& p = mesh_.pair().path();
    const std::vector<double> exit = positions(split_);
    if (split_ > 0.0 && exit.size() >= 2 && exit.back() >= p.e - 1e-9 * p.line_length)
      at_b = force + linear_solve(exit, 0).loads.back() * overshoot;
    return std::max({force, at_b, at_d});
  }
  if (segments_.size() < 2) return force;  // no step within the cycle
  const double k_double_end = segments_[0](segment_end_[0]), k_single_start = segments_[1](segment_start_[1]);
  const double k_single_end = segments_[1](segment_end_[1]), k_double_start = segments_[0](0.0);
  const double at_b = force * (1.0 + (1.0 - k_single_start / k_double_end) * overshoot);  // softening step
  const double at_d = force * k_double_start / k_single_end;                              // stiffening step
  return std::max({force, at_b, at_d});
}

double MeshDynamics::stiffness(double u) const {
  const double pb = mesh_.pair().path().base_pitch;
  u = std::fmod(u, pb);
  if (u < 0.0) u += pb;
  for (std::size_t i = 0; i < segments_.size(); ++i)
    if (u <= segment_end_[i] || i + 1 == segments_.size())
      return segments_[i](std::clamp(u, segment_start_[i], segment_end_[i]));
  return segments_.back()(u);
}

std::pair<double, double> MeshDynamics::speed_range() const {
  // f_mesh = v / p_b with v = r_b1 w along the line of action: w = f_mesh p_b / r_b1.
  const double per_hertz = mesh_.pair().path().base_pitch / mesh_.pair().pinion().base_radius;  // [rad/s per Hz]
  return {1e-5 * natural_frequency() * per_hertz, 1e3 * natural_frequency() * per_hertz};
}

SteadyCycle MeshDynamics::steady_cycle(const OdeIntegrator& integrator, double pinion_speed) const {
  const auto [slowest, fastest] = speed_range();
  if (!(pinion_speed >= slowest && pinion_speed <= fastest))
    throw std::invalid_argument(fmt::format(
        "pinion speed {:.6g} rad/s outside the dynamics model's range {:.4g} to {:.4g} rad/s (mesh frequency 1e-5 "
        "to 1e3 times the natural frequency {:.4g} Hz)",
        pinion_speed, slowest, fastest, natural_frequency()));
  const PathOfContact& p = mesh_.pair().path();
  const double velocity = mesh_.pair().pinion().base_radius * pinion_speed;  // along the line of action [m/s]
  const double period = p.base_pitch / velocity;
  const double force = mesh_.normal_force();
  const double x_static = force / mean_stiffness_;
  const double omega_n = 2.0 * kPi * natural_frequency();
  OdeSystem sys;
  sys.size = 2;
  sys.rhs = [&](double t, const std::vector<double>& y, std::vector<double>& dy) {
    dy.resize(2);
    dy[0] = y[1];
    dy[1] = (force - damping_ * y[1] - elastic_force(y[0], velocity * t)) / mass_;
  };
  OdeTolerances tol = settings_.tolerances;
  if (!(tol.absolute > 0.0)) tol.absolute = tol.relative * x_static;
  // Segment boundaries in time: the stiffness jumps at u = B - A and at u = p_b.
  std::vector<double> bounds{0.0};
  for (double e : segment_end_) bounds.push_back(e / velocity);
  const int m = settings_.samples_per_cycle;
  SteadyCycle c;
  c.pinion_speed = pinion_speed;
  c.period = period;
  c.mesh_frequency = 1.0 / period;
  c.static_force = force;
  std::vector<double> y{static_deflection(0.0), 0.0};
  std::vector<std::vector<double>> samples;
  double late_peak = 0.0;  // largest mesh force over the last cycles, for an aperiodic response
  for (int cycle = 1; cycle <= settings_.max_cycles; ++cycle) {
    const std::vector<double> start = y;
    samples.clear();
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
      std::vector<double> times;
      for (int i = 0; i < m; ++i) {
        const double t = period * i / m;
        if (t >= bounds[k] && (t < bounds[k + 1] || (k + 2 == bounds.size() && t <= bounds[k + 1]))) times.push_back(t);
      }
      // Each segment is integrated in its own time; the integrator restarts at the jump.
      c.steps += integrator.integrate(sys, bounds[k], bounds[k + 1], y, times, samples, tol);
    }
    // Per pair, the pairs are counted from the last to enter: at the cycle's end each moves one up
    // and its separation by the base pitch mismatch, so the deflection moves with it (the same
    // contact state in the next cycle's count).
    if (contact_) y[0] += contact_->flank(1).base_pitch_deviation() - contact_->flank(0).base_pitch_deviation();
    const double change =
        std::max(std::abs(y[0] - start[0]) / x_static, std::abs(y[1] - start[1]) / (omega_n * x_static));
    c.cycles = cycle;
    c.last_change = change;
    if (cycle > settings_.max_cycles - 100)
      for (int i = 0; i < m; ++i) {
        const double x = samples[static_cast<std::size_t>(i)][0], v = samples[static_cast<std::size_t>(i)][1];
        const double fe = elastic_force(x, velocity * period * i / m);
        if (fe != 0.0) late_peak = std::max(late_peak, fe + damping_ * v);
      }
    const double steady = settings_.steady_tolerance > 0.0 ? settings_.steady_tolerance : 100.0 * tol.relative;
    if (change < steady) break;
    if (cycle == settings_.max_cycles) c.periodic = false;
  }
  for (int i = 0; i < m; ++i) {
    const double t = period * i / m, u = velocity * t;
    const double x = samples[static_cast<std::size_t>(i)][0], v = samples[static_cast<std::size_t>(i)][1];
    const double k = stiffness(u);
    const double fe = elastic_force(x, u);
    const double f = fe != 0.0 ? fe + damping_ * v : 0.0;
    c.time.push_back(t);
    c.position.push_back(p.a + u);
    c.stiffness.push_back(k);
    c.deflection.push_back(x);
    c.static_deflection.push_back(static_deflection(u));
    c.force.push_back(f);
    c.dynamic_factor = std::max(c.dynamic_factor, f / force);
    // Contact is lost where no pair touches: x <= 0, or per pair x at or below every separation.
    double least = 0.0;
    if (contact_) {
      const std::vector<double> at = positions(u);
      least = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < at.size(); ++j)
        least = std::min(least, contact_->separation(at[j], static_cast<int>(j)));
    }
    c.contact_lost = c.contact_lost || x <= least;
  }
  if (!c.periodic) c.dynamic_factor = std::max(c.dynamic_factor, late_peak / force);
  c.dynamic_factor_quasi_static = c.dynamic_factor * force / quasi_static_peak();
  return c;
}

double MeshDynamics::pair_force(const SteadyCycle& cycle, double s) const {
  const PathOfContact& p = mesh_.pair().path();
  double u = std::fmod(s - p.a, p.base_pitch);
  if (u < 0.0) u += p.base_pitch;
  // Linear interpolation of the periodic mesh force at u.
  const double x = u / p.base_pitch * static_cast<double>(cycle.force.size());
  const std::size_t i = static_cast<std::size_t>(x) % cycle.force.size();
  const std::size_t j = (i + 1) % cycle.force.size();
  const double t = x - std::floor(x);
  const double mesh_force = (1.0 - t) * cycle.force[i] + t * cycle.force[j];
  if (!contact_) return mesh_.stiffness().pair(s).stiffness / stiffness(u) * mesh_force;
  // Per pair: its elastic force's part of the mesh's (the damping shared alike).
  const double deflection = (1.0 - t) * cycle.deflection[i] + t * cycle.deflection[j];
  const int k = static_cast<int>(std::floor((s - p.a) / p.base_pitch + 1e-12));
  const double own = contact_->linear_stiffness(s) * std::max(0.0, deflection - contact_->separation(s, k));
  const double all = elastic_force(deflection, u);
  return all > 0.0 ? own / all * mesh_force : 0.0;
}

}  // namespace geartrib::gear
