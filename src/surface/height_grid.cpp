#include "surface/height_grid.hpp"

#include "core/keyed_error.hpp"

#include <fmt/format.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace geartrib::surface {

std::size_t HeightGrid::missing() const { return static_cast<std::size_t>(std::count(valid.begin(), valid.end(), 0)); }

void HeightGrid::validate() const {
  if (nx < 2 || ny < 1) throw std::invalid_argument("height grid needs at least 2 x 1 points");
  if (!(dx >= kMinSpacing && dx <= kMaxSpacing) || !(dy >= kMinSpacing && dy <= kMaxSpacing))
    throw std::invalid_argument(
        fmt::format("grid spacing {:g} x {:g} m outside {:g} m to {:g} m", dx, dy, kMinSpacing, kMaxSpacing));
  if (z.size() != static_cast<std::size_t>(nx) * ny || valid.size() != z.size())
    throw std::invalid_argument("height grid arrays have the wrong size");
}

void set_heights(HeightGrid& g, std::span<const double> z) {
  if (z.size() != g.size())
    throw std::invalid_argument(fmt::format("{} heights for a grid of {} points", z.size(), g.size()));
  for (std::size_t k = 0; k < z.size(); ++k) {
    g.valid[k] = !std::isnan(z[k]);
    g.z[k] = std::isnan(z[k]) ? 0.0 : z[k];
  }
}

std::string height_rule(const HeightGrid& g) {
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.valid[k] && !(std::abs(g.z[k]) <= kMaxHeight))
      return fmt::format("z[{}, {}] = {:g} m: heights must lie within +-{:g} m (the topography readers' limit)",
                         k / static_cast<std::size_t>(g.nx), k % static_cast<std::size_t>(g.nx), g.z[k], kMaxHeight);
  if (g.size() - g.missing() < kMinValidPoints)
    return fmt::format("z has {} valid (not NaN) heights of {}; at least {} are needed", g.size() - g.missing(),
                       g.size(), kMinValidPoints);
  return {};
}

std::vector<double> heights_or_nan(const HeightGrid& g) {
  std::vector<double> z(g.z);
  for (std::size_t k = 0; k < z.size(); ++k)
    if (!g.valid[k]) z[k] = std::numeric_limits<double>::quiet_NaN();
  return z;
}

HeightGrid make_grid(int nx, int ny, double dx, double dy) {
  if (nx > 0 && ny > 0 && static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) > kMaxGridPoints)
    throw std::invalid_argument(
        fmt::format("{} x {} points: more than the {} a grid may hold", nx, ny, kMaxGridPoints));
  HeightGrid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = dx;
  g.dy = dy;
  if (nx > 0 && ny > 0) g.z.assign(static_cast<std::size_t>(nx) * ny, 0.0);
  g.valid.assign(g.z.size(), 1);
  g.validate();
  return g;
}

