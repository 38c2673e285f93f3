// Flank profiles: generated smooth, ground and hobbed profiles have the statistics they are made
// with (exact where the construction is exact, within sampling error where it is random); profiles
// come out of a grid's rows and columns; the statistics of a hand-worked profile; bad input refused.
#include "core/keyed_error.hpp"
#include "surface/flank_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace geartrib::surface;

namespace {
double mean_of(const std::vector<double>& z) {
  double m = 0.0;
  for (double v : z) m += v;
  return m / static_cast<double>(z.size());
}
}  // namespace

TEST(FlankProfile, SmoothIsAllZero) {
  GeneratedProfileSpec spec;
  spec.kind = ProfileKind::smooth;
  const FlankProfile p = generate_profile(spec, 100e-6);
  ASSERT_EQ(p.z.size(), 401u);  // ceil(100 um / 0.25 um) + 1: the ratio's round-off adds no point
  for (double v : p.z) EXPECT_EQ(v, 0.0);
  EXPECT_DOUBLE_EQ(p.length(), 100e-6);
  EXPECT_EQ(FlankProfile{}.length(), 0.0);
  EXPECT_EQ(generate_profile(spec, 0.1e-6).z.size(), 2u);  // at least the length: one interval
  const ProfileStatistics s = profile_statistics(p.z, p.spacing);
  EXPECT_EQ(s.rq, 0.0);
  EXPECT_EQ(s.rsk, 0.0);  // flat: no shape, 0 rather than 0/0
  EXPECT_EQ(s.peaks, 0);
  EXPECT_EQ(s.summit_radius, 0.0);
}

TEST(FlankProfile, GroundHasZeroMeanExactRqAndIsSeeded) {
  GeneratedProfileSpec spec;  // ground, 0.25 um spacing, Rq 0.3 um, lambda 10 um
  const FlankProfile p = generate_profile(spec, 1e-3);
  ASSERT_EQ(p.z.size(), 4001u);
  EXPECT_EQ(p.spacing, spec.spacing);
  // Mean removed, then scaled to Rq: both exact up to the round-off of sums over 4001 points.
  EXPECT_NEAR(mean_of(p.z), 0.0, 1e-12 * spec.rq);
  const ProfileStatistics s = profile_statistics(p.z, p.spacing);
  EXPECT_NEAR(s.rq / spec.rq, 1.0, 1e-12);
  EXPECT_NEAR(s.m0 / (spec.rq * spec.rq), 1.0, 1e-12);
  EXPECT_EQ(generate_profile(spec, 1e-3).z, p.z);  // the same seed: the same profile, bit for bit
  GeneratedProfileSpec other = spec;
  other.seed = 2;
  const FlankProfile q = generate_profile(other, 1e-3);
  ASSERT_EQ(q.z.size(), p.z.size());
  double diff = 0.0;
  for (std::size_t k = 0; k < p.z.size(); ++k) diff += (q.z[k] - p.z[k]) * (q.z[k] - p.z[k]);
  // Independent seeds: the difference has about twice the variance (not a few bits' change).
  EXPECT_GT(std::sqrt(diff / static_cast<double>(p.z.size())), 0.5 * spec.rq);
}

TEST(FlankProfile, GroundMomentsMatchTheGaussianAutocorrelation) {
  // For R(tau) = rq^2 exp(-tau^2/lambda^2): m2 = -R''(0) = 2 rq^2/lambda^2, m4 = R''''(0) = 12 rq^2/lambda^4.
  // Biases, all small: the finite differences at spacing/lambda = 1/50, -2 (s/lambda)^2 = -0.08% (m2)
  // and -5/3 (s/lambda)^2 = -0.07% (m4); the kernel's cut at +-4 sigma, a step of exp(-8) that adds
  // ~+0.5% to m4 at 25 spacings a sigma. The sampling error of a 105 mm profile (~21 000
  // correlation lengths) dominates: over seeds 1-200 the standard deviations were 0.94% (m2),
  // 1.2% (m4, mean +0.36%), 0.016 (Rsk) and 0.032 (Rku). Tolerances: about 4 of them.
  GeneratedProfileSpec spec;
  spec.spacing = 0.1e-6;
  spec.correlation_length = 5e-6;
  spec.rq = 0.3e-6;
  spec.seed = 5;
  const std::size_t n = std::size_t{1} << 20;
  const FlankProfile p = generate_profile(spec, static_cast<double>(n - 1) * spec.spacing);
  ASSERT_EQ(p.z.size(), n);
  const ProfileStatistics s = profile_statistics(p.z, p.spacing);
  const double rq2 = spec.rq * spec.rq, lambda = spec.correlation_length;
  EXPECT_NEAR(s.m2 / (2.0 * rq2 / (lambda * lambda)), 1.0, 0.04);
  EXPECT_NEAR(s.m4 / (12.0 * rq2 / std::pow(lambda, 4)), 1.0, 0.05);
  EXPECT_NEAR(s.rsk, 0.0, 0.06);  // Gaussian heights
  EXPECT_NEAR(s.rku, 3.0, 0.13);
}

