// Shared fixtures of the test suite: the seed's case and its equivalent asperity pair.
#pragma once

#include "case/asperity_setup.hpp"
#include "case/case.hpp"
#include "case/contact_setup.hpp"
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "surface/height_grid.hpp"

#include <filesystem>

namespace geartrib::test {

inline std::filesystem::path source_dir() { return GEARTRIB_SOURCE_DIR; }
// The seed's own scene: its pair dry, the whole Hertz load on the asperities.
inline const Case& seed_case() {
  static const Case c = io::prepare_case(io::load_case(source_dir() / "gears/m6z30-dry.toml"));
  return c;
}
// The default case: the same pair lubricated (ISO VG 220 at 70 degC, assumed).
inline const Case& lubricated_case() {
  static const Case c = io::prepare_case(io::load_case(source_dir() / "gears/m6z30.toml"));
  return c;
}
inline asperity::ContactPair seed_pair() { return asperity::contact_pair(seed_case()); }

// n log-spaced values from lo to hi, both included.
inline std::vector<double> log_space(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1)));
  v.back() = hi;
  return v;
}

// The autocorrelation of a grid's heights at a lag of k points along x (open) or y (cyclic), over
// their mean square.
inline double autocorrelation(const surface::HeightGrid& g, int k, bool along_x) {
  double sum = 0.0, var = 0.0;
  std::size_t n = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      var += g.at(i, j) * g.at(i, j);
      if (along_x && i + k >= g.nx) continue;
      sum += g.at(i, j) * (along_x ? g.at(i + k, j) : g.at(i, (j + k) % g.ny)), ++n;
    }
  return sum / static_cast<double>(n) / (var / static_cast<double>(g.size()));
}

}  // namespace geartrib::test