void remove_form(HeightGrid& g, int degree) {
  g.validate();
  if (degree < 0 || degree > 6) throw std::invalid_argument("form degree must lie in [0, 6]");
  // Monomials x^a y^b with a + b <= degree, on coordinates scaled to [-1, 1] for conditioning.
  std::vector<std::pair<int, int>> terms;
  for (int t = 0; t <= degree; ++t)
    for (int a = t; a >= 0; --a) terms.emplace_back(a, t - a);
  const std::size_t n = g.size() - g.missing();
  if (n < terms.size()) throw std::invalid_argument("too few valid points for the form");
  // Powers of the scaled coordinates, per column and per row.
  const int p = degree + 1;
  std::vector<double> px(static_cast<std::size_t>(g.nx) * p), py(static_cast<std::size_t>(g.ny) * p);
  for (int i = 0; i < g.nx; ++i)
    for (int e = 0; e < p; ++e)
      px[static_cast<std::size_t>(i) * p + e] = std::pow(g.nx > 1 ? 2.0 * i / (g.nx - 1) - 1.0 : 0.0, e);
  for (int j = 0; j < g.ny; ++j)
    for (int e = 0; e < p; ++e)
      py[static_cast<std::size_t>(j) * p + e] = std::pow(g.ny > 1 ? 2.0 * j / (g.ny - 1) - 1.0 : 0.0, e);
  auto term = [&](int i, int j, std::size_t t) {
    return px[static_cast<std::size_t>(i) * p + terms[t].first] * py[static_cast<std::size_t>(j) * p + terms[t].second];
  };
  // Least squares by a blocked QR of [A b]: the triangle R of the rows so far is stacked on the
  // next block and factored again, so memory stays O(block x terms) for any grid (A itself would
  // be points x terms: 7.5 GB at degree 6 on the largest grid).
  const Eigen::Index t = static_cast<Eigen::Index>(terms.size());
  constexpr Eigen::Index kBlock = 4096;
  Eigen::MatrixXd stack(kBlock + t + 1, t + 1);
  Eigen::Index rows = 0;  // rows of R at the top of the stack
  Eigen::Index filled = 0;
  auto factor = [&] {
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(stack.topRows(filled));
    const Eigen::Index k = std::min(filled, t + 1);
    const Eigen::MatrixXd r = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
    stack.topRows(k) = r;
    rows = filled = k;
  };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (!g.ok(i, j)) continue;
      for (std::size_t q = 0; q < terms.size(); ++q) stack(filled, static_cast<Eigen::Index>(q)) = term(i, j, q);
      stack(filled, t) = g.at(i, j);
      if (++filled == kBlock + t + 1) factor();
    }
  if (filled > rows || rows == 0) factor();
  const Eigen::VectorXd c = stack.topLeftCorner(rows, t).colPivHouseholderQr().solve(stack.col(t).head(rows));
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double f = 0.0;
      for (std::size_t q = 0; q < terms.size(); ++q) f += c(static_cast<Eigen::Index>(q)) * term(i, j, q);
      g.at(i, j) -= f;
    }
}

namespace {

// In-place radix-2 FFT of a power-of-two length. Twiddles computed directly (not by recurrence),
// one contiguous table a stage, so the error stays ~1e-16 log2(n) of the largest value.
class Fft {
 public:
  explicit Fft(std::size_t n) : n_(n), reversed_(n), twiddle_(n) {
    for (std::size_t i = 0, j = 0; i < n; ++i) {
      reversed_[i] = j;
      std::size_t bit = n >> 1;
      for (; bit && (j & bit); bit >>= 1) j ^= bit;
      j |= bit;
    }
    for (std::size_t h = 1; h < n; h <<= 1)
      for (std::size_t k = 0; k < h; ++k)
        twiddle_[h + k] = std::polar(1.0, -std::numbers::pi * static_cast<double>(k) / static_cast<double>(h));
  }
  std::size_t size() const { return n_; }
  void forward(std::complex<double>* a) const {
    for (std::size_t i = 0; i < n_; ++i)
      if (i < reversed_[i]) std::swap(a[i], a[reversed_[i]]);
    for (std::size_t h = 1; h < n_; h <<= 1)
      for (std::size_t i = 0; i < n_; i += 2 * h)
        for (std::size_t k = 0; k < h; ++k) {
          const std::complex<double> w = twiddle_[h + k], b = a[i + k + h];
          const double vr = b.real() * w.real() - b.imag() * w.imag(), vi = b.real() * w.imag() + b.imag() * w.real();
          const std::complex<double> u = a[i + k];
          a[i + k] = {u.real() + vr, u.imag() + vi};
          a[i + k + h] = {u.real() - vr, u.imag() - vi};
        }
  }

