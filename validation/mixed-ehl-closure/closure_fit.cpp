// The statistical closure's effective-roughness factor k fitted to the mixed-EHL fidelity
// (validation/mixed-ehl-closure/README.md). For each flank set and observable (asperity share,
// friction coefficient) the closure's value at every position along the path was tabulated by
// check.py on a grid uniform in ln k, the flanks' heights scaled by k for the statistical side
// only; here Ceres' cubic Hermite interpolator carries that table through automatic
// differentiation and the solver finds the k whose closure values best match the mixed-EHL run's
// at the same positions (absolute residuals, equal weights). The standard error is Ceres'
// covariance scaled by the residual variance (as src/fit/model_fit.cpp does for relative
// residuals of unknown scale). "pooled" fits one k to every set of an observable.
//
// Usage: geartrib_closure_fit RESPONSE.csv TARGET.csv   (the fits as CSV on standard output)
//        geartrib_closure_fit --self-test               (exact cases; exit 1 when one fails)
// RESPONSE.csv: set,observable,position,k,value (each (set, observable, position) on one ln-uniform k grid)
// TARGET.csv:   set,observable,position,value
#include <ceres/ceres.h>
#include <ceres/cubic_interpolation.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The k grid: k_j = exp(t0 + j dt), j = 0 .. n - 1.
struct LogGrid {
  double t0 = 0.0, dt = 0.0;
  int n = 0;
  double k(int j) const { return std::exp(t0 + dt * j); }
};

// One position: the closure's values on the grid and the mixed-EHL value it should match.
struct Series {
  std::vector<double> values;
  double target = kNaN;
};

struct Fit {
  double k = kNaN, std_error = kNaN, rms = kNaN;
  int observations = 0, iterations = 0;
  std::string status;
};

using Interpolator = ceres::CubicInterpolator<ceres::Grid1D<double>>;

// r = closure(k) - target, the closure's value interpolated in u = (ln k - t0)/dt.
struct Residual {
  const Interpolator* closure;
  double t0, dt, target;
  template <typename T>
  bool operator()(const T* k, T* r) const {
    using std::log;
    const T u = (log(k[0]) - t0) / dt;
    T v;
    closure->Evaluate(u, &v);
    r[0] = v - target;
    return true;
  }
};

// The least-squares k of the series on grid g: the best grid node as the start, Ceres within the
// grid's ends, the covariance scaled by s^2 = sum r^2/(m - 1). Status: ok; at bound (the optimum
// at the grid's end: the closure cannot reach the targets within it, the error meaningless or, where
// the closure is flat there, undefined: NaN); not identifiable (the Jacobian zero at an exact fit or
// inside the grid: a stretch of k fits equally; the error undefined, NaN); undetermined (a standard
// error above k).
Fit fit_k(const LogGrid& g, const std::vector<const Series*>& series) {
  Fit fit;
  fit.observations = static_cast<int>(series.size());
  if (series.size() < 2) throw std::invalid_argument("a fit needs at least two positions");
  std::vector<std::unique_ptr<ceres::Grid1D<double>>> grids;
  std::vector<std::unique_ptr<Interpolator>> closures;
  for (const Series* s : series) {
    if (static_cast<int>(s->values.size()) != g.n) throw std::invalid_argument("a series is not on the k grid");
    grids.push_back(std::make_unique<ceres::Grid1D<double>>(s->values.data(), 0, g.n));
    closures.push_back(std::make_unique<Interpolator>(*grids.back()));
  }
  auto cost_at_node = [&](int j) {
    double c = 0.0;
    for (const Series* s : series) c += (s->values[j] - s->target) * (s->values[j] - s->target);
    return c;
  };
  int best = 0;
  for (int j = 1; j < g.n; ++j)
    if (cost_at_node(j) < cost_at_node(best)) best = j;
  double k = g.k(best);
  const double lower = g.k(0), upper = g.k(g.n - 1);

  ceres::Problem problem;
  for (std::size_t i = 0; i < series.size(); ++i)
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Residual, 1, 1>(new Residual{closures[i].get(), g.t0, g.dt, series[i]->target}),
        nullptr, &k);
  problem.SetParameterLowerBound(&k, 0, lower);
  problem.SetParameterUpperBound(&k, 0, upper);

  // Identifiable only if some residual moves with k at the start or across the grid.
  bool moves = false;
  for (const Series* s : series)
    moves = moves || std::any_of(s->values.begin(), s->values.end(), [&](double v) { return v != s->values[0]; });
  if (!moves) {
    fit.k = k;
    fit.status = "not identifiable";
    fit.rms = std::sqrt(cost_at_node(best) / static_cast<double>(series.size()));
    return fit;
  }

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.function_tolerance = 1e-15;
  so.gradient_tolerance = 1e-15;
  so.parameter_tolerance = 1e-12;
  so.max_num_iterations = 200;
  so.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  if (summary.termination_type != ceres::CONVERGENCE)
    throw std::runtime_error("Ceres did not converge: " + summary.message);
  fit.k = k;
  fit.iterations = static_cast<int>(summary.iterations.size());
  const double m = static_cast<double>(series.size());
  fit.rms = std::sqrt(2.0 * summary.final_cost / m);

  // The Jacobian at the solution: zero (a flat stretch of every series) leaves k undetermined.
  ceres::CRSMatrix jacobian;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &jacobian);
  double jtj = 0.0;
  for (double v : jacobian.values) jtj += v * v;
  const bool at_bound = k <= lower * (1.0 + 1e-9) || k >= upper * (1.0 - 1e-9);
  if (!(jtj > 0.0)) {  // flat: an exact fit over a stretch of k, or the closure's floor above the targets
    fit.status = at_bound && fit.rms > 0.0 ? "at bound" : "not identifiable";
    return fit;
  }
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance covariance(co);
  const std::vector<std::pair<const double*, const double*>> pairs{{&k, &k}};
  double c = kNaN;
  if (covariance.Compute(pairs, &problem)) covariance.GetCovarianceBlock(&k, &k, &c);
  const double s2 = 2.0 * summary.final_cost / (m - 1.0);
  fit.std_error = std::sqrt(c * s2);
  // A standard error above k itself: a shallow optimum the data do not pin down.
  fit.status = at_bound ? "at bound" : fit.std_error < k ? "ok" : "undetermined (standard error above k)";
  return fit;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  std::string x;
  while (std::getline(ss, x, ',')) f.push_back(x);
  return f;
}

