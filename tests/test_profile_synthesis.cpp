// Profiles synthesised from a measured patch: the patch's profile spectrum (normalisation exact on
// bin-centred sines, the Nyquist bin half a bin, white noise flat), its interpolation and roll-off,
// the psd synthesis realising the spectrum exactly (no power below the patch's lowest frequency, Rq
// fixed by the spectrum), its statistical agreement with the patch, seeds, IAAFT keeping the height
// distribution exactly and the spectrum within its misfit, and refusals.
#include "surface/profile_synthesis.hpp"

#include "core/fftw_planner.hpp"
#include "surface/flank_profile.hpp"
#include "surface/synthetic_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace geartrib;
using namespace geartrib::surface;

namespace {

constexpr double kPi = std::numbers::pi;

// The one-sided periodogram density of a periodic profile over its whole length (no window):
// G_j = 2 d |X_j|^2 / m, j = 0..m/2 (also at j = m/2, as ProfileSpectrum).
std::vector<double> periodogram(const std::vector<double>& z, double d) {
  const std::size_t m = z.size(), bins = m / 2 + 1;
  const auto real = fftw_real_array(m);
  const auto spectrum = fftw_complex_array(bins);
  const int mi = static_cast<int>(m);
  const FftwPlan plan([&] { return fftw_plan_dft_r2c_1d(mi, real.get(), spectrum.get(), FFTW_ESTIMATE); });
  std::copy(z.begin(), z.end(), real.get());
  fftw_execute(plan.get());
  std::vector<double> g(bins);
  for (std::size_t j = 0; j < bins; ++j)
    g[j] = 2.0 * d * (spectrum[j][0] * spectrum[j][0] + spectrum[j][1] * spectrum[j][1]) / static_cast<double>(m);
  return g;
}

double mean_square(const std::vector<double>& z) {
  double s = 0.0;
  for (double v : z) s += v * v;
  return s / static_cast<double>(z.size());
}

// A grid of `lines` rows, each a function of (line, point).
template <class F>
HeightGrid lines_grid(int n, int lines, double d, F f) {
  HeightGrid g = make_grid(n, lines, d, d);
  for (int l = 0; l < lines; ++l)
    for (int j = 0; j < n; ++j) g.at(j, l) = f(l, j);
  return g;
}

// A profile cut into segments of n points, as the lines of a grid (the patch's estimator applied to a synthesis).
HeightGrid segments_grid(const FlankProfile& p, int n) {
  const int lines = static_cast<int>(p.z.size() / static_cast<std::size_t>(n));
  return lines_grid(n, lines, p.spacing,
                    [&](int l, int j) { return p.z[static_cast<std::size_t>(l) * static_cast<std::size_t>(n) + j]; });
}

// The shipped measured patch's kind (gears/surfaces/README.md): self-affine, roll-off 10 um, short
// cut-off 2.5 um, the lay along x (three times the correlation), 0.25 um spacing; plane removed.
HeightGrid shipped_like_patch(int nx, int ny, std::uint64_t seed) {
  SelfAffineSpec s;
  s.nx = nx, s.ny = ny, s.spacing = 0.25e-6, s.rq = 1e-6, s.rolloff_wavelength = 10e-6, s.cutoff_wavelength = 2.5e-6;
  s.anisotropy = 3.0, s.seed = seed;
  HeightGrid g = self_affine_surface(s);
  remove_form(g, 1);
  return g;
}

}  // namespace

