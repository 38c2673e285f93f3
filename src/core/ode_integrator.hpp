// An initial-value problem y' = f(t, y) and the interface of an integrator for it. The physics
// states its systems this way; the integrators (SUNDIALS CVODE, Boost.Odeint; src/solvers/) are
// plugged in by the caller.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace geartrib {

struct OdeSystem {
  int size = 0;
  std::function<void(double t, const std::vector<double>& y, std::vector<double>& dydt)> rhs;
};

struct OdeTolerances {
  double relative = 1e-8;
  double absolute = 1e-12;  // in the units of y
};

class OdeIntegrator {
 public:
  virtual ~OdeIntegrator() = default;
  virtual std::string name() const = 0;
  // Integrates from t0 to t1 (the right-hand side smooth on the open interval); y holds the state
  // at t0 on entry and at t1 on return. The states at `sample_times` (ascending, inside
  // [t0, t1]) are appended to `samples`. Returns the number of internal steps. Throws
  // std::runtime_error on failure.
  virtual long integrate(const OdeSystem& system, double t0, double t1, std::vector<double>& y,
                         const std::vector<double>& sample_times, std::vector<std::vector<double>>& samples,
                         const OdeTolerances& tolerances) const = 0;
};

}  // namespace geartrib
