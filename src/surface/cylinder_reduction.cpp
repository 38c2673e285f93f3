#include "surface/cylinder_reduction.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace geartrib::surface {

CylinderReduction reduce_to_cylinders(const HeightGrid& g, double lay_angle, double min_prominence, double cap) {
  g.validate();
  CylinderReduction r;
  r.lay_along_y = std::abs(std::sin(lay_angle)) > std::abs(std::cos(lay_angle));
  const int n = r.lay_along_y ? g.nx : g.ny, m = r.lay_along_y ? g.ny : g.nx;
  r.spacing_step = r.lay_along_y ? g.dx : g.dy;
  r.profile.assign(static_cast<std::size_t>(n), 0.0);
  for (int k = 0; k < n; ++k) {
    double s = 0.0;
    int c = 0;
    for (int q = 0; q < m; ++q) {
      const int i = r.lay_along_y ? k : q, j = r.lay_along_y ? q : k;
      if (g.ok(i, j)) s += g.at(i, j), ++c;
    }
    if (c == 0) throw std::invalid_argument("a profile position has no valid point along the lay");
    r.profile[static_cast<std::size_t>(k)] = s / c;
  }
  double mean = 0.0, var = 0.0;
  for (double z : r.profile) mean += z;
  mean /= n;
  for (double& z : r.profile) z -= mean, var += z * z;
  const double rq = std::sqrt(var / n);
  const auto& z = r.profile;
  // Peaks: local maxima whose prominence (height over the higher of the two valleys that
  // separate them from higher ground, or the profile ends) exceeds min_prominence Rq. The nearest
  // strictly higher point on each side and the lowest point before it, for every k at once by a
  // monotone stack (O(n); walking out from each peak is O(n^2) on a rising sawtooth).
  std::vector<int> higher_left(static_cast<std::size_t>(n)), higher_right(static_cast<std::size_t>(n));
  std::vector<double> base_left(static_cast<std::size_t>(n)), base_right(static_cast<std::size_t>(n));
  auto scan = [&](int from, int to, int step, std::vector<int>& higher, std::vector<double>& base) {
    std::vector<std::pair<int, double>> stack;  // index, lowest z since the entry below it
    for (int k = from; k != to; k += step) {
      double low = z[k];
      while (!stack.empty() && z[stack.back().first] <= z[k])
        low = std::min(low, stack.back().second), stack.pop_back();
      higher[static_cast<std::size_t>(k)] = stack.empty() ? from - step : stack.back().first;
      base[static_cast<std::size_t>(k)] = low;
      stack.emplace_back(k, low);
    }
  };
  scan(0, n, 1, higher_left, base_left);
  scan(n - 1, -1, -1, higher_right, base_right);
  for (int k = 1; k + 1 < n; ++k) {
    if (!(z[k] > z[k - 1] && z[k] >= z[k + 1])) continue;
    const double left = base_left[static_cast<std::size_t>(k)], right = base_right[static_cast<std::size_t>(k)];
    const double prominence = z[k] - std::max(left, right);
    if (prominence < min_prominence * rq) continue;
    // Parabola through the points within the top `cap` of the prominence, contiguous around k and
    // short of the higher ground on either side.
    const double floor = z[k] - cap * prominence;
    int lo = k, hi = k;
    while (lo - 1 > higher_left[static_cast<std::size_t>(k)] && z[lo - 1] >= floor) --lo;
    while (hi + 1 < higher_right[static_cast<std::size_t>(k)] && z[hi + 1] >= floor) ++hi;
    if (hi - lo + 1 < 5) continue;  // too few points for a parabola
    Eigen::MatrixXd A(hi - lo + 1, 3);
    Eigen::VectorXd y(hi - lo + 1);
    for (int q = lo; q <= hi; ++q) {
      const double x = (q - k) * r.spacing_step;
      A(q - lo, 0) = 1.0, A(q - lo, 1) = x, A(q - lo, 2) = x * x;
      y(q - lo) = z[q];
    }
    const Eigen::Vector3d c = A.colPivHouseholderQr().solve(y);
    if (!(c(2) < 0.0)) continue;
    CylinderAsperityFit f;
    f.tip_radius = -1.0 / (2.0 * c(2));
    const double xc = -c(1) / (2.0 * c(2));
    f.centre = k * r.spacing_step + xc;
    f.height = c(0) - c(1) * c(1) / (4.0 * c(2));
    r.asperities.push_back(f);
  }
  for (std::size_t i = 0; i + 1 < r.asperities.size(); ++i)
    r.asperities[i].spacing = r.asperities[i + 1].centre - r.asperities[i].centre;
  auto stats = [&](auto get, std::size_t count, double& mu, double& sd) {
    mu = sd = 0.0;
    if (count == 0) return;
    for (std::size_t i = 0; i < count; ++i) mu += get(r.asperities[i]);
    mu /= count;
    for (std::size_t i = 0; i < count; ++i) sd += std::pow(get(r.asperities[i]) - mu, 2);
    sd = count > 1 ? std::sqrt(sd / (count - 1)) : 0.0;
  };
  stats([](const CylinderAsperityFit& f) { return f.tip_radius; }, r.asperities.size(), r.mean_tip_radius,
        r.sd_tip_radius);
  stats([](const CylinderAsperityFit& f) { return f.height; }, r.asperities.size(), r.mean_height, r.sd_height);
  stats([](const CylinderAsperityFit& f) { return f.spacing; }, r.asperities.empty() ? 0 : r.asperities.size() - 1,
        r.mean_spacing, r.sd_spacing);
  return r;
}

}  // namespace geartrib::surface
