#include "surface/height_grid.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::surface {

std::size_t HeightGrid::missing() const { return static_cast<std::size_t>(std::count(valid.begin(), valid.end(), 0)); }

void HeightGrid::validate() const {
  if (nx < 2 || ny < 1) throw std::invalid_argument("height grid needs at least 2 x 1 points");
  if (!(dx > 0.0) || !(dy > 0.0) || !std::isfinite(dx) || !std::isfinite(dy))
    throw std::invalid_argument("grid spacing must be positive and finite");
  if (z.size() != static_cast<std::size_t>(nx) * ny || valid.size() != z.size())
    throw std::invalid_argument("height grid arrays have the wrong size");
}

HeightGrid make_grid(int nx, int ny, double dx, double dy) {
  HeightGrid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = dx;
  g.dy = dy;
  g.z.assign(static_cast<std::size_t>(nx) * ny, 0.0);
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
  auto sx = [&](int i) { return g.nx > 1 ? 2.0 * i / (g.nx - 1) - 1.0 : 0.0; };
  auto sy = [&](int j) { return g.ny > 1 ? 2.0 * j / (g.ny - 1) - 1.0 : 0.0; };
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(terms.size()));
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  Eigen::Index r = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (!g.ok(i, j)) continue;
      for (std::size_t t = 0; t < terms.size(); ++t)
        a(r, static_cast<Eigen::Index>(t)) = std::pow(sx(i), terms[t].first) * std::pow(sy(j), terms[t].second);
      b(r++) = g.at(i, j);
    }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double f = 0.0;
      for (std::size_t t = 0; t < terms.size(); ++t)
        f += c(static_cast<Eigen::Index>(t)) * std::pow(sx(i), terms[t].first) * std::pow(sy(j), terms[t].second);
      g.at(i, j) -= f;
    }
}

HeightGrid remove_waviness(HeightGrid& g, double cutoff) {
  g.validate();
  if (!(cutoff > 0.0)) throw std::invalid_argument("filter cut-off must be positive");
  const double alpha = std::sqrt(std::log(2.0) / std::numbers::pi);
  auto kernel = [&](double h) {
    const int half = static_cast<int>(std::ceil(cutoff / h));  // the weight is 2e-5 of its peak at lambda_c
    std::vector<double> w(static_cast<std::size_t>(2 * half + 1));
    for (int k = -half; k <= half; ++k) {
      const double t = k * h / (alpha * cutoff);
      w[static_cast<std::size_t>(k + half)] = std::exp(-std::numbers::pi * t * t);
    }
    return w;
  };
  const auto wx = kernel(g.dx), wy = kernel(g.dy);
  const int hx = static_cast<int>(wx.size() / 2), hy = static_cast<int>(wy.size() / 2);
  // Separable weighted mean of the valid points: numerator and weight sums.
  std::vector<double> num(g.size(), 0.0), den(g.size(), 0.0), num2(g.size(), 0.0), den2(g.size(), 0.0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double s = 0.0, w = 0.0;
      for (int k = -hx; k <= hx; ++k) {
        const int ii = i + k;
        if (ii < 0 || ii >= g.nx || !g.ok(ii, j)) continue;
        s += wx[static_cast<std::size_t>(k + hx)] * g.at(ii, j);
        w += wx[static_cast<std::size_t>(k + hx)];
      }
      num[static_cast<std::size_t>(j) * g.nx + i] = s;
      den[static_cast<std::size_t>(j) * g.nx + i] = w;
    }
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      double s = 0.0, w = 0.0;
      for (int k = -hy; k <= hy; ++k) {
        const int jj = j + k;
        if (jj < 0 || jj >= g.ny) continue;
        s += wy[static_cast<std::size_t>(k + hy)] * num[static_cast<std::size_t>(jj) * g.nx + i];
        w += wy[static_cast<std::size_t>(k + hy)] * den[static_cast<std::size_t>(jj) * g.nx + i];
      }
      num2[static_cast<std::size_t>(j) * g.nx + i] = s;
      den2[static_cast<std::size_t>(j) * g.nx + i] = w;
    }
  HeightGrid waviness = g;
  for (std::size_t k = 0; k < g.size(); ++k) {
    waviness.z[k] = den2[k] > 0.0 ? num2[k] / den2[k] : 0.0;
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
  while (g.missing() > 0) {
    std::vector<std::size_t> fill;
    std::vector<double> value;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        if (g.ok(i, j)) continue;
        double s = 0.0;
        int c = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int ii = i + di, jj = j + dj;
            if ((di || dj) && ii >= 0 && ii < g.nx && jj >= 0 && jj < g.ny && g.ok(ii, jj)) s += g.at(ii, jj), ++c;
          }
        if (c) fill.push_back(static_cast<std::size_t>(j) * g.nx + i), value.push_back(s / c);
      }
    for (std::size_t k = 0; k < fill.size(); ++k) {
      g.z[fill[k]] = value[k];
      g.valid[fill[k]] = 1;
    }
  }
}

HeightGrid grid_from_points(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                            double spacing) {
  if (x.size() != y.size() || x.size() != z.size()) throw std::invalid_argument("x, y and z need the same length");
  if (!(spacing > 0.0) || !std::isfinite(spacing)) throw std::invalid_argument("resampling spacing must be positive");
  if (x.empty()) throw std::invalid_argument("no points to grid");
  const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
  const auto [y0, y1] = std::minmax_element(y.begin(), y.end());
  const double nxd = std::floor((*x1 - *x0) / spacing) + 1, nyd = std::floor((*y1 - *y0) / spacing) + 1;
  if (nxd * nyd > 1e8) throw std::invalid_argument("resampling spacing too small: more than 1e8 grid points");
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
  if (!(spacing > 0.0) || !std::isfinite(spacing)) throw std::invalid_argument("resampling spacing must be positive");
  const double lx = (g.nx - 1) * g.dx, ly = (g.ny - 1) * g.dy;
  const int nx = static_cast<int>(std::floor(lx / spacing * (1 + 1e-12))) + 1;
  const int ny = static_cast<int>(std::floor(ly / spacing * (1 + 1e-12))) + 1;
  if (static_cast<double>(nx) * ny > 1e8)
    throw std::invalid_argument("resampling spacing too small: more than 1e8 grid points");
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
  if (form_degree < 0 || form_degree > 6) throw std::invalid_argument("form degree must lie in [0, 6]");
  if (!(waviness_cutoff >= 0.0) || !std::isfinite(waviness_cutoff))
    throw std::invalid_argument("waviness cut-off must be >= 0");
  if (!(outlier_limit == 0.0 || outlier_limit >= 2.0) || !std::isfinite(outlier_limit))
    throw std::invalid_argument("outlier limit must be 0 (off) or at least 2 robust standard deviations");
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
