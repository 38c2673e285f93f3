// Mixed lubrication of one contact: the load shared between the film and the asperities
// (Johnson, Greenwood & Poon, Wear 19, 1972; Gelinck & Schipper, Tribol. Int. 33, 2000), and the
// friction of the two shares.
#pragma once

#include "lubrication/ehl_film.hpp"
#include "lubrication/lubricant.hpp"

#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

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
  double film_thickness = 0.0;  // h [m]: the film's gap, as the caller's closure defines it
};
// h_smooth: the smooth film at the whole load [m]; film_exponent: u - g of the formula (> 0).
// h_smooth = 0 (no entrainment or viscosity), or a film share below kNegligibleFilmShare, gives
// exactly the dry contact: share 1.
inline constexpr double kNegligibleFilmShare = 1e-12;
// guess: ln(film share) of a neighbouring solution (a position along the path), tried first as a
// narrow bracket; the answer is the same to the solver's tolerance (1e-13 in ln share).
LoadShare share_load(double h_smooth, double film_exponent, const std::function<double(double)>& asperity_separation,
                     double guess = std::numeric_limits<double>::quiet_NaN());

// The film's traction (tau_f at the film's mean pressure p_f and sliding speed v_s):
//  - thermal-eyring (default): Eyring's fluid in simple shear with its own shear heating conducted
//    to both surfaces at T_s, viscosity eta_s exp(-beta (T - T_s)) (Johnson & Greenwood, Wear 61
//    (1980) 353-374). The energy equation is Bratu's; its closed form gives
//      tau0 sinh(tau/tau0) = (eta_s v_s/h) X/(sinh X cosh X),   X tanh X = beta tau v_s h/(8 k_f),
//    with the mid-film temperature rise (2/beta) ln cosh X. X -> 0 is the isothermal Eyring law;
//    the traction has a thermal maximum (at X tanh X = 1) and falls beyond it as v_s grows;
//  - isothermal-eyring: tau = tau0 asinh(eta v_s/(h tau0)) (geartrib 0.1's model);
//  - curve: the lubricant's measured traction curves at the position's SRR, Hertz pressure and
//    bulk temperature (lubrication/lubricant.hpp).
// Both Eyring forms take eta = eta0(T) exp(alpha p_f) (Barus) and are capped by the limiting shear
// stress Lambda p_f (Evans & Johnson, Proc. IMechE 200C (1986), the Eyring-limiting form).
enum class FilmTraction { thermal_eyring, isothermal_eyring, curve };
std::span<const NamedChoice<FilmTraction>> film_traction_choices();  // lubrication.traction
const char* film_traction_name(FilmTraction t);

struct FilmShear {
  double shear_stress = 0.0;  // tau_f [Pa]
  double midfilm_rise = 0.0;  // thermal Eyring: the mid-film temperature above the surfaces [K]
  bool limited = false;       // capped by Lambda p_f
};
// Isothermal Eyring [Pa]: eta [Pa s] already at the film's pressure and temperature.
double eyring_shear_stress(double eta, double eyring_stress, double sliding_speed, double film_thickness);
// Thermal Eyring (Johnson & Greenwood 1980) [Pa]: eta_s at the surfaces' temperature and the
// film's pressure, beta = -d ln(eta)/dT [1/K], k_f [W/(m K)].
FilmShear thermal_eyring_shear_stress(double eta_s, double eyring_stress, double temperature_viscosity,
                                      double oil_conductivity, double sliding_speed, double film_thickness);
// The film's shear stress by an Eyring model at the oil state `oil` (its temperature the surfaces'):
// Barus at p_f, capped at Lambda p_f.
FilmShear film_shear_stress(FilmTraction model, const OilState& oil, double mean_pressure, double sliding_speed,
                            double film_thickness);

}  // namespace geartrib::lubrication
