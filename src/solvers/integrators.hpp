// The ODE integrators of the mesh dynamics by their engine (gear::DynamicsEngine): cvode (SUNDIALS
// CVODE, BDF) or odeint (Boost.Odeint Dormand-Prince 5(4)).
#pragma once

#include "core/ode_integrator.hpp"
#include "gear/mesh_dynamics.hpp"

#include <memory>

namespace geartrib::solvers {

// Throws std::invalid_argument for DynamicsEngine::none (no integrator).
std::unique_ptr<OdeIntegrator> make_integrator(gear::DynamicsEngine engine);

}  // namespace geartrib::solvers
