// FFTW's planner is not thread-safe: creating or destroying a plan must not run on two threads
// at once, while executing plans may (FFTW 3 manual, section 5.4 "Thread safety"). Every plan
// geartrib makes or destroys holds this lock: sweep points on threads and the Python module's
// callers on threads of their own plan concurrently.
#pragma once

#include <mutex>

namespace geartrib {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex planner;
  return planner;
}

}  // namespace geartrib