TEST(ProfileSynthesis, SpectrumOfBinCentredSinesIsExact) {
  // A sine at bin k0 (an integer number of periods a line) has variance A^2/2. The periodic Hann
  // window multiplies its transform by (-1/4, 1/2, -1/4) over bins k0 - 1, k0, k0 + 1, so the density is
  // G_k0 = 2 d (A N/4)^2 / (3N/8) = A^2 N d/3 and G_k0+-1 = G_k0/4, nothing elsewhere; sum G df = A^2/2.
  // Each line its own phase: the same spectrum. Round-off only.
  const int n = 64, k0 = 5, lines = 4;
  const double d = 0.5e-6, a = 0.3e-6;
  const HeightGrid g = lines_grid(n, lines, d, [&](int l, int j) {
    return a * std::sin(2.0 * kPi * k0 * j / n + 0.7 * l) + 1e-6 * l;  // each line's own mean, removed
  });
  const ProfileSpectrum s = profile_spectrum(g, true);
  ASSERT_EQ(s.points, 64u);
  ASSERT_EQ(s.lines, 4u);
  ASSERT_EQ(s.psd.size(), 33u);
  EXPECT_EQ(s.spacing, d);
  EXPECT_DOUBLE_EQ(s.frequency_step(), 1.0 / (n * d));
  EXPECT_DOUBLE_EQ(s.highest_frequency(), 32.0 / (n * d));
  const double g0 = a * a * n * d / 3.0;
  EXPECT_NEAR(s.psd[k0] / g0, 1.0, 1e-12);
  EXPECT_NEAR(s.psd[k0 - 1] / g0, 0.25, 1e-12);
  EXPECT_NEAR(s.psd[k0 + 1] / g0, 0.25, 1e-12);
  for (std::size_t k = 0; k < s.psd.size(); ++k)
    if (k + 1 < k0 || k > k0 + 1) {
      EXPECT_LT(s.psd[k], 1e-24 * g0) << k;  // round-off of the transform
    }
  EXPECT_NEAR(s.variance() / (a * a / 2.0), 1.0, 1e-12);
  EXPECT_NEAR(s.rq() / (a / std::sqrt(2.0)), 1.0, 1e-12);  // sum of sin^2 over whole periods: N/2
  ASSERT_EQ(s.heights.size(), 256u);
  EXPECT_TRUE(std::is_sorted(s.heights.begin(), s.heights.end()));

  // The Nyquist bin of an even N covers half a bin: A (-1)^j (variance A^2) puts 2/3 of it there
  // (G_N/2 df/2 = 2 d (A N/2)^2/(3N/8) df/2) and 1/3 in bin N/2 - 1.
  const HeightGrid nyquist = lines_grid(n, 1, d, [&](int, int j) { return j % 2 == 0 ? a : -a; });
  const ProfileSpectrum sn = profile_spectrum(nyquist, true);
  EXPECT_NEAR(sn.variance() / (a * a), 1.0, 1e-12);
  EXPECT_NEAR(sn.psd[32] * sn.frequency_step() / 2.0 / (a * a), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(sn.psd[31] * sn.frequency_step() / (a * a), 1.0 / 3.0, 1e-12);
}

TEST(ProfileSynthesis, SpectrumOfWhiteNoiseIsFlat) {
  // Independent heights of variance sigma^2 at spacing d: G = 2 sigma^2 d at every frequency. The mean
  // of G_k / (2 sigma^2 d) over bins 2..N/2 - 1 of 64 lines: each bin of a line scatters 100%
  // (chi-squared, 2 degrees of freedom), neighbours correlated by the window; over seeds 1-200 this
  // mean's standard deviation was 1.5%. Tolerance: 4 of them.
  const int n = 256, lines = 64;
  const double d = 1e-6, sigma = 0.2e-6;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, sigma);
  const HeightGrid g = lines_grid(n, lines, d, [&](int, int) { return normal(rng); });
  const ProfileSpectrum s = profile_spectrum(g, true);
  double mean = 0.0;
  for (int k = 2; k < n / 2; ++k) mean += s.psd[static_cast<std::size_t>(k)];
  mean /= (n / 2 - 2) * 2.0 * sigma * sigma * d;
  EXPECT_NEAR(mean, 1.0, 0.06);
  // Along y: the grid's columns (256 lines of 64 points).
  const ProfileSpectrum sy = profile_spectrum(g, false);
  EXPECT_EQ(sy.points, 64u);
  EXPECT_EQ(sy.lines, 256u);
  EXPECT_EQ(sy.psd.size(), 33u);
}

