// Deterministic rough line contact (deterministic_contact.hpp, mesh_deterministic.hpp): the
// profile's exact element means, smooth flanks against Hertz (pressure, width, subsurface von
// Mises), the rolling frame of the gap, the hardness cap, a mesh pass on one and two threads and
// its shakedown, and the main job's deterministic fidelity on the seed's pair.
#include "contact/deterministic/mesh_deterministic.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/mesh_contact.hpp"
#include "flank_tracks.hpp"
#include "gear/gear_mesh.hpp"
#include "reference_solutions.hpp"
#include "runs/mesh_cycle.hpp"
#include "surface/flank_profile.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace geartrib;
using namespace geartrib::contact;

namespace {
constexpr double kPi = std::numbers::pi;
// Two 45-steel bodies (E = 206 GPa, nu = 0.3): E* = 1/(2 (1 - nu^2)/E) = 113.19 GPa, plane strain.
constexpr double kEstar = 113.19e9;
constexpr double kRadius = 0.0137;   // equivalent radius R [m]
constexpr double kLineLoad = 1.2e5;  // [N/m]
constexpr double kElement = 1e-6;    // element size of the strip tests [m]
constexpr double kSigmaP = 0.02;     // arc coordinates of the contact point [m]
constexpr double kSigmaW = 0.03;
const double kP0 = reference::hertz_line_peak(kLineLoad, kRadius, kEstar);       // Hertz peak, 561.8 MPa
const double kB = reference::hertz_line_half_width(kLineLoad, kRadius, kEstar);  // Hertz half-width, 136.0 um
// The von Mises maximum of the Hertz line contact on its axis (McEwen's closed-form axis stresses,
// plane strain, nu = 0.3, maximised on a 1e-5 b comb): 0.5575 p0 at 0.7043 b.
constexpr double kVonMisesRatio = 0.5575, kVonMisesDepth = 0.7043;

using test::flat;
using test::track;
// Smooth flanks covering +-300 um about the contact points (the strips reach +-1.5 b = 204 um).
FlankTrack flat_pinion() { return flat(kSigmaP - 300e-6, 0.5e-6, 1201); }
FlankTrack flat_wheel() { return flat(kSigmaW - 300e-6, 0.5e-6, 1201); }
StripPosition hertz_position(double line_load) { return {line_load, kRadius, kB, kSigmaP, kSigmaW}; }
DeterministicOptions strip_options() {
  DeterministicOptions o;
  o.element_size = kElement;
  return o;
}
surface::FlankProfile ground(std::uint64_t seed, double spacing, double length) {
  surface::GeneratedProfileSpec s;
  s.kind = surface::ProfileKind::ground;
  s.rq = 0.3e-6;
  s.correlation_length = 10e-6;
  s.spacing = spacing;
  s.seed = seed;
  return surface::generate_profile(s, length);
}
const std::vector<double>& values(const MeshContactResult& r, const std::string& name) {
  const Series* s = r.find(name);
  if (!s) throw std::logic_error("no series " + name);
  return s->values;
}
}  // namespace

TEST(DeterministicTrackMean, ExactForALinearProfile) {
  // z = z0 + g (sigma - start): the mean over [a, b] is the value at the midpoint. The start (2^-10 m)
  // and spacing (2^-22 m) are binary, so the interval ends are exact and only the heights and the
  // sum of up to 400 trapezoids round: 1e-14 relative (measured <= 2.2e-16).
  const double start = std::ldexp(1.0, -10), h = std::ldexp(1.0, -22), z0 = 0.5e-6, slope = 1e-3;
  std::vector<double> z;
  for (int k = 0; k <= 400; ++k) z.push_back(z0 + slope * k * h);
  const FlankTrack t = track(start, h, z);
  auto exact = [&](double a, double b) { return z0 + slope * (0.5 * (a + b) - start); };
  const std::pair<double, double> intervals[] = {
      {start + 0.3 * h, start + 0.7 * h},       // inside one interval
      {start + 10.2 * h, start + 13.9 * h},     // across three points
      {start, start + 400 * h},                 // the whole profile
      {start + 0.1 * h, start + 399.6 * h},     // partial intervals at both ends, whole ones between
      {start + 399.25 * h, start + 400.0 * h},  // the last interval
      {start + 5.0 * h, start + 6.0 * h}};      // from point to point
  for (const auto& [a, b] : intervals) {
    const double want = exact(a, b);
    EXPECT_NEAR(track_mean(t, a, b), want, 1e-14 * want) << (a - start) / h << " " << (b - start) / h;
  }
}

