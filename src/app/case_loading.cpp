#include "app/commands.hpp"

#include "io/case_file.hpp"

#include <iostream>

namespace geartrib::app {

std::filesystem::path default_case_file() {
  const std::filesystem::path local = "gears/m6z30.toml";
  if (std::filesystem::exists(local)) return local;
  return std::filesystem::path(GEARTRIB_SOURCE_DIR) / local;
}

Case load_case_reporting(const std::string& file) {
  Case c = io::load_case(file.empty() ? default_case_file() : std::filesystem::path(file));
  for (const auto& w : c.warnings) std::cerr << w << '\n';
  return c;
}

}  // namespace geartrib::app
