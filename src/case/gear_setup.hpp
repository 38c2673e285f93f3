// The case's gear mesh and its dynamics (a translator, case/ above the physics).
#pragma once

#include "case/case.hpp"
#include "gear/gear_mesh.hpp"
#include "gear/mesh_dynamics.hpp"

namespace geartrib::gear {

// The case's pair with its bodies' materials and mesh settings at its operating point. Throws
// GeometryError for an impossible pair.
GearMesh case_mesh(const Case& c);
// The case's dynamics settings with the solid discs' density from the pinion's material.
DynamicsSettings dynamics_settings(const Case& c);

}  // namespace geartrib::gear
