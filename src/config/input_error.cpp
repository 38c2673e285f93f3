#include "config/input_error.hpp"

#include <fmt/format.h>

namespace geartrib::io {

namespace {
// Control characters shown as escapes ("\x00"): a NUL would end the message wherever it is read as
// a C string (what(), Python's str(e)), a carriage return or an escape sequence would rewrite the
// terminal. A rule may hold line breaks and tabs of its own.
std::string printable(const std::string& s, bool keep_layout) {
  std::string out;
  for (const char ch : s) {
    const auto byte = static_cast<unsigned char>(ch);
    if ((byte < 0x20 || byte == 0x7f) && !(keep_layout && (ch == '\n' || ch == '\t')))
      out += fmt::format("\\x{:02x}", byte);
    else out += ch;
  }
  return out;
}

std::string format(const std::string& file_text, int line, const std::string& key_text, const std::string& value_text,
                   const std::string& rule_text) {
  const std::string file = printable(file_text, false), key = printable(key_text, false);
  const std::string value = printable(value_text, false), rule = printable(rule_text, true);
  const std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  const std::string what =
      key.empty() ? (value.empty() ? "" : fmt::format("{}: ", value))
                  : (value.empty() ? fmt::format("key '{}': ", key) : fmt::format("key '{}' = {}: ", key, value));
  return fmt::format("{}: {}{}", where, what, rule);
}
}  // namespace

InputError::InputError(std::string file, int line, std::string key, std::string value, std::string rule)
    : std::runtime_error(format(file, line, key, value, rule)),
      file_(std::move(file)),
      key_(std::move(key)),
      value_(std::move(value)),
      rule_(std::move(rule)),
      line_(line) {}

}  // namespace geartrib::io