TEST(FlankProfile, HobbedRidgesAreParabolasOfTheTipRadius) {
  GeneratedProfileSpec spec;
  spec.kind = ProfileKind::hobbed;
  spec.rq = 0.0;  // pure ridges
  spec.spacing = 0.25e-6;
  spec.ridge_spacing = 40e-6;  // 160 spacings: every ridge sampled alike
  spec.ridge_radius = 400e-6;
  spec.seed = 3;
  const int ridges = 50;
  const FlankProfile p = generate_profile(spec, ridges * spec.ridge_spacing);
  ASSERT_EQ(p.z.size(), 50u * 160u + 1u);
  EXPECT_NEAR(mean_of(p.z), 0.0, 1e-12 * 0.5e-6);  // mean removed (round-off of the sum)
  const ProfileStatistics s = profile_statistics(p.z, p.spacing);
  // The central second difference is exact on a parabola: every peak's three points lie on its
  // ridge (a peak is within half a spacing of the tip, the valleys 80 spacings away). Round-off:
  // heights ~0.5 um against second differences of spacing^2/R ~ 1.6e-10 m, ~1e-12 relative.
  EXPECT_NEAR(s.summit_radius / spec.ridge_radius, 1.0, 1e-9);
  // A profile of exactly 50 ridge spacings holds 50 ridge tips; this seed's phase puts none within
  // half a spacing of either end (where its peak would be an end point, not counted).
  EXPECT_EQ(s.peaks, ridges);
  EXPECT_NEAR(s.peak_density * spec.ridge_spacing, 1.0, 1e-12);
  // A parabolic ridge z = -h t^2, t uniform in [-1, 1], h = L^2/(8 R): Rq = h sqrt(4/45),
  // Rsk = -2 sqrt(5)/7 = -0.6389, Rku = 15/7. Discretisation: 160 points a ridge (the sums miss the
  // valleys' kinks by ~1/160^2 of each moment, amplified by the cancellation in the central
  // moments) and one ridge position counted twice (the two ends, ~1/8000). Worst over the ridge
  // phase, computed apart: Rq 3.5e-4 relative, Rsk 8.2e-4, Rku 2.2e-3.
  const double h = spec.ridge_spacing * spec.ridge_spacing / (8.0 * spec.ridge_radius);
  EXPECT_NEAR(s.rq / (h * std::sqrt(4.0 / 45.0)), 1.0, 1e-3);
  EXPECT_NEAR(s.rsk, -2.0 * std::sqrt(5.0) / 7.0, 1e-3);
  EXPECT_NEAR(s.rku, 15.0 / 7.0, 2.5e-3);
  // Each peak is a ridge tip, h/3 above the mean line (the mean of -h t^2 is -h/3); the sampled
  // tip lies within half a spacing of the true one, at most 3 (spacing/L)^2 = 1.2e-4 of h/3 below
  // it, and the discrete mean is off by ~1/160^2 = 4e-5: 2e-4.
  EXPECT_NEAR(s.peak_height / (h / 3.0), 1.0, 2e-4);

  // With a random component: the same ridges (the phase is the generator's first draw) plus a
  // profile of mean 0 and Rq exactly rq (round-off).
  GeneratedProfileSpec noisy = spec;
  noisy.rq = 0.05e-6;
  const FlankProfile q = generate_profile(noisy, ridges * spec.ridge_spacing);
  ASSERT_EQ(q.z.size(), p.z.size());
  std::vector<double> random(q.z.size());
  for (std::size_t k = 0; k < q.z.size(); ++k) random[k] = q.z[k] - p.z[k];
  EXPECT_NEAR(mean_of(random), 0.0, 1e-12 * 0.5e-6);
  // Subtracting the 0.5 um ridges again costs ~1e-16 x 0.5 um against 0.05 um: ~1e-15 relative.
  EXPECT_NEAR(profile_statistics(random, q.spacing).rq / noisy.rq, 1.0, 1e-12);
}

