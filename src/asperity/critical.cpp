#include "asperity/critical.hpp"

#include "asperity/axis_stress.hpp"
#include "core/maximize.hpp"

namespace geartrib::asperity {

Critical hertz_critical(const ContactPair& pair, double yield_peak_pressure) {
  Critical c;
  const double s = std::numbers::pi * yield_peak_pressure / (2.0 * pair.modulus);
  c.interference = s * s * pair.radius;
  c.load = hertz_load(c.interference, pair.radius, pair.modulus);
  c.area = std::numbers::pi * pair.radius * c.interference;
  c.peak_pressure = yield_peak_pressure;
  return c;
}

HertzYieldPoint hertz_yield_point(double nu) {
  const auto m =
      maximize_on_interval([nu](double z) { return von_mises_on_axis(hertz_axis_stress(z, nu)); }, 1e-4, 3.0, 64);
  return {m.x, m.value};
}

}  // namespace geartrib::asperity
