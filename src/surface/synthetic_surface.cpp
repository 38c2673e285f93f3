#include "surface/synthetic_surface.hpp"

#include "core/fftw_planner.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace geartrib::surface {

namespace {
constexpr double kPi = std::numbers::pi;
}

namespace {
// The grid limits of height_grid.hpp, before the spectrum is allocated.
void check_grid(int nx, int ny, double spacing) {
  if (static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) > kMaxGridPoints)
    throw std::invalid_argument("more than " + std::to_string(kMaxGridPoints) + " points");
  if (!(spacing >= kMinSpacing && spacing <= kMaxSpacing))
    throw std::invalid_argument("spacing outside 1e-12 m to 1000 m");
}
}  // namespace

HeightGrid self_affine_surface(const SelfAffineSpec& s) {
  if (s.nx < 8 || s.ny < 8 || !(s.spacing > 0.0) || !(s.rq > 0.0 && s.rq <= kMaxHeight))
    throw std::invalid_argument("bad self-affine surface size");
  check_grid(s.nx, s.ny, s.spacing);
  if (!(s.hurst > 0.0 && s.hurst < 1.0)) throw std::invalid_argument("Hurst exponent must lie in (0, 1)");
  if (!(s.cutoff_wavelength >= 2.0 * s.spacing && s.rolloff_wavelength > s.cutoff_wavelength))
    throw std::invalid_argument("need 2 spacings <= cut-off wavelength < roll-off wavelength");
  if (!(s.anisotropy >= 1.0)) throw std::invalid_argument("anisotropy must be >= 1");
  const int nx = s.nx, ny = s.ny, nxh = nx / 2 + 1;
  std::vector<std::complex<double>> spec(static_cast<std::size_t>(ny) * nxh);
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * kPi);
  const double qr = 2.0 * kPi / s.rolloff_wavelength, qs = 2.0 * kPi / s.cutoff_wavelength;
  const double c = std::cos(s.lay_angle), sn = std::sin(s.lay_angle);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nxh; ++i) {
      const double qx = 2.0 * kPi * i / (nx * s.spacing);
      const double qy = 2.0 * kPi * (j <= ny / 2 ? j : j - ny) / (ny * s.spacing);
      // Wavevector along and across the lay; the lay direction varies slowly (stretched).
      const double q_along = qx * c + qy * sn, q_across = -qx * sn + qy * c;
      const double q = std::hypot(s.anisotropy * q_along, q_across);
      double psd = 0.0;
      if (q > 0.0 && q <= qs) psd = q < qr ? 1.0 : std::pow(q / qr, -2.0 * (1.0 + s.hurst));
      // Random phase, amplitude sqrt(C(q)): the realised spectrum is the generating one.
      spec[static_cast<std::size_t>(j) * nxh + i] = std::sqrt(psd) * std::polar(1.0, phase(rng));
    }
  // Hermitian symmetry in the columns that are their own mirror (qx = 0 and, for even nx, the
  // Nyquist column): the entry at -qy is the conjugate of that at qy, and the self-conjugate
  // entries are real. Without it the c2r transform keeps only part of these modes' power.
  for (int i : {0, nx % 2 == 0 ? nx / 2 : -1}) {
    if (i < 0) continue;
    auto at = [&](int j) -> std::complex<double>& { return spec[static_cast<std::size_t>(j) * nxh + i]; };
    for (int j = ny / 2 + 1; j < ny; ++j) at(j) = std::conj(at(ny - j));
    at(0) = std::abs(at(0));
    if (ny % 2 == 0) at(ny / 2) = std::abs(at(ny / 2));
  }
  std::vector<double> z(static_cast<std::size_t>(nx) * ny);
  fftw_plan plan = nullptr;
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan = fftw_plan_dft_c2r_2d(ny, nx, reinterpret_cast<fftw_complex*>(spec.data()), z.data(), FFTW_ESTIMATE);
  }
  fftw_execute(plan);
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  double mean = 0.0, var = 0.0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(z.size());
  for (double& v : z) v -= mean, var += v * v;
  if (!(var > 0.0))  // no wavevector of the grid lies between the roll-off and the short cut-off
    throw std::invalid_argument("no wavelength of the spectrum fits the grid (short cut-off longer than the surface)");
  const double scale = s.rq / std::sqrt(var / static_cast<double>(z.size()));
  if (!std::isfinite(scale)) throw std::invalid_argument("the spectrum's amplitudes underflow: cannot scale to Rq");
  HeightGrid g = make_grid(nx, ny, s.spacing, s.spacing);
  for (std::size_t k = 0; k < z.size(); ++k) g.z[k] = z[k] * scale;
  return g;
}

