// A flank-sized map from a measured patch (surface/areal_synthesis.hpp): the patch's areal spectrum
// against Parseval and the Hann window's exact leakage, the synthesis's fixed amplitudes against the
// spectrum it was given, the lay kept, tiling by mirror images; its radial average (Persson's isotropic
// spectrum) against the areal spectrum's variance and gradient and against a Gaussian surface's own;
// and the generated ground (a lay) and superfinished (a plateau) surfaces of surface/synthetic_surface.hpp.
#include "contact/persson_contact.hpp"
#include "core/fftw_planner.hpp"
#include "surface/areal_synthesis.hpp"
#include "surface/synthetic_surface.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

using namespace geartrib;

namespace {
constexpr double kPi = std::numbers::pi;

double mean_square(const std::vector<double>& z) {
  double s = 0.0;
  for (double v : z) s += v * v;
  return s / static_cast<double>(z.size());
}

// The mean square slope along x (or y, cyclic) by forward differences [1].
double slope_variance(const surface::HeightGrid& g, bool along_x) {
  double s = 0.0;
  std::size_t n = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (along_x && i + 1 >= g.nx) continue;
      const double d = along_x ? (g.at(i + 1, j) - g.at(i, j)) / g.dx : (g.at(i, (j + 1) % g.ny) - g.at(i, j)) / g.dy;
      s += d * d, ++n;
    }
  return s / static_cast<double>(n);
}
// A self-affine surface of n x n points at 0.5 um with a lay along x (correlation 3 x longer along it),
// Rq 0.3 um, roll-off 20 um, cut-off 2 um.
surface::SelfAffineSpec lay_along_x(int n) {
  surface::SelfAffineSpec p;
  p.nx = p.ny = n;
  p.spacing = 0.5e-6;
  p.rq = 0.3e-6;
  p.rolloff_wavelength = 20e-6;
  p.cutoff_wavelength = 2e-6;
  p.anisotropy = 3.0;
  p.seed = 4;
  return p;
}
}  // namespace

TEST(ArealSpectrum, ParsevalAndADctBasisFunctionsSingleBin) {
  // z = a cos(pi k (i + 1/2)/n), a DCT-II basis function: its mirror extension to 2n points is the pure
  // cosine of k periods over 2n, so the spectrum holds it in one bin, (k, 0) and its mirror, with no
  // leakage: m2x/m0 = (pi k/L)^2, RSm along x = 2 L/k exactly, and none along y (constant there).
  const int n = 64, k = 8;
  const double d = 0.5e-6, a = 0.2e-6, length = n * d;
  surface::HeightGrid g = surface::make_grid(n, 32, d, d);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < n; ++i) g.at(i, j) = a * std::cos(kPi * k * (i + 0.5) / n);
  const surface::ArealSpectrum s = surface::areal_spectrum(g);
  EXPECT_NEAR(s.patch_rq, a / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(s.variance(), a * a / 2.0, 1e-12 * a * a);  // Parseval
  EXPECT_NEAR(s.length_x(), length, 1e-18);
  EXPECT_NEAR(s.element_spacing(true), 2.0 * length / k, 1e-9 * length);
  EXPECT_TRUE(std::isinf(s.element_spacing(false)));
  // At its bin, (a^2/4)/(dfx dfy) each of the pair; half a bin off, half of it (bilinear); beyond
  // Nyquist and inside one period across the patch, zero; C(-f) = C(f).
  const double dfx = 1.0 / (2.0 * length), dfy = 1.0 / (2.0 * g.ny * d);
  EXPECT_NEAR(s.at(k * dfx, 0.0), a * a / 4.0 / (dfx * dfy), 1e-9 * a * a / (dfx * dfy));
  EXPECT_NEAR(s.at((k + 0.5) * dfx, 0.0), 0.5 * s.at(k * dfx, 0.0), 1e-9 * s.at(k * dfx, 0.0));
  EXPECT_EQ(s.at(k * dfx, 0.5 * dfy), 0.5 * s.at(k * dfx, 0.0));
  EXPECT_EQ(s.at(0.6 / d, 0.0), 0.0);
  EXPECT_EQ(s.at(0.9 / length, 0.0), 0.0);
  EXPECT_EQ(s.at(-k * dfx, 0.0), s.at(k * dfx, 0.0));
  // Refused: a missing point, too few points.
  g.valid[5] = 0;
  EXPECT_THROW(surface::areal_spectrum(g), std::invalid_argument);
  EXPECT_THROW(surface::areal_spectrum(surface::make_grid(6, 32, d, d)), std::invalid_argument);
}

