// A smooth function on [a, b] interpolated at the n Chebyshev-Lobatto points x_j = (a + b)/2 +
// (b - a)/2 cos(pi j/(n - 1)) and evaluated by the barycentric formula of the second kind, weights
// (-1)^j halved at the ends (Berrut & Trefethen 2004, SIAM Review 46(3)): for a function analytic
// on [a, b] the error falls geometrically with n, and the evaluation is stable.
#pragma once

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace geartrib::core {

class ChebyshevInterpolant {
 public:
  template <class F>
  ChebyshevInterpolant(F&& f, double a, double b, int n) : a_(a), b_(b) {
    if (n < 2 || !(b > a)) throw std::invalid_argument("Chebyshev interpolant: n >= 2 points on a < b");
    for (int j = 0; j < n; ++j) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * std::cos(std::numbers::pi * j / (n - 1));
      nodes_.push_back(x);
      values_.push_back(f(x));
      weights_.push_back((j % 2 == 0 ? 1.0 : -1.0) * (j == 0 || j == n - 1 ? 0.5 : 1.0));
    }
  }
  double operator()(double x) const {
    double num = 0.0, den = 0.0;
    for (std::size_t j = 0; j < nodes_.size(); ++j) {
      const double d = x - nodes_[j];
      if (d == 0.0) return values_[j];
      const double w = weights_[j] / d;
      num += w * values_[j];
      den += w;
    }
    return num / den;
  }
  double lower() const { return a_; }
  double upper() const { return b_; }

 private:
  double a_, b_;
  std::vector<double> nodes_, values_, weights_;
};

}  // namespace geartrib::core
