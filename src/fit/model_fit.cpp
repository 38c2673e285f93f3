#include "fit/model_fit.hpp"

#include "asperity/laws.hpp"
#include "core/keyed_error.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geartrib::fit {

std::string_view to_string(Observable o) {
  switch (o) {
    case Observable::load_star:
      return "load_star";
    case Observable::area_star:
      return "area_star";
    case Observable::mean_pressure_over_yield:
      return "mean_pressure_over_yield";
    case Observable::plastic_area_fraction:
      return "plastic_area_fraction";
  }
  return "?";
}

Observable parse_observable(std::string_view name) {
  for (auto o : {Observable::load_star, Observable::area_star, Observable::mean_pressure_over_yield,
                 Observable::plastic_area_fraction})
    if (to_string(o) == name) return o;
  throw std::invalid_argument("unknown observed quantity '" + std::string(name) +
                              "' (known: load_star, area_star, mean_pressure_over_yield, plastic_area_fraction)");
}

std::string observation_problem(Observable what, double v) {
  if (!std::isfinite(v)) return "not a finite number";
  if (what == Observable::plastic_area_fraction)  // a fraction, measured with some noise
    return v >= -kFractionNoise && v <= 1.0 + kFractionNoise
               ? ""
               : fmt::format("a plastic area fraction must lie in [{:g}, {:g}] (0 to 1, with room for noise)",
                             -kFractionNoise, 1.0 + kFractionNoise);
  if (v < 0.0) return "must not be negative";
  if (v != 0.0 && (v < kMinObservation || v > kMaxObservation))
    return fmt::format("must be 0 or lie in [{:g}, {:g}] (dimensionless: a relative residual divides by it)",
                       kMinObservation, kMaxObservation);
  return "";
}

std::string std_dev_problem(double sd) {
  if (!std::isfinite(sd)) return "not a finite number";
  if (!(sd >= kMinObservation && sd <= kMaxObservation))
    return fmt::format("a standard deviation must lie in [{:g}, {:g}]", kMinObservation, kMaxObservation);
  return "";
}

std::string delta_star_problem(double x) {
  if (!std::isfinite(x)) return "not a finite number";
  if (!(x >= kMinDeltaStar && x <= kMaxDeltaStar))
    return fmt::format("must lie in [{:g}, {:g}] (the models' range of delta*)", kMinDeltaStar, kMaxDeltaStar);
  return "";
}

const ObservedColumn* FitData::column(Observable o) const {
  for (const auto& c : columns)
    if (c.what == o) return &c;
  return nullptr;
}

double fit_memory_bytes(const std::vector<FitData>& data, const std::vector<Observable>& observe) {
  double bytes = 0.0;
  for (const auto& d : data) {
    std::vector<const ObservedColumn*> columns;
    for (const auto& c : d.columns)
      if (observe.empty() || std::find(observe.begin(), observe.end(), c.what) != observe.end()) columns.push_back(&c);
    for (std::size_t r = 0; r < d.delta_star.size(); ++r) {
      double terms = 0.0;
      for (const ObservedColumn* c : columns) terms += std::isnan(c->values[r]) ? 0.0 : 1.0;
      if (terms > 0.0) bytes += kFitBytesPerRow + kFitBytesPerObservation * terms;
    }
  }
  return bytes;
}

Loss parse_loss(std::string_view name) {
  if (name == "squared" || name == "least-squares") return Loss::squared;
  if (name == "huber") return Loss::huber;
  if (name == "cauchy") return Loss::cauchy;
  throw std::invalid_argument("unknown loss '" + std::string(name) + "' (known: squared, huber, cauchy)");
}

namespace {

struct Term {
  Observable what;
  double observed;
  double scale;  // observed value (relative residual) or its standard deviation
  double weight;
};

// One row of data: residuals w (model - observed)/scale for each observed quantity, with the
// law evaluated on the scalar type Ceres passes (double or Jet).
template <class Law>
struct RowResidualFunctor {
  double delta_star;
  const asperity::ContactPair* pair;
  std::vector<Term> terms;

