#include "surface/surface_statistics.hpp"

#include "core/fftw_planner.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::surface {

namespace {
constexpr double kPi = std::numbers::pi;
}

std::vector<Summit> find_summits(const HeightGrid& g, double mean_plane) {
  g.validate();
  std::vector<Summit> out;
  for (int j = 1; j + 1 < g.ny; ++j)
    for (int i = 1; i + 1 < g.nx; ++i) {
      if (!g.ok(i, j)) continue;
      bool peak = true;
      for (int dj = -1; dj <= 1 && peak; ++dj)
        for (int di = -1; di <= 1; ++di)
          if ((di || dj) && (!g.ok(i + di, j + dj) || g.at(i + di, j + dj) >= g.at(i, j))) {
            peak = false;
            break;
          }
      if (!peak) continue;
      const double zxx = (g.at(i + 1, j) - 2.0 * g.at(i, j) + g.at(i - 1, j)) / (g.dx * g.dx);
      const double zyy = (g.at(i, j + 1) - 2.0 * g.at(i, j) + g.at(i, j - 1)) / (g.dy * g.dy);
      // A strict peak has zxx, zyy < 0, so its mean curvature is positive.
      out.push_back({i * g.dx, j * g.dy, g.at(i, j) - mean_plane, 1.0 / (-0.5 * (zxx + zyy))});
    }
  return out;
}

SurfaceStatistics surface_statistics(const HeightGrid& g) {
  g.validate();
  SurfaceStatistics s;
  s.points = g.size();
  s.missing = g.missing();
  const std::size_t n = g.size() - s.missing;
  if (n < 9) throw std::invalid_argument("too few valid points for surface statistics");
  double mean = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.valid[k]) mean += g.z[k];
  mean /= static_cast<double>(n);
  double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.valid[k]) {
      const double d = g.z[k] - mean;
      m1 += std::abs(d), m2 += d * d, m3 += d * d * d, m4 += d * d * d * d;
    }
  s.ra = m1 / n;
  s.m0 = m2 / n;
  s.rq = std::sqrt(s.m0);
  // A perfectly flat surface has no shape to its height distribution: Rsk = Rku = 0 (not 0/0).
  s.rsk = s.m0 > 0.0 ? m3 / n / (s.m0 * s.rq) : 0.0;
  s.rku = s.m0 > 0.0 ? m4 / n / (s.m0 * s.m0) : 0.0;

  // Slope covariance (central differences where both neighbours are valid) -> lay direction.
  double sxx = 0, sxy = 0, syy = 0;
  std::size_t ns = 0;
  for (int j = 1; j + 1 < g.ny; ++j)
    for (int i = 1; i + 1 < g.nx; ++i) {
      if (!(g.ok(i - 1, j) && g.ok(i + 1, j) && g.ok(i, j - 1) && g.ok(i, j + 1))) continue;
      const double zx = (g.at(i + 1, j) - g.at(i - 1, j)) / (2.0 * g.dx),
                   zy = (g.at(i, j + 1) - g.at(i, j - 1)) / (2.0 * g.dy);
      sxx += zx * zx, sxy += zx * zy, syy += zy * zy;
      ++ns;
    }
  if (ns == 0) throw std::invalid_argument("the grid needs at least 3 x 3 valid points for slopes");
  // The lay runs along the eigenvector of the smallest slope variance.
  const double theta = 0.5 * std::atan2(2.0 * sxy, sxx - syy);  // direction of the largest variance
  double lay = theta + 0.5 * kPi;
  if (lay > 0.5 * kPi) lay -= kPi;
  s.lay_angle = lay;
  // Directional moments from second differences along a direction (c, s): z_s = c z_x + s z_y,
  // z_ss = c^2 z_xx + 2 c s z_xy + s^2 z_yy.
  auto moments = [&](double angle, double& mm2, double& mm4) {
    const double c = std::cos(angle), sn = std::sin(angle);
    double a2 = 0, a4 = 0;
    std::size_t cnt = 0;
    for (int j = 1; j + 1 < g.ny; ++j)
      for (int i = 1; i + 1 < g.nx; ++i) {
        bool all = true;
        for (int dj = -1; dj <= 1 && all; ++dj)
          for (int di = -1; di <= 1; ++di) all = all && g.ok(i + di, j + dj);
        if (!all) continue;
        const double zx = (g.at(i + 1, j) - g.at(i - 1, j)) / (2.0 * g.dx);
        const double zy = (g.at(i, j + 1) - g.at(i, j - 1)) / (2.0 * g.dy);
        const double zxx = (g.at(i + 1, j) - 2.0 * g.at(i, j) + g.at(i - 1, j)) / (g.dx * g.dx);
        const double zyy = (g.at(i, j + 1) - 2.0 * g.at(i, j) + g.at(i, j - 1)) / (g.dy * g.dy);
        const double zxy =
            (g.at(i + 1, j + 1) - g.at(i + 1, j - 1) - g.at(i - 1, j + 1) + g.at(i - 1, j - 1)) / (4.0 * g.dx * g.dy);
        const double d1 = c * zx + sn * zy, d2 = c * c * zxx + 2.0 * c * sn * zxy + sn * sn * zyy;
        a2 += d1 * d1, a4 += d2 * d2;
        ++cnt;
      }
    mm2 = cnt ? a2 / cnt : 0.0;
    mm4 = cnt ? a4 / cnt : 0.0;
  };
  moments(s.lay_angle, s.m2_along, s.m4_along);
  moments(s.lay_angle + 0.5 * kPi, s.m2_across, s.m4_across);

  // Rz on each profile across the lay (rows when the lay is nearer the y axis, else columns).
  const bool rows = std::abs(std::sin(s.lay_angle)) > std::abs(std::cos(s.lay_angle));
  const int profiles = rows ? g.ny : g.nx, length = rows ? g.nx : g.ny;
  double rz_sum = 0.0;
  int rz_count = 0;
  for (int p = 0; p < profiles; ++p) {
    const int seg = length / 5;
    if (seg < 2) break;
    double total = 0.0;
    bool complete = true;
    for (int k = 0; k < 5 && complete; ++k) {
      double hi = -1e300, lo = 1e300;
      for (int q = k * seg; q < (k + 1) * seg; ++q) {
        const int i = rows ? q : p, j = rows ? p : q;
        if (!g.ok(i, j)) {
          complete = false;
          break;
        }
        hi = std::max(hi, g.at(i, j)), lo = std::min(lo, g.at(i, j));
      }
      total += hi - lo;
    }
    if (complete) rz_sum += total / 5.0, ++rz_count;
  }
  s.rz = rz_count ? rz_sum / rz_count : 0.0;

  // Summits.
  const std::vector<Summit> summits = find_summits(g, mean);
  s.summits = summits.size();
  double curvature = 0.0, hsum = 0.0, h2 = 0.0;
  for (const Summit& p : summits) curvature += 1.0 / p.radius, hsum += p.height, h2 += p.height * p.height;
  const double area = (g.nx - 2) * g.dx * (g.ny - 2) * g.dy * (1.0 - static_cast<double>(s.missing) / g.size());
  if (s.summits > 0) {
    s.summit_density = s.summits / area;
    s.summit_radius = curvature > 0.0 ? s.summits / curvature : 0.0;
    s.summit_mean_height = hsum / s.summits;
    s.summit_sigma = std::sqrt(std::max(0.0, h2 / s.summits - s.summit_mean_height * s.summit_mean_height));
  }
  // McCool with direction-averaged moments (isotropic equivalent).
  const double m2a = 0.5 * (s.m2_along + s.m2_across), m4a = 0.5 * (s.m4_along + s.m4_across);
  if (m2a > 0.0 && m4a > 0.0) {
    const double alpha = s.m0 * m4a / (m2a * m2a);
    s.mccool_density = m4a / (6.0 * kPi * std::sqrt(3.0) * m2a);
    s.mccool_radius = 0.375 * std::sqrt(kPi / m4a);
    s.mccool_summit_sigma = alpha > 0.8968 ? std::sqrt((1.0 - 0.8968 / alpha) * s.m0) : 0.0;
  }
  return s;
}

