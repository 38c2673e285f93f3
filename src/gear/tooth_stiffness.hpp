// Tooth and tooth-pair stiffness along the path of contact by the potential-energy method:
// bending, shear and axial compression of the tooth as a cantilever of variable section
// (Yang & Lin 1987; Tian 2004), the part between root and base circle as a constant section
// (Chen & Shao 2011), the fillet-foundation (gear body) compliance of Sainsot, Velex &
// Duverger (2004), and the Hertzian contact stiffness pi b E_t / 2 (Yang & Lin).
#pragma once

#include "gear/spur_pair.hpp"

namespace geartrib::gear {

// Compliances [m/N] of one tooth loaded on its flank at a contact point.
struct ToothCompliance {
  double bending = 0.0;
  double shear = 0.0;
  double axial = 0.0;
  double foundation = 0.0;
  double total() const { return bending + shear + axial + foundation; }
};

struct ToothMaterial {
  double youngs_modulus = 0.0;  // E [Pa]
  double poisson_ratio = 0.0;   // nu
};

// The rim ratio h = r_f/r_bore of the fillet-foundation fit. Sainsot et al. fix the body at its
// bore, so the foundation compliance grows with h (more body between the tooth and the seat) and
// has no thick-rim limit: a solid body (bore 0) has a foundation only where its shaft seat is. It
// is taken at a third of the root diameter, h = 3: the middle of the fit's range (1.4 to 7,
// geometric mean 3.1) and of the shipped cases' given bores (h = 2.1 to 3.8). From h = 3 to 7 the
// foundation compliance grows 2.4 times and the seed pair's mesh stiffness falls 45%, so the
// fit's end is no stand-in for a solid body (docs/theory/gear-geometry.md).
inline constexpr double kSolidBodyRimRatio = 3.0;
double foundation_rim_ratio(const GearBody& g);

// Compliance of gear body `g` (face width b) loaded at roll angle phi = rho/r_b of its involute.
// plane_strain uses E/(1 - nu^2) in the beam terms (a wide tooth); the foundation term uses E as
// fitted by Sainsot et al., at foundation_rim_ratio(g). Outside that fit's range
// (1.4 <= r_f/r_bore <= 7, 0.01 <= theta_f <= 0.12 rad) the formula is still evaluated;
// fillet_foundation_in_range tells.
ToothCompliance tooth_compliance(const GearBody& g, double roll_angle, const ToothMaterial& material, double face_width,
                                 bool plane_strain);
bool fillet_foundation_in_range(const GearBody& g);

// The tooth-pair stiffness at s [N/m] and its parts, for the pair's materials.
struct PairStiffness {
  ToothCompliance pinion;
  ToothCompliance wheel;
  double hertz_compliance = 0.0;  // 2/(pi b E_t) [m/N]
  double stiffness = 0.0;         // 1 / (sum of all compliances) [N/m]
};

class MeshStiffnessModel {
 public:
  MeshStiffnessModel(const SpurPair& pair, const ToothMaterial& pinion, const ToothMaterial& wheel,
                     double composite_modulus, bool plane_strain);
  PairStiffness pair(double s) const;

 private:
  const SpurPair& pair_;
  ToothMaterial material_[2];
  double hertz_compliance_;
  bool plane_strain_;
};

}  // namespace geartrib::gear
