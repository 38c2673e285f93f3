#include "contact/deterministic_contact.hpp"

#include "contact/position_threads.hpp"
#include "core/keyed_error.hpp"

#include "core/maximize.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace geartrib::contact {

void DeterministicOptions::validate() const {
  using core::KeyedError;
  if (!(element_size > 0.0 && std::isfinite(element_size)))
    throw KeyedError("element_size", "element size must be positive");
  if (!(strip_halfwidths >= kMinStripHalfwidths && strip_halfwidths <= kMaxStripHalfwidths))
    throw KeyedError("strip_halfwidths",
                     fmt::format("strip half-widths must lie in [{}, {}]", kMinStripHalfwidths, kMaxStripHalfwidths));
  if (!(pressure_cap > 0.0)) throw KeyedError("pressure_cap", "pressure cap must be positive");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    throw KeyedError("poisson_ratio", "Poisson ratio outside (-1, 0.5)");
  if (!(pinion_plastic_share >= 0.0 && pinion_plastic_share <= 1.0))
    throw KeyedError("pinion_plastic_share", "pinion plastic share outside [0, 1]");
  if (!(tolerance > 0.0 && tolerance < 1e-2)) throw KeyedError("tolerance", "tolerance outside (0, 0.01)");
  if (!(plastic_overlap >= 1e-15 && plastic_overlap <= 1e-3))
    throw KeyedError("plastic_overlap", "plastic overlap threshold outside [1e-15, 1e-3] m");
}

HalfPlaneGrid strip_grid(double half_length, const DeterministicOptions& o) {
  o.validate();
  if (!(half_length > 0.0 && std::isfinite(half_length))) throw std::invalid_argument("strip length must be positive");
  // Element edges at whole multiples of the element size from the contact point, whatever the
  // strip's length: a longer strip adds elements, it does not move them.
  const double elements = 2.0 * std::ceil(half_length / o.element_size);
  // The element size with the strip's length (a combination): unkeyed. The mesh cycle refuses it
  // first, at the keys (runs/mesh_cycle.cpp, the memory budget).
  if (elements > DeterministicOptions::kMaxElements)
    throw std::invalid_argument(fmt::format("the strip of {:.4g} mm needs {:.0f} elements of {:.4g} um (at most {})",
                                            2e3 * half_length, elements, o.element_size * 1e6,
                                            DeterministicOptions::kMaxElements));
  HalfPlaneGrid g;
  g.size = std::max(8, static_cast<int>(elements));
  g.spacing = o.element_size;
  g.start = -0.5 * g.size * g.spacing;
  return g;
}

namespace {

BemOptions bem_options(const HalfPlaneGrid& g, const DeterministicOptions& o) {
  BemOptions b;
  b.tolerance = o.tolerance;
  b.pressure_cap = o.pressure_cap;
  // Displacements referred to a depth of the strip's length (only the approach depends on it).
  b.reference_length = g.size * g.spacing;
  return b;
}

}  // namespace

double track_mean(const FlankTrack& t, double a, double b) {
  // The integral over [a, b]: whole trapezoids between the points inside, partial ones at the ends.
  const auto& z = t.profile.z;
  const double h = t.profile.spacing;
  if (z.size() < 2 || !(b > a)) throw std::invalid_argument("track_mean needs a profile and a < b");
  const double ua = a - t.start, ub = b - t.start;
  const auto last = static_cast<double>(z.size() - 1);
  if (!(ua >= -1e-9 * h && ub <= (last + 1e-9) * h))
    throw std::out_of_range(fmt::format("flank interval [{:.6g}, {:.6g}] mm outside its profile [{:.6g}, {:.6g}] mm",
                                        a * 1e3, b * 1e3, t.start * 1e3, t.end() * 1e3));
  const double pa = std::clamp(ua / h, 0.0, last), pb = std::clamp(ub / h, 0.0, last);
  const auto ka = std::min(static_cast<std::size_t>(pa), z.size() - 2);
  const auto kb = std::min(static_cast<std::size_t>(pb), z.size() - 2);
  auto partial = [&](std::size_t k, double f) {  // from point k to k + f
    return h * f * (z[k] + 0.5 * f * (z[k + 1] - z[k]));
  };
  double sum = -partial(ka, pa - static_cast<double>(ka));
  for (std::size_t k = ka; k < kb; ++k) sum += 0.5 * h * (z[k] + z[k + 1]);
  sum += partial(kb, pb - static_cast<double>(kb));
  return sum / (b - a);
}

