// The seed's multi-asperity trends (section 7) from the boundary-element solver, at the scale
// the seed's deformation table implies (delta_pc = 0.5797 nm; validation/seed-section7).
#include "contact/multi_asperity.hpp"

#include <gtest/gtest.h>

using namespace geartrib::contact;

namespace {
constexpr double kDeltaPc = 0.5797e-9;
MultiAsperitySpec spec(const std::string& layout, double h_steps, double spacing) {
  MultiAsperitySpec s;
  s.layout = layout;
  s.height_step = h_steps * kDeltaPc;
  s.spacing = spacing;
  s.approach = 6.0 * kDeltaPc;
  s.modulus = 206e9 / 0.91;
  s.pressure_cap = 1.1704e9;
  s.elements = 8192;
  return s;
}
}  // namespace

TEST(MultiAsperity, HighNeighboursUnloadTheMiddleOne) {
  // HLH: the middle asperity carries less load and less surface stress as h_m grows; the high
  // ones always take the full approach.
  double prev_load = 1e300, prev_stress = 1e300;
  for (double h : {0.0, 1.0, 2.0}) {
    const MultiAsperityResult r = solve_multi_asperity(spec("HLH", h, 0.5e-6));
    EXPECT_LT(r.asperities[1].load, prev_load) << h;
    EXPECT_LT(r.asperities[1].max_surface_von_mises, prev_stress) << h;
    prev_load = r.asperities[1].load;
    prev_stress = r.asperities[1].max_surface_von_mises;
    for (int k : {0, 2}) EXPECT_NEAR(r.asperities[k].max_deformation, 6.0 * kDeltaPc, 0.005 * 6.0 * kDeltaPc) << h;
    EXPECT_LT(r.complementarity_error, 1e-10);
  }
}

TEST(MultiAsperity, AreaGrowsWithSpacingTowardIndependentAsperities) {
  const double single = solve_multi_asperity(spec("H", 0.0, 0.5e-6)).total_contact_area;
  double prev_area = 0.0, prev_mid = 1e300;
  for (double d : {0.25e-6, 0.5e-6, 1e-6, 2e-6}) {
    const MultiAsperityResult r = solve_multi_asperity(spec("HHH", 0.0, d));
    EXPECT_GT(r.total_contact_area, prev_area) << d;
    EXPECT_LT(r.total_contact_area, 3.0 * single) << d;
    EXPECT_LT(r.midpoint_von_mises[0], prev_mid) << d;  // the midpoint stress falls with spacing
    prev_area = r.total_contact_area;
    prev_mid = r.midpoint_von_mises[0];
  }
}

TEST(MultiAsperity, AreaFallsAsHeightDifferencesGrow) {
  for (const std::string layout : {"LLH", "LHL", "LHH", "HLH"}) {
    const double a0 = solve_multi_asperity(spec(layout, 0.0, 0.5e-6)).total_contact_area;
    const double a1 = solve_multi_asperity(spec(layout, 1.0, 0.5e-6)).total_contact_area;
    const double a2 = solve_multi_asperity(spec(layout, 2.0, 0.5e-6)).total_contact_area;
    EXPECT_GT(a0, a1) << layout;
    EXPECT_GT(a1, a2) << layout;
  }
}

TEST(MultiAsperity, RejectsBadLayouts) {
  EXPECT_THROW(solve_multi_asperity(spec("LXL", 1.0, 0.5e-6)), std::invalid_argument);
  EXPECT_THROW(solve_multi_asperity(spec("LLL", 1.0, 0.5e-6)), std::invalid_argument);
}

