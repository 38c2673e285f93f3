#include "solvers/integrators.hpp"

#include "solvers/cvode_integrator.hpp"
#include "solvers/odeint_integrator.hpp"

#include <stdexcept>
#include <string>

namespace geartrib::solvers {

std::unique_ptr<OdeIntegrator> make_integrator(std::string_view name) {
  if (name == "cvode") return std::make_unique<CvodeIntegrator>();
  if (name == "odeint") return std::make_unique<OdeintIntegrator>();
  throw std::invalid_argument("unknown integrator '" + std::string(name) + "' (known: cvode, odeint)");
}

}  // namespace geartrib::solvers
