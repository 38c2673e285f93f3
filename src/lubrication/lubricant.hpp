// A lubricant's properties against temperature, SI: kinematic viscosity by Walther's law through
// the 40 and 100 degC values (ASTM D341), density by a linear law, the pressure-viscosity
// coefficient measured or from the ISO/TR 15144-1 correlation, and the thermal and traction data
// the film, friction and inlet-heating models need. Read from lubricants/*.toml or a case's
// [lubricant] table by io::load_case.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace geartrib::lubrication {

// The base stock, which selects the ISO/TS 6336-20 lubricant factor X_L of the mean friction.
// ISO/TS 6336-20 (ISO/TR 13989-1) tabulates X_L = 1.0 mineral, 0.8 polyalphaolefin, 0.7
// non-water-soluble polyglycol, 0.6 water-soluble polyglycol, 1.3 phosphate ester, 1.5 traction
// fluid. Synthetic (non-phosphate) esters are not in its table: an ester's file gives X_L itself.
enum class BaseOil {
  mineral,
  pao,
  ester,
  polyglycol_insoluble,
  polyglycol_water_soluble,
  phosphate_ester,
  traction_fluid
};
BaseOil base_oil_from_name(const std::string& name);  // throws std::invalid_argument
const char* base_oil_name(BaseOil b);
std::vector<std::string> base_oil_names();
// The tabulated X_L; NaN for a base stock the standard does not tabulate (ester).
double iso_lubricant_factor(BaseOil b);

// A traction curve measured on a twin-disc (or ball-on-disc) machine: the friction coefficient
// against the slide-to-roll ratio |v1 - v2|/u at a stated Hertz pressure, oil temperature and
// entrainment speed. Used as the film's traction coefficient (lubrication.traction = "curve").
struct TractionCurve {
  std::string name, source;
  double hertz_pressure = 0.0;                     // p_H [Pa]
  double temperature = 0.0;                        // oil (disc bulk) temperature [K]
  double entrainment_speed = 0.0;                  // u [m/s], stated (not interpolated: a run warns far from it)
  std::vector<double> slide_to_roll, coefficient;  // SRR ascending from >= 0, coefficient in [0, 1]
};
// A lubricant's curves form a grid in (Hertz pressure, temperature): every pressure at every
// temperature (one of either is allowed). Interpolated linearly in SRR along each curve and
// bilinearly between curves; beyond the grid the nearest curve's value, flagged.
struct TractionValue {
  double coefficient = 0.0;
  bool outside = false;  // SRR, pressure or temperature beyond the measured ranges
};
class TractionCurves {
 public:
  TractionCurves() = default;
  // Throws std::invalid_argument naming the curve and the rule (order, range, grid).
  explicit TractionCurves(std::vector<TractionCurve> curves);
  bool empty() const { return curves_.empty(); }
  const std::vector<TractionCurve>& curves() const { return curves_; }
  TractionValue at(double slide_to_roll, double hertz_pressure, double temperature) const;

 private:
  std::vector<TractionCurve> curves_;
  std::vector<double> pressures_, temperatures_;  // the grid's axes, ascending
  std::vector<std::size_t> index_;                // curve at (pressure i, temperature j): index_[i * nt + j]
};

struct Lubricant {
  static constexpr double kWaltherOffset = 0.7;  // cSt, ASTM D341 for nu >= 2 cSt
  std::string name;
  std::string source;
  BaseOil base_oil = BaseOil::mineral;
  // Temperature-dependent form (a lubricant file): Walther through these two points.
  double kinematic_viscosity_40 = 0.0;              // nu at 40 degC [m^2/s]
  double kinematic_viscosity_100 = 0.0;             // nu at 100 degC [m^2/s]
  double density_15 = 0.0;                          // rho at 15 degC [kg/m^3]
  double density_temperature_coefficient = 6.4e-4;  // c of rho = rho15 (1 - c (T - 15 degC)) [1/K]
  double pressure_viscosity = 0.0;  // alpha measured at pressure_viscosity_temperature [1/Pa]; 0: ISO/TR 15144-1
  double pressure_viscosity_temperature = 313.15;  // [K]
  // Fixed form (a case giving the oil at its inlet temperature): eta and alpha constant.
  double fixed_dynamic_viscosity = 0.0;  // [Pa s]; > 0 selects the fixed form
  // The defaults below are the fixed form's (typical mineral gear oil, assumed); a lubricant file
  // gives every value itself.
  double fixed_temperature_viscosity = 0.03;  // beta = -d ln(eta)/dT of the fixed form [1/K]
  double thermal_conductivity = 0.13;         // k_f [W/(m K)]
  double specific_heat = 0.0;                 // c_p [J/(kg K)]
  double eyring_stress = 5e6;                 // tau_0 [Pa]
  double limiting_shear_coefficient = 0.075;  // Lambda = tau_L / p [-]
  double min_temperature = 253.15;            // range of the data [K]
  double max_temperature = 423.15;
  double iso_lubricant_factor = 0.0;  // X_L given in the file (an ester's); 0: the base stock's tabulated value
  // FZG ratings of the oil: the failure load stage in the scuffing test A/8.3/90 (ISO 14635-1) and in
  // the micropitting test GF-C/8.3/90 (FVA 54/7); 0: not rated. Their provenance and whether assumed.
  int fzg_scuffing_stage = 0;
  int fzg_micropitting_stage = 0;
  std::string fzg_source;
  bool fzg_assumed = false;
  // The permissible specific film thickness lambda_GFP of ISO/TS 6336-22 given for this oil (the
  // supplier's, or read off the standard's informative Annex A figure), with its source; 0: from
  // fzg_micropitting_stage.
  double permissible_lambda = 0.0;
  std::string permissible_lambda_source;
  TractionCurves traction;  // measured traction curves (optional)

