// Reading a TOML data file key by key with units and validation. Every failure becomes an
// InputError naming the file, line, key, value and rule; keys that nothing read are reported as
// unknown (a misspelt key is an error, not a silent default).
#pragma once

#include "case/origin.hpp"
#include "config/input_error.hpp"
#include "config/units.hpp"

#include <toml++/toml.h>

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

class TomlReader {
 public:
  // Reads the whole file: a regular file of at most kMaxTomlFileBytes (1 MiB; config/text_lines.hpp),
  // else InputError naming the file.
  explicit TomlReader(const std::filesystem::path& file);
  // The same from text in memory (a case built in Python): `name` stands for the file in
  // messages; `directory` resolves relative file names (empty: name's folder). At most
  // kMaxTomlFileBytes.
  TomlReader(std::string text, const std::filesystem::path& name, const std::filesystem::path& directory = {});

  // Command-line changes, applied before reading: `set` gives a dotted key a value typed as on
  // the command line (TOML syntax if it parses as a TOML value: 30, 0.1, true, "x"; a bracketed
  // list of bare words as an array of them: [real_area, plastic_fraction]; otherwise the text as a
  // string: 4mm, kogut-etsion), creating tables as needed; `erase` removes a key.
  // Errors about a changed key name "--set key=value" instead of a line.
  void set(std::string_view key, const std::string& value_text);
  void erase(std::string_view key);

  const std::string& file() const { return file_; }
  // The folder relative file names in the file are taken from.
  std::filesystem::path directory() const {
    return directory_.empty() ? std::filesystem::path(file_).parent_path() : directory_;
  }

  bool has(std::string_view key) const;
  // Whether the key was given (or removed) by a command-line change.
  bool changed(std::string_view key) const { return changed_.contains(key); }
  bool is_string(std::string_view key) const;
  // Whether the key's value is a bare number: a TOML number, or a string holding a number
  // without a unit ("4.5"; a --set value typed 4.5 is a TOML number).
  bool is_bare_number(std::string_view key) const;
  // A quantity with a unit ("6 mm") or a bare SI number; required unless a fallback is given.
  double quantity(std::string_view key, Dimension d, std::optional<double> fallback = std::nullopt);
  std::vector<double> quantity_array(std::string_view key, Dimension d);
  double number(std::string_view key, std::optional<double> fallback = std::nullopt);
  long integer(std::string_view key, std::optional<long> fallback = std::nullopt);
  bool boolean(std::string_view key, std::optional<bool> fallback = std::nullopt);
  std::string string(std::string_view key, std::optional<std::string> fallback = std::nullopt);
  std::vector<std::string> string_array(std::string_view key);
  // The file's text as read.
  const std::string& text() const { return text_; }
  // Names of the entries of a table (empty when the table is absent).
  std::vector<std::string> keys_of(std::string_view table) const;

  // "file:line" of a key (or of its nearest enclosing table), or "file (--set key=value)" for a
  // key changed on the command line; for warnings and the parameters' origins.
  std::string where(std::string_view key) const;
  // The same as a structure: the key's file, the line and column of its value, or the --set
  // change naming it; an absent key's origin is the default, at its nearest enclosing table's line.
  Origin origin(std::string_view key) const;
  // The key's value as the file (or the --set) writes it: strings quoted, arrays item by item;
  // empty when absent.
  std::string value_text(std::string_view key) const;
  // "where: warning: key 'KEY' = VALUE: message", the form of every located warning.
  std::string warning(std::string_view key, const std::string& message) const;
  // Throws InputError for `key` with `rule`, pointing at the key's line and value.
  [[noreturn]] void fail(std::string_view key, const std::string& rule) const;
  // Throws for the first key that no accessor read.
  void check_all_used() const;

 private:
  void parse();
  const toml::node* find(std::string_view key) const;
  // The key's node, marked as read; nullptr when absent and a fallback exists; fails when
  // absent and required (`what` names the expected value).
  const toml::node* take(std::string_view key, bool has_fallback, const std::string& what);
  int line_of(std::string_view key) const;
  double to_quantity(const toml::node& n, std::string_view key, Dimension d) const;
  // A TOML integer or float as a double: finite, and an integer only within +-2^53 (exact).
  double node_number(const toml::node& n, std::string_view key) const;
  // The command-line change naming `key` (the key, a table it lies in, or a key inside it).
  const std::pair<const std::string, std::string>* change_of(std::string_view key) const;

  std::string file_;
  std::filesystem::path directory_;
  std::string text_;
  toml::table root_;
  std::set<std::string, std::less<>> used_;
  std::map<std::string, std::string, std::less<>> changed_;  // key -> value text from the command line
};

}  // namespace geartrib::io
