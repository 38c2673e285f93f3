#include "config/text_lines.hpp"

#include "config/input_error.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

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

namespace {
std::string size_text(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 20) && bytes % (std::uintmax_t{1} << 20) == 0)
    return fmt::format("{} MiB", bytes >> 20);
  return fmt::format("{} bytes", bytes);
}
}  // namespace

std::string data_file_problem(const std::filesystem::path& file, std::uintmax_t limit) {
  if (file.empty()) return "no file named (an empty path)";
  std::error_code ec;
  const auto st = std::filesystem::status(file, ec);  // follows symbolic links
  if (ec) {
    if (ec == std::errc::no_such_file_or_directory) return "file not found: " + file.string();
    return "cannot read " + file.string() + ": " + ec.message();
  }
  if (!std::filesystem::exists(st)) return "file not found: " + file.string();
  if (std::filesystem::is_directory(st)) return file.string() + " is a folder, not a file";
  if (!std::filesystem::is_regular_file(st))
    return file.string() + " is not a regular file (a device, pipe or socket is never read as data)";
  if (limit != kNoSizeLimit) {
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec) return "cannot read " + file.string() + ": " + ec.message();
    if (size > limit)
      return fmt::format("{} is {} bytes, beyond the {} limit of this kind of data file", file.string(), size,
                         size_text(limit));
  }
  return "";
}

std::string read_data_file(const std::filesystem::path& file, std::uintmax_t limit) {
  if (const std::string why = data_file_problem(file, limit); !why.empty())
    throw InputError(file.string(), 0, "", "", why);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "", "", std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (limit != kNoSizeLimit && text.size() > limit)
      throw InputError(file.string(), 0, "", "",
                       fmt::format("grew beyond the {} limit of this kind of data file while read", size_text(limit)));
  }
  if (in.bad()) throw InputError(file.string(), 0, "", "", "read error");
  return text;
}

}  // namespace geartrib::io
