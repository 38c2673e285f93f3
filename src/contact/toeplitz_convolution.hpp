// Discrete convolution with a Toeplitz kernel by FFT (FFTW): out_i = sum_j k(i - j) in_j for
// i, j in [0, n). Non-periodic (zero-padded to 2n, "DC-FFT", Liu, Wang & Liu 2000) or periodic
// (circular, size n). The plans and buffers are made once, at construction; apply() allocates
// nothing. FFTW_ESTIMATE plans: FFTW_MEASURE takes ~2 s to plan 2^15 points and ~9 s for 2^17
// to save 10-40% of a transform's ~0.1-0.7 ms, which a solve of a few hundred transforms never
// pays back (and wisdom would have to be kept between runs).
#pragma once

#include <fftw3.h>

#include <complex>
#include <memory>
#include <vector>

namespace geartrib::contact {

class ToeplitzConvolution {
 public:
  // kernel[m + n - 1] = k(m) for m = -(n-1) .. n-1 (non-periodic), or kernel[m] = k(m) for
  // m = 0 .. n-1 (periodic, k(-m) = k(n - m)).
  ToeplitzConvolution(const std::vector<double>& kernel, int n, bool periodic);
  ~ToeplitzConvolution();
  ToeplitzConvolution(const ToeplitzConvolution&) = delete;
  ToeplitzConvolution& operator=(const ToeplitzConvolution&) = delete;

  void apply(const double* in, double* out) const;
  // out = the first n of IFFT(factor .* FFT(in zero-padded to fft_size())), factor real, of
  // fft_size()/2 + 1 values and including the 1/fft_size() of the inverse transform: a
  // circulant operator with the eigenvalues factor * fft_size() (a preconditioner).
  void apply_spectral(const double* in, double* out, const std::vector<double>& factor) const;
  int size() const { return n_; }
  int fft_size() const { return m_; }
  // FFTs (one r2c or one c2r each) this thread's convolutions have executed, and the wall time
  // spent in them [s]: a solver's cost is the difference over its run.
  static long transforms();
  static double transform_seconds();

 private:
  int n_;
  int m_;  // FFT length
  std::vector<std::complex<double>> kernel_hat_;
  double* real_;
  fftw_complex* spectrum_;
  fftw_plan forward_;
  fftw_plan backward_;
  void execute(fftw_plan plan) const;
};

}  // namespace geartrib::contact