TEST(ProfileSynthesis, SpectrumInterpolationAndRollOff) {
  // Bins of a power law G = c f^-3 on bins 1..6 and a zero bin 7, 8: at() returns each bin's value, the
  // power law between them (linear in log-log), zero below f_1 and above the last bin, linear in G
  // next to a zero bin; resolved_variance() the power law's integral c (f_1^-2 - f_6^-2)/2 plus the
  // linear piece's G_6 df/2.
  ProfileSpectrum s;
  s.spacing = 1e-6;
  s.points = 16;  // bins 0..8, df = 1/(16 um)
  const double df = s.frequency_step(), c = 1e-20;
  s.psd.assign(9, 0.0);
  for (int k = 1; k <= 6; ++k) s.psd[static_cast<std::size_t>(k)] = c * std::pow(k * df, -3.0);
  s.heights = {-1e-6, 0.0, 1e-6};  // rq = sqrt(2/3) um
  for (int k = 1; k <= 8; ++k) EXPECT_EQ(s.at(k * df), s.psd[static_cast<std::size_t>(k)]) << k;
  for (double f : {1.3 * df, 2.5 * df, 5.99 * df}) EXPECT_NEAR(s.at(f) / (c * std::pow(f, -3.0)), 1.0, 1e-12) << f / df;
  EXPECT_EQ(s.at(0.0), 0.0);
  EXPECT_EQ(s.at(0.999 * df), 0.0);                              // wavelengths longer than the line: none
  EXPECT_EQ(s.at(8.001 * df), 0.0);                              // beyond the last bin: none
  EXPECT_NEAR(s.at(6.25 * df) / (0.75 * s.psd[6]), 1.0, 1e-12);  // linear toward the zero bin 7
  EXPECT_EQ(s.at(7.5 * df), 0.0);
  const double integral = c * (std::pow(df, -2.0) - std::pow(6.0 * df, -2.0)) / 2.0 + s.psd[6] * df / 2.0;
  EXPECT_NEAR(s.resolved_variance() / integral, 1.0, 1e-12);
  EXPECT_NEAR(s.rolled_off_fraction(), 1.0 - integral / (2e-12 / 3.0), 1e-12);
  // A G ~ 1/f segment (the closed form's p = -1 limit: g_k f_k ln(f_k+1/f_k)).
  ProfileSpectrum h = s;
  h.psd.assign(3, 0.0);
  h.points = 4;  // bins 0..2
  const double dh = h.frequency_step();
  h.psd[1] = 1e-18 / dh, h.psd[2] = 1e-18 / (2.0 * dh);
  EXPECT_NEAR(h.resolved_variance() / (1e-18 * std::log(2.0)), 1.0, 1e-12);
}

TEST(ProfileSynthesis, PsdSynthesisRealisesTheSpectrumExactly) {
  // Fixed amplitudes sqrt(2 G(f_j) df) at random phases: the profile's periodogram over its whole
  // (periodic) length is G(f_j) at every frequency, zero below the patch's f_1, and its variance the
  // sum of G(f_j) df, whatever the seed. Round-off: ~1e-16 of the largest amplitude in each.
  const HeightGrid patch = shipped_like_patch(256, 64, 1);
  const ProfileSpectrum s = profile_spectrum(patch, true);
  SynthesisOptions o;
  o.seed = 3;
  const SynthesisedProfile p = synthesise_profile(s, o, 10e-3);  // 10 mm: ~160 patch lengths
  const std::size_t m = p.profile.z.size();
  ASSERT_EQ(m, fast_fft_size(40001));  // ceil(10 mm / 0.25 um) + 1 points, to an FFT-friendly count
  EXPECT_EQ(p.profile.spacing, s.spacing);
  EXPECT_GE(p.profile.length(), 10e-3);
  EXPECT_EQ(p.iterations, 0);
  const std::vector<double> g = periodogram(p.profile.z, p.profile.spacing);
  const double df = 1.0 / (static_cast<double>(m) * p.profile.spacing);
  const double g_max = *std::max_element(s.psd.begin(), s.psd.end());
  double variance = 0.0, below = 0.0;
  for (std::size_t j = 1; j < g.size(); ++j) {
    const double f = static_cast<double>(j) * df, want = s.at(f);
    EXPECT_NEAR(g[j], want, 1e-9 * g_max) << j;
    variance += (j == m / 2 && m % 2 == 0 ? 0.5 : 1.0) * want * df;
    if (f < s.frequency_step()) below += g[j] * df;
  }
  EXPECT_LT(g[0], 1e-20 * g_max);      // mean zero
  EXPECT_LT(below, 1e-20 * variance);  // nothing longer than the patch's line
  EXPECT_NEAR(mean_square(p.profile.z) / variance, 1.0, 1e-12);
  // Its Rq: the patch's less the rolled-off variance, up to the synthesis's sampling of at(): a Riemann
  // sum of resolved_variance() at step df, within df (V + 2 max G), V the total variation of at() (each
  // interval between bins monotone: sum |G_k+1 - G_k|), 2 max G for the partial intervals at the ends.
  double total_variation = 0.0;
  for (std::size_t k = 1; k + 1 < s.psd.size(); ++k) total_variation += std::abs(s.psd[k + 1] - s.psd[k]);
  const double riemann = df * (total_variation + 2.0 * g_max);
  const double rq2 = s.rq() * s.rq();
  EXPECT_NEAR(variance, s.resolved_variance(), riemann);
  EXPECT_LT(riemann, 0.01 * rq2);  // a bound that binds
  EXPECT_NEAR(mean_square(p.profile.z) / rq2, 1.0 - s.rolled_off_fraction(), riemann / rq2);
}

