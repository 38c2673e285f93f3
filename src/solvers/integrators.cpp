#include "solvers/integrators.hpp"

#include "solvers/cvode_integrator.hpp"
#include "solvers/odeint_integrator.hpp"

#include <stdexcept>

namespace geartrib::solvers {

std::unique_ptr<OdeIntegrator> make_integrator(gear::DynamicsEngine engine) {
  switch (engine) {
    case gear::DynamicsEngine::cvode:
      return std::make_unique<CvodeIntegrator>();
    case gear::DynamicsEngine::odeint:
      return std::make_unique<OdeintIntegrator>();
    case gear::DynamicsEngine::none:
      break;
  }
  throw std::invalid_argument("no integrator for the dynamics engine 'none' (known: cvode, odeint)");
}

}  // namespace geartrib::solvers