HeightGrid hobbed_surface(const HobbedSpec& s) {
  if (s.nx < 8 || s.ny < 1 || !(s.spacing > 0.0) || !(s.wavelength > 4.0 * s.spacing) || !(s.tip_radius > 0.0))
    throw std::invalid_argument("bad hobbed-texture parameters");
  check_grid(s.nx, s.ny, s.spacing);
  if (!(s.wavelength * s.wavelength / (8.0 * s.tip_radius) + 6.0 * std::abs(s.noise_rq) <= kMaxHeight))
    throw std::invalid_argument("hobbed ridges deeper than 1 m (wavelength^2 / (8 tip radius) + 6 noise)");
  HeightGrid g = make_grid(s.nx, s.ny, s.spacing, s.spacing);
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const double x = i * s.spacing;
      const double local = std::remainder(x - 0.5 * s.wavelength, s.wavelength);  // distance to the nearest ridge axis
      g.at(i, j) = -local * local / (2.0 * s.tip_radius) + s.noise_rq * noise(rng);
    }
  return g;
}

HeightGrid gaussian_surface(const GaussianSurfaceSpec& s) {
  if (s.nx < 2 || s.ny < 1) throw std::invalid_argument("a Gaussian surface needs at least 2 x 1 points");
  check_grid(s.nx, s.ny, std::min(s.dx, s.dy));
  if (!(s.rq > 0.0 && s.rq <= kMaxHeight)) throw std::invalid_argument("rq must lie in (0, 1] m");
  if (!(s.correlation_length >= 2.0 * std::max(s.dx, s.dy)) || !(s.lambda_y() >= 2.0 * s.dy) ||
      !(s.lambda_y() <= 1e3 * s.correlation_length))
    throw std::invalid_argument(
        "the correlation length must be at least two spacings each way, and along y at most 1000 times that along x");
  // The kernel exp(-r^2/(2 sigma^2)), sigma = lambda/2, to 4 sigma = 2 lambda along x (the noise runs
  // on that far beyond the ends; the cyclic convolution over the noise's length then never wraps
  // into the outputs); along y the whole period (cyclic: the rows wrap). One 2-D transform.
  const int hx = static_cast<int>(std::ceil(2.0 * s.correlation_length / s.dx));
  const int mx = static_cast<int>(fast_fft_size(static_cast<std::size_t>(s.nx + 2 * hx))), my = s.ny;
  const int kx = mx / 2 + 1;
  const std::size_t real_size = static_cast<std::size_t>(mx) * my, spectral = static_cast<std::size_t>(kx) * my;
  if (real_size > 4 * kMaxGridPoints)
    throw std::invalid_argument("more than " + std::to_string(kMaxGridPoints) + " points");
  auto real = fftw_real_array(real_size);
  auto noise_hat = fftw_complex_array(spectral);
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_2d(my, mx, real.get(), noise_hat.get(), FFTW_ESTIMATE); });
  const FftwPlan backward([&] { return fftw_plan_dft_c2r_2d(my, mx, noise_hat.get(), real.get(), FFTW_ESTIMATE); });
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (std::size_t k = 0; k < real_size; ++k) real[k] = normal(rng);
  fftw_execute(forward.get());
  // The kernel's transform, separable: along x the truncated Gaussian's at the bins 0..mx/2 of mx,
  // along y the periodic one's (its offsets -my/2 < j <= my/2) at every bin.
  auto transform = [&](int bins, int m, double h, double lambda, int first, int last) {
    std::vector<double> t(static_cast<std::size_t>(bins));
    const double a = h / lambda;
    for (int b = 0; b < bins; ++b)
      for (int j = first; j <= last; ++j)
        t[static_cast<std::size_t>(b)] += std::exp(-2.0 * (a * j) * (a * j)) * std::cos(2.0 * kPi * b * j / m);
    return t;
  };
  const std::vector<double> tx_full = transform(kx, mx, s.dx, s.correlation_length, -hx, hx);
  // Along y the offsets of one period, or the kernel's 4 s_y where it is longer (its images wrap).
  const int hy = static_cast<int>(std::ceil(2.0 * s.lambda_y() / s.dy));
  const std::vector<double> ty =
      transform(my, my, s.dy, s.lambda_y(), -std::max((my - 1) / 2, hy), std::max(my / 2, hy));
  for (int by = 0; by < my; ++by)
    for (int bx = 0; bx < kx; ++bx) {
      const double f = tx_full[static_cast<std::size_t>(bx)] * ty[static_cast<std::size_t>(by)];
      fftw_complex& c = noise_hat[static_cast<std::size_t>(by) * kx + bx];
      c[0] *= f, c[1] *= f;
    }
  fftw_execute(backward.get());  // unnormalised: the scaling to rq absorbs it
  HeightGrid g = make_grid(s.nx, s.ny, s.dx, s.dy);
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) g.at(i, j) = real[static_cast<std::size_t>(j) * mx + i + hx];
  double mean = 0.0, var = 0.0;
  for (double v : g.z) mean += v;
  mean /= static_cast<double>(g.size());
  for (double& v : g.z) v -= mean, var += v * v;
  const double scale = s.rq / std::sqrt(var / static_cast<double>(g.size()));
  for (double& v : g.z) v *= scale;
  return g;
}