TEST(ProfileSynthesis, NothingRolledOffFromAPatchWithinItsBand) {
  // Lines holding no variance at wavelengths beyond their length (periodic, random phases, power
  // only in bins 4 to 32 of 256, flat): the synthesis leaves out little. The window spreads a sixth of
  // the edge bins' power to bins 3 and 33, whose outer halves the log-log interpolation toward the
  // empty bins beyond all but drops (~0.6% of the variance); each line's windowed mean square differs
  // from its mean square (the window weighs its middle). Over 256 lines and seeds 1-100 the rolled-off
  // fraction's mean was 1.0% and its standard deviation 1.0%. Tolerance 5%: the bias and 4 of those.
  const int n = 256, lines = 256;
  const double d = 0.25e-6;
  std::mt19937_64 rng(3);
  std::vector<double> phase(static_cast<std::size_t>(lines) * 33);
  for (double& v : phase) v = 2.0 * kPi * std::generate_canonical<double, 53>(rng);
  const HeightGrid g = lines_grid(n, lines, d, [&](int l, int j) {
    double z = 0.0;
    for (int k = 4; k <= 32; ++k)
      z += 1e-7 * std::cos(2.0 * kPi * k * j / n + phase[static_cast<std::size_t>(l) * 33 + k]);
    return z;
  });
  const ProfileSpectrum s = profile_spectrum(g, true);
  EXPECT_NEAR(s.rq(), 1e-7 * std::sqrt(29.0 / 2.0), 1e-12 * 1e-7);  // 29 cosines of amplitude 0.1 um
  EXPECT_NEAR(s.rolled_off_fraction(), 0.0, 0.05);
  // Against a patch of the shipped kind, whose spectrum is flat out to wavelengths near its length: 11%
  // of its variance lies there (the shipped pinion patch: 27%).
  EXPECT_GT(profile_spectrum(shipped_like_patch(384, 96, 1), true).rolled_off_fraction(), 0.1);
}

TEST(ProfileSynthesis, SeedsAreRepeatableAndIndependent) {
  const ProfileSpectrum s = profile_spectrum(shipped_like_patch(128, 32, 2), true);
  SynthesisOptions o;
  o.seed = 11;
  const SynthesisedProfile a = synthesise_profile(s, o, 2e-3), b = synthesise_profile(s, o, 2e-3);
  EXPECT_EQ(a.profile.z, b.profile.z);  // bit for bit
  o.seed = 12;
  const SynthesisedProfile c = synthesise_profile(s, o, 2e-3);
  ASSERT_EQ(c.profile.z.size(), a.profile.z.size());
  // The same amplitudes a_j at independent phases: the difference's mean square over 2 Rq^2 is
  // sum a_j^2 (1 - cos dphi_j) / sum a_j^2, of mean 1 and standard deviation sqrt(sum a^4 / 2)/sum a^2
  // (cos of a uniform phase: variance 1/2). Tolerance: 4 of them.
  std::vector<double> diff(a.profile.z.size());
  for (std::size_t k = 0; k < diff.size(); ++k) diff[k] = a.profile.z[k] - c.profile.z[k];
  const double df = 1.0 / (static_cast<double>(diff.size()) * s.spacing);
  double sum2 = 0.0, sum4 = 0.0;
  for (std::size_t j = 1; j <= diff.size() / 2; ++j) {
    const double g = s.at(static_cast<double>(j) * df);
    sum2 += g, sum4 += g * g;
  }
  const double sd = std::sqrt(sum4 / 2.0) / sum2;
  EXPECT_LT(sd, 0.1);  // enough modes for the test to mean something
  EXPECT_NEAR(mean_square(diff) / (2.0 * mean_square(a.profile.z)), 1.0, 4.0 * sd);
}