TEST(DeterministicTrackMean, ExactForAPiecewiseLinearProfile) {
  // Heights 0, 2, -1, 3, 1 (units u = 0.1 um) at h = 1 um, worked by hand as trapezoids (in u h):
  //   [0.5, 3.25]: 0.5 (1 + 2)/2 + (2 - 1)/2 + (-1 + 3)/2 + 0.25 (3 + 2.5)/2 = 2.9375 over 2.75 h;
  //   [0.5, 1.5]: 0.5 (1 + 2)/2 + 0.5 (2 + 0.5)/2 = 1.375 over 1 h;
  //   [2.25, 2.75]: heights 0 and 2 at the ends of one segment: mean 1;
  //   [0, 4]: (0 + 2)/2 + (2 - 1)/2 + (-1 + 3)/2 + (3 + 1)/2 = 4.5 over 4 h.
  // 1e-13 relative: the decimal arc coordinates (10 um + fractions of 1 um) round at ~1e-21 m on
  // slopes of 0.4, and a mean near zero (the interval [2.25, 2.75] sums -1 and 3) loses a few
  // digits to cancellation (measured <= 3.1e-15).
  const double u = 0.1e-6, h = 1e-6, start = 10e-6;
  const FlankTrack t = track(start, h, {0.0, 2 * u, -1 * u, 3 * u, 1 * u});
  struct Interval {
    double a, b, mean;
  };
  for (const Interval& c : {Interval{0.5, 3.25, 2.9375 / 2.75}, Interval{0.5, 1.5, 1.375}, Interval{2.25, 2.75, 1.0},
                            Interval{0.0, 4.0, 4.5 / 4.0}}) {
    EXPECT_NEAR(track_mean(t, start + c.a * h, start + c.b * h), c.mean * u, 1e-13 * c.mean * u) << c.a << " " << c.b;
  }
}

TEST(DeterministicTrackMean, RefusesIntervalsOutsideTheProfileAndEmptyOnes) {
  const double h = 1e-6, start = 10e-6;
  const FlankTrack t = track(start, h, {0.0, 1e-7, 2e-7, 1e-7, 0.0});  // [10, 14] um
  // Beyond either end by a thousandth of a spacing (far beyond the 1e-9 h the rounding of the
  // arc coordinates is allowed), or wholly outside.
  EXPECT_THROW(track_mean(t, start - 1e-3 * h, start + h), std::out_of_range);
  EXPECT_THROW(track_mean(t, start + h, start + 4.001 * h), std::out_of_range);
  EXPECT_THROW(track_mean(t, start + 5 * h, start + 6 * h), std::out_of_range);
  EXPECT_THROW(track_mean(t, start - 3 * h, start - 2 * h), std::out_of_range);
  EXPECT_THROW(track_mean(t, start + 2 * h, start + 2 * h), std::invalid_argument);  // b == a
  EXPECT_THROW(track_mean(t, start + 3 * h, start + 2 * h), std::invalid_argument);  // b < a
  EXPECT_NO_THROW(track_mean(t, start, start + 4 * h));                              // the ends themselves
  EXPECT_NO_THROW(track_mean(t, start - 1e-10 * h, start + h));  // within the 1e-9 h allowed for rounding
}

TEST(DeterministicStrip, SmoothFlanksGiveHertz) {
  const StripSolver solver(kEstar, 1.5 * kB, strip_options());  // 408 elements of 1 um, b/e = 136
  const DeterministicStrip s = solver.solve(flat_pinion(), flat_wheel(), hertz_position(kLineLoad), true);
  // Peak pressure within 0.1%: the centre element carries the ellipse's mean over its width,
  // p0 (1 - e^2/(24 b^2)) = p0 (1 - 2e-6), and the constant-pressure elements resolve the contact's
  // ends to an element (b/136), which shifts the load the ellipse carries (measured -7e-6).
  EXPECT_NEAR(s.peak_pressure / kP0, 1.0, 1e-3);
  // The contact's half-width within one element (its ends fall inside an element; measured 0.012 e).
  EXPECT_NEAR(s.contact_half_width, kB, kElement);
  EXPECT_NEAR(s.real_area_ratio, 1.0, kElement / kB);  // the same width over the nominal 2b
  EXPECT_EQ(s.contact_spots, 1);
  EXPECT_EQ(s.plastic_area_per_width, 0.0);  // no cap: nothing yields
  EXPECT_EQ(s.plastic_area_fraction, 0.0);
  EXPECT_EQ(s.max_plastic_deformation, 0.0);
  EXPECT_FALSE(s.edge_loaded);  // +-1.5 b: the pressure ends well inside the strip
  double load = 0.0;
  for (double p : s.pressure) load += p * kElement;
  EXPECT_NEAR(load / kLineLoad, 1.0, 1e-12);  // load control scales the pressure to the load: rounding only
  // The von Mises maximum within 0.2% of 0.5575 p0: the reference's four digits (3e-5), the peak
  // pressure's 0.1% above, and the element-wise pressure's steps at b/136 (measured 0.557514 p0).
  // Its depth within 1% of 0.7043 b: the maximum is flat in depth (1% off in depth lowers the stress
  // by ~1e-4), so the scan of 20 depths and Brent's 12 iterations place it only to the stress's
  // resolution (measured 0.704304 b). On the axis within an element: the problem is symmetric and
  // the refinement across +-2 elements brackets x = 0 (measured 5e-13 m).
  EXPECT_NEAR(s.max_von_mises / (kVonMisesRatio * kP0), 1.0, 2e-3);
  EXPECT_NEAR(s.max_von_mises_depth / (kVonMisesDepth * kB), 1.0, 0.01);
  EXPECT_NEAR(s.max_von_mises_x, 0.0, kElement);
}

