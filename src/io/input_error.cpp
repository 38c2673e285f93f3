#include "io/input_error.hpp"

#include <fmt/format.h>

namespace geartrib::io {

namespace {
std::string format(const std::string& file, int line, const std::string& key, const std::string& value,
                   const std::string& rule) {
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