StripSolver::StripSolver(double composite_modulus, double strip_half_length, const DeterministicOptions& options)
    : grid_(strip_grid(strip_half_length, options)),
      options_(options),
      bem_(grid_, composite_modulus, bem_options(grid_, options)) {
  if (std::isfinite(options.pressure_cap)) {
    BemOptions elastic = bem_options(grid_, options);
    elastic.pressure_cap = std::numeric_limits<double>::infinity();
    elastic_ = std::make_unique<HalfPlaneBem>(grid_, composite_modulus, elastic);
  }
}

std::vector<double> StripSolver::gap(const FlankTrack& pinion, const FlankTrack& wheel, const StripPosition& p) const {
  if (!(p.radius > 0.0)) throw std::invalid_argument("equivalent radius must be positive");
  std::vector<double> g(static_cast<std::size_t>(grid_.size));
  const double e = grid_.spacing;
  for (int j = 0; j < grid_.size; ++j) {
    const double x = grid_.x(j);
    // Element averages: the parabola's (x^2 + e^2/12)/(2R) and each flank's over the element.
    const double h1 = track_mean(pinion, p.sigma_pinion - x - 0.5 * e, p.sigma_pinion - x + 0.5 * e);
    const double h2 = track_mean(wheel, p.sigma_wheel + x - 0.5 * e, p.sigma_wheel + x + 0.5 * e);
    g[static_cast<std::size_t>(j)] = (x * x + e * e / 12.0) / (2.0 * p.radius) - h1 - h2;
  }
  return g;
}

