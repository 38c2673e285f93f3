#include "surface/flank_profile.hpp"

#include "core/fftw_planner.hpp"
#include "core/keyed_error.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <memory>
#include <random>
#include <stdexcept>

namespace geartrib::surface {

namespace {

// Removes the mean and scales to root-mean-square `rq`; false when the profile is flat.
bool scale_to_rq(std::vector<double>& z, double rq) {
  double mean = 0.0, var = 0.0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(z.size());
  for (double& v : z) v -= mean, var += v * v;
  if (!(var > 0.0)) return false;
  const double scale = rq / std::sqrt(var / static_cast<double>(z.size()));
  for (double& v : z) v *= scale;
  return true;
}

// n points of a Gaussian random profile with autocorrelation rq^2 exp(-tau^2/lambda^2): white noise convolved with
// the Gaussian kernel exp(-x^2/(2 sigma^2)), sigma = lambda/2 (the convolution of two such kernels is
// exp(-tau^2/(4 sigma^2))), truncated at +-4 sigma. The linear convolution is taken by FFT from n + 2 half noise
// values, zero-padded: the outputs half .. half + n - 1 of the circular one never wrap.
std::vector<double> gaussian_profile(std::mt19937_64& rng, std::size_t n, double spacing, double lambda, double rq) {
  const auto half = static_cast<std::size_t>(std::ceil(2.0 * lambda / spacing));  // 4 sigma [spacings]
  const std::size_t noise = n + 2 * half, f = fast_fft_size(noise), nh = f / 2 + 1;
  const auto real = fftw_real_array(f);
  const auto noise_hat = fftw_complex_array(nh), kernel_hat = fftw_complex_array(nh);
  const int fi = static_cast<int>(f);
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_1d(fi, real.get(), noise_hat.get(), FFTW_ESTIMATE); });
  const FftwPlan backward([&] { return fftw_plan_dft_c2r_1d(fi, noise_hat.get(), real.get(), FFTW_ESTIMATE); });
  std::normal_distribution<double> normal(0.0, 1.0);
  for (std::size_t k = 0; k < f; ++k) real[k] = k < noise ? normal(rng) : 0.0;
  fftw_execute(forward.get());
  // Kernel in circular layout: offset m >= 0 at m, -m at f - m.
  for (std::size_t k = 0; k < f; ++k) real[k] = 0.0;
  const double a = spacing / lambda;
  for (std::size_t m = 0; m <= half; ++m) {
    const double w = std::exp(-2.0 * (a * m) * (a * m));  // exp(-x^2/(2 sigma^2)), sigma = lambda/2
    real[m] = w;
    if (m > 0) real[f - m] = w;
  }
  fftw_execute_dft_r2c(forward.get(), real.get(), kernel_hat.get());
  for (std::size_t k = 0; k < nh; ++k) {
    const std::complex<double> v = std::complex<double>(noise_hat[k][0], noise_hat[k][1]) *
                                   std::complex<double>(kernel_hat[k][0], kernel_hat[k][1]);
    noise_hat[k][0] = v.real(), noise_hat[k][1] = v.imag();
  }
  fftw_execute(backward.get());  // unnormalised (x f): the scaling to rq absorbs it
  std::vector<double> z(real.get() + half, real.get() + half + n);
  if (!scale_to_rq(z, rq)) throw std::invalid_argument("the random profile came out flat: cannot scale it to Rq");
  return z;
}

}  // namespace

double FlankProfile::length() const { return z.size() < 2 ? 0.0 : spacing * static_cast<double>(z.size() - 1); }