  template <class T>
  bool operator()(T const* const* params, T* residuals) const {
    constexpr std::size_t n = Law::constants.size();
    std::array<T, n> c;
    for (std::size_t k = 0; k < n; ++k) c[k] = params[k][0];
    const asperity::Star<T> s = Law::star(T(delta_star), c.data(), *pair);
    for (std::size_t i = 0; i < terms.size(); ++i) {
      T value;
      switch (terms[i].what) {
        case Observable::load_star:
          value = s.load;
          break;
        case Observable::area_star:
          value = s.area;
          break;
        case Observable::plastic_area_fraction:
          value = s.plastic;
          break;
        default:  // F/A over S_y with F_c/A_c = 2/3 p_y
          value = s.load / s.area * (2.0 / 3.0) * Law::yield_peak_pressure(*pair, c.data()) / pair->yield_strength;
      }
      residuals[i] = terms[i].weight * (value - terms[i].observed) / terms[i].scale;
    }
    return true;
  }
};

template <class Law>
FitResult fit_law(const asperity::AsperityModel& model, const asperity::ContactPair& pair,
                  const std::vector<FitData>& data, const FitOptions& options) {
  constexpr std::size_t n = Law::constants.size();
  if (n == 0) throw std::invalid_argument("model '" + std::string(Law::name) + "' has no constants to fit");
  FitResult result;
  result.model = std::string(Law::name);
  std::array<double, n> values{};
  std::array<bool, n> is_free{};
  for (std::size_t k = 0; k < n; ++k) {
    values[k] = model.constants()[k];
    is_free[k] = options.free.empty();
  }
  for (const auto& name : options.free) {
    bool found = false;
    for (std::size_t k = 0; k < n; ++k)
      if (Law::constants[k].name == name) is_free[k] = found = true;
    if (!found) {
      std::string known;
      for (const auto& c : Law::constants) known += (known.empty() ? "" : ", ") + std::string(c.name);
      throw std::invalid_argument("model '" + std::string(Law::name) + "' has no constant '" + name +
                                  "' (known: " + known + ")");
    }
  }
  std::size_t free_count = 0;
  for (bool f : is_free) free_count += f;

  ceres::Problem problem;
  std::array<double, n> lower{}, upper{};
  for (std::size_t k = 0; k < n; ++k) lower[k] = Law::constants[k].lower, upper[k] = Law::constants[k].upper;
  for (const auto& [name, lo, hi] : options.bounds) {
    std::size_t k = 0;
    while (k < n && Law::constants[k].name != name) ++k;
    if (k == n) throw std::invalid_argument("bound for unknown constant '" + name + "'");
    if (!(lo <= hi && lo >= lower[k] && hi <= upper[k]))
      throw std::invalid_argument(
          fmt::format("bounds [{}, {}] of '{}' must be ordered and lie within its range [{}, {}]", lo, hi, name,
                      lower[k], upper[k]));
    lower[k] = lo;
    upper[k] = hi;
    values[k] = std::clamp(values[k], lo, hi);
  }
  for (std::size_t k = 0; k < n; ++k) {
    problem.AddParameterBlock(&values[k], 1);
    problem.SetParameterLowerBound(&values[k], 0, lower[k]);
    problem.SetParameterUpperBound(&values[k], 0, upper[k]);
    if (!is_free[k]) problem.SetParameterBlockConstant(&values[k]);
  }
  ceres::LossFunction* loss = nullptr;
  if (options.loss == Loss::huber) loss = new ceres::HuberLoss(options.loss_scale);
  if (options.loss == Loss::cauchy) loss = new ceres::CauchyLoss(options.loss_scale);
  std::vector<double*> blocks;
  blocks.reserve(values.size());
  for (auto& v : values) blocks.push_back(&v);

  std::vector<Observable> observe = options.observe;
  if (observe.empty())
    for (const auto& d : data)
      for (const auto& col : d.columns)
        if (std::find(observe.begin(), observe.end(), col.what) == observe.end()) observe.push_back(col.what);
  std::size_t observations = 0;
  bool has_sd = false;
  struct Pending {
    const FitData* data;
    std::size_t row;
    std::vector<Term> terms;
  };
  std::vector<Pending> rows;
  for (const auto& d : data) {
    for (std::size_t r = 0; r < d.delta_star.size(); ++r) {
      const double x = d.delta_star[r];
      if (const std::string why = delta_star_problem(x); !why.empty())
        throw std::invalid_argument(fmt::format("{}:{}: delta_star = {}: {}", d.name, d.line[r], x, why));
      if (!(std::isfinite(d.weight[r]) && d.weight[r] >= 0.0 && d.weight[r] <= kMaxRowWeight))
        throw std::invalid_argument(
            fmt::format("{}:{}: weight = {}: must lie in [0, {:g}]", d.name, d.line[r], d.weight[r], kMaxRowWeight));
      Pending p{&d, r, {}};
      for (std::size_t j = 0; j < observe.size(); ++j) {
        const ObservedColumn* col = d.column(observe[j]);
        if (!col || std::isnan(col->values[r])) continue;
        const double obs = col->values[r];
        if (const std::string why = observation_problem(observe[j], obs); !why.empty())
          throw std::invalid_argument(
              fmt::format("{}:{}: {} = {}: {}", d.name, d.line[r], to_string(observe[j]), obs, why));
        if (!col->std_dev.empty() && !std::isnan(col->std_dev[r]))
          if (const std::string why = std_dev_problem(col->std_dev[r]); !why.empty())
            throw std::invalid_argument(
                fmt::format("{}:{}: sd_{} = {}: {}", d.name, d.line[r], to_string(observe[j]), col->std_dev[r], why));
        const bool sd = !col->std_dev.empty() && std::isfinite(col->std_dev[r]) && col->std_dev[r] > 0.0;
        has_sd = has_sd || sd;
        if (!sd && obs == 0.0)
          throw std::invalid_argument(fmt::format(
              "{}:{}: a zero observation needs a standard deviation (residuals are relative)", d.name, d.line[r]));
        const double w = (options.observe_weight.size() > j ? options.observe_weight[j] : 1.0) * d.weight[r];
        p.terms.push_back({observe[j], obs, sd ? col->std_dev[r] : std::abs(obs), w});
      }
      if (p.terms.empty()) continue;
      observations += p.terms.size();
      rows.push_back(std::move(p));
    }
  }
  for (Observable o : observe) {
    bool present = false;
    for (const auto& d : data) present = present || d.column(o);
    if (!present)
      throw std::invalid_argument("no data set has the observed column '" + std::string(to_string(o)) + "'");
  }
  if (observations <= free_count)
    throw std::invalid_argument(
        fmt::format("{} observations cannot determine {} free constants", observations, free_count));
  std::vector<const ceres::CostFunction*> costs;
  for (const auto& p : rows) {
    auto* functor = new RowResidualFunctor<Law>{p.data->delta_star[p.row], &pair, p.terms};
    auto* cost = new ceres::DynamicAutoDiffCostFunction<RowResidualFunctor<Law>, 4>(functor);
    for (std::size_t k = 0; k < n; ++k) cost->AddParameterBlock(1);
    cost->SetNumResiduals(static_cast<int>(p.terms.size()));
    problem.AddResidualBlock(cost, loss, blocks);
    costs.push_back(cost);
  }

  // Before Ceres runs: every row's residuals and derivatives finite at the start (else the row is
  // named), and each free constant moving at least one observed value (else it cannot be fitted:
  // its column of the Jacobian is zero and its standard error undefined).
  {
    std::array<const double*, n> params;
    for (std::size_t k = 0; k < n; ++k) params[k] = &values[k];
    std::array<bool, n> moves{};
    std::vector<std::vector<bool>> moves_column(n, std::vector<bool>(observe.size(), false));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Pending& p = rows[i];
      const std::size_t m = p.terms.size();
      std::vector<double> res(m), jac(n * m);
      std::array<double*, n> jacobians;
      for (std::size_t k = 0; k < n; ++k) jacobians[k] = jac.data() + k * m;
      const bool ok = costs[i]->Evaluate(params.data(), res.data(), jacobians.data());
      for (std::size_t t = 0; t < m; ++t) {
        bool finite = ok && std::isfinite(res[t]);
        for (std::size_t k = 0; k < n; ++k) finite = finite && std::isfinite(jacobians[k][t]);
        if (!finite)
          throw std::invalid_argument(fmt::format(
              "{}:{}: {} = {:g} at delta_star {:g}: the model's residual or its derivatives are not finite at the "
              "start (the constants' values): check this observation",
              p.data->name, p.data->line[p.row], to_string(p.terms[t].what), p.terms[t].observed,
              p.data->delta_star[p.row]));
        const std::size_t j =
            static_cast<std::size_t>(std::find(observe.begin(), observe.end(), p.terms[t].what) - observe.begin());
        for (std::size_t k = 0; k < n; ++k)
          if (jacobians[k][t] != 0.0) moves[k] = true, moves_column[k][j] = true;
      }
    }
    std::string columns;
    for (Observable o : observe) columns += (columns.empty() ? "" : ", ") + std::string(to_string(o));
    for (std::size_t k = 0; k < n; ++k)
      if (is_free[k] && !moves[k]) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const auto& p : rows) {
          lo = std::min(lo, p.data->delta_star[p.row]);
          hi = std::max(hi, p.data->delta_star[p.row]);
        }
        throw std::invalid_argument(fmt::format(
            "free constant '{}' of model '{}' changes none of the observed values ({} at delta_star {:g} to {:g}): "
            "it cannot be fitted from these data; leave it out of --free, or observe a column (or a delta_star range) "
            "that depends on it",
            Law::constants[k].name, Law::name, columns, lo, hi));
      }
  }

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = options.max_iterations;
  so.function_tolerance = 1e-16;
  so.gradient_tolerance = 1e-16;
  so.parameter_tolerance = 1e-14;
  so.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  result.ceres_report = summary.FullReport();
  result.iterations = static_cast<int>(summary.iterations.size());
  result.final_cost = summary.final_cost;
  if (summary.termination_type == ceres::NO_CONVERGENCE)
    throw std::runtime_error(
        fmt::format("the fit did not converge in {} iterations (Ceres: {})", options.max_iterations, summary.message));
  if (summary.termination_type != ceres::CONVERGENCE)
    throw std::runtime_error(fmt::format("Ceres failed after {} iterations, the data and start having been checked: {}",
                                         summary.iterations.size(), summary.message));

  // Standard errors: Ceres' covariance, scaled by the residual variance when no standard
  // deviations were given (relative residuals of unknown scale).
  std::vector<std::size_t> free_index;
  for (std::size_t k = 0; k < n; ++k)
    if (is_free[k]) free_index.push_back(k);
  const std::size_t m = free_index.size();
  std::vector<std::vector<double>> cov(m, std::vector<double>(m, std::numeric_limits<double>::quiet_NaN()));
  {
    ceres::Covariance::Options co;
    co.algorithm_type = ceres::DENSE_SVD;
    co.null_space_rank = -1;
    ceres::Covariance covariance(co);
    std::vector<std::pair<const double*, const double*>> pairs;
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i; j < m; ++j) pairs.emplace_back(&values[free_index[i]], &values[free_index[j]]);
    const double s2 = has_sd ? 1.0 : 2.0 * summary.final_cost / static_cast<double>(observations - free_count);
    if (covariance.Compute(pairs, &problem)) {
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i; j < m; ++j) {
          double c = 0.0;
          covariance.GetCovarianceBlock(&values[free_index[i]], &values[free_index[j]], &c);
          cov[i][j] = cov[j][i] = c * s2;
        }
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    FittedConstant f{std::string(Law::constants[k].name), values[k], 0.0, is_free[k]};
    for (std::size_t i = 0; i < m; ++i)
      if (free_index[i] == k) f.std_error = std::sqrt(cov[i][i]);
    result.constants.push_back(f);
  }
  result.correlation.assign(m, std::vector<double>(m, 0.0));
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j) result.correlation[i][j] = cov[i][j] / std::sqrt(cov[i][i] * cov[j][j]);

  // Residuals at the solution, relative, per row and per observed column.
  std::vector<double> sum(observe.size(), 0.0);
  std::vector<int> count(observe.size(), 0);
  for (const auto& p : rows) {
    std::vector<double> res(p.terms.size());
    RowResidualFunctor<Law> f{p.data->delta_star[p.row], &pair, p.terms};
    std::array<const double*, n> params;
    for (std::size_t k = 0; k < n; ++k) params[k] = &values[k];
    f(params.data(), res.data());
    for (std::size_t i = 0; i < p.terms.size(); ++i) {
      const Term& t = p.terms[i];
      const double model_value = t.observed + res[i] * t.scale / t.weight;
      // A zero observation (e.g. no yielded surface) has no relative residual: NaN, left out of the rms.
      const double rel = t.observed != 0.0 ? model_value / t.observed - 1.0 : std::nan("");
      result.residuals.push_back(
          {p.data->name, p.data->line[p.row], p.data->delta_star[p.row], t.what, t.observed, model_value, rel});
      const std::size_t j =
          static_cast<std::size_t>(std::find(observe.begin(), observe.end(), t.what) - observe.begin());
      if (std::isnan(rel)) continue;
      sum[j] += rel * rel;
      ++count[j];
    }
  }
  for (std::size_t j = 0; j < observe.size(); ++j)
    result.rms_relative.emplace_back(observe[j], count[j] ? std::sqrt(sum[j] / count[j]) : 0.0);
  for (const auto& d : data)
    for (Observable o : observe) {
      double s2 = 0.0;
      int c = 0;
      for (const auto& x : result.residuals)
        if (x.data == d.name && x.what == o && !std::isnan(x.relative)) s2 += x.relative * x.relative, ++c;
      if (c) result.rms_by_data.push_back({d.name, o, std::sqrt(s2 / c)});
    }
  return result;
}

}  // namespace

