#include "surface/areal_synthesis.hpp"

#include "core/fftw_planner.hpp"
#include "core/portable_random.hpp"
#include "core/power_law_integral.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

namespace geartrib::surface {

namespace {

constexpr double kPi = std::numbers::pi;

void require_complete(const HeightGrid& g, const char* what) {
  if (g.missing() > 0)
    throw std::invalid_argument(
        fmt::format("{} has {} missing points: fill them first (the topography's fill = true)", what, g.missing()));
}

// A bin's weight on the full plane from the half plane fx >= 0: the columns 0 < i < nx/2 stand for
// themselves and their mirror at -f.
double half_plane_weight(int i, int nx) { return (i == 0 || (nx % 2 == 0 && i == nx / 2)) ? 1.0 : 2.0; }

// The signed index l' of row l of an n-point transform.
int signed_bin(int l, int n) { return l <= n / 2 ? l : l - n; }

}  // namespace

double ArealSpectrum::variance() const {
  const int kx = nx / 2 + 1;
  double sum = 0.0;
  for (int l = 0; l < ny; ++l)
    for (int i = 0; i < kx; ++i) sum += half_plane_weight(i, nx) * psd[static_cast<std::size_t>(l) * kx + i];
  return sum / (nx * dx * ny * dy);
}

double ArealSpectrum::slope_variance(bool along_x) const {
  const int kx = nx / 2 + 1;
  double sum = 0.0;
  for (int l = 0; l < ny; ++l)
    for (int i = 0; i < kx; ++i) {
      const double q = 2.0 * kPi * (along_x ? i / (nx * dx) : signed_bin(l, ny) / (ny * dy));
      sum += half_plane_weight(i, nx) * q * q * psd[static_cast<std::size_t>(l) * kx + i];
    }
  return sum / (nx * dx * ny * dy);
}

double ArealSpectrum::element_spacing(bool along_x) const {
  const double m2 = slope_variance(along_x);
  return m2 > 0.0 ? 2.0 * kPi * std::sqrt(variance() / m2) : std::numeric_limits<double>::infinity();
}

double ArealSpectrum::at(double fx, double fy) const {
  if (fx < 0.0) fx = -fx, fy = -fy;                         // C(-f) = C(f)
  const double u = fx * nx * dx, v = fy * ny * dy;          // in bins
  constexpr double kSlack = 1e-9;                           // a bin's own frequency, rounded
  const double px = fx * length_x(), py = fy * length_y();  // periods across the patch
  const int top_x = nx / 2, top_y = ny / 2;                 // the highest bins (an odd count's floor)
  if (u > top_x + kSlack || std::abs(v) > top_y + kSlack || px * px + py * py < 1.0 - kSlack) return 0.0;
  const int kx = nx / 2 + 1;
  const int i0 = std::min(static_cast<int>(std::floor(u)), kx - 1), i1 = std::min(i0 + 1, kx - 1);
  const double tu = std::clamp(u - i0, 0.0, 1.0);
  const int l0 = static_cast<int>(std::floor(v));
  const double tv = std::clamp(v - l0, 0.0, 1.0);
  // Row of signed bin l (within -ny/2..ny/2; the top of an even ny is its bottom).
  auto row = [&](int l) { return static_cast<std::size_t>(((l % ny) + ny) % ny) * kx; };
  const int l1 = std::min(l0 + 1, ny / 2);
  const std::size_t r0 = row(std::max(l0, -(ny / 2))), r1 = row(l1);
  return (1.0 - tv) * ((1.0 - tu) * psd[r0 + i0] + tu * psd[r0 + i1]) +
         tv * ((1.0 - tu) * psd[r1 + i0] + tu * psd[r1 + i1]);
}

ArealSpectrum areal_spectrum(const HeightGrid& patch) {
  patch.validate();
  require_complete(patch, "the patch");
  if (patch.nx < 8 || patch.ny < 8)
    throw std::invalid_argument(
        fmt::format("the patch has {} x {} points: an areal spectrum needs at least 8 each way", patch.nx, patch.ny));
  if (4 * patch.size() > kMaxGridPoints)
    throw std::invalid_argument(
        fmt::format("the patch's {} x {} points, mirrored to twice each way, exceed the {} a "
                    "height map may hold: resample it coarser",
                    patch.nx, patch.ny, kMaxGridPoints));
  ArealSpectrum s;
  s.nx = 2 * patch.nx, s.ny = 2 * patch.ny, s.dx = patch.dx, s.dy = patch.dy;
  const int nx = s.nx, ny = s.ny, kx = nx / 2 + 1;
  double mean = 0.0;
  for (double z : patch.z) mean += z;
  mean /= static_cast<double>(patch.size());
  for (double z : patch.z) s.patch_rq += (z - mean) * (z - mean);
  s.patch_rq = std::sqrt(s.patch_rq / static_cast<double>(patch.size()));
  const std::size_t size = static_cast<std::size_t>(nx) * ny;
  const auto real = fftw_real_array(size);
  const auto spectrum = fftw_complex_array(static_cast<std::size_t>(ny) * kx);
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_2d(ny, nx, real.get(), spectrum.get(), FFTW_ESTIMATE); });
  // The even extension: point (i, j) of 2N holds the patch's (i, j) folded back at each side.
  auto fold = [](int i, int n) { return i < n ? i : 2 * n - 1 - i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      real[static_cast<std::size_t>(j) * nx + i] = patch.at(fold(i, patch.nx), fold(j, patch.ny)) - mean;
  fftw_execute(forward.get());
  // C = dx dy |Z|^2 / (nx ny): its sum times dfx dfy = sum z^2 / (nx ny), the variance.
  s.psd.resize(static_cast<std::size_t>(ny) * kx);
  const double scale = s.dx * s.dy / static_cast<double>(size);
  for (std::size_t k = 0; k < s.psd.size(); ++k)
    s.psd[k] = scale * (spectrum[k][0] * spectrum[k][0] + spectrum[k][1] * spectrum[k][1]);
  s.psd[0] = 0.0;
  return s;
}

