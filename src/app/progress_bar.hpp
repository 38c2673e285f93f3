// A one-line progress bar with elapsed time and ETA on a terminal's stderr; silent when stderr is
// not a terminal (logs, CI) or when disabled. Thread-safe: workers may report concurrently.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace geartrib::app {

class ProgressBar {
 public:
  ProgressBar(bool enabled, std::string unit) : enabled_(enabled && ::isatty(STDERR_FILENO)), unit_(std::move(unit)) {}
  void operator()(int done, int total) {
    if (!enabled_ || total <= 0) return;
    const std::lock_guard lock(mutex_);
    const int width = 40, filled = width * done / total;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = done > 0 ? elapsed * (total - done) / done : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d %s  %.1f s  eta %.1f s", std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), done, total, unit_.c_str(), elapsed, eta);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

 private:
  bool enabled_;
  std::string unit_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace geartrib::app
