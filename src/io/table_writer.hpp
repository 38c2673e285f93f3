// Tables for people (aligned columns) or programs (CSV), and files written atomically.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace geartrib::io {

// A numeric table; when `labels` is not empty, each row starts with its label and header[0]
// names that label column.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<std::string> labels;
  // A labelled row (name/value summaries, per-asperity rows).
  void add_row(std::string label, std::vector<double> values) {
    labels.push_back(std::move(label));
    rows.push_back(std::move(values));
  }
};

// CSV: header line, then rows with full precision (%.10g). Text: right-aligned columns (%.6g).
std::string format_csv(const Table& t);
std::string format_text(const Table& t);

// The table as CSV or text, to stdout when `path` is empty, else to `path` atomically.
void output_table(const Table& t, bool csv, const std::string& path);

// Writes `path` through a temporary file in the same directory (written by `write_temporary`),
// renamed into place when complete: a reader never sees a half-written file, and a failure
// removes the temporary. Throws std::runtime_error.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write_temporary);
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace geartrib::io