 private:
  std::size_t n_;
  std::vector<std::size_t> reversed_;
  std::vector<std::complex<double>> twiddle_;
};

// Convolves `count` lines of n values (value k of line l at l * line_stride + k * step) of two
// arrays p and q with the symmetric kernel w (w[half + m]: the weight at offset m), out-of-range
// values counting as zero. Short kernels directly; long ones by FFT with p and q as the real and
// imaginary parts of one complex line (the kernel is real), zero-padded against wrap-around. The
// lines go in groups of 8 so that lines adjacent in memory (the columns) are gathered a row at a time.
void convolve_lines(std::vector<double>& p, std::vector<double>& q, int n, int count, std::size_t line_stride,
                    std::size_t step, const std::vector<double>& w) {
  const int half = static_cast<int>(w.size() / 2);
  auto at = [&](int l, int k) {
    return static_cast<std::size_t>(l) * line_stride + static_cast<std::size_t>(k) * step;
  };
  constexpr int kGroup = 8;
  if (w.size() <= 256) {  // the FFT path costs about as much as 300 weights a point
    std::vector<double> lp(static_cast<std::size_t>(n) * kGroup), lq(lp.size());
    for (int l0 = 0; l0 < count; l0 += kGroup) {
      const int lines = std::min(kGroup, count - l0);
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < lines; ++l) {
          lp[static_cast<std::size_t>(l) * n + k] = p[at(l0 + l, k)];
          lq[static_cast<std::size_t>(l) * n + k] = q[at(l0 + l, k)];
        }
      for (int l = 0; l < lines; ++l) {
        const double* a = lp.data() + static_cast<std::size_t>(l) * n;
        const double* b = lq.data() + static_cast<std::size_t>(l) * n;
        for (int i = 0; i < n; ++i) {
          double s = 0.0, d = 0.0;
          for (int m = std::max(-half, -i); m <= std::min(half, n - 1 - i); ++m) {
            s += w[static_cast<std::size_t>(m + half)] * a[i + m];
            d += w[static_cast<std::size_t>(m + half)] * b[i + m];
          }
          p[at(l0 + l, i)] = s;
          q[at(l0 + l, i)] = d;
        }
      }
    }
    return;
  }
  std::size_t size = 1;
  while (size < static_cast<std::size_t>(n) + static_cast<std::size_t>(half)) size <<= 1;
  const Fft fft(size);
  // The kernel's spectrum, real (the kernel is symmetric), with the 1/size of the inverse.
  std::vector<std::complex<double>> kernel(size, 0.0);
  for (int m = -half; m <= half; ++m)
    kernel[m >= 0 ? static_cast<std::size_t>(m) : size - static_cast<std::size_t>(-m)] =
        w[static_cast<std::size_t>(m + half)];
  fft.forward(kernel.data());
  std::vector<double> gain(size);
  for (std::size_t k = 0; k < size; ++k) gain[k] = kernel[k].real() / static_cast<double>(size);
  std::vector<std::complex<double>> buffer(size * kGroup);
  for (int l0 = 0; l0 < count; l0 += kGroup) {
    const int lines = std::min(kGroup, count - l0);
    std::fill(buffer.begin(), buffer.end(), 0.0);
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < lines; ++l)
        buffer[static_cast<std::size_t>(l) * size + k] = {p[at(l0 + l, k)], q[at(l0 + l, k)]};
    for (int l = 0; l < lines; ++l) {
      std::complex<double>* a = buffer.data() + static_cast<std::size_t>(l) * size;
      fft.forward(a);
      for (std::size_t k = 0; k < size; ++k) a[k] *= gain[k];
      fft.forward(a);  // the inverse, read backwards: IFFT(X)[k] = FFT(X)[-k] / size
    }
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < lines; ++l) {
        const std::complex<double> v = buffer[static_cast<std::size_t>(l) * size + (size - k) % size];
        p[at(l0 + l, k)] = v.real();
        q[at(l0 + l, k)] = v.imag();
      }
  }
}

}  // namespace