TEST(FlankProfile, FromGridTakesTheNearestRowOrColumn) {
  HeightGrid g = make_grid(5, 4, 1e-6, 2e-6);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.at(i, j) = 1e-9 * (i + 10 * j);
  auto expect_line = [&](bool along_x, double at, int line) {
    const FlankProfile p = profile_from_grid(g, along_x, at);
    ASSERT_EQ(p.z.size(), static_cast<std::size_t>(along_x ? g.nx : g.ny)) << along_x << " " << at;
    EXPECT_EQ(p.spacing, along_x ? g.dx : g.dy);
    for (int k = 0; k < static_cast<int>(p.z.size()); ++k)
      EXPECT_EQ(p.z[static_cast<std::size_t>(k)], along_x ? g.at(k, line) : g.at(line, k)) << along_x << " " << at;
  };
  expect_line(true, 0.0, 0);
  expect_line(true, 1.0, 3);
  expect_line(true, 0.4, 1);  // 0.4 x 3 = 1.2: row 1
  expect_line(true, 0.6, 2);  // 1.8: row 2
  expect_line(false, 0.0, 0);
  expect_line(false, 0.5, 2);  // 0.5 x 4 = 2: column 2
  expect_line(false, 1.0, 4);
  g.valid[static_cast<std::size_t>(3) * g.nx + 2] = 0;                    // (2, 3) missing
  EXPECT_THROW(profile_from_grid(g, true, 1.0), std::invalid_argument);   // row 3
  EXPECT_THROW(profile_from_grid(g, false, 0.5), std::invalid_argument);  // column 2
  expect_line(true, 0.0, 0);                                              // other lines still fine
  expect_line(false, 0.25, 1);
  EXPECT_THROW(profile_from_grid(g, true, -0.1), std::invalid_argument);
  EXPECT_THROW(profile_from_grid(g, true, 1.1), std::invalid_argument);
  EXPECT_THROW(profile_from_grid(g, true, std::nan("")), std::invalid_argument);
  const HeightGrid one_row = make_grid(6, 1, 1e-6, 1e-6);
  EXPECT_EQ(profile_from_grid(one_row, true, 0.5).z.size(), 6u);
  EXPECT_THROW(profile_from_grid(one_row, false, 0.5), std::invalid_argument);  // a column of 1 point
}

TEST(FlankProfile, StatisticsOfAHandWorkedProfile) {
  // Heights in um at 1 um spacing; mean -0.7 um. Peaks: index 1 (a plateau 2, 2 then 0: counted
  // once, curvature from its own neighbours 0, 2, 2: 2/um) and index 5 (-1, 3, -2: 9/um); index 8
  // (-4, -3, -4) is a local maximum below the mean line, not a peak. Exact to round-off.
  const std::vector<double> um = {0, 2, 2, 0, -1, 3, -2, -4, -3, -4};
  std::vector<double> z;
  for (double v : um) z.push_back(v * 1e-6);
  const ProfileStatistics s = profile_statistics(z, 1e-6);
  EXPECT_NEAR(s.ra / 2.1e-6, 1.0, 1e-12);
  EXPECT_NEAR(s.m0 / 5.81e-12, 1.0, 1e-12);
  EXPECT_NEAR(s.rq / std::sqrt(5.81e-12), 1.0, 1e-12);
  EXPECT_NEAR(s.rsk / (0.444 / std::pow(5.81, 1.5)), 1.0, 1e-12);
  EXPECT_NEAR(s.rku / (56.2217 / (5.81 * 5.81)), 1.0, 1e-12);
  EXPECT_NEAR(s.m2 / (19.25 / 8.0), 1.0, 1e-12);         // central-difference slopes
  EXPECT_NEAR(s.m4 / (137.0 / 8.0 * 1e12), 1.0, 1e-12);  // second differences / spacing^4
  EXPECT_EQ(s.peaks, 2);
  EXPECT_NEAR(s.summit_radius / (2.0 / 11.0 * 1e-6), 1.0, 1e-12);  // 1 / mean curvature, (2 + 9)/2 per um
  EXPECT_NEAR(s.peak_density / (2.0 / 9e-6), 1.0, 1e-12);          // 2 peaks over 9 um
  EXPECT_NEAR(s.peak_height / 3.2e-6, 1.0, 1e-12);                 // (2.7 + 3.7)/2 um above the mean
  EXPECT_THROW(profile_statistics(std::vector<double>{0.0, 1e-6}, 1e-6), std::invalid_argument);
  EXPECT_THROW(profile_statistics(z, 0.0), std::invalid_argument);
  z[4] = std::nan("");
  EXPECT_THROW(profile_statistics(z, 1e-6), std::invalid_argument);
}

