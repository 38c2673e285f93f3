// ISO 6336 load capacity of a spur pair, method B: pitting (ISO 6336-2) and tooth-root bending
// (ISO 6336-3), with the load factors of ISO 6336-1 (K_v method B, K_Halpha/K_Falpha, K_Fbeta from
// a given K_Hbeta) and the allowables of ISO 6336-5 (rating/iso6336_materials.hpp). Every factor
// is returned with its symbol, the clause it comes from and whether an input behind it was assumed,
// for the factor table of `geartrib rate` and /rating.
//
// Where it holds: external spur gears (beta = 0) cut by a rack without protuberance, 1 <= eps_alpha
// < 2.05 (Y_DT = 1), steels of the groups of iso6336_materials.hpp. Out of it: flagged in
// RatingResult::findings, never extrapolated silently. Left out: helical gears (Z_beta, Y_beta
// = 1), method C/A of any factor, K_Hbeta by method C (a given value is used), the work-hardening
// factor of a hard pinion on a soft wheel (Z_W = 1: conservative for the wheel), nitrided and cast
// materials, Y_epsilon (not in ISO 6336-3:2006/2019 method B; DIN 3990-3's 0.25 + 0.75/eps_alpha is
// reported beside it for comparison, not used).
#pragma once

#include "gear/spur_pair.hpp"
#include "material/material.hpp"
#include "rating/iso6336_materials.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace geartrib::rating {

// One factor or stress of the table.
struct RatingFactor {
  std::string symbol;  // "Z_H", "sigma_H0", "K_v"
  int gear = -1;       // 0 pinion, 1 wheel, -1 the pair
  double value = 0.0;  // SI (stresses in Pa)
  std::string unit;    // "1", "Pa", "m"
  std::string clause;  // "ISO 6336-2 eq. (9)"
  bool assumed = false;
  std::string note;  // what it rests on, when it needs saying
};

// The factor of that symbol (and gear: -1 the pair) in a table; nullptr if absent.
const RatingFactor* find_factor(const std::vector<RatingFactor>& factors, const std::string& symbol, int gear = -1);

// The settings of a rating (a case's [rating]); SI.
struct RatingSettings {
  double application_factor = 1.0;  // K_A
  double face_load_factor = 0.0;    // K_Hbeta, given; 0: not given, 1 assumed (an ideal lead on stiff shafts)
  // Z_NT, Y_NT beyond the knee: 1 (optimum) or down to 0.85 at 1e10
  enum class LongLife { optimum, normal } long_life = LongLife::optimum;
  enum class OilSupply { dip, spray } oil_supply = OilSupply::dip;  // X_S of the scuffing methods: 1.0, 1.2
  int accuracy_grade = 6;                                           // Q of ISO 1328-1:1995, for f_pb and f_falpha
  double load_cycles = 1e10;                                        // N_L of the pinion (the wheel's: N_L / u)
  std::array<double, 2> flank_rz = {0.0, 0.0};                      // Rz of each flank [m]; 0: 6 Ra (assumed)
  std::array<double, 2> root_rz = {0.0, 0.0};                       // Rz of each root fillet [m]; 0: 10 um (assumed)
  void validate() const;                                            // throws core::KeyedError naming the field
};
std::span<const NamedChoice<RatingSettings::LongLife>> long_life_choices();
std::span<const NamedChoice<RatingSettings::OilSupply>> oil_supply_choices();
inline constexpr double kRzOverRa = 6.0;         // Rz = 6 Ra when only Ra is known (assumed, ground flanks)
inline constexpr double kDefaultRootRz = 10e-6;  // a hobbed and hardened root [m] (assumed)

// What a rating is computed from: the pair, each gear's material and grade, the load and speed,
// the oil's nu40 (0: none, no Z_L/Z_v/Z_R: the pitting rating then needs one), the flanks' Ra and
// the tip reliefs (C_a; 0: ISO 6336-1's running-in amount).
struct LoadCapacityInputs {
  const gear::SpurPair* pair = nullptr;
  std::array<const Material*, 2> material = {nullptr, nullptr};
  std::array<MaterialGrade, 2> grade;
  RatingSettings settings;
  double pinion_torque = 0.0;                     // [N m]
  double pinion_speed = 0.0;                      // [rad/s]
  double viscosity_40 = 0.0;                      // nu40 [m^2/s]
  std::array<double, 2> flank_ra = {0.0, 0.0};    // [m]
  std::array<double, 2> tip_relief = {0.0, 0.0};  // C_a [m]
};

struct LoadCapacity {
  std::vector<RatingFactor> factors;
  std::array<double, 2> pitting_safety = {0.0, 0.0};  // S_H (0: not rated)
  std::array<double, 2> bending_safety = {0.0, 0.0};  // S_F
  std::array<double, 2> contact_stress = {0.0, 0.0};  // sigma_H [Pa]
  std::array<double, 2> root_stress = {0.0, 0.0};     // sigma_F [Pa]
  double dynamic_factor = 1.0,
         transverse_factor = 1.0;     // K_v, K_Halpha (the scuffing and micropitting methods use them)
  std::vector<std::string> findings;  // every range left, with the factor
  const RatingFactor* find(const std::string& symbol, int gear = -1) const {
    return find_factor(factors, symbol, gear);
  }
};

// A case's ratings: every method's factors in one table, each gear's safeties, the findings.
struct RatingResult {
  std::vector<std::string> methods;                   // rated: pitting, bending, scuffing, micropitting
  std::vector<RatingFactor> factors;                  // in the order the methods computed them
  std::array<double, 2> pitting_safety = {0.0, 0.0};  // S_H (0: not rated)
  std::array<double, 2> bending_safety = {0.0, 0.0};  // S_F
  double flash_scuffing_safety = 0.0;                 // S_B, ISO/TS 6336-20 (0: not rated)
  double integral_scuffing_safety = 0.0;              // S_intS, ISO/TS 6336-21
  double min_lambda = 0.0;                            // lambda_GF,min along the path, ISO/TS 6336-22
  double micropitting_safety = 0.0;                   // S_lambda = lambda_GF,min/lambda_GFP (0: not rated)
  std::vector<std::string> findings;
  bool assumed_any() const;
  const RatingFactor* find(const std::string& symbol, int gear = -1) const {
    return find_factor(factors, symbol, gear);
  }
};

// Pitting and bending per ISO 6336-2/-3 method B. `pitting`, `bending`: which to rate. Throws
// core::KeyedError naming the field ("viscosity_40", "grade") when an input it needs is missing.
LoadCapacity iso6336_load_capacity(const LoadCapacityInputs& in, bool pitting, bool bending);

// ISO 1328-1:1995 tolerances of grade Q for a gear of module m and reference diameter d [m]:
// single pitch f_pt = (0.3 (m + 0.4 sqrt d) + 4) 2^((Q-5)/2) and profile form
// f_falpha = (2.5 sqrt m + 0.17 sqrt d + 0.5) 2^((Q-5)/2) (mm inside, um out), m and d the geometric
// means of their size ranges and the result rounded as the standard's tables are (5.2.3: >10 um to
// 1 um, 5..10 um to 0.5 um, below to 0.1 um).
double single_pitch_tolerance(int grade, double module, double diameter);
double profile_form_tolerance(int grade, double module, double diameter);

}  // namespace geartrib::rating
