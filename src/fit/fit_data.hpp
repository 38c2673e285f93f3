// Reference observations for fitting a single-asperity model: rows of delta* with observed
// dimensionless quantities (normalised by the fitted model's critical values).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace geartrib::fit {

// plastic_area_fraction: the yielded share of the contact area at the surface (0..1), as
// `geartrib fem single-asperity` writes it.
enum class Observable { load_star, area_star, mean_pressure_over_yield, plastic_area_fraction };
std::string_view to_string(Observable o);
Observable parse_observable(std::string_view name);  // throws std::invalid_argument

// The plausible range of each value of the reference data (dimensionless, normalised by the
// model's critical values; docs/guide/fit.md): delta_star in [1e-9, 1e6] (the models' tested
// range); load_star, area_star and mean_pressure_over_yield 0 or of magnitude [1e-12, 1e12] (a
// relative residual divides by the observation: a denormal or an overflowing value breaks it);
// plastic_area_fraction in [-0.1, 1.1] (a fraction with room for the noise of a measurement or
// a mesh); sd_<column> in [1e-12, 1e12]; a row weight in [0, 1e6].
inline constexpr double kMinDeltaStar = 1e-9, kMaxDeltaStar = 1e6;
inline constexpr double kFractionNoise = 0.1;
inline constexpr double kMinObservation = 1e-12, kMaxObservation = 1e12;
inline constexpr double kMaxRowWeight = 1e6;
// Why a value of `what` is outside its range (the rule), or empty when it is fine.
std::string observation_problem(Observable what, double value);
std::string std_dev_problem(double sd);
std::string delta_star_problem(double delta_star);

struct ObservedColumn {
  Observable what = Observable::load_star;
  std::vector<double> values;   // NaN where a row has no observation of it
  std::vector<double> std_dev;  // empty, or per-row standard deviations (absolute)
};

struct FitData {
  std::string name;                                             // file name, for reports
  std::vector<std::pair<std::string, std::string>> provenance;  // '# key: value' lines
  std::vector<double> delta_star;
  std::vector<double> weight;  // per row (1 when absent)
  std::vector<int> line;       // source line of each row
  std::vector<ObservedColumn> columns;
  const ObservedColumn* column(Observable o) const;
};

}  // namespace geartrib::fit
