#include "gear/gear_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace geartrib::gear {

namespace {
ToothMaterial tooth_material(const Material& m) { return {m.youngs_modulus, m.poisson_ratio}; }
}  // namespace

void MeshSettings::validate() const {
  if (positions < 2) throw core::KeyedError("positions", "at least 2 positions sample a base pitch");
  for (int g = 0; g < 2; ++g) {
    const std::string prefix = fmt::format("modification[{}].", g);
    try {
      modification[g].validate();
    } catch (const core::KeyedError& e) {
      throw core::KeyedError(prefix + e.key(), e.what());
    }
    if (modification[g].any() && load_sharing != LoadSharing::compatibility)
      throw core::KeyedError(prefix + modification[g].first_given(),
                             "profile modifications act through load_sharing = \"compatibility\"; the load sharing "
                             "is " +
                                 std::string(to_string(load_sharing)));
  }
}

GearMesh::GearMesh(const GearPairSpec& spec, const Material& pinion, const Material& wheel,
                   const MeshSettings& settings, double pinion_torque, double pinion_speed)
    : composite_modulus_((settings.validate(), geartrib::composite_modulus(pinion, wheel))),
      pinion_speed_(pinion_speed),
      pinion_torque_(pinion_torque),
      cycle_positions_(settings.positions),
      pair_(spec),
      stiffness_(pair_, tooth_material(pinion), tooth_material(wheel), composite_modulus_, settings.plane_strain),
      tooth_contact_(settings.load_sharing == LoadSharing::compatibility
                         ? std::optional<LoadedToothContact>(std::in_place, pair_, stiffness_, tooth_material(pinion),
                                                             tooth_material(wheel), composite_modulus_,
                                                             settings.modification, settings.hertz_approach,
                                                             iso_effective_relief(pair_, tangential_line_load()))
                         : std::nullopt),
      analysis_(pair_, stiffness_, settings.load_sharing, pinion_torque / pair_.pinion().base_radius,
                composite_modulus_, tooth_contact()) {}

IsoStiffnessComparison GearMesh::iso_comparison(int positions) const {
  IsoStiffnessComparison k;
  k.model = analysis_.stiffness_stats(positions);
  k.iso = iso6336_mesh_stiffness(pair_, tangential_line_load());
  const double b = pair_.spec().face_width;
  k.ratio = k.model.mean / (k.iso.mesh * b);
  const double full = iso6336_mesh_stiffness(pair_, std::max(tangential_line_load(), kIsoFullLineLoad)).mesh * b;
  k.full_load_ratio = k.model.mean / full;
  return k;
}

std::string iso_stiffness_warning(const GearMesh& mesh, const IsoStiffnessComparison& k) {
  const double ratio = k.full_load_ratio;
  if (ratio <= kIsoStiffnessBand && ratio >= 1.0 / kIsoStiffnessBand) return "";
  auto body = [&](int i) {
    const GearBody& g = mesh.pair().gear(i);
    return g.bore_radius > 0.0 ? fmt::format("{:.3g}", foundation_rim_ratio(g))
                               : fmt::format("{:g} (solid)", kSolidBodyRimRatio);
  };
  return fmt::format(
      "the mean mesh stiffness {:.4g} N/m (potential energy) is {:.3g} x ISO 6336-1's c_gamma_alpha b = {:.4g} N/m "
      "(solid steel gears at 100 N/mm or more), beyond the factor {:g} either way that typical gear bodies stay "
      "within; the stiffness load sharing, the mesh_stiffness output and the dynamics use it. Check the bodies "
      "(r_f/r_bore = {} for pinion.bore_diameter, {} for wheel.bore_diameter; the foundation fit covers 1.4 to 7) "
      "and the materials (ISO's value is for steel)",
      k.model.mean, ratio, k.model.mean / ratio, kIsoStiffnessBand, body(0), body(1));
}

}  // namespace geartrib::gear
