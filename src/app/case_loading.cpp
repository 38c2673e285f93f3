#include "app/case_loading.hpp"

#include "config/case_file.hpp"

#include <iostream>
#include <string>

namespace geartrib::app {

std::filesystem::path default_case_file() {
  std::filesystem::path local = "gears/m6z30.toml";  // not const: returned by move
  if (std::filesystem::exists(local)) return local;
  // An installed tool: <prefix>/bin/geartrib with its data in <prefix>/share/geartrib.
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    std::filesystem::path installed = exe.parent_path().parent_path() / "share/geartrib" / local;
    if (std::filesystem::exists(installed)) return installed;
  }
  return std::filesystem::path(GEARTRIB_SOURCE_DIR) / local;
}

std::filesystem::path case_path(const CaseOptions& o) {
  return o.file.empty() ? default_case_file() : std::filesystem::path(o.file);
}

std::vector<io::CaseChange> case_changes(const CaseOptions& o) {
  std::vector<io::CaseChange> parsed;
  parsed.reserve(o.changes.size());
  for (const auto& text : o.changes) parsed.push_back(io::parse_case_change(text));
  return parsed;
}

Case load_case_reporting(const CaseOptions& o, unsigned parts) {
  Case c = io::prepare_case(io::load_case(case_path(o), case_changes(o), parts));
  for (const auto& w : c.warnings) std::cerr << w << '\n';
  return c;
}

}  // namespace geartrib::app
