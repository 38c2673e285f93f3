#include "io/table_writer.hpp"

#include <fmt/format.h>

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace geartrib::io {

std::string format_csv(const Table& t) {
  std::string out;
  for (std::size_t i = 0; i < t.header.size(); ++i) out += (i ? "," : "") + t.header[i];
  out += '\n';
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const bool labelled = !t.labels.empty();
    if (labelled) out += t.labels[r];
    for (std::size_t i = 0; i < t.rows[r].size(); ++i)
      out += fmt::format("{}{:.10g}", (i || labelled) ? "," : "", t.rows[r][i]);
    out += '\n';
  }
  return out;
}

std::string format_text(const Table& t) {
  std::vector<std::vector<std::string>> cells;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    std::vector<std::string> r;
    if (!t.labels.empty()) r.push_back(t.labels[k]);
    for (double v : t.rows[k]) r.push_back(fmt::format("{:.6g}", v));
    cells.push_back(std::move(r));
  }
  std::vector<std::size_t> width(t.header.size());
  for (std::size_t i = 0; i < t.header.size(); ++i) {
    width[i] = t.header[i].size();
    for (const auto& r : cells) width[i] = std::max(width[i], r[i].size());
  }
  std::string out;
  for (std::size_t i = 0; i < t.header.size(); ++i)
    out += fmt::format("{}{:>{}}", i ? "  " : "", t.header[i], width[i]);
  out += '\n';
  for (const auto& r : cells) {
    for (std::size_t i = 0; i < r.size(); ++i) out += fmt::format("{}{:>{}}", i ? "  " : "", r[i], width[i]);
    out += '\n';
  }
  return out;
}

void output_table(const Table& t, bool csv, const std::string& path) {
  const std::string text = csv ? format_csv(t) : format_text(t);
  if (path.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
  else write_file_atomically(path, text);
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write_temporary) {
  const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const auto tmp = dir / fmt::format(".{}.tmp.{}", path.filename().string(), ::getpid());
  try {
    write_temporary(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("cannot rename " + tmp.string() + " to " + path.string());
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out << content;
    out.flush();
    if (!out) throw std::runtime_error("error while writing " + tmp.string());
  });
}

}  // namespace geartrib::io
