#include "gear/involute.hpp"

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::gear {

double involute(double alpha) {
  // Below 0.1 rad tan(a) - a loses digits to cancellation (3 eps/a^2 relative); the Taylor
  // series of tan(a) - a through a^15 is accurate there to ~1e-16 relative.
  if (std::abs(alpha) < 0.1) {
    const double a2 = alpha * alpha;
    return alpha * a2 *
           (1.0 / 3.0 +
            a2 * (2.0 / 15.0 + a2 * (17.0 / 315.0 + a2 * (62.0 / 2835.0 + a2 * (1382.0 / 155925.0 +
                                                                                a2 * (21844.0 / 6081075.0 +
                                                                                      a2 * 929569.0 / 638512875.0))))));
  }
  return std::tan(alpha) - alpha;
}

double inverse_involute(double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) throw std::invalid_argument("inverse_involute: value must be >= 0");
  if (value == 0.0) return 0.0;
  // inv is increasing on [0, pi/2); start from the small-angle inverse alpha ~ (3 v)^(1/3).
  const double guess = std::min(std::cbrt(3.0 * value), 1.5);
  auto f = [value](double a) {
    const double t = std::tan(a);
    return std::make_pair(involute(a) - value, t * t);  // d inv/d alpha = tan^2
  };
  return boost::math::tools::newton_raphson_iterate(f, guess, 0.0, 0.5 * std::numbers::pi - 1e-9, 52);
}

}  // namespace geartrib::gear
