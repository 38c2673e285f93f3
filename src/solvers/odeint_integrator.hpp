// Boost.Odeint behind core/ode_integrator.hpp: the adaptive Dormand-Prince 5(4) stepper with
// dense output (explicit).
#pragma once

#include "core/ode_integrator.hpp"

namespace geartrib::solvers {

class OdeintIntegrator final : public OdeIntegrator {
 public:
  std::string name() const override { return "odeint"; }
  long integrate(const OdeSystem& system, double t0, double t1, std::vector<double>& y,
                 const std::vector<double>& sample_times, std::vector<std::vector<double>>& samples,
                 const OdeTolerances& tolerances) const override;
};

}  // namespace geartrib::solvers