DeterministicStrip StripSolver::solve(const FlankTrack& pinion, const FlankTrack& wheel, const StripPosition& p,
                                      bool keep_profiles) const {
  DeterministicStrip r;
  const double e = grid_.spacing;
  if (!(p.line_load > 0.0)) {  // no load: no contact
    if (keep_profiles) r.pressure.assign(static_cast<std::size_t>(grid_.size), 0.0), r.plastic = r.pressure;
    return r;
  }
  const std::vector<double> g0 = gap(pinion, wheel, p);
  BemSolution s;
  try {
    s = bem_.solve_load(g0, p.line_load);
  } catch (const std::runtime_error&) {
    // A load so light that the capped bracket cannot resolve it (the approach below the solves'
    // tolerance of the relief): the elastic answer, exact in load, is the answer when no element
    // reaches the cap.
    if (!elastic_) throw;
    s = elastic_->solve_load(g0, p.line_load);
    if (*std::max_element(s.pressure.begin(), s.pressure.end()) > options_.pressure_cap) throw;
  }
  r.iterations = s.iterations + s.coarse_iterations;
  const int n = grid_.size;
  int first = -1, last = -1, contact = 0, capped = 0;
  bool in_spot = false;
  for (int j = 0; j < n; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const bool touching = s.pressure[k] > 0.0;
    if (touching) {
      ++contact;
      if (first < 0) first = j;
      last = j;
      if (!in_spot) ++r.contact_spots;
      r.peak_pressure = std::max(r.peak_pressure, s.pressure[k]);
      if (-s.gap[k] > options_.plastic_overlap) {
        ++capped;
        r.max_plastic_deformation = std::max(r.max_plastic_deformation, -s.gap[k]);
      }
    }
    in_spot = touching;
  }
  r.edge_loaded = s.pressure.front() > 0.0 || s.pressure.back() > 0.0;
  r.real_area_per_width = contact * e;
  r.real_area_ratio = p.hertz_half_width > 0.0 ? r.real_area_per_width / (2.0 * p.hertz_half_width) : 0.0;
  r.mean_real_pressure = contact > 0 ? p.line_load / r.real_area_per_width : 0.0;
  r.plastic_area_per_width = capped * e;
  r.plastic_area_fraction = contact > 0 ? static_cast<double>(capped) / contact : 0.0;
  r.contact_half_width = first >= 0 ? 0.5 * (last - first + 1) * e : 0.0;
  if (keep_profiles) {
    r.pressure = s.pressure;
    r.plastic.resize(s.gap.size());
    for (std::size_t k = 0; k < s.gap.size(); ++k)
      r.plastic[k] = s.pressure[k] > 0.0 && -s.gap[k] > options_.plastic_overlap ? -s.gap[k] : 0.0;
  }
  if (options_.subsurface_stress && contact > 0) {
    // The von Mises maximum below the strip: a scan of columns (the spots' peaks and an even comb
    // across the contact) at depths from half an element to twice the Hertz half-width, then
    // Brent's method in depth at the best column and across the neighbouring elements.
    const SubsurfaceStressField field(grid_, s.pressure);
    const double nu = options_.poisson_ratio;
    std::vector<int> columns;
    std::vector<std::pair<double, int>> peaks;
    for (int j = first; j <= last; ++j) {
      const double pj = s.pressure[static_cast<std::size_t>(j)];
      const double left = j > 0 ? s.pressure[static_cast<std::size_t>(j - 1)] : 0.0;
      const double right = j + 1 < n ? s.pressure[static_cast<std::size_t>(j + 1)] : 0.0;
      if (pj > 0.0 && pj >= left && pj >= right) peaks.emplace_back(pj, j);
    }
    std::sort(peaks.begin(), peaks.end(), std::greater<>());
    for (std::size_t k = 0; k < peaks.size() && k < 32; ++k) columns.push_back(peaks[k].second);
    const int comb = 24;
    for (int k = 0; k <= comb; ++k) columns.push_back(first + (last - first) * k / comb);
    const double z_lo = 0.5 * e, z_hi = std::max(2.0 * std::max(p.hertz_half_width, r.contact_half_width), 4.0 * e);
    constexpr int kDepths = 20;
    double best = -1.0, best_x = 0.0, best_z = z_lo;
    for (int j : columns) {
      const double x = grid_.x(j);
      for (int m = 0; m < kDepths; ++m) {
        const double z = z_lo * std::pow(z_hi / z_lo, static_cast<double>(m) / (kDepths - 1));
        const double v = field.at(x, z, nu).von_mises();
        if (v > best) best = v, best_x = x, best_z = z;
      }
    }
    // Refine: depth at the best column, then across +-2 elements at that depth, then depth again.
    Maximum mz = maximize_on_interval([&](double z) { return field.at(best_x, z, nu).von_mises(); },
                                      std::max(0.25 * e, best_z / 3.0), std::min(3.0 * best_z, 2.0 * z_hi), 12);
    Maximum mx = maximize_on_interval([&](double x) { return field.at(x, mz.x, nu).von_mises(); }, best_x - 2.0 * e,
                                      best_x + 2.0 * e, 12);
    mz = maximize_on_interval([&](double z) { return field.at(mx.x, z, nu).von_mises(); },
                              std::max(0.25 * e, mz.x / 2.0), 2.0 * mz.x, 12);
    r.max_von_mises = std::max(best, mz.value);
    r.max_von_mises_depth = mz.value >= best ? mz.x : best_z;
    r.max_von_mises_x = mz.value >= best ? mx.x : best_x;
  }
  return r;
}