namespace {

// The radial average's rings: 2^(1/8) wide where a bin is narrower; the fixed point's stop, the
// rings' variance carried to 1e-13 of the whole, and its bound (~0.5 a step: ~45 steps).
constexpr double kRingRatio = 1.0905077326652577;
constexpr double kRingTolerance = 1e-13;
constexpr int kRingSteps = 200;

struct Ring {
  double inner = 0.0, outer = 0.0;  // [1/m]
  double power = 0.0;               // sum P: its share of the variance [m^2]
  double node = 0.0;                // [1/m]
  double value = 0.0;               // C there [m^4]
};

}  // namespace

RadialSpectrum radial_spectrum(const ArealSpectrum& s) {
  const int kx = s.nx / 2 + 1;
  const double dfx = 1.0 / (s.nx * s.dx), dfy = 1.0 / (s.ny * s.dy);
  const double fine = 2.0 * kPi * std::min(dfx, dfy), coarse = 2.0 * kPi * std::max(dfx, dfy);
  double largest = 0.0;
  for (int l = 0; l < s.ny; ++l)
    largest = std::max(largest, 2.0 * kPi * std::hypot((kx - 1) * dfx, signed_bin(l, s.ny) * dfy));
  std::vector<double> edges = {0.5 * fine};
  while (edges.back() <= largest) edges.push_back(std::max(kRingRatio * edges.back(), edges.back() + coarse));
  // Each ring's power P = C dfx dfy (a half-plane column standing for its mirror too), sum q^2 P, and
  // its bins' sum q^2 and count (a ring without power: its node at their rms).
  const std::size_t n_rings = edges.size() - 1;
  std::vector<double> p0(n_rings), p2(n_rings), q2(n_rings), count(n_rings);
  double variance = 0.0, gradient = 0.0;
  for (int l = 0; l < s.ny; ++l)
    for (int i = 0; i < kx; ++i) {
      const double q = 2.0 * kPi * std::hypot(i * dfx, signed_bin(l, s.ny) * dfy);
      if (q == 0.0) continue;
      const double p = half_plane_weight(i, s.nx) * s.psd[static_cast<std::size_t>(l) * kx + i] * dfx * dfy;
      const auto k = static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), q) - edges.begin()) - 1;
      p0[k] += p, p2[k] += q * q * p, q2[k] += q * q, count[k] += 1.0;
      variance += p, gradient += q * q * p;
    }
  if (!(variance > 0.0)) throw std::invalid_argument("the spectrum carries no power (a flat patch)");
  std::vector<Ring> rings;
  for (std::size_t k = 0; k < n_rings; ++k) {
    if (count[k] == 0.0) continue;
    Ring r{edges[k], edges[k + 1], p0[k]};
    r.node =
        std::clamp(std::sqrt(p0[k] > 0.0 ? p2[k] / p0[k] : q2[k] / count[k]), r.inner, std::nextafter(r.outer, 0.0));
    r.value = r.power / (kPi * (r.outer * r.outer - r.inner * r.inner));
    rings.push_back(r);
  }
  // The nodes: the range's ends (their rings' values) and the rings'.
  const bool low_end = rings.front().inner < rings.front().node;
  RadialSpectrum out;
  auto assemble = [&] {
    out.q.clear(), out.c.clear();
    if (low_end) out.q.push_back(rings.front().inner), out.c.push_back(rings.front().value);
    for (const Ring& r : rings) out.q.push_back(r.node), out.c.push_back(r.value);
    out.q.push_back(rings.back().outer), out.c.push_back(rings.back().value);
  };
  for (int step = 0;; ++step) {
    assemble();
    std::vector<double> carried(rings.size());
    double miss = 0.0;
    for (std::size_t k = 0; k < rings.size(); ++k) {
      carried[k] = 2.0 * kPi * core::log_log_moment(out.q, out.c, 1, rings[k].inner, rings[k].outer);
      miss += std::abs(carried[k] - rings[k].power);
    }
    if (miss <= kRingTolerance * variance || step == kRingSteps) break;
    for (std::size_t k = 0; k < rings.size(); ++k)
      if (carried[k] > 0.0 && rings[k].power > 0.0) rings[k].value *= rings[k].power / carried[k];
  }
  // C(q) -> a C(q/b)/b^2 keeps integral q C dq times a and multiplies integral q^3 C dq by a b^2.
  const double inf = std::numeric_limits<double>::infinity();
  const double m1 = core::log_log_moment(out.q, out.c, 1, 0.0, inf),
               m3 = core::log_log_moment(out.q, out.c, 3, 0.0, inf);
  const double a = variance / (2.0 * kPi * m1), b = std::sqrt(gradient / variance * m1 / m3);
  for (double& q : out.q) q *= b;
  for (double& c : out.c) c *= a / (b * b);
  out.scale = a, out.stretch = b;
  return out;
}