HeightGrid remove_waviness(HeightGrid& g, double cutoff) {
  g.validate();
  if (!(cutoff > 0.0) || !std::isfinite(cutoff)) throw std::invalid_argument("filter cut-off must be positive");
  // The cut-off against the grid, before any integer: at least two of the finer spacing (else the
  // filter takes the roughness itself), at most the longer side (a longer mean line is the form).
  const double finest = std::min(g.dx, g.dy), longest = std::max((g.nx - 1) * g.dx, (g.ny - 1) * g.dy);
  if (cutoff < 2.0 * finest)
    throw std::invalid_argument(
        fmt::format("cut-off {:g} m is shorter than two spacings ({:g} m): the filter would remove the roughness",
                    cutoff, 2.0 * finest));
  if (cutoff > longest)
    throw std::invalid_argument(
        fmt::format("cut-off {:g} m is longer than the surface ({:g} x {:g} m): the cut-off must lie within it", cutoff,
                    (g.nx - 1) * g.dx, (g.ny - 1) * g.dy));
  const double alpha = std::sqrt(std::log(2.0) / std::numbers::pi);
  auto kernel = [&](double h, int n) {
    // The weight is 6.5e-7 of its peak at lambda_c; beyond the grid's n - 1 no point contributes.
    const int half = static_cast<int>(std::min(std::ceil(cutoff / h), static_cast<double>(n - 1)));
    std::vector<double> w(static_cast<std::size_t>(2 * half + 1));
    for (int k = -half; k <= half; ++k) {
      const double t = k * h / (alpha * cutoff);
      w[static_cast<std::size_t>(k + half)] = std::exp(-std::numbers::pi * t * t);
    }
    return w;
  };
  // Separable weighted mean of the valid points: numerator and weight sums, along x then y.
  // The heights scaled to the weights' order (1): the FFT path carries both in one complex line,
  // whose rounding is relative to the larger of the two.
  double scale = 0.0;
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.valid[k]) scale = std::max(scale, std::abs(g.z[k]));
  if (!(scale > 0.0)) scale = 1.0;
  std::vector<double> num(g.size()), den(g.size());
  for (std::size_t k = 0; k < g.size(); ++k) {
    num[k] = g.valid[k] ? g.z[k] / scale : 0.0;
    den[k] = g.valid[k] ? 1.0 : 0.0;
  }
  const auto nx = static_cast<std::size_t>(g.nx);
  convolve_lines(num, den, g.nx, g.ny, nx, 1, kernel(g.dx, g.nx));
  if (g.ny > 1) convolve_lines(num, den, g.ny, g.nx, 1, nx, kernel(g.dy, g.ny));
  HeightGrid waviness = g;
  for (std::size_t k = 0; k < g.size(); ++k) {
    // A valid point's own weight is 1; below 1e-9 only a missing point far from every valid one.
    waviness.z[k] = den[k] > 1e-9 ? num[k] / den[k] * scale : 0.0;
    g.z[k] -= waviness.z[k];
  }
  return waviness;
}

std::size_t remove_outliers(HeightGrid& g, double k) {
  g.validate();
  if (!(k > 0.0)) throw std::invalid_argument("outlier threshold must be positive");
  std::vector<double> v;
  for (std::size_t i = 0; i < g.size(); ++i)
    if (g.valid[i]) v.push_back(g.z[i]);
  if (v.empty()) return 0;
  auto median = [](std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2), x.end());
    return x[x.size() / 2];
  };
  const double med = median(v);
  for (double& x : v) x = std::abs(x - med);
  const double sigma = 1.4826 * median(v);
  std::size_t removed = 0;
  for (std::size_t i = 0; i < g.size(); ++i)
    if (g.valid[i] && std::abs(g.z[i] - med) > k * sigma) {
      g.valid[i] = 0;
      ++removed;
    }
  return removed;
}

