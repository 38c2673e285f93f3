// The ODE integrators by name: "cvode" (SUNDIALS CVODE, BDF) or "odeint" (Boost.Odeint
// Dormand-Prince 5(4)).
#pragma once

#include "core/ode_integrator.hpp"

#include <memory>
#include <string_view>

namespace geartrib::solvers {

std::unique_ptr<OdeIntegrator> make_integrator(std::string_view name);  // throws std::invalid_argument

}  // namespace geartrib::solvers