// Rows of a CSV with a header line, as maps from column to text; the columns must be present.
std::vector<std::map<std::string, std::string>> read_csv(const std::string& path,
                                                         const std::vector<std::string>& columns) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read " + path);
  std::string line;
  if (!std::getline(in, line)) throw std::invalid_argument(path + ": empty");
  const auto header = split(line);
  for (const auto& c : columns)
    if (std::find(header.begin(), header.end(), c) == header.end())
      throw std::invalid_argument(path + ": no column '" + c + "'");
  std::vector<std::map<std::string, std::string>> rows;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const auto f = split(line);
    if (f.size() != header.size()) throw std::invalid_argument(fmt::format("{}:{}: {} fields", path, number, f.size()));
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < f.size(); ++i) row[header[i]] = f[i];
    rows.push_back(std::move(row));
  }
  return rows;
}

double number(const std::string& text) {
  std::size_t used = 0;
  const double v = std::stod(text, &used);
  if (used != text.size()) throw std::invalid_argument("not a number: '" + text + "'");
  return v;
}

using Key = std::tuple<std::string, std::string, int>;  // set, observable, position

int run(const std::string& response_path, const std::string& target_path) {
  std::map<Key, std::vector<std::pair<double, double>>> table;  // (k, value)
  for (const auto& r : read_csv(response_path, {"set", "observable", "position", "k", "value"}))
    table[{r.at("set"), r.at("observable"), std::stoi(r.at("position"))}].emplace_back(number(r.at("k")),
                                                                                       number(r.at("value")));
  std::map<Key, Series> series;
  std::map<std::string, LogGrid> grid;  // per observable: every set on the same grid
  for (auto& [key, points] : table) {
    std::sort(points.begin(), points.end());
    LogGrid g{std::log(points.front().first), 0.0, static_cast<int>(points.size())};
    if (g.n < 4) throw std::invalid_argument("a series needs at least 4 grid points");
    g.dt = (std::log(points.back().first) - g.t0) / (g.n - 1);
    for (int j = 0; j < g.n; ++j)
      if (std::abs(std::log(points[j].first) - (g.t0 + j * g.dt)) > 1e-9)
        throw std::invalid_argument(fmt::format("{} {} position {}: the k grid is not uniform in ln k",
                                                std::get<0>(key), std::get<1>(key), std::get<2>(key)));
    const auto [it, fresh] = grid.emplace(std::get<1>(key), g);
    if (!fresh &&
        (it->second.n != g.n || std::abs(it->second.t0 - g.t0) > 1e-9 || std::abs(it->second.dt - g.dt) > 1e-9))
      throw std::invalid_argument("observable " + std::get<1>(key) + ": the sets' k grids differ");
    Series& s = series[key];
    for (const auto& p : points) s.values.push_back(p.second);
  }
  for (const auto& r : read_csv(target_path, {"set", "observable", "position", "value"})) {
    const Key key{r.at("set"), r.at("observable"), std::stoi(r.at("position"))};
    const auto it = series.find(key);
    if (it == series.end())
      throw std::invalid_argument(fmt::format("target {} {} position {} has no closure series", std::get<0>(key),
                                              std::get<1>(key), std::get<2>(key)));
    it->second.target = number(r.at("value"));
  }
  std::map<std::pair<std::string, std::string>, std::vector<const Series*>> groups;  // (set, observable)
  for (const auto& [key, s] : series) {
    if (std::isnan(s.target))
      throw std::invalid_argument(
          fmt::format("{} {} position {}: no target", std::get<0>(key), std::get<1>(key), std::get<2>(key)));
    groups[{std::get<0>(key), std::get<1>(key)}].push_back(&s);
    groups[{"pooled", std::get<1>(key)}].push_back(&s);
  }
  fmt::print("set,observable,k,std_error,rms_residual,observations,iterations,status\n");
  for (const auto& [name, members] : groups) {
    const Fit f = fit_k(grid.at(name.second), members);
    fmt::print("{},{},{:.10g},{:.10g},{:.10g},{},{},{}\n", name.first, name.second, f.k, f.std_error, f.rms,
               f.observations, f.iterations, f.status);
  }
  return 0;
}

