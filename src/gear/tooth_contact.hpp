// Loaded tooth contact of a spur pair with profile modifications: each tooth pair's separation
// e_j (both flanks' modifications and deviations at its contact point, ISO 21771:2007 clause 7)
// and its load-dependent compliance (the teeth's bending, shear, axial and foundation compliance
// of the potential-energy model, plus the Hertzian approach of the line contact), and the load
// from compatibility: the common approach delta solves
//   sum_j F_j(delta - e_j)+ = F_bn,
// pairs with delta <= e_j carrying nothing (contact loss). delta is the static transmission error
// along the line of action (Harris 1958; Tavakoli & Houser 1986; Velex & Maatar 1996).
#pragma once

#include "core/chebyshev_interpolant.hpp"
#include "core/named_choices.hpp"
#include "gear/spur_pair.hpp"
#include "gear/tooth_stiffness.hpp"

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace geartrib::gear {

// The shape of a relief over its length, xi = 0 at its start to 1 at the profile's end
// (ISO 21771:2007 7.4): linear C xi; parabolic C xi^2; arc: the circle tangent to the involute at
// the start through C at the end, R - sqrt(R^2 - (xi L)^2) with R = (L^2 + C^2)/(2 C).
enum class ReliefShape { linear, parabolic, arc };
std::span<const NamedChoice<ReliefShape>> relief_shape_choices();

// A tip or root relief: its amount at the profile's end (tip relief: at the tip circle; root
// relief: at the root form circle d_Ff, where the generated involute starts) and its start, as a
// diameter or a roll length from that end. Amount 0: none (a start given with it is unused, so
// that a sweep of the amount may begin at 0).
struct Relief {
  double amount = 0.0;  // C_a or C_f [m], removed normal to the profile (along the line of action)
  ReliefShape shape = ReliefShape::linear;
  double start_diameter = 0.0;  // d_Ca or d_Cf [m]; 0: from `length`
  double length = 0.0;    // L_Ca or L_Cf: roll length from the profile's end to the start [m]; 0: from the diameter
  void validate() const;  // throws core::KeyedError naming the field ("amount", "length")
};

// A tip relief from a design rule instead of given values: the amount ISO/TS 6336-20 (ISO/TR
// 13989-1 B.1) calls effective, C_eff = F_t/(b cos alpha_t c_gamma) at the case's load, as a long
// relief: from the point of single contact to the tip. (The standards' short relief is not
// offered: its length could not be sourced.)
enum class ReliefDesign { given, long_relief };
std::span<const NamedChoice<ReliefDesign>> relief_design_choices();

// One gear's profile modifications and the deviations of its teeth (the same on every tooth).
struct ProfileModification {
  Relief tip;
  Relief root;
  ReliefDesign tip_design = ReliefDesign::given;
  // C_alpha [m]: parabolic profile crowning, 0 at the middle of the active profile and C_alpha at
  // its ends; a negative value is a hollow profile (a form deviation).
  double crowning = 0.0;
  // f_Halpha [m] over the active profile (ISO 1328-1): positive puts material on the tip side (the
  // flank stands out towards the tip, its separation falls linearly from root to tip by f_Halpha).
  double slope_deviation = 0.0;
  // f_pb [m]: the base pitch's deviation from p_b. The pair k pitches ahead of the last one to
  // enter has its separation changed by k (f_pb,wheel - f_pb,pinion).
  double base_pitch_deviation = 0.0;
  bool any() const;
  std::string first_given() const;  // the field of the first modification given ("tip.amount", "crowning"); "" for none
  void validate() const;            // throws core::KeyedError naming the field ("tip.amount", "crowning")
};

// The material removed from one gear's flank [m] against its roll length rho (distance from its
// base-circle tangent point, rho = sqrt(r^2 - r_b^2)), with the relief's ends resolved on the pair.
class FlankModification {
 public:
  // gear 0 pinion, 1 wheel; `design_relief` the amount of a designed tip relief [m] (C_eff).
  // Throws GeometryError naming the key ("pinion.tip_relief.start_diameter") when a relief starts
  // off the flank or reaches past the active profile's other end.
  FlankModification(const SpurPair& pair, int gear, const ProfileModification& m, double design_relief);
  double at(double rho) const;                     // [m], >= the deviations' share
  double tip_start() const { return tip_start_; }  // roll length where the tip relief begins [m]
  double root_start() const { return root_start_; }
  double tip_amount() const { return tip_.amount; }
  double base_pitch_deviation() const { return m_.base_pitch_deviation; }

 private:
  ProfileModification m_;
  Relief tip_;
  double tip_end_ = 0.0, tip_start_ = 0.0;    // roll lengths: the tip, the relief's start [m]
  double root_end_ = 0.0, root_start_ = 0.0;  // the root form point, the relief's start [m]
  double active_low_ = 0.0, active_high_ = 0.0;
};

// The Hertzian approach of a tooth pair's line contact, the load-dependent part of its compliance.
enum class HertzApproach {
  weber_banaschek,  // each body's surface against a depth h (Weber & Banaschek 1953)
  palmgren,         // empirical, steel rollers (Palmgren 1959)
  linear,           // the constant pi b E_t/2 of the stiffness model (Yang & Lin 1987)
};
std::span<const NamedChoice<HertzApproach>> hertz_approach_choices();  // mesh.hertz_approach

// The approach of one line contact [m] under normal force F [N], and its slope [m/N].
// Weber-Banaschek: per body delta_i = 2 w (1 - nu_i^2)/(pi E_i) (ln(2 h_i/a) - nu_i/(2(1 - nu_i)))
// with w = F/b and a the Hertz half-width: the exact half-plane approach between the surface and
// the point at depth h_i on the axis (Johnson 1985 4.3's axis stresses integrated); h_i the
// distance from the contact to the tooth's centre line along the line of action. Holds for
// a << h; the log term is floored at 1/2 (where the approach would stop growing with the load:
// a ~ h), and `in_range` is false from a > h/4.
// Palmgren: delta = 3.84e-5 mm F^0.9/l^0.8 (F in N, l in mm) for one steel line contact, scaled
// by (E_t,steel/E_t)^0.9 for other materials (then `in_range` is false: Palmgren fitted steel).
struct LineContactApproach {
  HertzApproach model = HertzApproach::weber_banaschek;
  double face_width = 0.0;            // l [m]
  double radius = 0.0;                // equivalent radius of curvature [m]
  double composite_modulus = 0.0;     // E_t = 1/sum((1 - nu^2)/E) [Pa]
  double youngs_modulus[2] = {0, 0};  // [Pa]
  double poisson_ratio[2] = {0, 0};
  double depth[2] = {0, 0};        // h_i [m]
  double linear_compliance = 0.0;  // the linear model's 2/(pi b E_t) [m/N]
  double approach(double force) const { return approach_and_slope(force).first; }
  double slope(double force) const { return approach_and_slope(force).second; }
  std::pair<double, double> approach_and_slope(double force) const;  // [m], [m/N]
  bool in_range(double force) const;
};

// One tooth pair at an instant: its separation and compliance.
struct PairContact {
  double separation = 0.0;  // e_j [m]
  double compliance = 0.0;  // the teeth's linear compliance (bending, shear, axial, foundation) [m/N]
  LineContactApproach hertz;
  double deflection(double force) const { return compliance * force + hertz.approach(force); }  // y(F) [m]
  // F(y): the inverse, 0 for y <= 0 [N]; and dy/dF there [m/N] (infinite at F = 0 but for linear).
  // `guess` a load near the answer (a previous solve's) or 0 for none.
  std::pair<double, double> load_and_compliance(double deflection, double guess = 0.0) const;
  double load(double deflection) const { return load_and_compliance(deflection).first; }
};

struct CompatibilitySolution {
  double approach = 0.0;           // delta: the static transmission error along the line of action [m]
  std::vector<double> loads;       // F_j [N], in the order of the pairs
  double tangent_stiffness = 0.0;  // dF_bn/d delta: the loaded pairs' tangent stiffnesses summed [N/m]
  bool hertz_in_range = true;      // every loaded pair's approach within its model's range
};

// delta and the loads for total force F >= 0. At F = 0: delta = min e_j and every load 0.
CompatibilitySolution solve_compatibility(std::span<const PairContact> pairs, double force);

// The pair's loaded tooth contact: builds each pair's PairContact at its position and solves.
class LoadedToothContact {
 public:
  // `design_relief` the C_eff [m] of a designed tip relief (ReliefDesign). Throws GeometryError.
  LoadedToothContact(const SpurPair& pair, const MeshStiffnessModel& stiffness, const ToothMaterial& pinion,
                     const ToothMaterial& wheel, double composite_modulus, const ProfileModification (&m)[2],
                     HertzApproach approach, double design_relief);
  // The pairs at `positions` (ascending, as from pairs_in_contact): k = 0 the first.
  std::vector<PairContact> pairs(const std::vector<double>& positions) const;
  // Separation of the pair at s, k pitches ahead of the last pair to enter [m].
  double separation(double s, int k) const;
  CompatibilitySolution solve(const std::vector<double>& positions, double force) const;
  const FlankModification& flank(int gear) const { return flank_[gear]; }
  HertzApproach approach_model() const { return approach_; }
  // The teeth's linear compliance of the pair at s in [A, E] [m/N]: the stiffness model's bending,
  // shear, axial and foundation terms of both teeth, interpolated at kCompliancePoints Chebyshev
  // points along the path (smooth there; within 1e-8 of the model, tests/test_tooth_contact.cpp).
  double teeth_compliance(double s) const;
  static constexpr int kCompliancePoints = 25;
  // The pair's linear stiffness at s [N/m]: teeth and the stiffness model's constant Hertz term
  // (what the mesh dynamics integrates per pair).
  double linear_stiffness(double s) const { return 1.0 / (teeth_compliance(s) + hertz_compliance_); }

 private:
  const SpurPair& pair_;
  core::ChebyshevInterpolant compliance_;
  double hertz_compliance_;  // the stiffness model's linear Hertz term [m/N]
  ToothMaterial material_[2];
  double composite_modulus_;
  FlankModification flank_[2];
  HertzApproach approach_;
};

// The distance from the contact at roll length rho to gear g's tooth centre line along the line
// of action [m]: r sin(psi)/cos(alpha - psi), psi the half angular thickness at radius r.
double tooth_centre_depth(const GearBody& g, double rho);

}  // namespace geartrib::gear
