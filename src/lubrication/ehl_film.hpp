// Smooth isothermal EHL film of a line contact and its corrections, in the dimensionless groups
// of Dowson and Higginson: U = eta0 u/(E' R), G = alpha E', W = w/(E' R), H = h/R, with
// E' = 2 E* = 2/((1 - nu1^2)/E1 + (1 - nu2^2)/E2) (twice the thesis's E_t), u the entrainment
// speed (v1 + v2)/2, R the reduced radius and w the load per unit face width.
#pragma once

#include "core/named_choices.hpp"

#include <span>
#include <string>
#include <vector>

namespace geartrib::lubrication {

struct EhlGroups {
  double speed = 0.0;     // U
  double material = 0.0;  // G
  double load = 0.0;      // W
};
// reduced_modulus: E' [Pa]; eta0 [Pa s], alpha [1/Pa], entrainment u [m/s], line_load w [N/m],
// radius R [m].
EhlGroups ehl_groups(double eta0, double alpha, double entrainment, double line_load, double radius,
                     double reduced_modulus);

// Moes's groups of a line contact (Moes, Proc. IMechE 180 (1965-66) part 3B; in the form of Venner &
// Lubrecht, Multilevel Methods in Lubrication, 2000): M = W (2U)^-1/2, L = G (2U)^1/4, with U on
// the mean speed as above. Two groups fix the dimensionless solution; with W given, (M, L) give U
// and G back: U = (W/M)^2/2, G = L (2U)^-1/4.
struct MoesGroups {
  double load = 0.0;      // M
  double material = 0.0;  // L
};
MoesGroups moes_groups(const EhlGroups& g);
EhlGroups groups_from_moes(const MoesGroups& m, double load);  // load: W

// The film formulas, H = k U^u G^g W^w:
//  - dowson-higginson: minimum, 2.65 U^0.70 G^0.54 W^-0.13 (Dowson & Higginson, Elasto-hydrodynamic
//    lubrication, SI ed., 1977) -- the default, the form GEARpie and ISO/TS 6336-22 build on;
//  - pan-hamrock-min: 1.714 U^0.694 G^0.568 W^-0.128 (Pan & Hamrock, J. Tribol. 111, 1989);
//  - pan-hamrock-central: 2.922 U^0.692 G^0.470 W^-0.166 (same paper);
//  - dowson-toyoda: central, 3.06 U^0.69 G^0.56 W^-0.10 (Dowson & Toyoda, Leeds-Lyon 5, 1979).
enum class FilmFormula { dowson_higginson, pan_hamrock_min, pan_hamrock_central, dowson_toyoda };
struct FilmLaw {
  const char* name;
  double k, speed_exponent, material_exponent, load_exponent;
  bool central;  // central (true) or minimum film
  const char* source;
};
const FilmLaw& film_law(FilmFormula f);
// The formulas by name (lubrication.film_formula): film_law(f).name.
std::span<const NamedChoice<FilmFormula>> film_formula_choices();
const char* film_formula_name(FilmFormula f);
// Isothermal smooth film [m].
double smooth_film(FilmFormula f, const EhlGroups& g, double radius);

// Inlet shear heating: the film times a factor phi_T <= 1 of the thermal loading
// L = beta eta0 u^2 / k_f (beta = -d ln eta/dT, k_f the oil's conductivity):
//  - gupta (default): Gupta, Cheng, Zhu, Forster & Schrand, Tribol. Trans. 35 (1992) 269-274:
//    phi_T = (1 - 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 SRR^0.83) L^0.64), floored at 0.05;
//  - murch-wilson: Murch & Wilson, J. Lubr. Technol. 97 (1975), pure rolling: 3.94/(3.94 + L^0.62);
//  - none: 1.
enum class InletHeating { none, murch_wilson, gupta };
std::span<const NamedChoice<InletHeating>> inlet_heating_choices();  // lubrication.inlet_heating
const char* inlet_heating_name(InletHeating model);
double thermal_loading(double temperature_viscosity, double eta0, double entrainment, double oil_conductivity);
// srr: |v1 - v2|/u; hertz_over_modulus: p_h/E'.
double inlet_heating_factor(InletHeating model, double thermal_load, double srr, double hertz_over_modulus);
inline constexpr double kMinInletHeatingFactor = 0.05;  // Gupta's numerator changes sign beyond its fitted range

// Lubrication regime of a line contact (Johnson 1970; Hooke 1977; the line-contact asymptotes
// of Hamrock, Fundamentals of Fluid Film Lubrication, 1994): with g_V = G W^(3/2)/U^(1/2),
// g_E = W/U^(1/2) and H~ = H W/U, the four asymptotic minimum films are rigid-isoviscous 4.9,
// rigid-piezoviscous 1.66 g_V^(2/3), elastic-isoviscous 2.45 g_E^0.8 and elastic-piezoviscous
// 1.654 g_V^0.54 g_E^0.06. The map's boundaries are where two asymptotes meet: elasticity
// matters where the elastic-isoviscous film exceeds the rigid-isoviscous one, pressure-viscosity
// where the rigid-piezoviscous film does; with both, the contact is elastic-piezoviscous unless
// that film reaches the rigid-piezoviscous one (elasticity negligible) or falls to the
// elastic-isoviscous one (piezoviscosity negligible).
enum class EhlRegime { rigid_isoviscous = 0, rigid_piezoviscous = 1, elastic_isoviscous = 2, elastic_piezoviscous = 3 };
EhlRegime ehl_regime(const EhlGroups& g);
const char* ehl_regime_name(EhlRegime r);

}  // namespace geartrib::lubrication