TEST(DeterministicStrip, FourElementsAcrossASpotResolveItsPeak) {
  // mesh_deterministic.cpp flags spots narrower than four elements (kMinElementsPerSpot) on the
  // ground that a Hertzian spot's peak pressure is within ~5% from four elements across: Hertz
  // contacts of half-width 1.75 to 2.5 elements, each placed differently on the element grid,
  // cover 3 to 6 elements and peak within 5% of p0 (measured <= 2.7%).
  for (double ratio : {1.75, 2.0, 2.1, 2.25, 2.5}) {
    const double b = ratio * kElement, w = reference::hertz_line_load_of_half_width(b, kRadius, kEstar),
                 p0 = reference::hertz_line_peak_of_half_width(w, b);
    const StripSolver solver(kEstar, 3.0 * b, strip_options());
    const DeterministicStrip s = solver.solve(flat_pinion(), flat_wheel(), {w, kRadius, b, kSigmaP, kSigmaW}, false);
    EXPECT_NEAR(s.peak_pressure / p0, 1.0, 0.05) << ratio;
    EXPECT_GE(s.real_area_per_width, 3.0 * kElement) << ratio;
    EXPECT_LE(s.real_area_per_width, 6.0 * kElement) << ratio;
    EXPECT_EQ(s.contact_spots, 1) << ratio;
  }
}

TEST(DeterministicStrip, NoLoadNoContact) {
  const StripSolver solver(kEstar, 1.5 * kB, strip_options());
  const DeterministicStrip s = solver.solve(flat_pinion(), flat_wheel(), hertz_position(0.0), true);
  EXPECT_EQ(s.peak_pressure, 0.0);
  EXPECT_EQ(s.real_area_per_width, 0.0);
  EXPECT_EQ(s.contact_spots, 0);
  EXPECT_EQ(s.contact_half_width, 0.0);
  EXPECT_EQ(s.max_von_mises, 0.0);
  ASSERT_EQ(s.pressure.size(), static_cast<std::size_t>(solver.grid().size));
  ASSERT_EQ(s.plastic.size(), s.pressure.size());
  for (std::size_t k = 0; k < s.pressure.size(); ++k) EXPECT_EQ(s.pressure[k] + s.plastic[k], 0.0);
}

TEST(DeterministicGap, InvariantWhenFlankAndContactPointShiftTogether) {
  // The gap reads each flank at sigma - start: shifting a flank's start and its contact point by the
  // same arc length leaves it. Within 1e-15 m: the shifted arc coordinates (~3 cm) round at
  // ulp(0.03 m) ~ 3.5e-18 m, which moves the element ends by ~1e-11 of the element (heights < 1.5 um
  // on slopes < 0.2: ~1e-17 m at most; measured 6e-19 m).
  const StripSolver solver(kEstar, 50e-6, strip_options());
  const FlankTrack p = track(kSigmaP - 100e-6, 0.25e-6, ground(1, 0.25e-6, 200e-6).z);
  const FlankTrack w = track(kSigmaW - 100e-6, 0.25e-6, ground(2, 0.25e-6, 200e-6).z);
  const StripPosition at{kLineLoad, kRadius, kB, kSigmaP, kSigmaW};
  const std::vector<double> g0 = solver.gap(p, w, at);
  for (const auto& [d1, d2] : {std::pair{3.7e-3, 0.0}, {0.0, -1.3e-3}, {1.234567e-6, 7.654321e-3}}) {
    FlankTrack p1 = p, w1 = w;
    p1.start += d1, w1.start += d2;
    StripPosition at1 = at;
    at1.sigma_pinion += d1, at1.sigma_wheel += d2;
    const std::vector<double> g1 = solver.gap(p1, w1, at1);
    ASSERT_EQ(g1.size(), g0.size());
    double worst = 0.0;
    for (std::size_t j = 0; j < g0.size(); ++j) worst = std::max(worst, std::abs(g1[j] - g0[j]));
    EXPECT_LT(worst, 1e-15) << d1 << " " << d2;
  }
}

