#include "material/material.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace geartrib {

void Material::validate() const {
  auto fail = [&](const std::string& rule) { throw std::invalid_argument("material '" + name + "': " + rule); };
  if (!(youngs_modulus > 0.0)) fail("Young's modulus must be positive");
  if (!(poisson_ratio > 0.0 && poisson_ratio < 0.5)) fail("Poisson's ratio must lie in (0, 0.5)");
  if (!(yield_strength > 0.0)) fail("yield strength must be positive");
  if (!(hardness >= yield_strength)) fail("hardness must be at least the yield strength");
  if (!(density > 0.0)) fail("density must be positive");
  if (!flow_curve.empty()) {
    if (flow_curve.front().plastic_strain != 0.0) fail("flow curve must start at zero plastic strain");
    for (std::size_t i = 1; i < flow_curve.size(); ++i) {
      if (!(flow_curve[i].plastic_strain > flow_curve[i - 1].plastic_strain))
        fail("flow curve plastic strain must increase strictly (row " + std::to_string(i + 1) + ")");
      if (flow_curve[i].stress < flow_curve[i - 1].stress)
        fail("flow curve stress must not decrease (row " + std::to_string(i + 1) + ")");
    }
  }
}

double Material::flow_stress(double plastic_strain) const {
  if (flow_curve.empty() || plastic_strain <= 0.0)
    return flow_curve.empty() ? yield_strength : flow_curve.front().stress;
  const auto it = std::upper_bound(flow_curve.begin(), flow_curve.end(), plastic_strain,
                                   [](double e, const FlowPoint& p) { return e < p.plastic_strain; });
  if (it == flow_curve.end()) return flow_curve.back().stress;
  const auto& hi = *it;
  const auto& lo = *(it - 1);
  const double t = (plastic_strain - lo.plastic_strain) / (hi.plastic_strain - lo.plastic_strain);
  return lo.stress + t * (hi.stress - lo.stress);
}

double composite_modulus(const Material& a, const Material& b) {
  return 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
}

double tabor_flow_curve_hardness(const Material& m) {
  return kTaborHardnessRatio * m.flow_stress(kTaborRepresentativeStrain);
}

}  // namespace geartrib
