#include "surface/profile_synthesis.hpp"

#include "core/fftw_planner.hpp"
#include "core/portable_random.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>

namespace geartrib::surface {

namespace {

constexpr double kPi = std::numbers::pi;

// The last bin of an N-point one-sided spectrum: N/2 (the Nyquist bin when N is even).
std::size_t last_bin(std::size_t n) { return n / 2; }

}  // namespace

double ProfileSpectrum::frequency_step() const { return 1.0 / (static_cast<double>(points) * spacing); }

double ProfileSpectrum::highest_frequency() const { return static_cast<double>(last_bin(points)) * frequency_step(); }

double ProfileSpectrum::variance() const {
  double sum = 0.0;
  for (std::size_t k = 1; k < psd.size(); ++k) sum += psd[k];
  if (points % 2 == 0 && psd.size() > 1) sum -= 0.5 * psd.back();  // the Nyquist bin: half a bin wide
  return sum * frequency_step();
}

double ProfileSpectrum::rq() const {
  double sum = 0.0;
  for (double h : heights) sum += h * h;
  return heights.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(heights.size()));
}

double ProfileSpectrum::resolved_variance() const {
  const double df = frequency_step();
  double sum = 0.0;
  for (std::size_t k = 1; k + 1 < psd.size(); ++k) {
    const double fk = static_cast<double>(k) * df, gk = psd[k], gk1 = psd[k + 1];
    if (!(gk > 0.0 && gk1 > 0.0)) {
      sum += 0.5 * (gk + gk1) * df;  // linear between the bins
      continue;
    }
    // int_{f_k}^{f_k+1} g_k (f/f_k)^p df = g_k f_k (r^(p+1) - 1)/(p + 1), r = f_k+1/f_k, p = ln(g_k+1/g_k)/ln r.
    const double log_r = std::log1p(1.0 / static_cast<double>(k)), p1 = std::log(gk1 / gk) / log_r + 1.0;
    const double x = p1 * log_r;
    sum += gk * fk * (std::abs(x) < 1e-12 ? log_r : std::expm1(x) / p1);
  }
  return sum;
}

double ProfileSpectrum::rolled_off_fraction() const {
  const double r = rq();
  return r > 0.0 ? 1.0 - resolved_variance() / (r * r) : 0.0;
}

double ProfileSpectrum::at(double f) const {
  if (psd.size() < 2) return 0.0;
  const double df = frequency_step();
  if (!(f >= df) || f > highest_frequency()) return 0.0;
  const auto k = std::min(static_cast<std::size_t>(f / df), psd.size() - 2);  // f in [f_k, f_{k+1}], k >= 1
  const double fk = static_cast<double>(k) * df, fk1 = static_cast<double>(k + 1) * df;
  const double gk = psd[k], gk1 = psd[k + 1];
  if (gk > 0.0 && gk1 > 0.0) return gk * std::pow(gk1 / gk, std::log(f / fk) / std::log(fk1 / fk));
  return gk + (gk1 - gk) * (f - fk) / df;
}

ProfileSpectrum profile_spectrum(const HeightGrid& g, bool along_x) {
  g.validate();
  const int count = along_x ? g.nx : g.ny, lines = along_x ? g.ny : g.nx;
  if (count < 8)
    throw std::invalid_argument(
        fmt::format("a line along {} has {} points: a spectrum needs at least 8", along_x ? "x" : "y", count));
  ProfileSpectrum s;
  s.spacing = along_x ? g.dx : g.dy;
  s.points = static_cast<std::size_t>(count);
  const std::size_t n = s.points, bins = last_bin(n) + 1;
  s.psd.assign(bins, 0.0);
  std::vector<double> window(n), line(n);
  double window_power = 0.0;  // sum w_j^2 (3N/8)
  for (std::size_t j = 0; j < n; ++j) {
    window[j] = 0.5 * (1.0 - std::cos(2.0 * kPi * static_cast<double>(j) / static_cast<double>(n)));
    window_power += window[j] * window[j];
  }
  const auto real = fftw_real_array(n);
  const auto spectrum = fftw_complex_array(bins);
  const int ni = count;
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_1d(ni, real.get(), spectrum.get(), FFTW_ESTIMATE); });
  s.heights.reserve(n * static_cast<std::size_t>(lines));
  for (int l = 0; l < lines; ++l) {
    bool complete = true;
    double mean = 0.0;
    for (int k = 0; k < count && complete; ++k) {
      const int i = along_x ? k : l, j = along_x ? l : k;
      complete = g.ok(i, j);
      line[static_cast<std::size_t>(k)] = g.at(i, j);
      mean += g.at(i, j);
    }
    if (!complete) continue;
    mean /= static_cast<double>(n);
    for (std::size_t k = 0; k < n; ++k) {
      line[k] -= mean;
      s.heights.push_back(line[k]);
      real[k] = window[k] * line[k];
    }
    fftw_execute(forward.get());
    // One-sided density 2 d |X_k|^2 / sum w^2 (the two-sided periodogram doubled; at k = N/2 too, where
    // variance() counts half a bin).
    for (std::size_t k = 1; k < bins; ++k)
      s.psd[k] += 2.0 * s.spacing * (spectrum[k][0] * spectrum[k][0] + spectrum[k][1] * spectrum[k][1]) / window_power;
    ++s.lines;
  }
  if (s.lines == 0)
    throw std::invalid_argument(fmt::format(
        "no line along {} is complete (every one has a missing point): fill the surface first", along_x ? "x" : "y"));
  for (double& v : s.psd) v /= static_cast<double>(s.lines);
  std::sort(s.heights.begin(), s.heights.end());
  return s;
}

