#include "lubrication/lubricant.hpp"

#include "core/named_choices.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace geartrib::lubrication {

namespace {
constexpr double kZeroCelsius = 273.15;  // [K]
constexpr double kT40 = kZeroCelsius + 40.0, kT100 = kZeroCelsius + 100.0, kT15 = kZeroCelsius + 15.0;
constexpr double kCentistokes = 1e-6;  // [m^2/s]

// Walther's constants A, B through the 40 and 100 degC points.
struct Walther {
  double a, b;
};
double walther_w(double nu) { return std::log10(std::log10(nu / kCentistokes + Lubricant::kWaltherOffset)); }
Walther walther(const Lubricant& l) {
  const double w40 = walther_w(l.kinematic_viscosity_40), w100 = walther_w(l.kinematic_viscosity_100);
  const double b = (w40 - w100) / (std::log10(kT100) - std::log10(kT40));
  return {w40 + b * std::log10(kT40), b};
}
// The laws unchecked (validate() and law_range() evaluate them at the range's edges).
double walther_viscosity(const Walther& w, double t) {
  return (std::pow(10.0, std::pow(10.0, w.a - w.b * std::log10(t))) - Lubricant::kWaltherOffset) * kCentistokes;
}
// The temperature at which Walther's law gives nu [m^2/s] (B > 0).
double walther_temperature(const Walther& w, double nu) { return std::pow(10.0, (w.a - walther_w(nu)) / w.b); }
double density_ratio(const Lubricant& l, double t) { return 1.0 - l.density_temperature_coefficient * (t - kT15); }

// ISO/TR 15144-1 temperature law of alpha, relative to 38 degC (311 K in the standard).
double iso_alpha_temperature_factor(double t) { return 1.0 + 516.0 * (1.0 / t - 1.0 / 311.0); }

// A law asked outside its law range `r` (law_range(l)): refused, naming the law, the temperature
// and the range.
void require_in_range(const Lubricant& l, const TemperatureRange& r, double t, const char* law) {
  if (l.fixed()) return;
  if (!r.contains(t))
    throw OutsideLawRange(fmt::format("{} of {} asked at {:.6g} K, outside [{:.2f}, {:.2f}] K where its laws hold", law,
                                      l.name, t, r.lo, r.hi));
}
}  // namespace

TemperatureRange data_range(const Lubricant& l) { return {l.min_temperature, l.max_temperature}; }

TemperatureRange law_range(const Lubricant& l) {
  if (l.fixed()) return data_range(l);
  TemperatureRange r{kMinOilTemperature, kMaxOilTemperature};
  const Walther w = walther(l);
  if (w.b > 0.0 && std::isfinite(w.a))  // nu40 > nu100
    r.lo = std::max(r.lo, walther_temperature(w, kWaltherMaxViscosity));
  if (l.density_temperature_coefficient > 0.0) {
    double half = kT15 + 0.5 / l.density_temperature_coefficient;  // the density at half its 15 degC value
    // Rounded, the line may be a hair below half there (fuzz_lubricant's finding): the last
    // temperature at which it is not.
    for (int k = 0; k < 8 && density_ratio(l, half) < 0.5; ++k) half = std::nextafter(half, 0.0);
    r.hi = std::min(r.hi, half);
  }
  return r;
}

TemperatureRange operating_range(const Lubricant& l) {
  if (l.fixed()) return data_range(l);
  const TemperatureRange law = law_range(l);
  return {std::max(law.lo, l.min_temperature - kColdExtrapolation),
          std::min(law.hi, l.max_temperature + kHotExtrapolation)};
}

namespace {
constexpr NamedChoice<BaseOil> kBaseOils[] = {
    {BaseOil::mineral, "mineral"},
    {BaseOil::pao, "pao"},
    {BaseOil::ester, "ester"},
    {BaseOil::polyglycol_insoluble, "polyglycol-insoluble"},
    {BaseOil::polyglycol_water_soluble, "polyglycol-water-soluble"},
    {BaseOil::phosphate_ester, "phosphate-ester"},
    {BaseOil::traction_fluid, "traction-fluid"},
};
}  // namespace

