// Errors in input files: every message names the file, line, key, value and the rule broken.
// The command line exits with status 2 on this error, after writing nothing. In the message
// (what()) control characters are escapes ("\x00"; a rule keeps its line breaks and tabs); the
// parts keep their text as given.
#pragma once

#include <stdexcept>
#include <string>

namespace geartrib::io {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string key, std::string value, std::string rule);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string file_, key_, value_, rule_;
  int line_;
};

}  // namespace geartrib::io