TEST(DeterministicGap, FlanksRollThroughTheStripInOppositeDirections) {
  // A tent bump of height A and half-width L on the pinion's flank centred at sigma1c + c1 (ahead of
  // the contact point) appears at x = -c1 (sigma1 = sigma1c - x); one on the wheel's at sigma2c + c2
  // appears at x = +c2 (sigma2 = sigma2c + x). The gap is the parabola's element mean
  // x^2/(2R) + e^2/(24R) less the bump's element mean, integrated here in closed form. The kinks lie
  // on profile points, so the profile's linear interpolation is the tent itself. Within 1e-15 m:
  // arc coordinates round at ~3.5e-18 m on slopes of 0.1, the element's length so by ~1e-11 of the
  // heights (< 1 um), and the heights themselves at 1e-22 m (measured 2e-19 m).
  const double h = 0.25e-6, a_height = 1e-6, half = 10e-6, c1 = 23.5e-6, c2 = 31e-6;
  const StripSolver solver(kEstar, 60.3e-6, strip_options());
  const HalfPlaneGrid& g = solver.grid();
  const double e = g.spacing;
  ASSERT_EQ(g.size, 122);  // 2 ceil(60.3): element edges at whole micrometres from -61 to 61 um
  // tent(u) = A max(0, 1 - |u - c|/L) in the flank's own coordinate u = sigma - start.
  const test::Tent tent{a_height, half};
  const std::size_t points = 1001;  // 250 um of profile
  const double lead = 125e-6;       // the contact point's distance from the profile's start
  const FlankTrack p = tent.track(kSigmaP - lead, h, points, lead + c1);
  const FlankTrack w = tent.track(kSigmaW - lead, h, points, lead + c2);
  const FlankTrack p0 = flat(kSigmaP - lead, h, points), w0 = flat(kSigmaW - lead, h, points);
  const StripPosition at{kLineLoad, kRadius, kB, kSigmaP, kSigmaW};
  const std::vector<double> gp = solver.gap(p, w0, at), gw = solver.gap(p0, w, at);
  int touched_p = 0, touched_w = 0, deepest_p = 0, deepest_w = 0;
  double relief_p = 0.0, relief_w = 0.0;  // the largest bump the gap shows
  for (int j = 0; j < g.size; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const double x = g.x(j), parabola = x * x / (2.0 * kRadius) + e * e / (24.0 * kRadius);
    // Pinion: sigma1 = sigma1c - x, u = lead - x; wheel: u = lead + x.
    const double bump_p = tent.mean(lead - x, e, lead + c1), bump_w = tent.mean(lead + x, e, lead + c2);
    EXPECT_NEAR(gp[k], parabola - bump_p, 1e-15) << x;
    EXPECT_NEAR(gw[k], parabola - bump_w, 1e-15) << x;
    touched_p += bump_p > 1e-3 * a_height, touched_w += bump_w > 1e-3 * a_height;
    if (parabola - gp[k] > relief_p) relief_p = parabola - gp[k], deepest_p = j;
    if (parabola - gw[k] > relief_w) relief_w = parabola - gw[k], deepest_w = j;
  }
  // The bumps lie whole inside the strip, on opposite sides: the pinion's over the 21 elements
  // centred at -33.5 .. -13.5 um (its ends inside elements), deepest at -23.5 um; the wheel's over
  // the 20 of 21.5 .. 40.5 um, deepest at one of the two elements either side of 31 um (an edge).
  EXPECT_EQ(touched_p, 21);
  EXPECT_EQ(touched_w, 20);
  EXPECT_NEAR(g.x(deepest_p), -c1, 1e-12);           // rounding of the element centres only
  EXPECT_NEAR(g.x(deepest_w), c2, 0.5 * e + 1e-12);  // either element at the edge
}

