// FFTW's planner is not thread-safe: creating or destroying a plan must not run on two threads
// at once, while executing plans may (FFTW 3 manual, section 5.4 "Thread safety"). Every plan
// geartrib makes or destroys holds this lock: sweep points on threads and the Python module's
// callers on threads of their own plan concurrently.
#pragma once

#include <fftw3.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>

namespace geartrib {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex planner;
  return planner;
}

// Frees FFTW's aligned arrays: std::unique_ptr<double[], FftwFree>(fftw_alloc_real(n)).
struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

// FFTW-aligned arrays of n doubles or n complex values; std::bad_alloc when FFTW cannot allocate.
inline std::unique_ptr<double[], FftwFree> fftw_real_array(std::size_t n) {
  std::unique_ptr<double[], FftwFree> p(fftw_alloc_real(n));
  if (!p) throw std::bad_alloc();
  return p;
}
inline std::unique_ptr<fftw_complex[], FftwFree> fftw_complex_array(std::size_t n) {
  std::unique_ptr<fftw_complex[], FftwFree> p(fftw_alloc_complex(n));
  if (!p) throw std::bad_alloc();
  return p;
}

// An FFTW plan made and destroyed under the planner lock: FftwPlan p([&] { return fftw_plan_...; }).
class FftwPlan {
 public:
  template <class Make>
  explicit FftwPlan(Make make) {
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      p_ = make();
    }
    if (!p_) throw std::runtime_error("FFTW could not make a plan");
  }
  ~FftwPlan() {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(p_);
  }
  FftwPlan(const FftwPlan&) = delete;
  FftwPlan& operator=(const FftwPlan&) = delete;
  fftw_plan get() const { return p_; }

 private:
  fftw_plan p_ = nullptr;
};

// The smallest m' >= m with no prime factor above 7 (a fast FFTW size).
inline std::size_t fast_fft_size(std::size_t m) {
  for (;; ++m) {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

}  // namespace geartrib