MeshPass mesh_pass(const FlankTrack& pinion, const FlankTrack& wheel, const std::vector<StripPosition>& positions,
                   double composite_modulus, double strip_half_length, const DeterministicOptions& options,
                   const std::vector<bool>& keep, int threads, const std::function<void(int, int)>& progress) {
  const int n = static_cast<int>(positions.size());
  MeshPass out;
  out.strips.resize(positions.size());
  out.plastic_pinion.assign(pinion.profile.z.size(), 0.0);
  out.plastic_wheel.assign(wheel.profile.z.size(), 0.0);
  std::mutex merge;
  const double share1 = options.pinion_plastic_share, share2 = 1.0 - share1;
  run_in_threads(
      threads, n,
      [&](ThreadItems& items) {
        const StripSolver solver(composite_modulus, strip_half_length, options);
        const HalfPlaneGrid& g = solver.grid();
        std::vector<double> d1(out.plastic_pinion.size(), 0.0), d2(out.plastic_wheel.size(), 0.0);
        // The plastic deformation at a flank's points: linear between the element centres (a
        // piecewise-constant one would leave steps of the element size on the finer profile).
        // direction: +1 when sigma = sigma_c + x (wheel), -1 when sigma = sigma_c - x (pinion).
        auto lay = [&g](const FlankTrack& t, double sigma_c, int direction, const std::vector<double>& d, int jlo,
                        int jhi, double share, std::vector<double>& into) {
          const double h = t.profile.spacing;
          const double x_lo = g.x(std::max(jlo - 1, 0)), x_hi = g.x(std::min(jhi + 1, g.size - 1));
          const double s_lo = direction > 0 ? sigma_c + x_lo : sigma_c - x_hi;
          const double s_hi = direction > 0 ? sigma_c + x_hi : sigma_c - x_lo;
          const auto last = static_cast<long>(t.profile.z.size()) - 1;
          const long k0 = std::max(0L, static_cast<long>(std::ceil((s_lo - t.start) / h)));
          const long k1 = std::min(last, static_cast<long>(std::floor((s_hi - t.start) / h)));
          for (long k = k0; k <= k1; ++k) {
            const double x = direction * (t.start + k * h - sigma_c);
            const double f = (x - g.x(0)) / g.spacing;
            const int j = std::clamp(static_cast<int>(std::floor(f)), 0, g.size - 2);
            const double w = std::clamp(f - j, 0.0, 1.0);
            const double dk =
                share * ((1.0 - w) * d[static_cast<std::size_t>(j)] + w * d[static_cast<std::size_t>(j + 1)]);
            auto& slot = into[static_cast<std::size_t>(k)];
            slot = std::max(slot, dk);
          }
        };
        for (int i = items.take(); i >= 0; i = items.take()) {
          const auto ui = static_cast<std::size_t>(i);
          const bool keep_i = ui < keep.size() && keep[ui];
          DeterministicStrip st;
          try {
            st = solver.solve(pinion, wheel, positions[ui], true);
          } catch (const std::runtime_error& e) {
            // Where, and the key that changes what the solves must resolve: their tolerance is relative to
            // the gap's relief across the strip (its parabola grows with the strip's length squared).
            throw std::runtime_error(fmt::format(
                "at position {} of {} (s = {:.6g} mm, line load {:.6g} N/m): {}; a shorter strip "
                "(contact.strip_halfwidths) or coarser elements (contact.element_size) ask less of the solves",
                i + 1, n, positions[ui].path * 1e3, positions[ui].line_load, e.what()));
          }
          int jlo = g.size, jhi = -1;
          for (int j = 0; j < g.size; ++j)
            if (st.plastic[static_cast<std::size_t>(j)] > 0.0) jlo = std::min(jlo, j), jhi = j;
          if (jhi >= 0) {
            if (share1 > 0.0) lay(pinion, positions[ui].sigma_pinion, -1, st.plastic, jlo, jhi, share1, d1);
            if (share2 > 0.0) lay(wheel, positions[ui].sigma_wheel, +1, st.plastic, jlo, jhi, share2, d2);
          }
          st.plastic = {};  // laid on the flanks: no output keeps it
          if (!keep_i) st.pressure = {};
          out.strips[ui] = std::move(st);
          items.finished();
        }
        const std::lock_guard lock(merge);
        for (std::size_t k = 0; k < d1.size(); ++k) out.plastic_pinion[k] = std::max(out.plastic_pinion[k], d1[k]);
        for (std::size_t k = 0; k < d2.size(); ++k) out.plastic_wheel[k] = std::max(out.plastic_wheel[k], d2[k]);
      },
      progress);
  for (double d : out.plastic_pinion) out.max_new_plastic = std::max(out.max_new_plastic, d);
  for (double d : out.plastic_wheel) out.max_new_plastic = std::max(out.max_new_plastic, d);
  return out;
}

surface::ProfileStatistics active_statistics(const FlankTrack& t, double a, double b) {
  const double h = t.profile.spacing;
  const auto last = static_cast<long>(t.profile.z.size()) - 1;
  const long k0 = std::clamp(static_cast<long>(std::ceil((a - t.start) / h)), 0L, last);
  const long k1 = std::clamp(static_cast<long>(std::floor((b - t.start) / h)), 0L, last);
  if (k1 - k0 < 2) throw std::invalid_argument("active part of the flank shorter than three profile points");
  return surface::profile_statistics(
      std::span<const double>(t.profile.z.data() + k0, static_cast<std::size_t>(k1 - k0 + 1)), h);
}

}  // namespace geartrib::contact
