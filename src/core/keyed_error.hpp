// A refusal of an input that the physics can pin on one named input: `key` is the dotted case-file
// key when the code works on a Case ("contact.strip_halfwidths"), or the field of the struct it
// validates ("rq" of a surface::GeneratedProfileSpec), which its caller maps to the case-file key.
// The callers that know where the key came from (src/io, src/runs) turn it into an io::InputError
// naming the file, line, key and value; the message is the rule.
#pragma once

#include <stdexcept>
#include <string>

namespace geartrib::core {

class KeyedError : public std::invalid_argument {
 public:
  KeyedError(std::string key, const std::string& rule) : std::invalid_argument(rule), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

}  // namespace geartrib::core
