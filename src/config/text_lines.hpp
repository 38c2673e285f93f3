// Line-level pieces shared by the ASCII readers (reference tables, fit data, topography files),
// and the one way a data file is opened: a regular file of bounded size, checked before reading.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
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

// Size limits of the files read whole into memory (docs/reference/units.md, "Data files").
inline constexpr std::uintmax_t kMaxTomlFileBytes = std::uintmax_t{1} << 20;    // case, material, lubricant: 1 MiB
inline constexpr std::uintmax_t kMaxTableFileBytes = std::uintmax_t{64} << 20;  // fit data, reference tables: 64 MiB
inline constexpr std::uintmax_t kNoSizeLimit = std::numeric_limits<std::uintmax_t>::max();

// Why `file` cannot be read as a data file of at most `limit` bytes: not found, not a regular
// file (a folder, a device such as /dev/zero, a pipe), larger than the limit, or a path the system
// refuses (a name too long, a component that is not a folder, no permission). Empty when it can.
// Never throws: the reasons come from error codes, not std::filesystem exceptions.
std::string data_file_problem(const std::filesystem::path& file, std::uintmax_t limit);
// The whole text of `file`, at most `limit` bytes (a file that grows past the limit while it is
// read is refused too); throws InputError(file, 0, "", "", reason) when it cannot be read.
std::string read_data_file(const std::filesystem::path& file, std::uintmax_t limit);

}  // namespace geartrib::io
