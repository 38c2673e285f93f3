// Mixed lubrication of one contact: the load shared between the film and the asperities
// (Johnson, Greenwood & Poon, Wear 19, 1972; Gelinck & Schipper, Tribol. Int. 33, 2000), and the
// friction of the two shares.
#pragma once

#include "lubrication/ehl_film.hpp"
#include "lubrication/lubricant.hpp"

#include <functional>
#include <limits>

namespace geartrib::lubrication {

// The film carries w/gamma1 and the asperities w/gamma2 with 1/gamma1 + 1/gamma2 = 1. The film is
// the smooth formula with the load and E' both scaled by 1/gamma1 (the film's pressure over the
// same Hertz width), which leaves W unchanged, multiplies U by gamma1 and divides G by it:
//   h_film = h_smooth gamma1^(u - g)   (u, g: the formula's speed and material exponents).
// The asperities carry the rest at the same mean-plane separation h = d + y_s (d from the summit
// mean plane, y_s the summits' mean height). asperity_separation(share) returns that h [m] for
// the asperities carrying `share` of the load (non-increasing in share).
struct LoadShare {
  double asperity_share = 0.0;  // 1/gamma2
  double film_share = 1.0;      // 1/gamma1
  double film_thickness = 0.0;  // h [m], the separation of the mean planes
};
// h_smooth: the smooth film at the whole load [m]; film_exponent: u - g of the formula (> 0).
// h_smooth = 0 (no entrainment or viscosity), or a film share below kNegligibleFilmShare, gives
// exactly the dry contact: share 1.
inline constexpr double kNegligibleFilmShare = 1e-12;
// guess: ln(film share) of a neighbouring solution (a position along the path), tried first as a
// narrow bracket; the answer is the same to the solver's tolerance (1e-13 in ln share).
LoadShare share_load(double h_smooth, double film_exponent, const std::function<double(double)>& asperity_separation,
                     double guess = std::numeric_limits<double>::quiet_NaN());

// Mean shear stress of the film [Pa]: Eyring, tau = tau0 asinh(eta v_s/(h tau0)), with the
// Barus viscosity eta0 exp(alpha p) at the film's mean pressure p, capped by the limiting shear
// stress Lambda p (Evans & Johnson, Proc. IMechE 200C, 1986, for the Eyring-limiting form).
// Isothermal: the film's own shear heating is not modelled (it lowers the traction at high
// sliding speed; the limiting shear stress bounds it).
double film_shear_stress(const OilState& oil, double mean_pressure, double sliding_speed, double film_thickness);

// The mixed friction coefficient: mu = share_a mu_b + share_f tau_f/p_f, with p_f the film's mean
// pressure over the Hertz width (film_share w / 2b).
struct MixedFriction {
  double coefficient = 0.0;       // mu [-]
  double film_coefficient = 0.0;  // tau_f / p_f [-]
};
MixedFriction mixed_friction(const OilState& oil, const LoadShare& share, double boundary_coefficient, double line_load,
                             double hertz_half_width, double sliding_speed);

}  // namespace geartrib::lubrication