void GeneratedProfileSpec::validate() const {
  if (kind != ProfileKind::smooth && kind != ProfileKind::ground && kind != ProfileKind::hobbed)
    throw core::KeyedError("kind", "kind must be smooth, ground or hobbed");
  if (!(spacing >= kMinSpacing && spacing <= kMaxSpacing))
    throw core::KeyedError(
        "spacing", fmt::format("spacing must lie in {:g} m to {:g} m (got {:g} m)", kMinSpacing, kMaxSpacing, spacing));
  if (kind == ProfileKind::smooth) return;
  if (kind == ProfileKind::ground && !(rq > 0.0 && rq <= kMaxHeight))
    throw core::KeyedError(
        "rq",
        fmt::format("rq must lie in (0, {:g}] m for a ground profile (got {:g} m; smooth for none)", kMaxHeight, rq));
  if (kind == ProfileKind::hobbed && !(rq >= 0.0 && rq <= kMaxHeight))
    throw core::KeyedError("rq",
                           fmt::format("rq must lie in [0, {:g}] m for a hobbed profile (got {:g} m)", kMaxHeight, rq));
  if (rq > 0.0) {
    if (!(correlation_length >= 2.0 * spacing))
      throw core::KeyedError("correlation_length",
                             fmt::format("correlation_length must be at least 2 spacings ({:g} m; got {:g} m)",
                                         2.0 * spacing, correlation_length));
    // The kernel spans +-2 lambda: at most kMaxProfilePoints/2 points.
    if (!(correlation_length <= static_cast<double>(kMaxProfilePoints) / 8.0 * spacing))
      throw core::KeyedError(
          "correlation_length",
          fmt::format("correlation_length must be at most {} spacings ({:g} m; got {:g} m)", kMaxProfilePoints / 8,
                      static_cast<double>(kMaxProfilePoints) / 8.0 * spacing, correlation_length));
  }
  if (kind == ProfileKind::hobbed) {
    if (!(ridge_spacing >= 4.0 * spacing && ridge_spacing <= kMaxSpacing))
      throw core::KeyedError("ridge_spacing",
                             fmt::format("ridge_spacing must lie in 4 spacings ({:g} m) to {:g} m (got {:g} m)",
                                         4.0 * spacing, kMaxSpacing, ridge_spacing));
    if (!(ridge_radius > 0.0 && std::isfinite(ridge_radius)))
      throw core::KeyedError("ridge_radius", fmt::format("ridge_radius must be positive (got {:g} m)", ridge_radius));
    // As hobbed_surface: ridge depth plus six standard deviations of the noise within the height limit.
    if (!(ridge_spacing * ridge_spacing / (8.0 * ridge_radius) + 6.0 * rq <= kMaxHeight))
      throw core::KeyedError(
          "ridge_radius",
          fmt::format("ridge depth ridge_spacing^2/(8 ridge_radius) + 6 rq must be at most {:g} m (got {:g} m)",
                      kMaxHeight, ridge_spacing * ridge_spacing / (8.0 * ridge_radius) + 6.0 * rq));
  }
}

ProfileKind profile_kind(const std::string& name) {
  for (ProfileKind k : {ProfileKind::smooth, ProfileKind::ground, ProfileKind::hobbed})
    if (name == profile_kind_name(k)) return k;
  throw std::invalid_argument("unknown profile kind '" + name + "' (known: smooth, ground, hobbed)");
}

const char* profile_kind_name(ProfileKind k) {
  switch (k) {
    case ProfileKind::smooth:
      return "smooth";
    case ProfileKind::ground:
      return "ground";
    case ProfileKind::hobbed:
      return "hobbed";
  }
  return "ground";
}

FlankProfile generate_profile(const GeneratedProfileSpec& s, double length) {
  s.validate();
  if (!(length > 0.0 && std::isfinite(length)))
    throw std::invalid_argument(fmt::format("profile length must be positive and finite (got {:g} m)", length));
  // Intervals: ceil(length/spacing), the ratio taken 1e-12 relative lower so that its round-off adds no point.
  const double intervals = std::ceil(length / s.spacing * (1.0 - 1e-12));
  if (!(intervals + 1.0 <= static_cast<double>(kMaxProfilePoints)))
    throw std::invalid_argument(fmt::format("a profile of {:g} m at spacing {:g} m needs {:.4g} points, more than {}",
                                            length, s.spacing, intervals + 1.0, kMaxProfilePoints));
  const auto n = static_cast<std::size_t>(intervals) + 1;
  FlankProfile p;
  p.spacing = s.spacing;
  if (s.kind == ProfileKind::smooth) {
    p.z.assign(n, 0.0);
    return p;
  }
  std::mt19937_64 rng(s.seed);
  if (s.kind == ProfileKind::ground) {
    p.z = gaussian_profile(rng, n, s.spacing, s.correlation_length, s.rq);
    return p;
  }
  // Hobbed: ridge axes at x_k = phase + k ridge_spacing; each point on the parabola of its nearest axis.
  const double phase = std::uniform_real_distribution<double>(0.0, s.ridge_spacing)(rng);
  p.z.resize(n);
  double mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double u = std::remainder(static_cast<double>(k) * s.spacing - phase, s.ridge_spacing);
    p.z[k] = -u * u / (2.0 * s.ridge_radius);
    mean += p.z[k];
  }
  mean /= static_cast<double>(n);
  for (double& v : p.z) v -= mean;
  if (s.rq > 0.0) {
    const std::vector<double> noise = gaussian_profile(rng, n, s.spacing, s.correlation_length, s.rq);
    for (std::size_t k = 0; k < n; ++k) p.z[k] += noise[k];
  }
  return p;
}