FlankRoughness measured_roughness(const SurfaceStatistics& s) {
  if (!(s.summit_density > 0.0 && s.summit_radius > 0.0 && s.summit_sigma > 0.0))
    throw std::invalid_argument("the measured surface has no usable summits");
  FlankRoughness r;
  r.form = FlankRoughness::Form::summits;
  r.summit_density = s.summit_density;
  r.summit_sigma = s.summit_sigma;
  r.summit_radius = s.summit_radius;
  r.height_rq = s.rq;
  r.height_ra = s.ra;
  return r;
}

double spectral_rms_gradient(const HeightGrid& g) {
  g.validate();
  if (g.missing() > 0) throw std::invalid_argument("spectral_rms_gradient: the grid has missing points");
  const int hx = g.nx / 2 + 1;
  auto real = fftw_real_array(g.size());
  auto spectrum = fftw_complex_array(static_cast<std::size_t>(g.ny) * hx);
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_2d(g.ny, g.nx, real.get(), spectrum.get(), FFTW_ESTIMATE); });
  std::copy(g.z.begin(), g.z.end(), real.get());
  fftw_execute(forward.get());
  const double n = static_cast<double>(g.size());
  double sum = 0.0;
  for (int ky = 0; ky < g.ny; ++ky)
    for (int kx = 0; kx < hx; ++kx) {
      // Along an axis' Nyquist frequency the harmonic is a cosine whose derivative vanishes on the
      // grid: that axis' part of q is left out (the bin's other part kept).
      const bool nyquist_x = g.nx % 2 == 0 && kx == g.nx / 2, nyquist_y = g.ny % 2 == 0 && ky == g.ny / 2;
      const int sy = ky <= g.ny / 2 ? ky : ky - g.ny;
      const double qx = nyquist_x ? 0.0 : 2.0 * std::numbers::pi * kx / (g.nx * g.dx);
      const double qy = nyquist_y ? 0.0 : 2.0 * std::numbers::pi * sy / (g.ny * g.dy);
      const fftw_complex& c = spectrum[static_cast<std::size_t>(ky) * hx + kx];
      const double weight = (kx == 0 || nyquist_x) ? 1.0 : 2.0;  // the half spectrum's mirrored bins
      sum += weight * (qx * qx + qy * qy) * (c[0] * c[0] + c[1] * c[1]) / (n * n);
    }
  return std::sqrt(sum);
}

}  // namespace geartrib::surface
