#include "case/gear_setup.hpp"

namespace geartrib::gear {

GearMesh case_mesh(const Case& c) {
  return GearMesh(c.gear_pair, c.pinion.material, c.wheel.material, c.mesh, c.operating.pinion_torque,
                  c.operating.pinion_speed);
}

DynamicsSettings dynamics_settings(const Case& c) {
  DynamicsSettings s = c.dynamics;
  s.density = c.pinion.material.density;
  return s;
}

}  // namespace geartrib::gear