// Exact cases: closure values linear in ln k (which the cubic Hermite spline reproduces away from
// the grid's ends) make the fit a linear least-squares problem with a closed-form answer.
int self_test() {
  int failed = 0;
  auto expect = [&](bool ok, const std::string& what) {
    fmt::print("{} {}\n", ok ? "ok  " : "FAIL", what);
    failed += !ok;
  };
  const LogGrid g{std::log(0.1), std::log(30.0) / 40.0, 41};  // k 0.1 .. 3
  const double truth = 0.7, t = std::log(truth);
  const std::vector<double> a{0.05, 0.2, 0.1, -0.3, 0.0}, c{1.0, 2.0, -1.0, 0.5, 3.0},
      e{0.01, -0.02, 0.015, -0.005, 0.0};
  std::vector<Series> store(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (int j = 0; j < g.n; ++j) store[i].values.push_back(a[i] + c[i] * (g.t0 + g.dt * j));
    store[i].target = a[i] + c[i] * t + e[i];
  }
  std::vector<const Series*> all;
  for (const auto& s : store) all.push_back(&s);
  // Least squares in ln k: ln k = t + sum c e/sum c^2; se(k) = k s/sqrt(sum c^2), s^2 = sum r^2/(m - 1).
  double cc = 0.0, ce = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) cc += c[i] * c[i], ce += c[i] * e[i];
  const double t_hat = t + ce / cc, k_hat = std::exp(t_hat);
  double rr = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) rr += std::pow(e[i] - c[i] * (t_hat - t), 2);
  const double se = k_hat * std::sqrt(rr / (c.size() - 1.0) / cc);
  const Fit f = fit_k(g, all);
  // 1e-8: Ceres' parameter tolerance 1e-12 and the covariance's SVD, far below the test's scale.
  expect(std::abs(f.k / k_hat - 1.0) < 1e-8 && f.status == "ok",
         fmt::format("linear in ln k with noise: k {:.12g} (exact {:.12g}), status {}", f.k, k_hat, f.status));
  expect(std::abs(f.std_error / se - 1.0) < 1e-6,
         fmt::format("its standard error {:.12g} (exact {:.12g})", f.std_error, se));
  expect(std::abs(f.rms - std::sqrt(rr / c.size())) < 1e-10, fmt::format("its rms residual {:.12g}", f.rms));

  // Without noise the fit returns the truth and no scatter.
  for (std::size_t i = 0; i < a.size(); ++i) store[i].target = a[i] + c[i] * t;
  const Fit exact = fit_k(g, all);
  expect(std::abs(exact.k / truth - 1.0) < 1e-8 && exact.std_error < 1e-8,
         fmt::format("noise-free: k {:.12g} (exact {}), standard error {:.3g}", exact.k, truth, exact.std_error));

  // Targets the closure cannot reach within the grid: the fit stops at the grid's end.
  for (std::size_t i = 0; i < a.size(); ++i) store[i].target = a[i] + c[i] * (t + 100.0);
  const Fit bound = fit_k(g, all);
  expect(bound.status == "at bound" && std::abs(bound.k / g.k(g.n - 1) - 1.0) < 1e-9,
         fmt::format("unreachable targets: k {:.6g} at the grid's end {:.6g}, status {}", bound.k, g.k(g.n - 1),
                     bound.status));

  // A closure that does not move with k: no information on k.
  for (auto& s : store) std::fill(s.values.begin(), s.values.end(), 0.0), s.target = 0.01;
  const Fit flat = fit_k(g, all);
  expect(flat.status == "not identifiable" && std::isnan(flat.std_error),
         fmt::format("a flat closure: status {}", flat.status));
  fmt::print("{} of 6 self-test checks failed\n", failed);
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 2 && std::string(argv[1]) == "--self-test") return self_test();
    if (argc != 3) {
      std::cerr << "usage: geartrib_closure_fit RESPONSE.csv TARGET.csv | --self-test\n";
      return 2;
    }
    return run(argv[1], argv[2]);
  } catch (const std::exception& e) {
    std::cerr << "geartrib_closure_fit: " << e.what() << "\n";
    return 2;
  }
}