TEST(DeterministicStrip, HardnessCapsThePressureAndYields) {
  DeterministicOptions o = strip_options();
  o.pressure_cap = 0.8 * kP0;  // H below the Hertz peak: the middle of the contact yields
  const double cap = o.pressure_cap;
  const StripSolver solver(kEstar, 1.5 * kB, o);
  const DeterministicStrip s = solver.solve(flat_pinion(), flat_wheel(), hertz_position(kLineLoad), true);
  EXPECT_NEAR(s.peak_pressure / cap, 1.0, 1e-9);  // the solver clamps to the cap: exact in fact
  EXPECT_GT(s.plastic_area_per_width, 0.0);
  EXPECT_GT(s.plastic_area_fraction, 0.0);
  EXPECT_GT(s.max_plastic_deformation, o.plastic_overlap);
  EXPECT_GT(s.contact_half_width, kB);  // the capped pressure spreads the load wider than Hertz
  ASSERT_EQ(s.plastic.size(), s.pressure.size());
  double load = 0.0, largest = 0.0;
  int plastic = 0;
  for (std::size_t k = 0; k < s.pressure.size(); ++k) {
    EXPECT_GE(s.plastic[k], 0.0) << k;
    EXPECT_LE(s.pressure[k], cap) << k;
    if (s.plastic[k] > 0.0) {
      EXPECT_EQ(s.pressure[k], cap) << k;  // only capped elements are pressed beyond the elastic answer
      ++plastic;
    }
    largest = std::max(largest, s.plastic[k]);
    load += s.pressure[k] * kElement;
  }
  EXPECT_EQ(plastic * kElement, s.plastic_area_per_width);
  EXPECT_EQ(largest, s.max_plastic_deformation);
  // The line load is carried as exactly as the capped load control's solves resolve it: each is
  // exact to its complementarity tolerance (1e-8) of the gap's relief, (1.5 b)^2/(2 R) = 1.5 um, so
  // to e = 1.5e-14 m of the approach, and the load to 2 s (w + 2 e) with s = dW/d(approach)
  // ~ W/(5 um) at this load: 2e-8 relative (measured 6e-9); 1e-7 leaves room for the slope's estimate.
  EXPECT_NEAR(load / kLineLoad, 1.0, 1e-7);
}

TEST(DeterministicStrip, CappedLoadControlAcrossTheStripRange) {
  // Rough (ground) flanks as the shipped deterministic case has them (0.125 um profile under 0.5 um
  // elements) at 45 steel's hardness, on strips of 1.05 to 20 Hertz half-widths, the key's whole
  // range. The gap's relief grows with the strip's length squared ((20 b)^2/(2 R) = 0.27 mm) and the
  // solves' tolerance with it: the bracket of the approach used to stop at 1e-15 m, far below what they
  // resolve (e = 1e-8 x 0.27 mm = 2.7e-12 m), and then demand 1e-6 of the load: this position failed at
  // 20 half-widths ("reached 60000.07685 N/m for 60000 N/m"). Now the load is carried to the solves'
  // resolution.
  const double h = 0.125e-6, length = 8e-3, load = 0.5 * kLineLoad;
  const FlankTrack p = track(kSigmaP - 0.5 * length, h, ground(1, h, length).z);
  const FlankTrack w = track(kSigmaW - 0.5 * length, h, ground(2, h, length).z);
  const StripPosition at{load, kRadius, kB, kSigmaP + 100e-6, kSigmaW - 100e-6};
  DeterministicOptions o = strip_options();
  o.element_size = 0.5e-6;
  o.pressure_cap = 1.1704e9;
  o.subsurface_stress = false;  // not under test here
  for (double halfwidths :
       {DeterministicOptions::kMinStripHalfwidths, 15.0, DeterministicOptions::kMaxStripHalfwidths}) {
    o.strip_halfwidths = halfwidths;
    const StripSolver solver(kEstar, halfwidths * kB, o);
    DeterministicStrip s;
    ASSERT_NO_THROW(s = solver.solve(p, w, at, true)) << halfwidths;
    EXPECT_GT(s.plastic_area_per_width, 0.0) << halfwidths;  // capped: the bracket, not the elastic solve
    double carried = 0.0;
    for (double x : s.pressure) carried += x * o.element_size;
    // The resolution 2 s (w + 2 e) <= 6 s e: e = 2.7e-12 m at 20 half-widths and s ~ W/(2.5 um) (the
    // approach of this line load on a strip of 20 b), 6.5e-6 relative; less on shorter strips.
    EXPECT_NEAR(carried / load, 1.0, 1e-5) << halfwidths;
  }
}

