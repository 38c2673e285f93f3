#include "gear/gear_mesh.hpp"

namespace geartrib::gear {

namespace {
ToothMaterial tooth_material(const Material& m) { return {m.youngs_modulus, m.poisson_ratio}; }
}  // namespace

GearMesh::GearMesh(const Case& c, std::optional<LoadSharing> method)
    : composite_modulus_(geartrib::composite_modulus(c.pinion.material, c.wheel.material)),
      pinion_speed_(c.operating.pinion_speed),
      pair_(c.gear_pair),
      stiffness_(pair_, tooth_material(c.pinion.material), tooth_material(c.wheel.material), composite_modulus_,
                 c.mesh.plane_strain),
      analysis_(pair_, stiffness_, method.value_or(parse_load_sharing(c.mesh.load_sharing)),
                c.operating.pinion_torque / pair_.pinion().base_radius, composite_modulus_) {}

}  // namespace geartrib::gear