TEST(ArealSpectrum, AMeasuredCutOfAKnownSurfaceKeepsItsSlopesAndVariance) {
  // 128^2 cuts (not periodic: a patch as measured) of a periodic self-affine surface of 1024^2 at
  // 0.5 um with a lay along x (correlation 3 x longer along it; roll-off 20 um, cut-off 2 um): the
  // spectrum's slope variances each way within 15 % of the parent's (finite differences over the
  // whole surface), and the share of variance it resolves within 10 % of the parent's share at the
  // wavelengths the cut holds, at three places (a cut holds about three roll-off lengths each way).
  const surface::SelfAffineSpec p = lay_along_x(1024);
  const surface::HeightGrid parent = surface::self_affine_surface(p);
  const double along = slope_variance(parent, true), across = slope_variance(parent, false);
  ASSERT_GT(across / along, 5.0);  // a lay to keep
  // The parent's variance at the waves a 64 um cut holds (one period or more across it), from its
  // exact periodogram (it is periodic: no window), by Parseval over those bins.
  const int n = p.nx, kx = n / 2 + 1;
  const auto real = fftw_real_array(parent.size());
  const auto spectrum = fftw_complex_array(static_cast<std::size_t>(n) * kx);
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_2d(n, n, real.get(), spectrum.get(), FFTW_ESTIMATE); });
  std::copy(parent.z.begin(), parent.z.end(), real.get());
  fftw_execute(forward.get());
  double held = 0.0;
  const double cut_side = 128 * p.spacing, side = n * p.spacing;
  for (int l = 0; l < n; ++l)
    for (int i = 0; i < kx; ++i) {
      const double fx = i / side, fy = (l <= n / 2 ? l : l - n) / side;
      if (std::pow(fx * cut_side, 2) + std::pow(fy * cut_side, 2) < 1.0) continue;
      const fftw_complex& c = spectrum[static_cast<std::size_t>(l) * kx + i];
      held += ((i == 0 || i == n / 2) ? 1.0 : 2.0) * (c[0] * c[0] + c[1] * c[1]);
    }
  held /= std::pow(static_cast<double>(parent.size()), 2);
  ASSERT_LT(held, 0.9 * p.rq * p.rq);  // the cut misses a share: the comparison below is not with Rq^2
  for (int offset : {0, 300, 600}) {
    surface::HeightGrid cut = surface::make_grid(128, 128, p.spacing, p.spacing);
    for (int j = 0; j < 128; ++j)
      for (int i = 0; i < 128; ++i) cut.at(i, j) = parent.at(i + offset, j + offset / 2);
    const surface::ArealSpectrum s = surface::areal_spectrum(cut);
    // The spectral slopes are the continuous (2 pi f)^2 C; finite differences see (2 sin(pi f d)/d)^2:
    // compared on a synthesis at the same spacing, which both carry.
    const surface::SynthesisedSurface m = surface::synthesise_surface(s, 1024, 512, p.spacing, p.spacing, 7);
    EXPECT_NEAR(slope_variance(m.grid, true) / along, 1.0, 0.15) << offset;
    EXPECT_NEAR(slope_variance(m.grid, false) / across, 1.0, 0.15) << offset;
    // The share of the cut's own variance the synthesis keeps against the parent's share at those
    // waves: the cut's variance itself scatters by 5-20 % about the parent's (a random sample), which
    // the share divides out. Within 10 % (measured 1-6 %).
    EXPECT_NEAR(m.resolved_fraction / (held / (p.rq * p.rq)), 1.0, 0.10) << offset;
  }
}

