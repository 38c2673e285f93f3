// A flank-long profile synthesised from a measured patch shorter than the flank (an interferometer's
// field): the patch's profile power spectrum along the involute given random phases at a stated seed,
// optionally with the patch's height distribution kept by IAAFT (Schreiber & Schmitz, Phys. Rev.
// Lett. 77 (1996) 635). It cannot invent what the patch does not hold: no wavelength longer than the
// patch's line (zero power below 1/(N d)), no detail finer than its spacing (finer spacings refused).
#pragma once

#include "surface/flank_profile.hpp"
#include "surface/height_grid.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace geartrib::surface {

// A patch's one-sided profile power spectral density along one axis, the mean over its lines of each
// line's Hann-windowed periodogram (the line's mean removed, w_j = (1 - cos(2 pi j/N))/2, normalised by
// sum w_j^2 so that a stationary line's variance is sum G_k df; Press et al., Numerical Recipes, 3rd ed.,
// sec. 13.4). Lines with a missing point are left out. Also the lines' heights (each about its own mean),
// pooled and sorted: the height distribution IAAFT keeps.
struct ProfileSpectrum {
  double spacing = 0.0;         // d [m]
  std::size_t points = 0;       // N, each line's points (the transform's length)
  std::size_t lines = 0;        // lines averaged
  std::vector<double> psd;      // G_k [m^3] at f_k = k/(N d), k = 0..N/2 (density, also at k = N/2); G_0 = 0
  std::vector<double> heights;  // the lines' heights about their own means, ascending [m]

  double frequency_step() const;     // df = 1/(N d) [1/m]: the lowest frequency resolved, f_1
  double highest_frequency() const;  // f_{floor(N/2)} [1/m]
  // sum_{k>=1} G_k df, the Nyquist bin of an even N counted half (it covers [f_N - df/2, f_N]) [m^2]:
  // the lines' mean windowed variance (Parseval).
  double variance() const;
  double rq() const;  // root-mean-square of `heights` [m]
  // The variance a synthesis takes: the integral of at(f) from f_1 to the highest bin [m^2], in closed
  // form on each interval between bins.
  double resolved_variance() const;
  // The share of the patch's height variance (rq()^2) a synthesis leaves out: 1 - resolved_variance()/rq^2.
  // It lies at wavelengths near and beyond the line's length: the half of bin 1 below f_1 (bin k stands
  // for [f_k - df/2, f_k + df/2]) and what a window of the line's length cannot resolve (longer waves,
  // seen in part as each line's slope and bow).
  double rolled_off_fraction() const;
  // The PSD a synthesis takes at f [1/m]: zero below f_1 (no wavelength longer than the line) and
  // above the highest bin; between bins k and k + 1 interpolated linearly in log f and log G (exact for
  // a power law), linearly in G where either bin is zero.
  double at(double f) const;
};

// Throws std::invalid_argument for a grid with no complete line, or lines of fewer than 8 points.
ProfileSpectrum profile_spectrum(const HeightGrid& g, bool along_x);

enum class SynthesisMethod { none, psd, iaaft };
SynthesisMethod synthesis_method(const std::string& name);  // "none" | "psd" | "iaaft"; invalid_argument otherwise
const char* synthesis_method_name(SynthesisMethod m);

// The IAAFT's stopping rule. Converged: the rank-ordered profile's Fourier amplitudes within kIaaftMisfit
// (rms, relative) of the spectrum's, ~1% in power, below a measured spectrum's own scatter (a patch's
// band powers scatter by percents); and its curvature moment m4 = sum (2 pi f)^4 G df within
// kIaaftCurvature of the spectrum's: the rank step adds roughness at the sampling scale, small in
// height but weighted by f^4 in m4 (summit radii ~ m4^-1/2: within 2.5%). Stopped unconverged after
// max_iterations spectrum restorations, or at a fixed point (the ranks unchanged by a pass; Schreiber &
// Schmitz). Patches with power down to their sampling scale converge in a few to tens of passes (Rsk
// 1.6: 11 passes); on the shipped synthetic patches, bare below 7.5 um wavelengths along x, the first
// rank step nearly doubles m4: the pinion's converges after 110 passes, the wheel's stalls at +8%.
inline constexpr double kIaaftMisfit = 5e-3;
inline constexpr double kIaaftCurvature = 0.05;
inline constexpr int kIaaftIterations = 200;

struct SynthesisOptions {
  SynthesisMethod method = SynthesisMethod::psd;
  std::uint64_t seed = 1;
  double spacing = 0.0;  // [m]; 0: the patch's. Finer than the patch's: refused; coarser: G above its Nyquist dropped
  int max_iterations = kIaaftIterations;  // IAAFT, >= 1
};

struct SynthesisedProfile {
  FlankProfile profile;
  int iterations = 0;            // IAAFT spectrum restorations run (0 for psd)
  bool converged = true;         // IAAFT: both misfits within bounds (kIaaftMisfit, kIaaftCurvature)
  double spectrum_misfit = 0.0;  // IAAFT: rms of |Z_j| - A_j over rms A_j (A_j the PSD's amplitudes), at the end
  double curvature_ratio = 1.0;  // IAAFT: its m4 over the spectrum's, at the end
  double height_scale = 1.0;     // IAAFT: the factor c on the patch's heights (below)
};

// A profile of at least `length` [m]: m points, m the smallest FFT-friendly count (no prime factor above
// 7) of at least ceil(length/spacing) + 1, periodic with period m spacings.
//  - psd: z = sum_j a_j cos(2 pi f_j x + phi_j), f_j = j/(m d), a_j = sqrt(2 G(f_j) df_m) (G the spectrum's
//    at(), df_m = 1/(m d)): fixed amplitudes, so the profile's periodogram is G(f_j) at every f_j and its
//    variance sum G(f_j) df_m, whatever the seed; phases phi_j uniform on [0, 2 pi) from std::mt19937_64(seed),
//    one draw per j ascending, as (draw >> 11) 2^-53 (portable: no std distribution); the Nyquist term, a
//    real coefficient, takes the sign of the draw's half. Mean zero.
//  - iaaft: from that profile, alternately (1) heights replaced, rank for rank, by the patch's
//    distribution at m points, scaled by c = sqrt(the psd profile's variance / rq()^2) (its sorted heights at
//    fractional positions (i + 1/2) M/m - 1/2, linear between them, times c; M the patch's heights: exactly
//    c times them when m = M), (2) Fourier amplitudes reset to a_j with the phases kept, until converged
//    (kIaaftMisfit, kIaaftCurvature), the ranks stop changing or max_iterations; the result is a step (1). The patch's
//    height distribution is kept in shape (every quantile over Rq, so Rsk and Rku) at the variance of the spectrum the
//    synthesis resolves: the variance rolled off is not put back at other wavelengths. The spectrum is kept
//    approximately (spectrum_misfit).
// Throws std::invalid_argument for a finer spacing than the patch's, a length beyond kMaxProfilePoints
// points, or an empty spectrum.
SynthesisedProfile synthesise_profile(const ProfileSpectrum& s, const SynthesisOptions& o, double length);

}  // namespace geartrib::surface
