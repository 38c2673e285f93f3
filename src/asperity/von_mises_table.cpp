#include "asperity/von_mises_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geartrib::asperity {

VonMisesTable::VonMisesTable(double nu, int intervals) : nu_(nu), intervals_(intervals) {
  if (!(nu >= 0.0 && nu < 0.5)) throw std::invalid_argument(fmt::format("Poisson's ratio {} outside [0, 0.5)", nu));
  if (intervals < kMinIntervals || intervals > kMaxIntervals)
    throw std::invalid_argument(
        fmt::format("von Mises table intervals must lie in [{}, {}]", kMinIntervals, kMaxIntervals));
  nodes_.resize(static_cast<std::size_t>(intervals) + 1);
}

const VonMisesTable::Node& VonMisesTable::node(int i) {
  Node& n = nodes_[static_cast<std::size_t>(i)];
  if (!n.ready) {
    const double c = static_cast<double>(i) / intervals_;
    const VonMisesMaximum m = two_zone_profile(1.0, 1.0, c * c).von_mises_maximum(nu_);
    n = {m.value, m.depth, true};
    ++computed_;
  }
  return n;
}

VonMisesMaximum VonMisesTable::at(double contact_radius, double mean_pressure, double plastic_share) {
  if (!(contact_radius > 0.0)) return {};
  const double x = std::sqrt(std::clamp(plastic_share, 0.0, 1.0)) * intervals_;
  // Lagrange through the k = min(4, intervals + 1) nodes i0 .. i0 + k - 1 around x, shifted
  // inward at the ends.
  const int k = std::min(4, intervals_ + 1);
  const int i0 = std::clamp(static_cast<int>(x) - (k - 1) / 2, 0, intervals_ + 1 - k);
  double value = 0.0, depth = 0.0;
  for (int j = 0; j < k; ++j) {
    double w = 1.0;
    for (int m = 0; m < k; ++m)
      if (m != j) w *= (x - (i0 + m)) / static_cast<double>(j - m);
    const Node& n = node(i0 + j);
    value += w * n.value;
    depth += w * n.depth;
  }
  return {mean_pressure * value, contact_radius * depth};
}

}  // namespace geartrib::asperity