TEST(ArealSynthesis, FixedAmplitudesGiveTheSpectrumsVarianceAndKeepTheLay) {
  // A self-affine patch with a lay along x (correlation 3 x longer along it), 128^2 at 0.5 um,
  // synthesised onto a map 4 x longer along x and 2 x across.
  const surface::SelfAffineSpec p = lay_along_x(128);
  const surface::HeightGrid patch = surface::self_affine_surface(p);
  const surface::ArealSpectrum s = surface::areal_spectrum(patch);
  const int nx = 512, ny = 256;
  const double dx = 0.5e-6, dy = 0.5e-6;
  const surface::SynthesisedSurface a = surface::synthesise_surface(s, nx, ny, dx, dy, 7);
  // Identity: the map's mean square is sum C(f) dfx dfy over its wavevectors (the amplitudes fixed),
  // summed here over the whole plane from at() directly.
  double expected = 0.0;
  for (int l = -ny / 2 + 1; l <= ny / 2; ++l)
    for (int i = -nx / 2 + 1; i <= nx / 2; ++i) expected += s.at(i / (nx * dx), l / (ny * dy));
  expected /= nx * dx * ny * dy;
  EXPECT_NEAR(mean_square(a.grid.z), expected, 1e-10 * expected);
  EXPECT_NEAR(a.resolved_fraction, expected / (s.patch_rq * s.patch_rq), 1e-12);
  // What it leaves out lies at wavelengths longer than the patch: a share, not most.
  EXPECT_GT(a.resolved_fraction, 0.6);
  EXPECT_LT(a.resolved_fraction, 1.0);
  // The lay kept: the slope variance across the lay over that along it, the patch's own within 10 %
  // (both carry sampling scatter: the patch ~100 correlation areas across the lay's short axis).
  const double patch_ratio = slope_variance(patch, false) / slope_variance(patch, true);
  const double map_ratio = slope_variance(a.grid, false) / slope_variance(a.grid, true);
  EXPECT_GT(patch_ratio, 3.0);  // the lay is there to keep
  EXPECT_NEAR(map_ratio / patch_ratio, 1.0, 0.1);
  // The same seed the same map; another seed another.
  const surface::SynthesisedSurface b = surface::synthesise_surface(s, nx, ny, dx, dy, 7);
  const surface::SynthesisedSurface c = surface::synthesise_surface(s, nx, ny, dx, dy, 8);
  EXPECT_EQ(a.grid.z, b.grid.z);
  EXPECT_NE(a.grid.z, c.grid.z);
  EXPECT_NEAR(mean_square(c.grid.z), expected, 1e-10 * expected);  // whatever the seed
  // Refused: finer than the patch's spacing.
  EXPECT_THROW(surface::synthesise_surface(s, nx, ny, 0.25e-6, dy, 7), std::invalid_argument);
}

TEST(ArealSynthesis, TilingByMirrorImagesIsContinuousAndPeriodicInTwoSides) {
  surface::SelfAffineSpec p;
  p.nx = p.ny = 32;
  p.spacing = 1e-6;
  p.rolloff_wavelength = 10e-6;
  p.cutoff_wavelength = 4e-6;
  const surface::HeightGrid patch = surface::self_affine_surface(p);
  const surface::HeightGrid t = surface::tile_surface(patch, 200, 100, 1e-6, 1e-6);
  double mean = 0.0;
  for (double z : patch.z) mean += z;
  mean /= static_cast<double>(patch.size());
  for (int j = 0; j < 31; ++j)
    for (int i = 0; i < 31; ++i) {
      EXPECT_NEAR(t.at(i, j), patch.at(i, j) - mean, 1e-18);  // the patch itself
      EXPECT_NEAR(t.at(62 - i, j), t.at(i, j), 1e-18);        // mirrored at x = L
      EXPECT_NEAR(t.at(i + 62, j + 62), t.at(i, j), 1e-18);   // period 2 L each way
    }
  surface::HeightGrid holed = patch;
  holed.valid[3] = 0;
  EXPECT_THROW(surface::tile_surface(holed, 10, 10, 1e-6, 1e-6), std::invalid_argument);
}

