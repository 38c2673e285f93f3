// Discrete convolution with a Toeplitz kernel by FFT (FFTW): out_i = sum_j k(i - j) in_j for
// i, j in [0, n). Non-periodic (zero-padded to 2n, "DC-FFT", Liu, Wang & Liu 2000) or periodic
// (circular, size n).
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
  int size() const { return n_; }

 private:
  int n_;
  int m_;  // FFT length
  std::vector<std::complex<double>> kernel_hat_;
  double* real_;
  fftw_complex* spectrum_;
  fftw_plan forward_;
  fftw_plan backward_;
};

}  // namespace geartrib::contact