TEST(DeterministicMeshPass, AFailedSolveNamesItsPositionAndTheKeys) {
  // A tolerance below rounding (1e-17 of the relief) cannot be met: the boundary elements' failure
  // comes back with the position it happened at and the keys that ask less of the solves.
  DeterministicOptions o = strip_options();
  o.element_size = 4e-6;
  o.tolerance = 1e-17;
  o.subsurface_stress = false;
  const std::vector<StripPosition> positions{{kLineLoad, kRadius, kB, kSigmaP, kSigmaW, 1.5e-3}};
  try {
    mesh_pass(flat_pinion(), flat_wheel(), positions, kEstar, 1.5 * kB, o, {}, 1);
    FAIL() << "no failure";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("at position 1 of 1 (s = 1.5 mm, line load 120000 N/m): boundary elements:"), std::string::npos)
        << what;
    EXPECT_NE(what.find("contact.strip_halfwidths"), std::string::npos) << what;
    EXPECT_NE(what.find("contact.element_size"), std::string::npos) << what;
  }
}

TEST(DeterministicMeshPass, ThreadsAgreeAndTheFlanksShakeDown) {
  // Ground flanks (Rq 0.3 um, lambda 10 um, 0.25 um spacing) over 1.2 mm, six positions 30 um
  // apart (their strips overlap, so a flank point is deformed by several), 45 steel's hardness.
  const double h = 0.25e-6, length = 1.2e-3, start_p = kSigmaP - 0.6e-3, start_w = kSigmaW - 0.6e-3;
  FlankTrack p = track(start_p, h, ground(1, h, length).z), w = track(start_w, h, ground(2, h, length).z);
  DeterministicOptions o = strip_options();
  o.pressure_cap = 1.1704e9;
  o.subsurface_stress = false;  // not under test here
  std::vector<StripPosition> positions;
  for (int i = 0; i < 6; ++i) positions.push_back({kLineLoad, kRadius, kB, kSigmaP + 30e-6 * i, kSigmaW - 30e-6 * i});
  const std::vector<bool> keep(positions.size(), true);
  const MeshPass one = mesh_pass(p, w, positions, kEstar, 1.5 * kB, o, keep, 1);
  const MeshPass two = mesh_pass(p, w, positions, kEstar, 1.5 * kB, o, keep, 2);
  ASSERT_GT(one.max_new_plastic, o.plastic_overlap);  // the first pass yields (else nothing to shake down)
  // Bitwise equal: each position is solved by its own deterministic solve on an identical grid
  // (the same FFTW plans, on aligned buffers) whichever thread takes it, and the flanks'
  // deformations merge by max, which is exact and independent of the order.
  ASSERT_EQ(one.strips.size(), two.strips.size());
  for (std::size_t i = 0; i < one.strips.size(); ++i) {
    EXPECT_EQ(one.strips[i].pressure, two.strips[i].pressure) << i;
    EXPECT_EQ(one.strips[i].peak_pressure, two.strips[i].peak_pressure) << i;
    EXPECT_EQ(one.strips[i].real_area_per_width, two.strips[i].real_area_per_width) << i;
    EXPECT_EQ(one.strips[i].max_plastic_deformation, two.strips[i].max_plastic_deformation) << i;
  }
  EXPECT_EQ(one.plastic_pinion, two.plastic_pinion);
  EXPECT_EQ(one.plastic_wheel, two.plastic_wheel);
  EXPECT_EQ(one.max_new_plastic, two.max_new_plastic);
  // Equal hardness: each flank takes half of an element's overlap, interpolated between element
  // centres, so no flank point takes more than half the largest overlap.
  double largest = 0.0;
  for (const auto& s : one.strips) largest = std::max(largest, s.max_plastic_deformation);
  const double p_max = *std::max_element(one.plastic_pinion.begin(), one.plastic_pinion.end());
  const double w_max = *std::max_element(one.plastic_wheel.begin(), one.plastic_wheel.end());
  EXPECT_GT(p_max, 0.0);
  EXPECT_GT(w_max, 0.0);
  EXPECT_LE(p_max, 0.5 * largest);
  EXPECT_LE(w_max, 0.5 * largest);
  EXPECT_EQ(one.max_new_plastic, std::max(p_max, w_max));
  // The flanks lowered by what they took: the same mesh deforms them less (shakedown).
  for (std::size_t k = 0; k < p.profile.z.size(); ++k) p.profile.z[k] -= one.plastic_pinion[k];
  for (std::size_t k = 0; k < w.profile.z.size(); ++k) w.profile.z[k] -= one.plastic_wheel[k];
  const MeshPass again = mesh_pass(p, w, positions, kEstar, 1.5 * kB, o, {}, 1);
  EXPECT_LT(again.max_new_plastic, one.max_new_plastic);  // measured 0.51 um, then 0.018 um
  EXPECT_TRUE(again.strips.front().pressure.empty());     // keep empty: no profiles kept
}

