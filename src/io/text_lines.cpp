#include "io/text_lines.hpp"

#include <sstream>

namespace geartrib::io {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

std::optional<std::pair<std::string, std::string>> comment_entry(const std::string& line) {
  if (line.empty() || line[0] != '#') return std::nullopt;
  const auto colon = line.find(':');
  if (colon == std::string::npos) return std::nullopt;
  return std::pair{trim(line.substr(1, colon - 1)), trim(line.substr(colon + 1))};
}

}  // namespace geartrib::io
