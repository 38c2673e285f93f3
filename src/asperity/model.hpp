// Single-asperity models chosen by name from one registry. A model owns the values of its
// named constants; it evaluates a sphere-on-flat contact at an interference and returns every
// output the tool reports.
#pragma once

#include "asperity/contact_pair.hpp"
#include "asperity/critical.hpp"
#include "asperity/laws.hpp"
#include "asperity/pressure_profile.hpp"
#include "asperity/von_mises_table.hpp"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::asperity {

// Everything known about one asperity contact at an interference, SI units.
struct AsperityState {
  double delta = 0.0;                // interference [m]
  double delta_star = 0.0;           // delta / delta_c (the model's own delta_c)
  double load = 0.0;                 // F [N]
  double load_star = 0.0;            // F / F_c
  double area = 0.0;                 // A [m^2]
  double area_star = 0.0;            // A / A_c
  double contact_radius = 0.0;       // a = sqrt(A/pi) [m]
  double plastic_radius = 0.0;       // r_p, radius of the plastic core of the pressure profile [m]
  double mean_pressure = 0.0;        // F/A [Pa]
  double max_pressure = 0.0;         // peak contact pressure [Pa]
  double plastic_fraction = 0.0;     // share of the contact area whose surface has yielded, (r_p/a)^2
  double max_von_mises = 0.0;        // largest von Mises stress of the elastic field on the axis [Pa]
  double von_mises_depth = 0.0;      // its depth [m]
  bool beyond_fitted_range = false;  // delta* past the law's fitted range (LawRange)
  bool beyond_paraboloid = false;    // contact radius past the law's a/R limit
  bool fully_plastic_limit = false;  // the switch to the fully plastic limit governs the answer
};

// What to compute: the load, area and plastic share only (cheap); also the pressure profile
// (peak pressure, plastic core radius: cheap); or also the von Mises maximum (a maximisation over
// the depth of closed forms: ~4 us; or a table look-up, VonMisesTable).
enum class Detail { load_area, profile, full };

class AsperityModel {
 public:
  virtual ~AsperityModel() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view citation() const = 0;
  virtual std::span<const ConstantSpec> constant_specs() const = 0;

  const std::vector<double>& constants() const { return constants_; }
  double constant(std::string_view name) const;
  // Sets a named constant; throws std::invalid_argument for an unknown name or a value outside
  // the constant's admissible range.
  void set_constant(std::string_view name, double value);

  // Hertz peak pressure at this model's first yield [Pa], and its critical values.
  virtual double yield_peak_pressure(const ContactPair& pair) const = 0;
  Critical critical(const ContactPair& pair) const { return hertz_critical(pair, yield_peak_pressure(pair)); }

  // The law as published (or fitted), at delta* = delta/delta_c, without the switch below.
  virtual Star<double> law_star(double delta_star, const ContactPair& pair) const = 0;
  // The range the law was built for.
  virtual LawRange range() const = 0;
  // delta* where the law jumps or kinks (unsorted; the switch point included).
  std::vector<double> breakpoints(const ContactPair& pair) const;

  // delta* from which the fully plastic limit takes over (infinity for laws that need no switch):
  // the smaller of the fitted range's end and the delta* at which the fully plastic contact
  // radius sqrt(2 R delta) reaches the range's a/R limit.
  double switch_delta_star(const ContactPair& pair) const;
  double switch_delta_star(const ContactPair& pair, const Critical& crit) const;
  // The model's answer at delta*: the law inside its range; past switch_delta_star, continuously
  // onto the fully plastic limit A = 2 pi R delta, F = H A (H the pair's hardness):
  //   X(d) = X_fp(d) r^(d_s/d),  r = X_law(d_s)/X_fp(d_s),
  // for load and area, equal to the law at d_s and tending to the limit; monotone when ln r < 1
  // (d ln X/d ln d = 1 - (d_s/d) ln r). The plastic share stays the law's.
  Star<double> star(double delta_star, const ContactPair& pair) const;
  Star<double> star(double delta_star, const ContactPair& pair, double switch_delta_star) const;
  // Contact pressure profile: the two-zone profile with the model's plastic share
  // (two_zone_profile), Hertz for phi = 0.
  PressureProfile profile(double plastic_share, double load, double area) const;

  // Full evaluation at an interference delta >= 0 [m]. With a stress table (of the pair's
  // Poisson's ratio), Detail::full reads the von Mises maximum off it instead of maximising.
  AsperityState evaluate(const ContactPair& pair, double delta, Detail detail = Detail::full,
                         VonMisesTable* stress_table = nullptr) const;

 protected:
  virtual void law_breakpoints(std::vector<double>& out) const = 0;

  std::vector<double> constants_;
};

// Registry: the names of the models and a factory. Throws std::invalid_argument for an
// unknown name, listing the known ones.
std::span<const std::string_view> asperity_model_names();
std::unique_ptr<AsperityModel> make_asperity_model(std::string_view name);

}  // namespace geartrib::asperity
