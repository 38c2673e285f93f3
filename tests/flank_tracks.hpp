// Flank profiles for the tests of the fidelities that roll the flanks' profiles through the
// contact (the deterministic and the mixed-EHL ones): a track of heights, a flat one, and a tent
// bump with its closed-form integral, from which the tests take the exact element and node means.
#pragma once

#include "contact/deterministic_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace geartrib::test {

// A flank of heights z, `spacing` apart, starting at the arc sigma = start.
inline contact::FlankTrack track(double start, double spacing, std::vector<double> z) {
  return {{spacing, std::move(z)}, start};
}
inline contact::FlankTrack flat(double start, double spacing, std::size_t points) {
  return track(start, spacing, std::vector<double>(points, 0.0));
}

// tent(u) = height max(0, 1 - |u - centre|/half_width) in a flank's own coordinate u = sigma - start.
struct Tent {
  double height = 0.0, half_width = 0.0;
  double at(double u, double centre) const { return height * std::max(0.0, 1.0 - std::abs(u - centre) / half_width); }
  // int_{-inf}^{u} tent(v) dv, in closed form.
  double integral(double u, double centre) const {
    const double v = std::clamp((u - centre) / half_width, -1.0, 1.0);
    return height * half_width * (v <= 0.0 ? 0.5 * (1.0 + v) * (1.0 + v) : 1.0 - 0.5 * (1.0 - v) * (1.0 - v));
  }
  // The tent's mean over [u - e/2, u + e/2].
  double mean(double u, double e, double centre) const {
    return (integral(u + 0.5 * e, centre) - integral(u - 0.5 * e, centre)) / e;
  }
  // A flank of `points` heights `spacing` apart from `start` carrying the tent at u = centre.
  contact::FlankTrack track(double start, double spacing, std::size_t points, double centre) const {
    std::vector<double> z(points);
    for (std::size_t k = 0; k < points; ++k) z[k] = at(static_cast<double>(k) * spacing, centre);
    return test::track(start, spacing, std::move(z));
  }
};

}  // namespace geartrib::test