void SuperfinishedSpec::validate() const {
  if (!(plateau > 0.0 && plateau < 1.0)) throw std::invalid_argument("the plateau fraction must lie in (0, 1)");
  if (!(fine_rq >= 0.0 && fine_rq <= kMaxHeight))
    throw std::invalid_argument("the fine texture's rq must lie in [0, 1] m");
  if (fine_rq > 0.0 && !(fine_correlation >= 2.0 * std::max(ground.dx, ground.dy)))
    throw std::invalid_argument("the fine texture's correlation length must be at least two spacings each way");
}

HeightGrid superfinished_surface(const SuperfinishedSpec& s) {
  s.validate();
  HeightGrid g = gaussian_surface(s.ground);
  std::vector<double> sorted = g.z;
  // The cut: the height above which `plateau` of the area lies (the lower order statistic).
  const auto k = static_cast<std::size_t>(std::floor((1.0 - s.plateau) * static_cast<double>(sorted.size() - 1)));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
  const double cut = sorted[k];
  for (double& z : g.z) z = std::min(z, cut);
  if (s.fine_rq > 0.0) {
    GaussianSurfaceSpec fine = s.ground;
    fine.rq = s.fine_rq, fine.correlation_length = s.fine_correlation, fine.correlation_length_y = 0.0;
    fine.seed = s.ground.seed + 1;
    const HeightGrid f = gaussian_surface(fine);
    for (std::size_t i = 0; i < g.z.size(); ++i) g.z[i] += f.z[i];
  }
  double mean = 0.0;
  for (double z : g.z) mean += z;
  mean /= static_cast<double>(g.size());
  for (double& z : g.z) z -= mean;
  return g;
}

}  // namespace geartrib::surface