TEST(GeneratedSurfaces, GroundLayAndIsotropicIdentity) {
  // A lay along y: lambda_y = 4 lambda_x; along each axis the autocorrelation at its own lambda is e^-1.
  // 512 x 512, lambda_x 8 points, lambda_y 32: ~1000 correlation areas, scatter ~0.04.
  surface::GaussianSurfaceSpec s;
  s.nx = s.ny = 512;
  s.dx = s.dy = 1e-6;
  s.correlation_length = 8e-6;
  s.correlation_length_y = 32e-6;
  s.seed = 3;
  const surface::HeightGrid g = surface::gaussian_surface(s);
  auto acf = [&](int k, bool along_x) { return test::autocorrelation(g, k, along_x); };
  EXPECT_NEAR(acf(8, true), std::exp(-1.0), 0.05);
  EXPECT_NEAR(acf(32, false), std::exp(-1.0), 0.08);  // fewer correlation lengths along y: more scatter
  EXPECT_NEAR(acf(8, false), std::exp(-1.0 / 16.0), 0.03);
  // lambda_y = lambda_x is the isotropic surface, bit for bit.
  surface::GaussianSurfaceSpec iso = s, same = s;
  iso.correlation_length_y = 0.0;
  same.correlation_length_y = s.correlation_length;
  EXPECT_EQ(surface::gaussian_surface(iso).z, surface::gaussian_surface(same).z);
}

TEST(GeneratedSurfaces, SuperfinishedPlateauCutsThePeaks) {
  // Without the fine texture: the area at the cut's height is the plateau fraction (to one point in
  // the order statistic), nothing above it, and the cut skews the heights negative (valleys left).
  surface::SuperfinishedSpec f;
  f.ground.nx = f.ground.ny = 128;
  f.ground.dx = f.ground.dy = 1e-6;
  f.ground.correlation_length = 8e-6;
  f.ground.correlation_length_y = 64e-6;
  f.plateau = 0.7;
  f.fine_rq = 0.0;
  const surface::HeightGrid g = surface::superfinished_surface(f);
  const double top = *std::max_element(g.z.begin(), g.z.end());
  const auto at_top = std::count_if(g.z.begin(), g.z.end(), [&](double z) { return z >= top - 1e-18; });
  EXPECT_NEAR(static_cast<double>(at_top) / static_cast<double>(g.size()), 0.7, 2.0 / static_cast<double>(g.size()));
  double m2 = 0.0, m3 = 0.0;
  for (double z : g.z) m2 += z * z, m3 += z * z * z;
  EXPECT_LT(m3 / static_cast<double>(g.size()) / std::pow(m2 / static_cast<double>(g.size()), 1.5), -1.0);
  f.plateau = 1.0;
  EXPECT_THROW(surface::superfinished_surface(f), std::invalid_argument);
}

TEST(RadialSpectrum, KeepsThePatchsVarianceAndFullGradient) {
  // A cut of a self-affine surface with a lay (3:1) taken at spacings 0.5 um along x and 0.375 um along y
  // (two bin spacings: the rings' widths follow the coarser): the isotropic nodes, as Persson's tabulated
  // part takes them, hold the patch's variance and its full gradient variance m2x + m2y to rounding (the
  // final scaling makes them so: 1e-12). The scaling itself within 1 % of 1: before it the rings carry
  // each their variance exactly and the gradient to the place of their power inside them (measured 0.03 %).
  const surface::HeightGrid parent = surface::self_affine_surface(lay_along_x(256));
  surface::HeightGrid cut = surface::make_grid(192, 160, 0.5e-6, 0.375e-6);
  for (int j = 0; j < cut.ny; ++j)
    for (int i = 0; i < cut.nx; ++i) cut.at(i, j) = parent.at(i + 40, j + 70);
  const surface::ArealSpectrum s = surface::areal_spectrum(cut);
  const surface::RadialSpectrum r = surface::radial_spectrum(s);
  const contact::SpectrumPart t = contact::SpectrumPart::tabulated(r.q, r.c);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(2.0 * kPi * t.moment(1, inf) / s.variance(), 1.0, 1e-12);
  EXPECT_NEAR(2.0 * kPi * t.moment(3, inf) / (s.slope_variance(true) + s.slope_variance(false)), 1.0, 1e-12);
  EXPECT_NEAR(r.scale, 1.0, 1e-12);  // the rings' fixed point reached: each carries its variance
  EXPECT_NEAR(r.stretch, 1.0, 0.01);
  // The range: from half the finer bin spacing (2 pi/(2 nx dx)) to past the square of bins' corner.
  const double fine = 2.0 * kPi / (s.nx * s.dx), corner = std::hypot(kPi / s.dx, kPi / s.dy);
  EXPECT_NEAR(r.q.front() / (0.5 * fine * r.stretch), 1.0, 1e-12);
  EXPECT_GT(r.q.back(), corner);
  EXPECT_LT(r.q.back(), 1.1 * corner);  // the last ring at most 2^(1/8) wide
  // A flat patch has no spectrum to average.
  surface::HeightGrid flat = surface::make_grid(16, 16, 1e-6, 1e-6);
  EXPECT_THROW(surface::radial_spectrum(surface::areal_spectrum(flat)), std::invalid_argument);
}