TEST(ProfileSynthesis, SpectrumAgreesWithThePatchStatistically) {
  // The patch's estimator applied to syntheses (each cut into 512 lines of the patch's length) against
  // the patch's spectrum, in octave bands over the resolved band: bin 2 (bin 1 of a synthesis lacks the
  // band below f_1) to the last bin above 1e-4 of the peak (beyond it the estimate is the window's
  // leakage, not the surface's). Over seeds 1-100 the band ratios' means were 0.980-1.008 (the window's
  // smoothing applied twice, at the spectrum's knee: -2% in bins 4-7) and their standard deviations
  // 0.9-2.8% for one seed; the mean of 8 seeds: 0.3-1.0%. Tolerance 5%: the bias and 3 of those.
  const int n = 256;
  SelfAffineSpec sa;  // isotropic: a broad band (roll-off 8 um, cut-off 1 um on a 64 um line)
  sa.nx = n, sa.ny = 128, sa.spacing = 0.25e-6, sa.rq = 0.5e-6, sa.rolloff_wavelength = 8e-6;
  sa.cutoff_wavelength = 1e-6, sa.seed = 4;
  HeightGrid patch = self_affine_surface(sa);
  remove_form(patch, 1);
  const ProfileSpectrum s = profile_spectrum(patch, true);
  const double peak = *std::max_element(s.psd.begin(), s.psd.end());
  std::size_t last = 2;
  while (last + 1 < s.psd.size() && s.psd[last + 1] > 1e-4 * peak) ++last;
  ASSERT_EQ(last, 63u);  // five octaves: 2-3, 4-7, 8-15, 16-31, 32-63 (wavelengths 32 um to 1 um)
  std::vector<double> mean(s.psd.size(), 0.0);
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    SynthesisOptions o;
    o.seed = static_cast<std::uint64_t>(seed);
    const SynthesisedProfile p = synthesise_profile(s, o, 512 * n * sa.spacing);
    const ProfileSpectrum r = profile_spectrum(segments_grid(p.profile, n), true);
    ASSERT_EQ(r.lines, 512u);
    for (std::size_t k = 0; k < r.psd.size(); ++k) mean[k] += r.psd[k] / seeds;
  }
  for (std::size_t lo = 2; lo <= last; lo *= 2) {
    double a = 0.0, b = 0.0;
    for (std::size_t k = lo; k < std::min(2 * lo, last + 1); ++k) a += s.psd[k], b += mean[k];
    EXPECT_NEAR(b / a, 1.0, 0.05) << "bins " << lo << " to " << 2 * lo - 1;
  }
}