TEST(MultiAsperity, MeasuredProfileReproducesTheLayoutItDescribes) {
  // The same three cylinders given as a measured profile (arbitrary datum and offset) give the
  // same contact as the layout HLH: the geometry agrees to round-off (~1e-22 m after the datum and
  // offset are removed), so the iterative solver stops within its tolerance of the same solution
  // (observed 3e-8 relative; 1e-6 allows for the stopping point).
  const MultiAsperitySpec layout = spec("HLH", 1.0, 0.5e-6);
  MultiAsperitySpec measured = layout;
  const double datum = 3e-6, offset = 17e-6;
  measured.profile = {
      {offset - 0.5e-6, datum, 6.6e-6}, {offset, datum - kDeltaPc, 6.6e-6}, {offset + 0.5e-6, datum, 6.6e-6}};
  const MultiAsperityResult a = solve_multi_asperity(layout), b = solve_multi_asperity(measured);
  ASSERT_EQ(b.asperities.size(), 3u);
  const std::string kinds{b.asperities[0].kind, b.asperities[1].kind, b.asperities[2].kind};
  EXPECT_EQ(kinds, "HLH");
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.asperities[k].load / a.asperities[k].load, 1.0, 1e-6) << k;
  EXPECT_NEAR(b.total_contact_area / a.total_contact_area, 1.0, 1e-6);
  // Unequal radii: the blunter middle asperity (same tip height) carries more than a sharp one.
  measured.profile[1] = {offset, datum, 20e-6};
  const MultiAsperityResult blunt = solve_multi_asperity(measured);
  measured.profile[1].tip_radius = 2e-6;
  EXPECT_GT(blunt.asperities[1].load, solve_multi_asperity(measured).asperities[1].load);
  // Out of order or non-positive radii are rejected.
  measured.profile[1].tip_radius = 0.0;
  EXPECT_THROW(solve_multi_asperity(measured), std::invalid_argument);
}

TEST(MultiAsperity, ColdAndCoarseStartsGiveTheSameStudy) {
  // The default solver (preconditioned, started from 4096 elements and the rigid overlap) and
  // the plain one (zero start, no preconditioner) on the HLH study at 8192 elements: both stop
  // within the tolerance (1e-10 of the 4 um relief, ~1e-7 of the approach) of one solution.
  // Loads to 1e-6 relative (observed 4e-8); contact widths to one element (observed equal);
  // peak pressures and stresses to 1e-4 (one element's stiffness E*/h times the gap tolerance
  // is ~1e-4 of the peak; observed 2e-6).
  const MultiAsperitySpec fast = spec("HLH", 1.0, 0.5e-6);
  MultiAsperitySpec plain = fast;
  plain.precondition = false;
  plain.coarse_elements = 0;
  plain.overlap_start = false;
  const MultiAsperityResult a = solve_multi_asperity(fast), b = solve_multi_asperity(plain);
  EXPECT_GT(a.coarse_iterations, 0);
  EXPECT_EQ(b.coarse_iterations, 0);
  EXPECT_LT(a.iterations, b.iterations);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(a.asperities[k].load / b.asperities[k].load, 1.0, 1e-6) << k;
    EXPECT_NEAR(a.asperities[k].contact_width, b.asperities[k].contact_width, 1.01 * a.grid.spacing) << k;
    EXPECT_NEAR(a.asperities[k].max_pressure / b.asperities[k].max_pressure, 1.0, 1e-4) << k;
    EXPECT_NEAR(a.asperities[k].max_surface_von_mises / b.asperities[k].max_surface_von_mises, 1.0, 1e-4) << k;
  }
  EXPECT_NEAR(a.midpoint_von_mises[0] / b.midpoint_von_mises[0], 1.0, 1e-4);
  EXPECT_NEAR(a.inflection_von_mises / b.inflection_von_mises, 1.0, 1e-4);
  EXPECT_EQ(a.inflection_depth, b.inflection_depth);  // the same sample of the depth profile
  // The cost is counted: FFTs within the solve, the solve within the study.
  EXPECT_GT(a.transforms, 0);
  EXPECT_LE(a.transform_seconds, a.solve_seconds);
  EXPECT_LE(a.solve_seconds, a.seconds);
  MultiAsperitySpec bad = fast;
  bad.coarse_elements = -1;
  EXPECT_THROW(solve_multi_asperity(bad), std::invalid_argument);
}