TEST(RadialSpectrum, AnIsotropicGaussianSurfaceGivesTheGaussianSpectrum) {
  // Four seeded isotropic Gaussian surfaces (autocorrelation rq^2 exp(-r^2/lambda^2), 512^2 at 0.5 um,
  // lambda = 4 um) against the Gaussian part: the variance exactly (each map is scaled to rq, and the
  // average keeps it: 1e-12); the full gradient variance 4 rq^2/lambda^2 in the mean of the four within
  // 4 standard deviations of a sample's: a map's mean of |grad h|^2 scatters by sqrt(pi/2) lambda/L
  // (Isserlis over the gradient's autocorrelation) = 2.0 % a map, 1.0 % the mean: 3.9 % allowed
  // (measured +0.2 %; the maps alone 1.4-2.5 % each). Persson's u on the average against his u on the
  // Gaussian at 0.01 and 0.1 E* h'_rms (the moderate loads of the closure): within 2 % in the mean
  // (measured -0.3 % at both; a map's 0.5 % and 0.8 % apart at most over six seeds: u rests on the
  // spectrum over all q, below the gradient's wavenumbers as well, and scatters less than it).
  const double rq = 0.3e-6, lambda = 4e-6, e_star = 1e11;
  const contact::RoughnessSpectrum gaussian{{contact::SpectrumPart::gaussian(rq, lambda)}};
  const contact::PerssonSeparation exact(gaussian, e_star);
  const std::vector<double> loads = {0.01, 0.1};
  double gradient = 0.0;
  std::vector<double> u(loads.size(), 0.0);
  const int maps = 4;
  for (int seed = 1; seed <= maps; ++seed) {
    surface::GaussianSurfaceSpec g;
    g.nx = g.ny = 512;
    g.dx = g.dy = 0.5e-6;
    g.rq = rq;
    g.correlation_length = lambda;
    g.seed = static_cast<std::uint64_t>(seed);
    const surface::RadialSpectrum r = surface::radial_spectrum(surface::areal_spectrum(surface::gaussian_surface(g)));
    const contact::RoughnessSpectrum average{{contact::SpectrumPart::tabulated(r.q, r.c)}};
    EXPECT_NEAR(average.rms_height() / rq, 1.0, 1e-12) << seed;
    gradient += average.rms_gradient() * average.rms_gradient() / maps;
    const contact::PerssonSeparation law(average, e_star);
    for (std::size_t k = 0; k < loads.size(); ++k) {
      const double p = loads[k] * e_star * exact.rms_gradient();
      u[k] += law.separation(p) / exact.separation(p) / maps;
    }
  }
  EXPECT_NEAR(gradient / (4.0 * rq * rq / (lambda * lambda)), 1.0,
              4.0 * std::sqrt(kPi / 2.0) * lambda / (512 * 0.5e-6) / 2.0);
  for (std::size_t k = 0; k < loads.size(); ++k) EXPECT_NEAR(u[k], 1.0, 0.02) << loads[k];
}