TEST(ProfileSynthesis, IaaftKeepsTheHeightDistributionExactly) {
  // A skewed patch (the exponential of a self-affine surface with power down to 1 um wavelengths: Rsk
  // 1.6) of M = 64 lines x 256 = 16384 heights, synthesised at m = M points: the IAAFT profile's sorted
  // heights are the patch's times c exactly (a permutation of them), c^2 the psd profile's variance over
  // the patch's Rq^2; Rsk and Rku, scale-free, the patch's (round-off). The psd profile of the same seed,
  // a sum of ~8000 random-phase cosines, is nearly Gaussian.
  SelfAffineSpec sa;
  sa.nx = 256, sa.ny = 64, sa.spacing = 0.25e-6, sa.rq = 0.5e-6, sa.rolloff_wavelength = 8e-6;
  sa.cutoff_wavelength = 1e-6, sa.seed = 6;
  HeightGrid patch = self_affine_surface(sa);
  remove_form(patch, 1);
  for (double& v : patch.z) v = 1e-6 * std::exp(v / 1e-6);
  const ProfileSpectrum s = profile_spectrum(patch, true);
  ASSERT_EQ(s.heights.size(), 16384u);
  SynthesisOptions o;
  o.seed = 9;
  const SynthesisedProfile psd = synthesise_profile(s, o, 16383 * s.spacing);
  o.method = SynthesisMethod::iaaft;
  const SynthesisedProfile p = synthesise_profile(s, o, 16383 * s.spacing);
  ASSERT_EQ(p.profile.z.size(), 16384u);
  EXPECT_TRUE(p.converged);
  EXPECT_LE(p.spectrum_misfit, kIaaftMisfit);
  EXPECT_NEAR(p.curvature_ratio, 1.0, kIaaftCurvature);
  EXPECT_GE(p.iterations, 1);
  EXPECT_NEAR(p.height_scale * p.height_scale * s.rq() * s.rq() / mean_square(psd.profile.z), 1.0, 1e-12);
  std::vector<double> sorted = p.profile.z;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], p.height_scale * s.heights[i]) << i;
  const ProfileStatistics patch_stats = profile_statistics(s.heights, s.spacing);  // order does not matter
  const ProfileStatistics iaaft_stats = profile_statistics(p.profile.z, p.profile.spacing);
  const ProfileStatistics psd_stats = profile_statistics(psd.profile.z, psd.profile.spacing);
  ASSERT_GT(patch_stats.rsk, 1.0);
  EXPECT_NEAR(iaaft_stats.rsk / patch_stats.rsk, 1.0, 1e-9);
  EXPECT_NEAR(iaaft_stats.rku / patch_stats.rku, 1.0, 1e-9);
  EXPECT_NEAR(iaaft_stats.rq / psd_stats.rq, 1.0, 1e-9);
  // The psd profile's Rsk scatters about 0 by ~sqrt(6/400) = 0.12 (~400 correlation lengths of ~40
  // points): within 0.4 of it, far from the patch's.
  EXPECT_LT(std::abs(psd_stats.rsk), 0.4);
  // The spectrum within the misfit: for a band B of the amplitudes A_j (|Z_j| the profile's),
  // |sum_B |Z|^2 - sum_B A^2| <= mu |A| (2 |A_B| + mu |A|) (Cauchy-Schwarz; mu the rms misfit over |A|).
  const std::vector<double> g = periodogram(p.profile.z, p.profile.spacing);
  const double df = 1.0 / (16384.0 * s.spacing);
  double total = 0.0, m4 = 0.0, m4_spectrum = 0.0;
  for (std::size_t j = 1; j < g.size(); ++j) {
    const double w = std::pow(2.0 * kPi * static_cast<double>(j) * df, 4);
    total += s.at(static_cast<double>(j) * df);
    m4 += w * g[j], m4_spectrum += w * s.at(static_cast<double>(j) * df);
  }
  EXPECT_NEAR(m4 / m4_spectrum, p.curvature_ratio, 1e-9);  // the reported curvature, from the profile
  for (std::size_t lo = 1; lo < g.size(); lo *= 2) {
    double want = 0.0, got = 0.0;
    for (std::size_t j = lo; j < std::min(2 * lo, g.size()); ++j)
      want += s.at(static_cast<double>(j) * df), got += g[j];
    if (!(want > 0.0)) continue;
    const double rho = std::sqrt(total / want), mu = p.spectrum_misfit;
    EXPECT_LE(std::abs(got / want - 1.0), mu * rho * (2.0 + mu * rho)) << "bins " << lo << " to " << 2 * lo - 1;
  }
  EXPECT_EQ(synthesise_profile(s, o, 16383 * s.spacing).profile.z, p.profile.z);  // repeatable
  // Stopped early: not converged, the distribution exact all the same.
  o.max_iterations = 2;
  const SynthesisedProfile early = synthesise_profile(s, o, 16383 * s.spacing);
  EXPECT_FALSE(early.converged);
  EXPECT_EQ(early.iterations, 2);
  EXPECT_TRUE(early.spectrum_misfit > kIaaftMisfit || std::abs(early.curvature_ratio - 1.0) > kIaaftCurvature);
  sorted = early.profile.z;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], early.height_scale * s.heights[i]) << i;
  o.max_iterations = kIaaftIterations;
  // At another count (m = 24000 > M): the patch's quantiles, linear between its sorted heights; Rsk and
  // Rku within that interpolation's smoothing of the tails.
  const SynthesisedProfile q = synthesise_profile(s, o, 23999 * s.spacing);
  ASSERT_EQ(q.profile.z.size(), 24000u);
  const ProfileStatistics q_stats = profile_statistics(q.profile.z, q.profile.spacing);
  // Computed: -0.9e-5 (Rsk), -4.4e-5 (Rku) relative: the tails smoothed, of order 1/M.
  EXPECT_NEAR(q_stats.rsk / patch_stats.rsk, 1.0, 1e-4);
  EXPECT_NEAR(q_stats.rku / patch_stats.rku, 1.0, 1e-4);
  o.method = SynthesisMethod::psd;
  const SynthesisedProfile q_psd = synthesise_profile(s, o, 23999 * s.spacing);
  EXPECT_NEAR(q_stats.rq / profile_statistics(q_psd.profile.z, s.spacing).rq, 1.0, 1e-4);
}