void FitOptions::validate() const {
  if (!observe_weight.empty() && observe_weight.size() != observe.size())
    throw core::KeyedError("observe_weight",
                           fmt::format("observe_weight: needs one weight per observed column, {} for {}",
                                       observe_weight.size(), observe.size()));
  for (std::size_t j = 0; j < observe_weight.size(); ++j) {
    const double w = observe_weight[j];
    if (!(std::isfinite(w) && w > 0.0 && w <= kMaxRowWeight))
      throw core::KeyedError(
          "observe_weight",
          fmt::format("observe_weight {} (for {}): a weight must be finite, positive and at most {:g}", w,
                      to_string(observe[j]), kMaxRowWeight));
  }
  if (!(std::isfinite(loss_scale) && loss_scale > 0.0))
    throw core::KeyedError("loss_scale", fmt::format("loss_scale {}: must be finite and positive", loss_scale));
  if (max_iterations < 1)
    throw core::KeyedError("max_iterations", fmt::format("max_iterations {}: must be at least 1", max_iterations));
  for (const auto& [name, lo, hi] : bounds)
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi))
      throw core::KeyedError("bounds",
                             fmt::format("bounds {}={}:{}: must be finite with lower <= upper", name, lo, hi));
}

FitResult fit_model(const asperity::AsperityModel& model, const asperity::ContactPair& pair,
                    const std::vector<FitData>& data, const FitOptions& options) {
  options.validate();
  if (data.empty()) throw std::invalid_argument("no reference data to fit");
  return asperity::visit_law(
      model.name(), [&](auto tag) { return fit_law<typename decltype(tag)::type>(model, pair, data, options); });
}

double model_observable(const asperity::AsperityModel& model, const asperity::ContactPair& pair, double delta_star,
                        Observable what) {
  const asperity::Star<double> s = model.law_star(delta_star, pair);  // the law the fit fits (no switch)
  switch (what) {
    case Observable::load_star:
      return s.load;
    case Observable::area_star:
      return s.area;
    case Observable::plastic_area_fraction:
      return s.plastic;
    default:
      return s.load / s.area * (2.0 / 3.0) * model.yield_peak_pressure(pair) / pair.yield_strength;
  }
}

}  // namespace geartrib::fit
