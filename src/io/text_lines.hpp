// Line-level pieces shared by the ASCII readers (reference tables, fit data, topography files).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::io {

// Without leading and trailing blanks (space, tab, carriage return).
std::string trim(const std::string& s);
// Comma-separated cells, each trimmed; a trailing comma gives a final empty cell.
std::vector<std::string> split_csv(const std::string& line);
// A '# key: value' comment line (the '#' first on the line): key and value, trimmed.
std::optional<std::pair<std::string, std::string>> comment_entry(const std::string& line);

}  // namespace geartrib::io
