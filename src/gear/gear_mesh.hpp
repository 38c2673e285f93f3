// A gear mesh, assembled: the pair's geometry, its tooth-pair stiffness model and the loaded-mesh
// analysis at an operating point (a case's: case/gear_setup.hpp).
#pragma once

#include "core/keyed_error.hpp"
#include "gear/iso6336_stiffness.hpp"
#include "gear/load_sharing.hpp"
#include "gear/mesh_analysis.hpp"
#include "gear/spur_pair.hpp"
#include "gear/tooth_contact.hpp"
#include "gear/tooth_stiffness.hpp"
#include "material/material.hpp"

#include <optional>
#include <string>

namespace geartrib::gear {

// Mesh-cycle settings: how the load is shared between simultaneous tooth pairs, how many
// positions sample one base pitch, the beam model of the tooth stiffness, and (for the
// compatibility sharing) each gear's profile modifications and the Hertzian approach.
struct MeshSettings {
  LoadSharing load_sharing = LoadSharing::iso;
  int positions = 64;                   // samples of one base pitch of pinion rotation
  bool plane_strain = true;             // tooth beam in plane strain (wide face) or plane stress
  ProfileModification modification[2];  // pinion, wheel; only the compatibility sharing reads them
  HertzApproach hertz_approach = HertzApproach::weber_banaschek;
  // throws core::KeyedError naming the field ("modification[0].tip.amount"); modifications under
  // another sharing than compatibility are refused (they would change nothing).
  void validate() const;
};

// The potential-energy mesh stiffness over one base pitch beside ISO 6336-1's c_gamma_alpha b
// (method B, solid steel gears) at the case's load.
struct IsoStiffnessComparison {
  MeshStiffnessStats model;  // [N/m]
  IsoMeshStiffness iso;      // per unit face width, at the case's line load
  double ratio = 0.0;        // model.mean / (iso.mesh b)
  // The same against ISO at full load (kIsoFullLineLoad or more): the band is checked on this. The
  // model has perfect involutes, no light-load term: below 100 N/mm ISO's c' falls with the load
  // and any model of perfect teeth leaves it, whatever the bodies.
  double full_load_ratio = 0.0;
};

// How far either way the mean mesh stiffness may lie from ISO's c_gamma_alpha b before a run
// that uses it is warned. Bodies on shaft seats from thin rims (r_f/r_bore = 1.4) to a quarter of
// the root diameter (4) give 0.72 to 1.10 of ISO on the shipped pairs (and ISO is itself an
// empirical fit); a factor 1.5 lies beyond that spread, so past it the bores, the materials (ISO's
// value is steel's) or the tooth form are outside what either method describes for typical gears
// (docs/theory/gear-geometry.md).
inline constexpr double kIsoStiffnessBand = 1.5;

class GearMesh {
 public:
  // The pair of `spec` with the pinion's and the wheel's materials at pinion torque T1 [N m] and
  // speed omega1 [rad/s]. Throws GeometryError for an impossible pair.
  GearMesh(const GearPairSpec& spec, const Material& pinion, const Material& wheel, const MeshSettings& settings,
           double pinion_torque, double pinion_speed);
  GearMesh(const GearMesh&) = delete;
  GearMesh& operator=(const GearMesh&) = delete;

  const SpurPair& pair() const { return pair_; }
  const MeshStiffnessModel& stiffness() const { return stiffness_; }
  const MeshAnalysis& analysis() const { return analysis_; }
  // The loaded tooth contact of the compatibility sharing; null under another sharing.
  const LoadedToothContact* tooth_contact() const { return tooth_contact_ ? &*tooth_contact_ : nullptr; }
  double composite_modulus() const { return composite_modulus_; }
  double pinion_speed() const { return pinion_speed_; }
  int cycle_positions() const { return cycle_positions_; }  // mesh.positions: samples of one base pitch
  // F_bn = T1 / r_b1 [N]
  double normal_force() const { return analysis_.normal_force(); }
  // ISO's tangential line load F_t/b = T1/(r1 b) [N/m].
  double tangential_line_load() const { return pair_.tangential_line_load(pinion_torque_); }
  // The mean mesh stiffness over `positions` of one base pitch beside ISO's.
  IsoStiffnessComparison iso_comparison(int positions) const;

 private:
  double composite_modulus_;
  double pinion_speed_;
  double pinion_torque_;
  int cycle_positions_;
  SpurPair pair_;
  MeshStiffnessModel stiffness_;
  std::optional<LoadedToothContact> tooth_contact_;
  MeshAnalysis analysis_;
};

// The warning when the comparison's ratio lies beyond kIsoStiffnessBand either way, naming the
// bodies' rim ratios; empty within it.
std::string iso_stiffness_warning(const GearMesh& mesh, const IsoStiffnessComparison& k);

}  // namespace geartrib::gear