TEST(FlankProfile, KindNames) {
  for (ProfileKind k : {ProfileKind::smooth, ProfileKind::ground, ProfileKind::hobbed})
    EXPECT_EQ(profile_kind(profile_kind_name(k)), k);
  EXPECT_EQ(profile_kind("hobbed"), ProfileKind::hobbed);
  EXPECT_THROW(profile_kind("milled"), std::invalid_argument);
  EXPECT_THROW(profile_kind("Ground"), std::invalid_argument);
}

TEST(FlankProfile, BadSpecsRefused) {
  // Each change breaks one rule; validate() and generate_profile() refuse it, naming the field.
  const std::vector<std::pair<std::string, std::function<void(GeneratedProfileSpec&)>>> bad = {
      {"spacing", [](GeneratedProfileSpec& s) { s.spacing = 0.0; }},
      {"spacing", [](GeneratedProfileSpec& s) { s.spacing = std::nan(""); }},
      {"spacing", [](GeneratedProfileSpec& s) { s.spacing = 2e3; }},
      {"rq", [](GeneratedProfileSpec& s) { s.rq = 0.0; }},  // ground: use smooth for none
      {"rq", [](GeneratedProfileSpec& s) { s.rq = -1e-6; }},
      {"rq", [](GeneratedProfileSpec& s) { s.rq = 2.0; }},
      {"correlation_length", [](GeneratedProfileSpec& s) { s.correlation_length = 1.9 * s.spacing; }},
      {"correlation_length", [](GeneratedProfileSpec& s) { s.correlation_length = std::nan(""); }},
      {"correlation_length", [](GeneratedProfileSpec& s) { s.correlation_length = 1e7 * s.spacing; }},
      {"rq", [](GeneratedProfileSpec& s) { s.kind = ProfileKind::hobbed, s.rq = -1e-9; }},
      {"ridge_spacing",
       [](GeneratedProfileSpec& s) { s.kind = ProfileKind::hobbed, s.ridge_spacing = 3.9 * s.spacing; }},
      {"ridge_radius", [](GeneratedProfileSpec& s) { s.kind = ProfileKind::hobbed, s.ridge_radius = 0.0; }},
      {"ridge_radius",
       [](GeneratedProfileSpec& s) { s.kind = ProfileKind::hobbed, s.ridge_radius = 1e-12; }},  // 200 m deep
      {"kind", [](GeneratedProfileSpec& s) { s.kind = static_cast<ProfileKind>(7); }},
  };
  for (const auto& [field, change] : bad) {
    GeneratedProfileSpec s;
    change(s);
    try {
      s.validate();
      ADD_FAILURE() << field << ": accepted";
    } catch (const geartrib::core::KeyedError& e) {  // the field as its key: the case reader names its key
      EXPECT_EQ(e.key(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << field << ": " << e.what();
    }
    EXPECT_THROW(generate_profile(s, 100e-6), std::invalid_argument) << field;
  }
  // Fields the kind does not use are not checked: a smooth profile ignores rq and lambda.
  GeneratedProfileSpec smooth;
  smooth.kind = ProfileKind::smooth;
  smooth.rq = -1.0, smooth.correlation_length = 0.0;
  EXPECT_NO_THROW(smooth.validate());
  // Lengths: positive, finite, at most kMaxProfilePoints points (refused before allocating).
  const GeneratedProfileSpec good;
  for (double length : {0.0, -1e-6, std::nan(""), std::numeric_limits<double>::infinity(),
                        static_cast<double>(kMaxProfilePoints) * good.spacing})
    EXPECT_THROW(generate_profile(good, length), std::invalid_argument) << length;
}