SynthesisedSurface synthesise_surface(const ArealSpectrum& s, int nx, int ny, double dx, double dy,
                                      std::uint64_t seed) {
  if (nx < 2 || ny < 1) throw std::invalid_argument("a synthesised surface needs at least 2 x 1 points");
  if (dx < s.dx * (1.0 - 1e-9) || dy < s.dy * (1.0 - 1e-9))
    throw std::invalid_argument(fmt::format(
        "spacings of {:.4g} x {:.4g} um are finer than the patch's {:.4g} x {:.4g} um: the patch holds no detail "
        "that fine",
        dx * 1e6, dy * 1e6, s.dx * 1e6, s.dy * 1e6));
  HeightGrid g = make_grid(nx, ny, dx, dy);  // checks kMaxGridPoints before the spectrum is allocated
  const int kx = nx / 2 + 1;
  const double dfx = 1.0 / (nx * dx), dfy = 1.0 / (ny * dy);
  std::vector<std::complex<double>> spec(static_cast<std::size_t>(ny) * kx);
  std::mt19937_64 rng(seed);
  for (int l = 0; l < ny; ++l)
    for (int i = 0; i < kx; ++i) {
      const double phase = 2.0 * kPi * core::uniform01(rng);
      // Each half-plane bin's |X|^2 = C df df (and its mirror's): the map's mean square is sum C df df.
      const double amplitude = std::sqrt(s.at(i * dfx, signed_bin(l, ny) * dfy) * dfx * dfy);
      spec[static_cast<std::size_t>(l) * kx + i] = std::polar(amplitude, phase);
    }
  // The columns that are their own mirror (fx = 0 and an even nx's Nyquist): the entry at -fy the
  // conjugate of that at fy, the self-conjugate ones real (the draw's cosine's sign).
  for (int i : {0, nx % 2 == 0 ? nx / 2 : -1}) {
    if (i < 0) continue;
    auto at = [&](int l) -> std::complex<double>& { return spec[static_cast<std::size_t>(l) * kx + i]; };
    for (int l = ny / 2 + 1; l < ny; ++l) at(l) = std::conj(at(ny - l));
    for (int l : {0, ny % 2 == 0 ? ny / 2 : 0}) at(l) = std::abs(at(l)) * (at(l).real() < 0.0 ? -1.0 : 1.0);
  }
  {
    const FftwPlan backward([&] {
      return fftw_plan_dft_c2r_2d(ny, nx, reinterpret_cast<fftw_complex*>(spec.data()), g.z.data(), FFTW_ESTIMATE);
    });
    fftw_execute(backward.get());  // z = sum X e^{+i 2 pi f.r}, unnormalised: as the amplitudes are set
  }
  double variance = 0.0;
  for (double z : g.z) variance += z * z;
  variance /= static_cast<double>(g.size());
  if (!(variance > 0.0))
    throw std::invalid_argument("no wavevector of the map carries the patch's power (sides shorter than its spacing)");
  SynthesisedSurface out;
  out.grid = std::move(g);
  out.resolved_fraction = s.patch_rq > 0.0 ? variance / (s.patch_rq * s.patch_rq) : 0.0;
  return out;
}

