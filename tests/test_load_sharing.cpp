// Load sharing between simultaneous tooth pairs, both methods, over the mesh cycle.
#include "gear/gear_mesh.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

using namespace geartrib;
using namespace geartrib::gear;

namespace {
// The seed pair's mesh with the load shared by `method`.
GearMesh seed_mesh(LoadSharing method) {
  Case c = test::seed_case();
  c.mesh.load_sharing = method;
  return case_mesh(c);
}
}  // namespace

TEST(LoadSharing, IsoFactorShape) {
  const SpurPair p(test::seed_case().gear_pair);
  const PathOfContact& path = p.path();
  EXPECT_DOUBLE_EQ(iso_load_sharing_factor(path, path.a), 1.0 / 3.0);
  EXPECT_NEAR(iso_load_sharing_factor(path, path.b), 2.0 / 3.0, 1e-12);  // double-contact side
  EXPECT_DOUBLE_EQ(iso_load_sharing_factor(path, path.b, true), 1.0);    // single-tooth side
  EXPECT_DOUBLE_EQ(iso_load_sharing_factor(path, path.c), 1.0);
  EXPECT_NEAR(iso_load_sharing_factor(path, path.d), 2.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(iso_load_sharing_factor(path, path.d, true), 1.0);
  EXPECT_NEAR(iso_load_sharing_factor(path, path.e), 1.0 / 3.0, 1e-12);
}

TEST(LoadSharing, SharesSumToOneOverTheCycleForBothMethods) {
  for (auto method : {LoadSharing::iso, LoadSharing::stiffness}) {
    const GearMesh mesh = seed_mesh(method);
    const auto cycle = mesh.analysis().cycle(257);
    int single = 0, dual = 0;
    for (const auto& m : cycle) {
      double sum = 0.0;
      for (const auto& p : m.pairs) sum += p.share;
      EXPECT_NEAR(sum, 1.0, 1e-12) << to_string(method);
      (m.pairs.size() == 1 ? single : dual)++;
      EXPECT_LE(m.pairs.size(), 2u);
    }
    // eps_alpha = 1.6535: double contact for 65% of the cycle (+- one sample).
    EXPECT_NEAR(dual / 257.0, 0.6535, 1.0 / 257.0 + 1e-3) << to_string(method);
  }
}

TEST(LoadSharing, IsoSharesOfThePairsAreComplementary) {
  // With pairs at s (in AB) and s + p_b (in DE): 1/3 + x/3 and 2/3 - x/3 sum to 1 exactly.
  const GearMesh mesh = seed_mesh(LoadSharing::iso);
  const PathOfContact& p = mesh.pair().path();
  for (double t : {0.0, 0.25, 0.5, 0.99}) {
    const double s = p.a + t * (p.b - p.a);
    EXPECT_NEAR(iso_load_sharing_factor(p, s) + iso_load_sharing_factor(p, s + p.base_pitch), 1.0, 1e-12);
  }
}

TEST(LoadSharing, OneToOnePairIsSymmetric) {
  // Identical gears: the stiffness at s equals that at the mirror point T1T2 - s, so shares and
  // mesh stiffness mirror about the pitch point.
  const GearMesh mesh = seed_mesh(LoadSharing::stiffness);
  const PathOfContact& p = mesh.pair().path();
  for (double t : {0.0, 0.1, 0.3, 0.45}) {
    const double s = p.a + t * p.length, mirror = p.line_length - s;
    EXPECT_NEAR(mesh.stiffness().pair(s).stiffness / mesh.stiffness().pair(mirror).stiffness, 1.0, 1e-12) << t;
    const MeshInstant m1 = mesh.analysis().at(s), m2 = mesh.analysis().at(mirror);
    EXPECT_NEAR(m1.mesh_stiffness / m2.mesh_stiffness, 1.0, 1e-12) << t;
  }
}
