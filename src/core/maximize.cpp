#include "core/maximize.hpp"

#include <boost/math/tools/minima.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace geartrib {

Maximum maximize_on_interval(const std::function<double(double)>& f, double lo, double hi, int samples) {
  if (!(lo < hi) || samples < 3) throw std::invalid_argument("maximize_on_interval: need lo < hi and >= 3 samples");
  std::vector<double> xs(static_cast<std::size_t>(samples));
  const bool geometric = lo > 0.0;
  for (int i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / (samples - 1);
    xs[static_cast<std::size_t>(i)] = geometric ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t;
  }
  std::size_t best = 0;
  double best_value = f(xs[0]);
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const double v = f(xs[i]);
    if (v > best_value) {
      best_value = v;
      best = i;
    }
  }
  const double a = xs[best == 0 ? 0 : best - 1];
  const double b = xs[best + 1 == xs.size() ? best : best + 1];
  if (a == b) return {xs[best], best_value};
  // Brent minimises; 40 bits of precision gives ~1e-12 relative in x (Boost.Math brent_find_minima).
  const auto r = boost::math::tools::brent_find_minima([&](double x) { return -f(x); }, a, b, 40);
  if (-r.second >= best_value) return {r.first, -r.second};
  return {xs[best], best_value};
}

}  // namespace geartrib
