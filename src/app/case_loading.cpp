#include "app/commands.hpp"

#include "io/case_file.hpp"

#include <iostream>

namespace geartrib::app {

void add_table_options(CLI::App* cmd, bool& csv, std::string& output) {
  cmd->add_flag("--csv", csv, "CSV with a header instead of aligned columns");
  cmd->add_option("-o,--output", output, "Write the table to this file (atomically) instead of stdout");
}

double quantity_option(const std::string& option, const std::string& text, io::Dimension d) {
  try {
    return io::parse_quantity(text, d);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(option + " '" + text + "': " + e.what());
  }
}

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