HeightGrid tile_surface(const HeightGrid& patch, int nx, int ny, double dx, double dy, double x0) {
  patch.validate();
  require_complete(patch, "the patch");
  if (patch.nx < 2 || patch.ny < 2) throw std::invalid_argument("a tiled patch needs at least 2 x 2 points");
  HeightGrid g = make_grid(nx, ny, dx, dy);
  double mean = 0.0;
  for (double z : patch.z) mean += z;
  mean /= static_cast<double>(patch.size());
  // The patch's coordinate of t by mirror images: t folded into [0, 2 L) and reflected beyond L.
  auto fold = [](double t, double length) {
    t = std::fmod(t, 2.0 * length);
    if (t < 0.0) t += 2.0 * length;
    return t > length ? 2.0 * length - t : t;
  };
  const double lx = (patch.nx - 1) * patch.dx, ly = (patch.ny - 1) * patch.dy;
  for (int j = 0; j < ny; ++j) {
    const double v = fold(j * dy, ly) / patch.dy;
    const int j0 = std::min(static_cast<int>(v), patch.ny - 2);
    const double tv = v - j0;
    for (int i = 0; i < nx; ++i) {
      const double u = fold(x0 + i * dx, lx) / patch.dx;
      const int i0 = std::min(static_cast<int>(u), patch.nx - 2);
      const double tu = u - i0;
      g.at(i, j) = (1.0 - tv) * ((1.0 - tu) * patch.at(i0, j0) + tu * patch.at(i0 + 1, j0)) +
                   tv * ((1.0 - tu) * patch.at(i0, j0 + 1) + tu * patch.at(i0 + 1, j0 + 1)) - mean;
    }
  }
  return g;
}

}  // namespace geartrib::surface
