// Shared by the libFuzzer harnesses: the input written to a file (the loaders read files), and
// the rule every harness enforces: an input may be refused only as geartrib refuses bad input
// (io::InputError or std::invalid_argument: exit 2 with a message); any other exception would be
// exit 1 (an internal failure) and is a finding, as are crashes, sanitizer reports, hangs
// (-timeout) and allocations beyond -rss_limit_mb.
#pragma once

#include "config/input_error.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace geartrib::fuzz {

// A folder of this process's own under the temporary directory, made once.
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("geartrib-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const auto path = scratch() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

// Runs `body`; returns normally for an accepted input or a located refusal, aborts otherwise.
template <class Body>
void expect_accepted_or_refused(Body&& body) {
  try {
    body();
  } catch (const io::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: an exception other than a located input error: %s\n", e.what());
    std::abort();
  }
}

// A number that reached the outputs must be finite (exit 0 with NaN or inf is a finding).
inline void expect_finite(double v, const char* what) {
  if (!std::isfinite(v)) {
    std::fprintf(stderr, "finding: %s = %g accepted\n", what, v);
    std::abort();
  }
}

}  // namespace geartrib::fuzz
