// The antiderivative of ln|t|, t ln|t| - t (0 at t = 0, its limit): the element integrals of the
// line load's logarithmic kernels (the half-plane boundary elements, the rough strip, the mixed-EHL
// line contact, the areal window periodic along one direction).
#pragma once

#include <cmath>

namespace geartrib::core {

inline double log_antiderivative(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }

}  // namespace geartrib::core
