// The involute function and its inverse (ISO 21771; Litvin, Gear Geometry).
#pragma once

namespace geartrib::gear {

// inv(alpha) = tan(alpha) - alpha [rad]
double involute(double alpha);
// alpha in [0, pi/2) with inv(alpha) = value >= 0 (Newton on a bracketing start, ~1e-15 rad).
double inverse_involute(double value);

}  // namespace geartrib::gear
