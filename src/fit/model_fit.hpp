// Fitting a registered asperity model's named constants to reference data with Ceres: automatic
// differentiation through the same scalar-templated law the simulator runs (laws.hpp), bounds
// from the constants' admissible ranges, a robust loss if asked, standard errors and
// correlations from Ceres' covariance.
#pragma once

#include "asperity/contact_pair.hpp"
#include "asperity/model.hpp"
#include "fit/fit_data.hpp"

#include <string>
#include <tuple>
#include <vector>

namespace geartrib::fit {

enum class Loss { squared, huber, cauchy };
Loss parse_loss(std::string_view name);  // throws std::invalid_argument

struct FitOptions {
  std::vector<std::string> free;                                // constants to fit; empty: all
  std::vector<Observable> observe;                              // empty: every observed column present in the data
  std::vector<double> observe_weight;                           // relative weight per observed column (1 when empty)
  std::vector<std::tuple<std::string, double, double>> bounds;  // (constant, lower, upper) within its range
  Loss loss = Loss::squared;
  double loss_scale = 0.1;  // residual scale of the robust losses (a relative 10%)
  int max_iterations = 500;
  // Each field within its range: throws core::KeyedError whose key is the field (observe_weight,
  // loss_scale, max_iterations, bounds) and whose message starts with it, then the value and the
  // rule. The constants' names and ranges are the model's: fit_model checks those.
  void validate() const;
};

struct FittedConstant {
  std::string name;
  double value = 0.0;
  double std_error = 0.0;  // NaN when not identifiable; 0 for fixed constants
  bool free = false;
};

struct RowResidual {
  std::string data;  // data set name
  int line = 0;
  double delta_star = 0.0;
  Observable what = Observable::load_star;
  double observed = 0.0;
  double model = 0.0;
  double relative = 0.0;  // model/observed - 1 (NaN for a zero observation)
};

struct FitResult {
  std::string model;
  std::vector<FittedConstant> constants;
  std::vector<std::vector<double>> correlation;  // among the free constants, in their order
  std::vector<RowResidual> residuals;
  std::vector<std::pair<Observable, double>> rms_relative;  // per observed column
  struct DataRms {
    std::string data;
    Observable what;
    double rms;
  };
  std::vector<DataRms> rms_by_data;  // per data set and observed column
  std::string ceres_report;          // Ceres' full report
  int iterations = 0;
  double final_cost = 0.0;
};

// Starts from `model`'s current constants. Throws std::invalid_argument for unusable input
// (unknown constant, no observations of a column, NaN, fewer observations than free
// constants) and std::runtime_error when Ceres does not converge.
FitResult fit_model(const asperity::AsperityModel& model, const asperity::ContactPair& pair,
                    const std::vector<FitData>& data, const FitOptions& options);

// The memory a fit of these data holds [bytes], estimated before it starts: 480 bytes a data row with
// an observation and 370 an observation (Ceres' residual blocks and their automatic differentiation, the
// residuals' report), measured with /usr/bin/time's peak RSS on 83119 and 332475 rows of one and of
// three observed columns (docs/reference/performance.md#budgets). observe: the columns fitted (empty: all).
inline constexpr double kFitBytesPerRow = 480.0, kFitBytesPerObservation = 370.0;
double fit_memory_bytes(const std::vector<FitData>& data, const std::vector<Observable>& observe);

// The model's dimensionless value of an observable at delta* (as the fit computes it: the law
// itself, without the switch to the fully plastic limit past its range).
double model_observable(const asperity::AsperityModel& model, const asperity::ContactPair& pair, double delta_star,
                        Observable what);

}  // namespace geartrib::fit