BaseOil base_oil_from_name(const std::string& name) {
  try {
    return choice_from_name<BaseOil>(kBaseOils, name, "base oil");
  } catch (const std::invalid_argument& e) {
    std::string known;
    for (const auto& n : base_oil_names()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument(std::string(e.what()) + " (known: " + known + ")");
  }
}
const char* base_oil_name(BaseOil b) { return choice_name<BaseOil>(kBaseOils, b); }
std::vector<std::string> base_oil_names() { return choice_names<BaseOil>(kBaseOils); }

double iso_lubricant_factor(BaseOil b) {
  switch (b) {
    case BaseOil::mineral:
      return 1.0;
    case BaseOil::pao:
      return 0.8;
    case BaseOil::polyglycol_insoluble:
      return 0.7;
    case BaseOil::polyglycol_water_soluble:
      return 0.6;
    case BaseOil::phosphate_ester:
      return 1.3;
    case BaseOil::traction_fluid:
      return 1.5;
    case BaseOil::ester:
      break;  // not tabulated
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double Lubricant::lubricant_factor() const {
  return iso_lubricant_factor > 0.0 ? iso_lubricant_factor : lubrication::iso_lubricant_factor(base_oil);
}

TractionCurves::TractionCurves(std::vector<TractionCurve> curves) : curves_(std::move(curves)) {
  auto fail = [](const TractionCurve& c, const char* member, const std::string& rule) {
    throw std::invalid_argument(fmt::format("traction_curves.{}.{}: {}", c.name, member, rule));
  };
  for (const TractionCurve& c : curves_) {
    if (c.slide_to_roll.size() != c.coefficient.size())
      fail(c, "coefficient", fmt::format("must have as many entries as slide_to_roll ({})", c.slide_to_roll.size()));
    if (c.slide_to_roll.size() < 2) fail(c, "slide_to_roll", "needs at least two points");
    if (!(c.slide_to_roll.front() >= 0.0)) fail(c, "slide_to_roll", "must start at 0 or above (SRR = |v1 - v2|/u)");
    for (std::size_t i = 1; i < c.slide_to_roll.size(); ++i)
      if (!(c.slide_to_roll[i] > c.slide_to_roll[i - 1]))
        fail(c, "slide_to_roll",
             fmt::format("must increase strictly (entry {} after {:g})", i, c.slide_to_roll[i - 1]));
    if (!(c.slide_to_roll.back() <= 2.0)) fail(c, "slide_to_roll", "must not exceed 2 (pure sliding)");
    for (std::size_t i = 0; i < c.coefficient.size(); ++i)
      if (!(c.coefficient[i] >= 0.0 && c.coefficient[i] <= 1.0))
        fail(c, "coefficient", fmt::format("must lie in [0, 1] (entry {}: {:g})", i, c.coefficient[i]));
    if (!(c.hertz_pressure > 0.0)) fail(c, "hertz_pressure", "must be positive");
    if (!(c.temperature > 0.0)) fail(c, "temperature", "must be positive (K)");
    if (!(c.entrainment_speed > 0.0)) fail(c, "entrainment_speed", "must be positive");
  }
  for (const TractionCurve& c : curves_) {
    if (std::find(pressures_.begin(), pressures_.end(), c.hertz_pressure) == pressures_.end())
      pressures_.push_back(c.hertz_pressure);
    if (std::find(temperatures_.begin(), temperatures_.end(), c.temperature) == temperatures_.end())
      temperatures_.push_back(c.temperature);
  }
  std::sort(pressures_.begin(), pressures_.end());
  std::sort(temperatures_.begin(), temperatures_.end());
  const std::size_t np = pressures_.size(), nt = temperatures_.size();
  index_.assign(np * nt, curves_.size());
  for (std::size_t k = 0; k < curves_.size(); ++k) {
    const TractionCurve& c = curves_[k];
    const auto i = static_cast<std::size_t>(std::find(pressures_.begin(), pressures_.end(), c.hertz_pressure) -
                                            pressures_.begin());
    const auto j = static_cast<std::size_t>(std::find(temperatures_.begin(), temperatures_.end(), c.temperature) -
                                            temperatures_.begin());
    if (index_[i * nt + j] != curves_.size())
      fail(c, "temperature",
           fmt::format("a second curve at {:g} Pa and {:g} K (also '{}')", c.hertz_pressure, c.temperature,
                       curves_[index_[i * nt + j]].name));
    index_[i * nt + j] = k;
  }
  for (std::size_t i = 0; i < np; ++i)
    for (std::size_t j = 0; j < nt; ++j)
      if (index_[i * nt + j] == curves_.size())
        throw std::invalid_argument(fmt::format(
            "traction_curves: the curves must form a grid of Hertz pressure x temperature; none at {:g} Pa and {:g} K",
            pressures_[i], temperatures_[j]));
}

namespace {
// The bracketing pair (i, i + 1) of an ascending axis and the weight of i + 1, clamped.
struct Bracket {
  std::size_t lo, hi;
  double t;
};
Bracket bracket(const std::vector<double>& axis, double at, bool& outside) {
  if (axis.size() == 1 || at <= axis.front()) {
    outside = outside || at < axis.front() || (axis.size() == 1 && at > axis.front());
    return {0, 0, 0.0};
  }
  if (at >= axis.back()) {
    outside = outside || at > axis.back();
    return {axis.size() - 1, axis.size() - 1, 0.0};
  }
  const auto k = static_cast<std::size_t>(std::upper_bound(axis.begin(), axis.end(), at) - axis.begin());
  return {k - 1, k, (at - axis[k - 1]) / (axis[k] - axis[k - 1])};
}
// Linear interpolation in an ascending table, clamped at its ends; `outside` set when clamped.
double table_value(const std::vector<double>& x, const std::vector<double>& y, double at, bool& outside) {
  const Bracket b = bracket(x, at, outside);
  return (1.0 - b.t) * y[b.lo] + b.t * y[b.hi];
}
}  // namespace

TractionValue TractionCurves::at(double srr, double p, double temperature) const {
  TractionValue v;
  if (curves_.empty()) return v;
  // A single pressure or temperature is a stated condition, not a range: a value away from it is
  // outside what was measured (flagged), the curve is used as it is.
  const Bracket bp = bracket(pressures_, p, v.outside), bt = bracket(temperatures_, temperature, v.outside);
  const std::size_t nt = temperatures_.size();
  auto curve = [&](std::size_t i, std::size_t j) {
    const TractionCurve& c = curves_[index_[i * nt + j]];
    return table_value(c.slide_to_roll, c.coefficient, std::abs(srr), v.outside);
  };
  const double lo = (1.0 - bt.t) * curve(bp.lo, bt.lo) + bt.t * curve(bp.lo, bt.hi);
  const double hi = (1.0 - bt.t) * curve(bp.hi, bt.lo) + bt.t * curve(bp.hi, bt.hi);
  v.coefficient = (1.0 - bp.t) * lo + bp.t * hi;
  return v;
}

void Lubricant::validate() const {
  auto fail = [](const char* member, const std::string& rule) {
    throw std::invalid_argument(fmt::format("{}: {}", member, rule));
  };
  if (fixed()) {
    if (!(pressure_viscosity > 0.0)) fail("pressure_viscosity_coefficient", "must be positive");
    if (!(fixed_temperature_viscosity >= 0.0)) fail("temperature_viscosity_coefficient", "must be >= 0");
  } else {
    if (!(kinematic_viscosity_100 >= 2.0 * kCentistokes))
      fail("kinematic_viscosity_100C", "must be at least 2 mm^2/s (Walther's law, ASTM D341)");
    if (!(kinematic_viscosity_40 > kinematic_viscosity_100))
      fail("kinematic_viscosity_40C", "must exceed the 100 degC viscosity");
    if (!(density_15 > 0.0)) fail("density_15C", "must be positive");
    if (!(density_temperature_coefficient >= 0.0 && density_temperature_coefficient < 2e-3))
      fail("density_temperature_coefficient", "must lie in [0, 2e-3) 1/K");
    if (!(pressure_viscosity >= 0.0)) fail("pressure_viscosity_coefficient", "must be positive (or omitted)");
    if (!(pressure_viscosity_temperature > 0.0)) fail("pressure_viscosity_temperature", "must be positive (K)");
  }
  if (!(thermal_conductivity > 0.0)) fail("thermal_conductivity", "must be positive");
  if (!(specific_heat >= 0.0)) fail("specific_heat", "must be >= 0");
  if (!(eyring_stress > 0.0)) fail("eyring_stress", "must be positive");
  if (!(limiting_shear_coefficient > 0.0 && limiting_shear_coefficient <= 1.0))
    fail("limiting_shear_coefficient", "must lie in (0, 1]");
  if (!(min_temperature > 0.0 && max_temperature > min_temperature))
    fail("max_temperature", "must exceed min_temperature (both in K, positive)");
  if (!(iso_lubricant_factor >= 0.0 && iso_lubricant_factor <= 2.0))
    fail("iso_lubricant_factor", "must lie in [0, 2] (0: the base stock's tabulated value; the table: 0.6 to 1.5)");
  if (!(lubricant_factor() > 0.0))
    fail("iso_lubricant_factor",
         fmt::format("ISO/TS 6336-20 tabulates no lubricant factor X_L for base oil '{}': give iso_lubricant_factor "
                     "with its source",
                     base_oil_name(base_oil)));
  if (fixed()) return;
  // The data range inside every law's range (law_range), and what is carried from a temperature
  // (alpha's reference, the correlation's 38 degC) inside the operating range.
  const Walther w = walther(*this);
  auto viscosity_text = [](double nu) {
    return std::isfinite(nu) ? fmt::format("{:.3g} mm^2/s", nu / kCentistokes) : std::string("beyond 1e308 m^2/s");
  };
  const double nu_cold = walther_viscosity(w, min_temperature), nu_hot = walther_viscosity(w, max_temperature);
  if (!(nu_cold <= kWaltherMaxViscosity))
    fail("min_temperature",
         fmt::format("Walther's law through the 40 and 100 degC viscosities gives {} at {:.2f} K, beyond the 2e7 "
                     "mm^2/s top of ASTM D341's range: raise min_temperature to at least {:.2f} K",
                     viscosity_text(nu_cold), min_temperature, walther_temperature(w, kWaltherMaxViscosity)));
  if (!(min_temperature >= kMinOilTemperature))
    fail("min_temperature", fmt::format("below {:.2f} K (-100 degC), the coldest at which an oil's laws are taken: no "
                                        "gear oil flows there",
                                        kMinOilTemperature));
  if (!(max_temperature <= kMaxOilTemperature))
    fail(
        "max_temperature",
        fmt::format("beyond {:.2f} K (400 degC), the hottest at which an oil's laws are taken: no gear oil is a liquid "
                    "with data past it, and ISO/TR 15144-1's pressure-viscosity factor 1 + 516 (1/T - 1/311 K) falls "
                    "to 0.107 there and to 0 at {:.1f} K",
                    kMaxOilTemperature, 1.0 / (1.0 / 311.0 - 1.0 / 516.0)));
  if (!(nu_hot >= kWaltherMinViscosity))
    fail("max_temperature",
         fmt::format("Walther's law through the 40 and 100 degC viscosities gives {} at {:.2f} K, below the 2 mm^2/s "
                     "where ASTM D341's nu + 0.7 form holds: lower max_temperature to at most {:.2f} K",
                     viscosity_text(nu_hot), max_temperature, walther_temperature(w, kWaltherMinViscosity)));
  // A liquid oil's density falls by well under half over its whole liquid range (c ~ 7e-4 1/K:
  // about a quarter from 15 to 350 degC); the line beyond that is no oil's (and beta's density
  // term c/(1 - c dT) grows without bound as it nears zero).
  if (!(density_ratio(*this, max_temperature) >= 0.5))
    fail("density_temperature_coefficient",
         fmt::format("the density line falls to {:.3g} of its 15 degC value at max_temperature ({:.2f} K); it must "
                     "stay above half of it over the data range",
                     density_ratio(*this, max_temperature), max_temperature));
  const TemperatureRange r = operating_range(*this);
  if (pressure_viscosity > 0.0 && !r.contains(pressure_viscosity_temperature))
    fail("pressure_viscosity_temperature",
         fmt::format("{:.2f} K lies outside [{:.2f}, {:.2f}] K, this oil's data range with at most {:g} K below and "
                     "{:g} K above it: the measured alpha is carried from there by ISO/TR 15144-1's temperature law",
                     pressure_viscosity_temperature, r.lo, r.hi, kColdExtrapolation, kHotExtrapolation));
  if (!(pressure_viscosity > 0.0) && !r.contains(kZeroCelsius + 38.0))
    fail(
        "pressure_viscosity_coefficient",
        fmt::format("omitted, so ISO/TR 15144-1's correlation takes the viscosity at 38 degC, outside [{:.2f}, {:.2f}] "
                    "K (this oil's data range with at most {:g} K below and {:g} K above it): give a measured "
                    "pressure_viscosity_coefficient and its pressure_viscosity_temperature",
                    r.lo, r.hi, kColdExtrapolation, kHotExtrapolation));
}

double kinematic_viscosity(const Lubricant& l, double t) {
  require_in_range(l, law_range(l), t, "Walther's viscosity");
  return walther_viscosity(walther(l), t);
}

double density(const Lubricant& l, double t) {
  require_in_range(l, law_range(l), t, "the density line");
  return l.density_15 * density_ratio(l, t);
}

namespace {
// alpha(T) of the temperature-dependent form, unchecked (the callers check T; validate() checks 38 degC).
double alpha_at(const Lubricant& l, const Walther& w, double t) {
  if (l.pressure_viscosity > 0.0)
    return l.pressure_viscosity * iso_alpha_temperature_factor(t) /
           iso_alpha_temperature_factor(l.pressure_viscosity_temperature);
  const double t38 = kZeroCelsius + 38.0;
  const double eta38 = walther_viscosity(w, t38) * l.density_15 * density_ratio(l, t38);  // [Pa s]
  return 2.657e-8 * std::pow(eta38, 0.1348) * iso_alpha_temperature_factor(t);
}
}  // namespace

double pressure_viscosity_coefficient(const Lubricant& l, double t) {
  if (l.fixed()) return l.pressure_viscosity;
  require_in_range(l, law_range(l), t, "the pressure-viscosity coefficient");
  return alpha_at(l, walther(l), t);
}

OilState oil_state(const Lubricant& l, double t) { return oil_state(l, t, law_range(l)); }

OilState oil_state(const Lubricant& l, double t, const TemperatureRange& law) {
  OilState s;
  s.temperature = t;
  s.thermal_conductivity = l.thermal_conductivity;
  s.eyring_stress = l.eyring_stress;
  s.limiting_shear_coefficient = l.limiting_shear_coefficient;
  s.iso_lubricant_factor = l.lubricant_factor();
  if (l.fixed()) {
    s.pressure_viscosity = l.pressure_viscosity;
    s.dynamic_viscosity = l.fixed_dynamic_viscosity;
    s.temperature_viscosity = l.fixed_temperature_viscosity;
    s.density = l.density_15;
    return s;
  }
  require_in_range(l, law, t, "the oil state");  // once for every law below
  const Walther w = walther(l);
  s.pressure_viscosity = alpha_at(l, w, t);
  s.density = l.density_15 * density_ratio(l, t);
  const double nu = walther_viscosity(w, t);
  s.dynamic_viscosity = nu * s.density;
  // beta = -d ln(nu)/dT - d ln(rho)/dT, Walther differentiated:
  // d nu/dT = -(nu + 0.7) ln10 10^Z B / T with Z = A - B log10 T (nu in cSt).
  const double nu_cst = nu / kCentistokes;
  const double dnu_dt =
      -(nu_cst + Lubricant::kWaltherOffset) * std::log(10.0) * std::pow(10.0, w.a - w.b * std::log10(t)) * w.b / t;
  s.temperature_viscosity =
      -dnu_dt / nu_cst + l.density_temperature_coefficient / (1.0 - l.density_temperature_coefficient * (t - kT15));
  return s;
}

}  // namespace geartrib::lubrication
