#include "contact/toeplitz_convolution.hpp"

#include "core/fftw_planner.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace geartrib::contact {

namespace {
thread_local long executed = 0;
thread_local double executed_seconds = 0.0;
}  // namespace

long ToeplitzConvolution::transforms() { return executed; }
double ToeplitzConvolution::transform_seconds() { return executed_seconds; }

ToeplitzConvolution::ToeplitzConvolution(const std::vector<double>& kernel, int n, bool periodic)
    : n_(n), m_(periodic ? n : 2 * n) {
  if (n < 1) throw std::invalid_argument("convolution size must be positive");
  if (kernel.size() != static_cast<std::size_t>(periodic ? n : 2 * n - 1))
    throw std::invalid_argument("kernel has the wrong length");
  real_ = fftw_alloc_real(static_cast<std::size_t>(m_));
  spectrum_ = fftw_alloc_complex(static_cast<std::size_t>(m_ / 2 + 1));
  if (!real_ || !spectrum_) throw std::bad_alloc();
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward_ = fftw_plan_dft_r2c_1d(m_, real_, spectrum_, FFTW_ESTIMATE);
    backward_ = fftw_plan_dft_c2r_1d(m_, spectrum_, real_, FFTW_ESTIMATE);
  }
  // Circular layout of the kernel: index m >= 0 at m, negative m at m_ + m.
  std::fill(real_, real_ + m_, 0.0);
  if (periodic) {
    std::copy(kernel.begin(), kernel.end(), real_);
  } else {
    for (int m = -(n - 1); m <= n - 1; ++m) real_[m >= 0 ? m : m_ + m] = kernel[static_cast<std::size_t>(m + n - 1)];
  }
  execute(forward_);
  kernel_hat_.resize(static_cast<std::size_t>(m_ / 2 + 1));
  for (int k = 0; k <= m_ / 2; ++k)
    kernel_hat_[static_cast<std::size_t>(k)] =
        std::complex<double>(spectrum_[k][0], spectrum_[k][1]) / static_cast<double>(m_);
}

ToeplitzConvolution::~ToeplitzConvolution() {
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(forward_);
    fftw_destroy_plan(backward_);
  }
  fftw_free(real_);
  fftw_free(spectrum_);
}

void ToeplitzConvolution::execute(fftw_plan plan) const {
  const auto start = std::chrono::steady_clock::now();
  fftw_execute(plan);
  executed_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++executed;
}

void ToeplitzConvolution::apply(const double* in, double* out) const {
  std::copy(in, in + n_, real_);
  std::fill(real_ + n_, real_ + m_, 0.0);
  execute(forward_);
  for (int k = 0; k <= m_ / 2; ++k) {
    const std::complex<double> v =
        std::complex<double>(spectrum_[k][0], spectrum_[k][1]) * kernel_hat_[static_cast<std::size_t>(k)];
    spectrum_[k][0] = v.real();
    spectrum_[k][1] = v.imag();
  }
  execute(backward_);
  std::copy(real_, real_ + n_, out);
}

void ToeplitzConvolution::apply_spectral(const double* in, double* out, const std::vector<double>& factor) const {
  if (factor.size() != static_cast<std::size_t>(m_ / 2 + 1))
    throw std::invalid_argument("spectral factor has the wrong length");
  std::copy(in, in + n_, real_);
  std::fill(real_ + n_, real_ + m_, 0.0);
  execute(forward_);
  for (int k = 0; k <= m_ / 2; ++k) {
    spectrum_[k][0] *= factor[static_cast<std::size_t>(k)];
    spectrum_[k][1] *= factor[static_cast<std::size_t>(k)];
  }
  execute(backward_);
  std::copy(real_, real_ + n_, out);
}

}  // namespace geartrib::contact