namespace {
// The seed's case in the deterministic fidelity, a few positions on coarse elements.
Case deterministic_case(int positions, double element) {
  Case c = test::seed_case();
  c.contact.fidelity = ContactFidelity::deterministic;
  c.contact.positions = positions;
  c.contact.boundary_elements.element_size = element;
  c.contact.threads = 1;
  return c;
}
// Flanks for the span: per tooth, a profile from `make` at the span's first point.
// extra[g]: tracks more (or fewer) than the run asks for.
FlankSource source(std::function<surface::FlankProfile(int g, int tooth, double length)> make,
                   std::array<int, 2> extra = {0, 0}) {
  return [make, extra](const FlankSpan& span, const int teeth[2]) {
    RollingFlanks f;
    for (int g = 0; g < 2; ++g)
      for (int t = 0; t < teeth[g] + extra[static_cast<std::size_t>(g)]; ++t)
        (g == 0 ? f.pinion : f.wheel).push_back({make(g, t, span.length(g)), span.first[g]});
    return f;
  };
}
surface::FlankProfile smooth(double spacing, double length) {
  return {spacing, std::vector<double>(static_cast<std::size_t>(std::ceil(length / spacing)) + 1, 0.0)};
}
}  // namespace

TEST(DeterministicMeshContact, SmoothFlanksGiveHertzAlongThePath) {
  const double e = 2e-6;
  const Case c = deterministic_case(11, e);
  const gear::GearMesh mesh = gear::case_mesh(c);
  const MeshContactResult r = runs::run_mesh_contact(
      c, mesh, nullptr, {}, 0, nullptr, source([e](int, int, double length) { return smooth(e, length); }));
  EXPECT_EQ(r.fidelity, "deterministic");
  const auto& p0 = values(r, "hertz_p0_Pa");
  const auto& b = values(r, "hertz_halfwidth_m");
  const auto& peak = values(r, "max_pressure_Pa");
  const auto& half = values(r, "contact_halfwidth_m");
  ASSERT_EQ(p0.size(), 11u);
  ASSERT_EQ(peak.size(), 11u);
  // Elastic only if the Hertz peak stays below the hardness that caps the pressure (45 steel,
  // 1.17 GPa): the seed's pair is at most ~0.6 GPa.
  ASSERT_LT(*std::max_element(p0.begin(), p0.end()), std::min(c.pinion.material.hardness, c.wheel.material.hardness));
  for (std::size_t i = 0; i < p0.size(); ++i) {
    // 1%: the element averages and the contact ends resolved to one element of 2 um on half-widths
    // of 81 um or more (b/40; measured <= 7.5e-5). A wrong modulus (E instead of E*: 4.6%) fails.
    EXPECT_NEAR(peak[i] / p0[i], 1.0, 0.01) << i;
    EXPECT_NEAR(half[i], b[i], e) << i;  // the contact's ends fall inside an element (measured <= 0.76 um)
  }
  EXPECT_EQ(values(r, "plastic_area_fraction"), std::vector<double>(11, 0.0));
  EXPECT_EQ(r.regime, "elastic");
  EXPECT_TRUE(r.statistical.empty());  // smooth flanks have no statistics to run the statistical model on
  EXPECT_FALSE(r.running_in.has_value());
  // The profiles kept (at A, B, C, D, E, the default) peak at the position's peak pressure.
  ASSERT_FALSE(r.pressure_profiles.empty());
  for (const PressureProfile& q : r.pressure_profiles)
    EXPECT_EQ(*std::max_element(q.pressure.begin(), q.pressure.end()), peak[static_cast<std::size_t>(q.position)])
        << q.point;
}

TEST(DeterministicMeshContact, RefusesMissingOrWrongFlanks) {
  const double e = 2e-6;
  const Case c = deterministic_case(3, e);
  const gear::GearMesh mesh = gear::case_mesh(c);
  EXPECT_THROW(runs::run_mesh_contact(c, mesh, nullptr, {}, 0, nullptr, {}), std::invalid_argument);
  // A pair (one tooth each): one pinion track too many, or no wheel track.
  auto flat_source = [e](std::array<int, 2> extra) {
    return source([e](int, int, double length) { return smooth(e, length); }, extra);
  };
  EXPECT_THROW(runs::run_mesh_contact(c, mesh, nullptr, {}, 0, nullptr, flat_source({1, 0})), std::logic_error);
  EXPECT_THROW(runs::run_mesh_contact(c, mesh, nullptr, {}, 0, nullptr, flat_source({0, -1})), std::logic_error);
  EXPECT_NO_THROW(runs::run_mesh_contact(c, mesh, nullptr, {}, 0, nullptr, flat_source({0, 0})));
}