void fill_missing(HeightGrid& g) {
  g.validate();
  if (g.missing() == g.size()) throw std::invalid_argument("no valid point to fill from");
  // Ring by ring: each pass fills the missing points next to a valid one by the mean of their
  // valid neighbours; the next ring is the missing neighbours of this one (O(points) in all).
  std::vector<std::uint8_t> queued(g.size(), 0);
  std::vector<std::size_t> ring, next;
  auto each_neighbour = [&](std::size_t c, auto&& f) {
    const int i = static_cast<int>(c % static_cast<std::size_t>(g.nx)), j = static_cast<int>(c / g.nx);
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int ii = i + di, jj = j + dj;
        if ((di || dj) && ii >= 0 && ii < g.nx && jj >= 0 && jj < g.ny) f(static_cast<std::size_t>(jj) * g.nx + ii);
      }
  };
  for (std::size_t c = 0; c < g.size(); ++c) {
    if (g.valid[c]) continue;
    bool touches = false;
    each_neighbour(c, [&](std::size_t b) { touches = touches || g.valid[b]; });
    if (touches) ring.push_back(c), queued[c] = 1;
  }
  std::vector<double> value;
  while (!ring.empty()) {
    value.assign(ring.size(), 0.0);
    for (std::size_t k = 0; k < ring.size(); ++k) {
      double s = 0.0;
      int n = 0;
      each_neighbour(ring[k], [&](std::size_t b) {
        if (g.valid[b]) s += g.z[b], ++n;
      });
      value[k] = s / n;
    }
    next.clear();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      g.z[ring[k]] = value[k];
      g.valid[ring[k]] = 1;
    }
    for (std::size_t c : ring)
      each_neighbour(c, [&](std::size_t b) {
        if (!g.valid[b] && !queued[b]) queued[b] = 1, next.push_back(b);
      });
    ring.swap(next);
  }
}

HeightGrid grid_from_points(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                            double spacing) {
  if (x.size() != y.size() || x.size() != z.size()) throw std::invalid_argument("x, y and z need the same length");
  if (!(spacing >= kMinSpacing && spacing <= kMaxSpacing))
    throw std::invalid_argument(
        fmt::format("resampling spacing {:g} m outside {:g} m to {:g} m", spacing, kMinSpacing, kMaxSpacing));
  if (x.empty()) throw std::invalid_argument("no points to grid");
  const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
  const auto [y0, y1] = std::minmax_element(y.begin(), y.end());
  const double nxd = std::floor((*x1 - *x0) / spacing) + 1, nyd = std::floor((*y1 - *y0) / spacing) + 1;
  if (!(std::max(nxd, 2.0) * nyd <= static_cast<double>(kMaxGridPoints)))
    throw std::invalid_argument(fmt::format("spacing {:g} m gives {:.3g} x {:.3g} grid points, more than {}", spacing,
                                            std::max(nxd, 2.0), nyd, kMaxGridPoints));
  HeightGrid g = make_grid(std::max(2, static_cast<int>(nxd)), std::max(1, static_cast<int>(nyd)), spacing, spacing);
  std::vector<int> count(g.size(), 0);
  std::fill(g.z.begin(), g.z.end(), 0.0);
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (std::isnan(z[k])) continue;
    const int i = std::min(g.nx - 1, static_cast<int>((x[k] - *x0) / spacing));
    const int j = std::min(g.ny - 1, static_cast<int>((y[k] - *y0) / spacing));
    const std::size_t c = static_cast<std::size_t>(j) * g.nx + i;
    g.z[c] += z[k];
    ++count[c];
  }
  for (std::size_t c = 0; c < g.size(); ++c) {
    g.valid[c] = count[c] > 0;
    if (count[c] > 0) g.z[c] /= count[c];
  }
  return g;
}

