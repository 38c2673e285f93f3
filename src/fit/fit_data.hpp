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
