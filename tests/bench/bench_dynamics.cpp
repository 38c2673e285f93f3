// The steady mesh cycle of the reference pair at 1000 rpm by both integrators at several
// tolerances: time, steps, and the error of the mesh force against a CVODE reference at 1e-12.
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "solvers/integrators.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

using namespace geartrib;

namespace {
const Case& reference_case() {
  static const Case c =
      io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30.toml"));
  return c;
}
constexpr double kSpeed = 1000.0 * 2.0 * std::numbers::pi / 60.0;

const gear::SteadyCycle& reference_cycle(const gear::MeshDynamics& dyn) {
  static const gear::SteadyCycle r = [&] {
    return dyn.steady_cycle(*solvers::make_integrator(gear::DynamicsEngine::cvode), kSpeed);
  }();
  return r;
}

void steady_cycle(benchmark::State& state, gear::DynamicsEngine engine) {
  const gear::GearMesh mesh = gear::case_mesh(reference_case());
  gear::DynamicsSettings tight = gear::dynamics_settings(reference_case());
  tight.tolerances.relative = 1e-12;
  const gear::MeshDynamics reference(mesh, tight);
  const gear::SteadyCycle& ref = reference_cycle(reference);
  gear::DynamicsSettings s = gear::dynamics_settings(reference_case());
  s.tolerances.relative = std::pow(10.0, -static_cast<double>(state.range(0)));
  const gear::MeshDynamics dyn(mesh, s);
  const auto integrator = solvers::make_integrator(engine);
  gear::SteadyCycle c;
  for (auto _ : state) c = dyn.steady_cycle(*integrator, kSpeed);
  double error = 0.0;
  for (std::size_t i = 0; i < c.force.size(); ++i)
    error = std::max(error, std::abs(c.force[i] - ref.force[i]) / c.static_force);
  state.counters["rtol_exp"] = -static_cast<double>(state.range(0));
  state.counters["error"] = error;
  state.counters["steps"] = static_cast<double>(c.steps);
  state.counters["cycles"] = c.cycles;
}
}  // namespace

BENCHMARK_CAPTURE(steady_cycle, cvode, gear::DynamicsEngine::cvode)
    ->DenseRange(4, 10, 2)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(steady_cycle, odeint, gear::DynamicsEngine::odeint)
    ->DenseRange(4, 10, 2)
    ->Unit(benchmark::kMillisecond);