SynthesisMethod synthesis_method(const std::string& name) {
  for (SynthesisMethod m : {SynthesisMethod::none, SynthesisMethod::psd, SynthesisMethod::iaaft})
    if (name == synthesis_method_name(m)) return m;
  throw std::invalid_argument("unknown synthesis method '" + name + "' (known: none, psd, iaaft)");
}

const char* synthesis_method_name(SynthesisMethod m) {
  switch (m) {
    case SynthesisMethod::none:
      return "none";
    case SynthesisMethod::psd:
      return "psd";
    case SynthesisMethod::iaaft:
      return "iaaft";
  }
  return "none";
}

SynthesisedProfile synthesise_profile(const ProfileSpectrum& s, const SynthesisOptions& o, double length) {
  if (o.method != SynthesisMethod::psd && o.method != SynthesisMethod::iaaft)
    throw std::invalid_argument("the synthesis method must be psd or iaaft");
  if (s.psd.size() < 2 || !(s.spacing > 0.0) || s.heights.empty())
    throw std::invalid_argument("the patch's spectrum is empty");
  const double d = o.spacing > 0.0 ? o.spacing : s.spacing;
  if (d < s.spacing * (1.0 - 1e-9))
    throw std::invalid_argument(
        fmt::format("a spacing of {:g} m is finer than the patch's {:g} m: nothing is measured at those wavelengths", d,
                    s.spacing));
  if (!(d <= kMaxSpacing)) throw std::invalid_argument(fmt::format("spacing must be at most {:g} m", kMaxSpacing));
  if (!(o.max_iterations >= 1)) throw std::invalid_argument("max_iterations must be at least 1");
  if (!(length > 0.0 && std::isfinite(length)))
    throw std::invalid_argument(fmt::format("profile length must be positive and finite (got {:g} m)", length));
  // As generate_profile: ceil(length/d) intervals, the ratio taken 1e-12 lower so that round-off adds none.
  const double intervals = std::ceil(length / d * (1.0 - 1e-12));
  if (!(intervals + 1.0 <= static_cast<double>(kMaxProfilePoints)))
    throw std::invalid_argument(fmt::format("a profile of {:g} m at spacing {:g} m needs {:.4g} points, more than {}",
                                            length, d, intervals + 1.0, kMaxProfilePoints));
  const std::size_t m = fast_fft_size(static_cast<std::size_t>(intervals) + 1);
  if (m > kMaxProfilePoints)
    throw std::invalid_argument(
        fmt::format("a profile of {:g} m at spacing {:g} m needs more than {} points", length, d, kMaxProfilePoints));
  const std::size_t bins = m / 2 + 1;
  const double df = 1.0 / (static_cast<double>(m) * d);
  // Amplitudes |C_j| of the unnormalised inverse transform z_i = sum_j C_j exp(2 pi i i j/m): a cosine
  // 2 |C_j| cos(...) of variance G df for 0 < j < m/2; the Nyquist term C (-1)^i of variance G df/2.
  std::vector<double> amplitude(bins, 0.0);
  for (std::size_t j = 1; j < bins; ++j) {
    const double g = s.at(static_cast<double>(j) * df);
    amplitude[j] = std::sqrt(g * df / 2.0);
  }
  const auto real = fftw_real_array(m);
  const auto spectrum = fftw_complex_array(bins);
  const int mi = static_cast<int>(m);
  const FftwPlan backward([&] { return fftw_plan_dft_c2r_1d(mi, spectrum.get(), real.get(), FFTW_ESTIMATE); });
  std::mt19937_64 rng(o.seed);
  spectrum[0][0] = spectrum[0][1] = 0.0;  // mean zero
  for (std::size_t j = 1; j < bins; ++j) {
    const double u = core::uniform01(rng);
    if (m % 2 == 0 && j == m / 2) {  // the Nyquist coefficient is real: phase 0 or pi
      spectrum[j][0] = u < 0.5 ? amplitude[j] : -amplitude[j];
      spectrum[j][1] = 0.0;
      continue;
    }
    spectrum[j][0] = amplitude[j] * std::cos(2.0 * kPi * u);
    spectrum[j][1] = amplitude[j] * std::sin(2.0 * kPi * u);
  }
  fftw_execute(backward.get());
  SynthesisedProfile out;
  out.profile.spacing = d;
  out.profile.z.assign(real.get(), real.get() + m);
  if (o.method == SynthesisMethod::psd) return out;

  // IAAFT (Schreiber & Schmitz 1996). The target heights: the patch's distribution at m points, scaled to
  // the variance of the psd profile (sum 2 C_j^2, C_N^2 at the Nyquist bin).
  double variance = 0.0;
  for (std::size_t j = 1; j < bins; ++j)
    variance += (m % 2 == 0 && j == m / 2 ? 1.0 : 2.0) * amplitude[j] * amplitude[j];
  const double patch_rq = s.rq();
  const double c = patch_rq > 0.0 ? std::sqrt(variance) / patch_rq : 0.0;
  out.height_scale = c;
  const std::size_t big_m = s.heights.size();
  std::vector<double> target(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double p =
        std::clamp((static_cast<double>(i) + 0.5) * static_cast<double>(big_m) / static_cast<double>(m) - 0.5, 0.0,
                   static_cast<double>(big_m - 1));
    const auto lo = static_cast<std::size_t>(p);
    const std::size_t hi = std::min(lo + 1, big_m - 1);
    const double w = p - static_cast<double>(lo);
    target[i] = c * (w == 0.0 ? s.heights[lo] : (1.0 - w) * s.heights[lo] + w * s.heights[hi]);
  }
  const FftwPlan forward([&] { return fftw_plan_dft_r2c_1d(mi, real.get(), spectrum.get(), FFTW_ESTIMATE); });
  std::vector<double>& x = out.profile.z;  // the spectrum-restored profile
  std::vector<double> y(m);                // its rank-ordered twin: the target's heights
  std::vector<std::size_t> order(m), previous;
  auto rank_order = [&] {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return x[a] < x[b] || (x[a] == x[b] && a < b); });
    for (std::size_t i = 0; i < m; ++i) y[order[i]] = target[i];
  };
  // Each pass: y's misfits; done when both are within bounds or at max_iterations, else the amplitudes
  // restored (y's phases kept; a zero coefficient takes phase 0) and y rank-ordered anew; a fixed point
  // (the ranks unchanged) leaves y as it was, and stops.
  rank_order();
  for (;;) {
    std::copy(y.begin(), y.end(), real.get());
    fftw_execute(forward.get());
    // |Y_j|/m against a_j (the unnormalised forward transform is m C_j); the curvature moment
    // sum (2 pi f_j)^4 C_j^2 against sum (2 pi f_j)^4 a_j^2 (the factor of the Nyquist bin alike on both).
    double misfit = 0.0, norm = 0.0, curvature = 0.0, curvature_norm = 0.0;
    for (std::size_t j = 1; j < bins; ++j) {
      const double r = std::hypot(spectrum[j][0], spectrum[j][1]) / static_cast<double>(m);
      const double w = std::pow(2.0 * kPi * static_cast<double>(j) * df, 4);
      misfit += (r - amplitude[j]) * (r - amplitude[j]);
      norm += amplitude[j] * amplitude[j];
      curvature += w * r * r;
      curvature_norm += w * amplitude[j] * amplitude[j];
    }
    out.spectrum_misfit = norm > 0.0 ? std::sqrt(misfit / norm) : 0.0;
    out.curvature_ratio = curvature_norm > 0.0 ? curvature / curvature_norm : 1.0;
    out.converged = out.spectrum_misfit <= kIaaftMisfit && std::abs(out.curvature_ratio - 1.0) <= kIaaftCurvature;
    if (out.converged || out.iterations >= o.max_iterations) break;
    for (std::size_t j = 0; j < bins; ++j) {
      const double r = std::hypot(spectrum[j][0], spectrum[j][1]);
      const double a = j == 0 ? 0.0 : amplitude[j];
      if (r > 0.0) {
        spectrum[j][0] *= a / r, spectrum[j][1] *= a / r;
      } else {
        spectrum[j][0] = a, spectrum[j][1] = 0.0;
      }
    }
    fftw_execute(backward.get());
    std::copy(real.get(), real.get() + m, x.begin());
    ++out.iterations;
    previous = order;
    rank_order();
    if (order == previous) break;  // a fixed point: y and its misfits as they were
  }
  x = y;
  return out;
}

}  // namespace geartrib::surface
