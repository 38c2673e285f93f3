// Reading and cleaning a topography file from the command line (surface, multi-asperity).
#pragma once

#include "config/input_error.hpp"
#include "topography/topography_files.hpp"

#include <stdexcept>

#include <string>

namespace CLI {
class App;
}

namespace geartrib::app {

struct SurfaceInputOptions {
  std::string unit = "um";  // ASCII length unit when the file does not state one
  std::string spacing;      // grid files without '# spacing:'
  std::string resample;     // regrid spacing
  int form_degree = 2;      // polynomial form removed
  std::string cutoff;       // Gaussian waviness cut-off
  double outliers = 0.0;    // k robust standard deviations; 0 off
  bool fill = false;
};
void add_surface_input_options(CLI::App* cmd, SurfaceInputOptions& o);
// Loads and cleans, printing the unit warnings and the clean-up report to stderr.
io::LoadedSurface load_surface_reporting(const std::string& file, const SurfaceInputOptions& o);
// Runs f on a loaded surface (statistics, summits, cylinders), turning the std::invalid_argument of
// a surface they refuse (too few valid points for slopes, a profile without points) into an
// InputError naming the file: exit 2 with the file named.
template <class F>
auto about_surface(const std::string& file, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw io::InputError(file, 0, "", "", e.what());
  }
}

}  // namespace geartrib::app
