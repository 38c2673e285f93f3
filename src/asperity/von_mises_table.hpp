// The highest on-axis von Mises stress of the two-zone pressure profile, normalised. The profile
// (two_zone_profile) scales with the mean pressure p_m and the contact radius a, so
// sigma_vm,max/p_m and its depth z/a depend only on the plastic share phi and Poisson's ratio:
// one table serves every asperity model, interference and material of that nu.
// Nodes on a uniform grid in c = sqrt(phi) (the core radius over a: the stresses are smooth in
// c, not in phi, near phi = 0), each computed by the exact maximisation
// (PressureProfile::von_mises_maximum) the first time an interval needs it; cubic Lagrange
// through the four nearest nodes (fewer when the table has fewer). Error against the exact
// maximisation, falling as h^4: 1.3e-7 of p_m at 64 intervals, 2e-5 at 16
// (tests/test_axis_stress.cpp).
#pragma once

#include "asperity/pressure_profile.hpp"

#include <vector>

namespace geartrib::asperity {

class VonMisesTable {
 public:
  static constexpr int kMinIntervals = 1, kMaxIntervals = 100000;
  // nu in [0, 0.5); intervals in [kMinIntervals, kMaxIntervals] over c = sqrt(phi) in [0, 1].
  VonMisesTable(double nu, int intervals);
  // The largest von Mises stress [Pa] and its depth [m] of two_zone_profile(a, p_m, phi).
  VonMisesMaximum at(double contact_radius, double mean_pressure, double plastic_share);
  double poisson_ratio() const { return nu_; }
  int nodes_computed() const { return computed_; }

 private:
  struct Node {
    double value = 0.0;  // sigma_vm,max / p_m
    double depth = 0.0;  // z / a
    bool ready = false;
  };
  const Node& node(int i);
  double nu_;
  int intervals_;
  int computed_ = 0;
  std::vector<Node> nodes_;
};

}  // namespace geartrib::asperity
