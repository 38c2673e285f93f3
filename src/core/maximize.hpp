// One-dimensional maximisation on a bounded interval: a coarse scan followed by Brent's method
// (Boost.Math) around the best sample, so a function with one interior peak (the usual case for
// subsurface stresses) is found to full precision and a peak at an end of the interval is kept.
#pragma once

#include <functional>

namespace geartrib {

struct Maximum {
  double x = 0.0;      // abscissa of the maximum
  double value = 0.0;  // function value there
};

// Maximises f on [lo, hi] (lo < hi). Samples `samples` points geometrically spaced when
// lo > 0 (linearly otherwise), then refines with Brent to about 1e-10 relative in x.
Maximum maximize_on_interval(const std::function<double(double)>& f, double lo, double hi, int samples = 48);

}  // namespace geartrib