TEST(DeterministicMeshContact, RoughFlanksRunTheStatisticalModelAndRunIn) {
  // Ground flanks (Rq 0.3 um, 0.5 um spacing) on 2 um elements at five positions, three meshes.
  const double e = 2e-6;
  Case c = deterministic_case(5, e);
  c.running_in.meshes = 3;
  const gear::GearMesh mesh = gear::case_mesh(c);
  const MeshContactResult r =
      runs::run_mesh_contact(c, mesh, nullptr, {}, 0, nullptr, source([](int g, int t, double length) {
                               return ground(static_cast<std::uint64_t>(1 + g + 2 * t), 0.5e-6, length);
                             }));
  ASSERT_FALSE(r.statistical.empty());
  for (const Series& s : r.statistical) {
    EXPECT_EQ(s.name.rfind("statistical_", 0), 0u) << s.name;
    EXPECT_EQ(s.values.size(), 5u) << s.name;
  }
  EXPECT_NE(r.find("statistical_real_area_ratio"), nullptr);
  ASSERT_TRUE(r.running_in.has_value());
  const RunningInResult& ri = *r.running_in;
  ASSERT_GE(ri.meshes, 1);
  ASSERT_LE(ri.meshes, 3);
  EXPECT_TRUE(ri.meshes == 3 || ri.shakedown_mesh == ri.meshes);  // stops early only at shakedown
  auto column = [&](const std::string& name) -> const std::vector<double>& {
    for (const Series& s : ri.history)
      if (s.name == name) return s.values;
    throw std::logic_error("no history column " + name);
  };
  const auto& meshes = column("mesh");
  ASSERT_EQ(meshes.size(), static_cast<std::size_t>(ri.meshes + 1));  // row 0: the new flanks
  for (std::size_t k = 0; k < meshes.size(); ++k) EXPECT_EQ(meshes[k], static_cast<double>(k));
  const auto& plastic = column("new_plastic_deformation_m");
  ASSERT_GT(plastic[1],
            c.contact.boundary_elements.plastic_overlap);  // the first mesh yields: there is running-in to see
  const auto& rq = column("pinion_rq_m");
  EXPECT_LT(plastic.back(), plastic[1]);  // the later meshes yield less than the first (toward shakedown)
  EXPECT_LE(rq.back(), rq.front());       // running-in lowers the peaks
}

TEST(DeterministicCost, FromTheRunsSizes) {
  // The hunting order of a z = 1000 pair keeps every tooth's flank: 2000 profiles of 1.64e6 points of
  // 8 bytes (26.3 GB, finding 11 of issue 30); 201 positions x 30 meshes x 1000 pinion teeth solves.
  FlankSpan span;
  span.positions = 201;
  span.elements = 1280;
  DeterministicWork w;
  w.flank_points[0] = w.flank_points[1] = 1.64e6;
  w.teeth[0] = w.teeth[1] = 1000;
  w.meshes = 30;
  w.kept_profiles = 5;
  w.threads = w.cores = 2;
  const DeterministicCost c = deterministic_cost(span, w);
  EXPECT_DOUBLE_EQ(c.flank_bytes, 8.0 * 1.64e6 * 2000);
  EXPECT_DOUBLE_EQ(c.profile_bytes, 24.0 * 5 * 1280);
  EXPECT_DOUBLE_EQ(c.solver_bytes, 240.0 * 2 * 1280);
  EXPECT_DOUBLE_EQ(c.solves, 201.0 * 30 * 1000);
  EXPECT_DOUBLE_EQ(c.solve_seconds, 5.9e-3);  // the shipped case's strip, measured
  EXPECT_DOUBLE_EQ(c.seconds, c.solves * 5.9e-3 / 2);
  // Elements cost more than in proportion (the iterations grow): 20 half-widths at 0.125 um, 51200
  // elements, measured 1.43 s a solve on this machine; the estimate is within a factor of 2.
  EXPECT_GT(strip_solve_seconds(51200), 1.43 / 2);
  EXPECT_LT(strip_solve_seconds(51200), 1.43 * 2);
  // More threads than positions cost no more: each position is one thread's at a time.
  span.positions = 1;
  w.cores = 64;
  EXPECT_DOUBLE_EQ(deterministic_cost(span, w).seconds, 30 * 1000 * 5.9e-3);
}
