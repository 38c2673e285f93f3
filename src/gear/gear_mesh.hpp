// A case's gear mesh, assembled: the pair's geometry, its tooth-pair stiffness model and the
// loaded-mesh analysis at the case's operating point.
#pragma once

#include "case/case.hpp"
#include "gear/load_sharing.hpp"
#include "gear/mesh_analysis.hpp"
#include "gear/spur_pair.hpp"
#include "gear/tooth_stiffness.hpp"

#include <optional>

namespace geartrib::gear {

class GearMesh {
 public:
  // Throws GeometryError for an impossible pair; `method` overrides the case's load sharing.
  explicit GearMesh(const Case& c, std::optional<LoadSharing> method = std::nullopt);
  GearMesh(const GearMesh&) = delete;
  GearMesh& operator=(const GearMesh&) = delete;

  const SpurPair& pair() const { return pair_; }
  const MeshStiffnessModel& stiffness() const { return stiffness_; }
  const MeshAnalysis& analysis() const { return analysis_; }
  double composite_modulus() const { return composite_modulus_; }
  double pinion_speed() const { return pinion_speed_; }
  // F_bn = T1 / r_b1 [N]
  double normal_force() const { return analysis_.normal_force(); }

 private:
  double composite_modulus_;
  double pinion_speed_;
  SpurPair pair_;
  MeshStiffnessModel stiffness_;
  MeshAnalysis analysis_;
};

}  // namespace geartrib::gear
