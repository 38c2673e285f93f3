// SUNDIALS CVODE (variable-order BDF, dense direct linear solver, difference-quotient Jacobian)
// behind core/ode_integrator.hpp.
#pragma once

#include "core/ode_integrator.hpp"

namespace geartrib::solvers {

class CvodeIntegrator final : public OdeIntegrator {
 public:
  std::string name() const override { return "cvode"; }
  long integrate(const OdeSystem& system, double t0, double t1, std::vector<double>& y,
                 const std::vector<double>& sample_times, std::vector<std::vector<double>>& samples,
                 const OdeTolerances& tolerances) const override;
};

}  // namespace geartrib::solvers
