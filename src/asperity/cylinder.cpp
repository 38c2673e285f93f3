#include "asperity/cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace geartrib::asperity {

void CylinderAsperity::validate() const {
  auto fail = [](const std::string& rule) { throw std::invalid_argument("cylinder asperity: " + rule); };
  if (!(tip_radius > 0.0)) fail("tip radius must be positive");
  if (!(modulus > 0.0)) fail("modulus must be positive");
  if (!(yield_strength > 0.0)) fail("yield strength must be positive");
  if (!(hardness >= yield_strength)) fail("hardness must be at least the yield strength");
  if (!(poisson_ratio > 0.0 && poisson_ratio < 0.5)) fail("Poisson's ratio must lie in (0, 0.5)");
  if (!(yield_constant > 0.0)) fail("yield constant C must be positive");
  if (!(2.0 * modulus / yield_strength > std::exp(1.0))) fail("ln(2 E_t/sigma_s) must exceed 1");
}

double seed_critical_interference(const CylinderAsperity& c) {
  c.validate();
  return 2.0 * c.tip_radius * c.yield_strength / c.modulus * (std::log(2.0 * c.modulus / c.yield_strength) - 1.0) *
         c.yield_constant;
}

double hertz_half_width(double load_per_length, double radius, double modulus) {
  return std::sqrt(4.0 * load_per_length * radius / (std::numbers::pi * modulus));
}

LineCritical line_critical(const CylinderAsperity& c) {
  c.validate();
  LineCritical lc;
  lc.peak_pressure = c.yield_constant * c.yield_strength;
  lc.half_width = 2.0 * c.tip_radius * lc.peak_pressure / c.modulus;
  lc.load_per_length = std::numbers::pi * lc.half_width * lc.half_width * c.modulus / (4.0 * c.tip_radius);
  return lc;
}

LineContactState line_contact(const CylinderAsperity& c, double load_per_length) {
  if (!(load_per_length >= 0.0) || !std::isfinite(load_per_length))
    throw std::invalid_argument("line load must be finite and non-negative");
  const LineCritical lc = line_critical(c);
  LineContactState s;
  s.load_per_length = load_per_length;
  if (load_per_length <= lc.load_per_length) {
    s.half_width = hertz_half_width(load_per_length, c.tip_radius, c.modulus);
    s.mean_pressure = 0.25 * std::numbers::pi * c.modulus * s.half_width / (2.0 * c.tip_radius);
  } else {
    const double pmc = 0.25 * std::numbers::pi * lc.peak_pressure;
    const double h = std::max(c.hardness, pmc * (1.0 + 1e-12));
    const double beta = pmc / (2.0 * (h - pmc));
    s.mean_pressure = h - (h - pmc) * std::pow(load_per_length / lc.load_per_length, -beta);
    s.half_width = load_per_length / (2.0 * s.mean_pressure);
    s.plastic = true;
  }
  s.area_per_length = 2.0 * s.half_width;
  return s;
}

}  // namespace geartrib::asperity
