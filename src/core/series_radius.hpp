// The series (equivalent) radius of two curved bodies in contact: 1/R = 1/R1 + 1/R2 (Johnson,
// Contact Mechanics, 1985, eq. 4.2). Summits, flanks and cylinders all use this one.
#pragma once

namespace geartrib {

constexpr double series_radius(double r1, double r2) { return r1 * r2 / (r1 + r2); }

}  // namespace geartrib
