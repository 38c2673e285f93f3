#include "solvers/odeint_integrator.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include <boost/numeric/odeint.hpp>

#include <algorithm>

namespace geartrib::solvers {

long OdeintIntegrator::integrate(const OdeSystem& system, double t0, double t1, std::vector<double>& y,
                                 const std::vector<double>& sample_times, std::vector<std::vector<double>>& samples,
                                 const OdeTolerances& tol) const {
  namespace odeint = boost::numeric::odeint;
  using State = std::vector<double>;
  auto stepper = odeint::make_dense_output(tol.absolute, tol.relative, odeint::runge_kutta_dopri5<State>());
  auto rhs = [&](const State& x, State& dxdt, double t) { system.rhs(t, x, dxdt); };
  const double span = t1 - t0;
  stepper.initialize(y, t0, std::min(span, 1e-3 * span));
  long steps = 0;
  std::size_t next = 0;
  while (next < sample_times.size() && sample_times[next] <= t0) samples.push_back(y), ++next;
  // A bound on the steps (the adaptive step can collapse on a stiff or singular system): an error
  // naming the interval instead of a hang. The cycles of geartrib take 10^3 to 10^6 steps.
  constexpr long kMaxSteps = 50'000'000;
  while (stepper.current_time() < t1) {
    if (steps == kMaxSteps)
      throw std::runtime_error(
          fmt::format("odeint: more than {} steps from t = {:.6g} s to {:.6g} s (stopped at {:.6g} s)", kMaxSteps, t0,
                      t1, stepper.current_time()));
    // Never step past t1: the right-hand side jumps there.
    if (stepper.current_time() + stepper.current_time_step() > t1)
      stepper.initialize(stepper.current_state(), stepper.current_time(), t1 - stepper.current_time());
    stepper.do_step(rhs);
    ++steps;
    while (next < sample_times.size() && sample_times[next] <= stepper.current_time()) {
      State s(y.size());
      stepper.calc_state(sample_times[next], s);
      samples.push_back(std::move(s));
      ++next;
    }
  }
  y = stepper.current_state();
  return steps;
}

}  // namespace geartrib::solvers