TEST(ProfileSynthesis, MethodNamesAndRefusals) {
  for (SynthesisMethod m : {SynthesisMethod::none, SynthesisMethod::psd, SynthesisMethod::iaaft})
    EXPECT_EQ(synthesis_method(synthesis_method_name(m)), m);
  EXPECT_THROW(synthesis_method("fft"), std::invalid_argument);
  const HeightGrid patch = shipped_like_patch(64, 16, 1);
  const ProfileSpectrum s = profile_spectrum(patch, true);
  SynthesisOptions o;
  // A coarser spacing: the spectrum up to its Nyquist frequency, no finer.
  o.spacing = 2.0 * s.spacing;
  const SynthesisedProfile coarse = synthesise_profile(s, o, 1e-3);
  EXPECT_EQ(coarse.profile.spacing, 2.0 * s.spacing);
  const std::vector<double> g = periodogram(coarse.profile.z, coarse.profile.spacing);
  const double df = 1.0 / (static_cast<double>(coarse.profile.z.size()) * coarse.profile.spacing);
  const double g_max = *std::max_element(s.psd.begin(), s.psd.end());
  for (std::size_t j = 1; j < g.size(); ++j) EXPECT_NEAR(g[j], s.at(static_cast<double>(j) * df), 1e-9 * g_max);
  // Refused: a finer spacing (nothing measured there), no method, a bad length, too many points, an
  // empty spectrum.
  o.spacing = 0.5 * s.spacing;
  EXPECT_THROW(synthesise_profile(s, o, 1e-3), std::invalid_argument);
  o.spacing = 0.0;
  o.method = SynthesisMethod::none;
  EXPECT_THROW(synthesise_profile(s, o, 1e-3), std::invalid_argument);
  o.method = SynthesisMethod::iaaft;
  o.max_iterations = 0;
  EXPECT_THROW(synthesise_profile(s, o, 1e-3), std::invalid_argument);
  o.max_iterations = kIaaftIterations;
  for (double length : {0.0, -1e-3, std::nan(""), std::numeric_limits<double>::infinity(),
                        static_cast<double>(kMaxProfilePoints) * s.spacing})
    EXPECT_THROW(synthesise_profile(s, o, length), std::invalid_argument) << length;
  EXPECT_THROW(synthesise_profile(ProfileSpectrum{}, o, 1e-3), std::invalid_argument);
  // The patch: lines of at least 8 points, at least one complete.
  EXPECT_THROW(profile_spectrum(make_grid(7, 4, 1e-6, 1e-6), true), std::invalid_argument);
  EXPECT_NO_THROW(profile_spectrum(make_grid(8, 4, 1e-6, 1e-6), true));
  HeightGrid holes = patch;
  for (int l = 0; l < holes.ny; ++l) holes.valid[static_cast<std::size_t>(l) * holes.nx + 3] = 0;
  EXPECT_THROW(profile_spectrum(holes, true), std::invalid_argument);
  holes.valid[3] = 1;  // line 0 complete: the others are left out
  EXPECT_EQ(profile_spectrum(holes, true).lines, 1u);
  EXPECT_EQ(profile_spectrum(holes, true).heights.size(), 64u);
}
