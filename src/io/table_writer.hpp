// Tables for people (aligned columns) or programs (CSV), and files written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace geartrib::io {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

// CSV: header line, then rows with full precision (%.10g). Text: right-aligned columns (%.6g).
std::string format_csv(const Table& t);
std::string format_text(const Table& t);

// Writes `content` to `path` through a temporary file in the same directory, renamed into
// place when complete: a reader never sees a half-written file. Throws std::runtime_error.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace geartrib::io