  bool fixed() const { return fixed_dynamic_viscosity > 0.0; }
  // X_L: the file's, or the base stock's tabulated value.
  double lubricant_factor() const;
  // Throws std::invalid_argument naming the member and the rule (positive viscosities with
  // nu40 > nu100 >= 2 cSt, positive thermal data, 0 <= Lambda <= 1, min < max temperature, an
  // X_L for an ester) and, for the temperature-dependent form, a data range that leaves a law's
  // range (law_range below: Walther's viscosity beyond ASTM D341's 2 to 2e7 mm^2/s, a temperature
  // beyond 400 degC, the density line below half its 15 degC value) or an alpha reference
  // temperature (or the correlation's 38 degC) outside operating_range.
  void validate() const;
};

// Temperatures of a lubricant file's laws [K]. Three nested ranges:
//  - the data range, min_temperature .. max_temperature: what the file's data cover;
//  - operating_range: the data range widened by kColdExtrapolation below and kHotExtrapolation
//    above (inside law_range): where the oil (inlet) and a given bulk temperature may lie
//    (io::load_case refuses them beyond it and warns outside the data);
//  - law_range: where every law is sound, finite and positive, viscosity, density and alpha
//    falling with temperature: Walther's viscosity at most 2e7 mm^2/s (the top of ASTM D341's
//    charts; colder, the double form overflows), at least -100 degC (kMinOilTemperature), at most
//    400 degC (kMaxOilTemperature), and the density line above half its 15 degC value. A run evaluates the oil anywhere
//    in it (beyond the data: extrapolated, flagged) and clamps it at its ends (flagged), or fails when the bulk
//    temperature leaves it (contact/mesh_lubrication.cpp).
// The fixed form has no temperature laws: every range is its one temperature.
struct TemperatureRange {
  double lo = 0.0, hi = 0.0;  // [K]
  bool contains(double t) const { return t >= lo && t <= hi; }
};
inline constexpr double kColdExtrapolation = 40.0, kHotExtrapolation = 60.0;  // beyond the data [K]
inline constexpr double kWaltherMinViscosity = 2e-6;  // [m^2/s]: ASTM D341's nu + 0.7 form holds at and above 2 cSt
inline constexpr double kWaltherMaxViscosity = 20.0;  // [m^2/s]: 2e7 cSt, the top of ASTM D341's charts
// No gear oil is a liquid with data past 400 degC (mineral and synthetic base stocks crack, boil or
// ignite below it); ISO/TR 15144-1's alpha factor 1 + 516 (1/T - 1/311 K) is 0.107 there and 0 at
// 782.8 K.
inline constexpr double kMaxOilTemperature = 673.15;  // [K]
// No gear oil flows at -100 degC (the pour points of mineral and PAO gear oils lie above -60 degC):
// the floor of the law range where Walther's viscosity is nearly flat in temperature (a viscosity
// index far past any oil's), which alone would reach 0 K, where alpha's factor is infinite.
inline constexpr double kMinOilTemperature = 173.15;  // [K]
TemperatureRange data_range(const Lubricant& l);
TemperatureRange operating_range(const Lubricant& l);
TemperatureRange law_range(const Lubricant& l);

// A law evaluated outside its range: a run-time failure (the command line's exit 1, Python's
// RuntimeError), not bad input.
class OutsideLawRange : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The oil as a contact sees it at one temperature.
struct OilState {
  double temperature = 0.0;                 // [K]
  double dynamic_viscosity = 0.0;           // eta_0 [Pa s]
  double pressure_viscosity = 0.0;          // alpha [1/Pa]
  double temperature_viscosity = 0.0;       // beta = -d ln(eta)/dT [1/K]
  double density = 0.0;                     // [kg/m^3]
  double thermal_conductivity = 0.0;        // [W/(m K)]
  double eyring_stress = 0.0;               // [Pa]
  double limiting_shear_coefficient = 0.0;  // [-]
  double iso_lubricant_factor = 1.0;        // X_L
};

// The laws at a temperature inside law_range(l); outside it each throws OutsideLawRange naming
// the law, the temperature and the range (a validated lubricant's laws are finite there).
// nu(T) [m^2/s] by Walther (ASTM D341): log10 log10(nu_cSt + 0.7) = A - B log10(T/K). The
// temperature-dependent form only (the fixed form has no density law: use oil_state).
double kinematic_viscosity(const Lubricant& l, double temperature);
double density(const Lubricant& l, double temperature);
// ISO/TR 15144-1 (and ISO/TS 6336-22): alpha_38 = 2.657e-8 eta_38^0.1348 (eta in N s/m^2, alpha in
// m^2/N: 1.9e-8 for an ISO VG 100 mineral oil, the typical measured value; eta in mPa s would give
// 4.9e-8, twice any measurement) and alpha(T) = alpha_38 (1 + 516 (1/T - 1/311 K)). A measured
// alpha is carried to T by the same temperature law.
double pressure_viscosity_coefficient(const Lubricant& l, double temperature);
OilState oil_state(const Lubricant& l, double temperature);
// The same with the oil's law range given (law_range(l), computed once by a caller that evaluates
// the oil many times: the mesh cycle's traction solves).
OilState oil_state(const Lubricant& l, double temperature, const TemperatureRange& law);

}  // namespace geartrib::lubrication