FlankProfile profile_from_grid(const HeightGrid& g, bool along_x, double at) {
  g.validate();
  if (!(at >= 0.0 && at <= 1.0)) throw std::invalid_argument(fmt::format("at must lie in [0, 1] (got {:g})", at));
  const int lines = along_x ? g.ny : g.nx, count = along_x ? g.nx : g.ny;
  const int line = static_cast<int>(std::lround(at * (lines - 1)));
  const char* name = along_x ? "row" : "column";
  if (count < 2)
    throw std::invalid_argument(fmt::format("{} {} has {} point: a profile needs at least 2", name, line, count));
  FlankProfile p;
  p.spacing = along_x ? g.dx : g.dy;
  p.z.resize(static_cast<std::size_t>(count));
  int missing = 0;
  for (int k = 0; k < count; ++k) {
    const int i = along_x ? k : line, j = along_x ? line : k;
    if (!g.ok(i, j)) ++missing;
    p.z[static_cast<std::size_t>(k)] = g.at(i, j);
  }
  if (missing > 0)
    throw std::invalid_argument(
        fmt::format("{} {} ({} = {:g} m) has {} missing point(s): clean or fill the surface first", name, line,
                    along_x ? "y" : "x", line * (along_x ? g.dy : g.dx), missing));
  return p;
}

ProfileStatistics profile_statistics(std::span<const double> z, double spacing) {
  const std::size_t n = z.size();
  if (n < 3) throw std::invalid_argument(fmt::format("profile statistics need at least 3 points (got {})", n));
  if (!(spacing > 0.0 && std::isfinite(spacing)))
    throw std::invalid_argument(fmt::format("profile spacing must be positive (got {:g} m)", spacing));
  double mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(z[k])) throw std::invalid_argument(fmt::format("profile height {} is not finite", k));
    mean += z[k];
  }
  mean /= static_cast<double>(n);
  // ISO 4287 amplitude parameters about the mean line.
  double a1 = 0, a2 = 0, a3 = 0, a4 = 0;
  for (double v : z) {
    const double d = v - mean;
    a1 += std::abs(d), a2 += d * d, a3 += d * d * d, a4 += d * d * d * d;
  }
  const auto nd = static_cast<double>(n);
  ProfileStatistics s;
  s.ra = a1 / nd;
  s.m0 = a2 / nd;
  s.rq = std::sqrt(s.m0);
  // A flat profile has no shape to its height distribution: Rsk = Rku = 0 (not 0/0), as surface_statistics.
  s.rsk = s.m0 > 0.0 ? a3 / nd / (s.m0 * s.rq) : 0.0;
  s.rku = s.m0 > 0.0 ? a4 / nd / (s.m0 * s.m0) : 0.0;
  // Slope and curvature variances over the interior points (McCool 1986).
  double b2 = 0, b4 = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double slope = (z[i + 1] - z[i - 1]) / (2.0 * spacing);
    const double second = (z[i + 1] - 2.0 * z[i] + z[i - 1]) / (spacing * spacing);
    b2 += slope * slope, b4 += second * second;
  }
  s.m2 = b2 / static_cast<double>(n - 2);
  s.m4 = b4 / static_cast<double>(n - 2);
  // Peaks: higher than the point before and than the first different point after (a plateau counts once, at its
  // first point), above the mean line. Curvature from the point's own neighbours; positive at every peak.
  double curvature = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (!(z[i] > z[i - 1])) continue;
    std::size_t j = i + 1;
    while (j < n && z[j] == z[i]) ++j;
    if (j == n || !(z[j] < z[i]) || !(z[i] > mean)) continue;
    curvature += -(z[i - 1] - 2.0 * z[i] + z[i + 1]) / (spacing * spacing);
    s.peak_height += z[i] - mean;
    ++s.peaks;
  }
  if (s.peaks > 0) s.summit_radius = curvature > 0.0 ? s.peaks / curvature : 0.0;
  if (s.peaks > 0) s.peak_height /= s.peaks;
  s.peak_density = s.peaks / (spacing * static_cast<double>(n - 1));
  return s;
}

FlankRoughness spectral_roughness(const ProfileStatistics& s) {
  FlankRoughness r;
  r.form = FlankRoughness::Form::spectral;
  r.m0 = s.m0, r.m2 = s.m2, r.m4 = s.m4;
  r.height_rq = s.rq;
  r.height_ra = s.ra;
  return r;
}

}  // namespace geartrib::surface