HeightGrid resample(const HeightGrid& g, double spacing) {
  g.validate();
  if (!(spacing >= kMinSpacing && spacing <= kMaxSpacing))
    throw std::invalid_argument(
        fmt::format("resampling spacing {:g} m outside {:g} m to {:g} m", spacing, kMinSpacing, kMaxSpacing));
  const double lx = (g.nx - 1) * g.dx, ly = (g.ny - 1) * g.dy;
  const double nxd = std::floor(lx / spacing * (1 + 1e-12)) + 1, nyd = std::floor(ly / spacing * (1 + 1e-12)) + 1;
  if (!(std::max(nxd, 2.0) * nyd <= static_cast<double>(kMaxGridPoints)))
    throw std::invalid_argument(fmt::format("spacing {:g} m gives {:.3g} x {:.3g} grid points, more than {}", spacing,
                                            std::max(nxd, 2.0), nyd, kMaxGridPoints));
  const int nx = static_cast<int>(nxd), ny = static_cast<int>(nyd);
  HeightGrid r = make_grid(std::max(nx, 2), ny, spacing, spacing);
  for (int j = 0; j < r.ny; ++j)
    for (int i = 0; i < r.nx; ++i) {
      const double u = std::min(i * spacing / g.dx, g.nx - 1.0),
                   v = g.ny > 1 ? std::min(j * spacing / g.dy, g.ny - 1.0) : 0.0;
      const int i0 = std::min(static_cast<int>(u), g.nx - 2),
                j0 = g.ny > 1 ? std::min(static_cast<int>(v), g.ny - 2) : 0;
      const int j1 = g.ny > 1 ? j0 + 1 : 0;
      const double fu = u - i0, fv = g.ny > 1 ? v - j0 : 0.0;
      const bool ok = g.ok(i0, j0) && g.ok(i0 + 1, j0) && g.ok(i0, j1) && g.ok(i0 + 1, j1);
      r.valid[static_cast<std::size_t>(j) * r.nx + i] = ok;
      r.at(i, j) = ok ? (1 - fu) * (1 - fv) * g.at(i0, j0) + fu * (1 - fv) * g.at(i0 + 1, j0) +
                            (1 - fu) * fv * g.at(i0, j1) + fu * fv * g.at(i0 + 1, j1)
                      : 0.0;
    }
  return r;
}

void CleanupOptions::validate() const {
  using core::KeyedError;
  if (form_degree < 0 || form_degree > 6) throw KeyedError("form_degree", "form degree must lie in [0, 6]");
  if (!(waviness_cutoff >= 0.0) || !std::isfinite(waviness_cutoff))
    throw KeyedError("waviness_cutoff", "waviness cut-off must be >= 0");
  if (!(outlier_limit == 0.0 || outlier_limit >= 2.0) || !std::isfinite(outlier_limit))
    throw KeyedError("outlier_limit", "outlier limit must be 0 (off) or at least 2 robust standard deviations");
}

CleanupReport clean_surface(HeightGrid& g, const CleanupOptions& o) {
  o.validate();
  g.validate();
  CleanupReport r;
  r.missing_in = g.missing();
  // Outliers are judged on the form-free surface (a curved flank's form would dominate the
  // median absolute deviation), then masked on the original heights.
  if (o.outlier_limit > 0.0) {
    HeightGrid probe = g;
    if (o.form_degree > 0) remove_form(probe, o.form_degree);
    r.outliers = remove_outliers(probe, o.outlier_limit);
    g.valid = probe.valid;
  }
  if (o.fill) {
    r.filled = g.missing();
    fill_missing(g);
  }
  if (o.form_degree > 0) remove_form(g, o.form_degree);
  if (o.waviness_cutoff > 0.0) remove_waviness(g, o.waviness_cutoff);
  r.missing_out = g.missing();
  return r;
}

HeightGrid equivalent_surface(const HeightGrid& upper, const HeightGrid& lower, Mirror mirror) {
  upper.validate();
  lower.validate();
  if (upper.nx != lower.nx || upper.ny != lower.ny || std::abs(upper.dx / lower.dx - 1.0) > 1e-9 ||
      std::abs(upper.dy / lower.dy - 1.0) > 1e-9)
    throw std::invalid_argument("the two flanks' grids must have the same size and spacing");
  HeightGrid e = lower;
  for (int j = 0; j < e.ny; ++j)
    for (int i = 0; i < e.nx; ++i) {
      const int iu = mirror == Mirror::x ? e.nx - 1 - i : i, ju = mirror == Mirror::y ? e.ny - 1 - j : j;
      e.at(i, j) = lower.at(i, j) + upper.at(iu, ju);
      e.valid[static_cast<std::size_t>(j) * e.nx + i] = lower.ok(i, j) && upper.ok(iu, ju);
    }
  return e;
}

}  // namespace geartrib::surface
