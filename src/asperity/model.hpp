// Single-asperity models chosen by name from one registry. A model owns the values of its
// named constants; it evaluates a sphere-on-flat contact at an interference and returns every
// output the tool reports.
#pragma once

#include "asperity/contact_pair.hpp"
#include "asperity/critical.hpp"
#include "asperity/laws.hpp"
#include "asperity/pressure_profile.hpp"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::asperity {

// Everything known about one asperity contact at an interference, SI units.
struct AsperityState {
  double delta = 0.0;             // interference [m]
  double delta_star = 0.0;        // delta / delta_c (the model's own delta_c)
  double load = 0.0;              // F [N]
  double load_star = 0.0;         // F / F_c
  double area = 0.0;              // A [m^2]
  double area_star = 0.0;         // A / A_c
  double contact_radius = 0.0;    // a = sqrt(A/pi) [m]
  double plastic_radius = 0.0;    // r_p, radius of the plastic core of the pressure profile [m]
  double mean_pressure = 0.0;     // F/A [Pa]
  double max_pressure = 0.0;      // peak contact pressure [Pa]
  double plastic_fraction = 0.0;  // plastic share of the contact area (r_p/a)^2
  double max_von_mises = 0.0;     // largest von Mises stress of the elastic field on the axis [Pa]
  double von_mises_depth = 0.0;   // its depth [m]
};

// What to compute: the load and area only (cheap); also the pressure profile (peak pressure,
// plastic core and share: cheap); or also the von Mises maximum (a quadrature: ~0.3 ms).
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

  // Dimensionless law at delta* = delta/delta_c.
  virtual Star<double> star(double delta_star, const ContactPair& pair) const = 0;

  // Contact pressure profile at delta*, given the law's load and area. The default
  // reconstructs it from the mean pressure (profile_from_mean_pressure); models with a
  // profile of their own override it.
  virtual PressureProfile profile(double delta_star, const ContactPair& pair, const Critical& crit,
                                  double load, double area) const;

  // Full evaluation at an interference delta >= 0 [m].
  AsperityState evaluate(const ContactPair& pair, double delta, Detail detail = Detail::full) const;

 protected:
  std::vector<double> constants_;
};

// Registry: the names of the models and a factory. Throws std::invalid_argument for an
// unknown name, listing the known ones.
std::span<const std::string_view> asperity_model_names();
std::unique_ptr<AsperityModel> make_asperity_model(std::string_view name);

}  // namespace geartrib::asperity
