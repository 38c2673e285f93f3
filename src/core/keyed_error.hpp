// A refusal of an input that the physics can pin on one named input: `key` is the dotted case-file
// key when the code works on a Case ("contact.strip_halfwidths"), or the field of the struct it
// validates ("rq" of a surface::GeneratedProfileSpec), which its caller maps to the case-file key.
// The callers that know where the key came from (src/io, src/runs) turn it into an io::InputError
// naming the file, line, key and value; the message is the rule.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace geartrib::core {

class KeyedError : public std::invalid_argument {
 public:
  KeyedError(std::string key, const std::string& rule) : std::invalid_argument(rule), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// A member struct's validate() (`member` its name in the enclosing struct): its refusal keyed by
// the field's path from the enclosing struct ("clean" + "outlier_limit": "clean.outlier_limit"),
// which the table maps to a case key as it maps a field of the enclosing struct.
template <class Options>
void validate_member(std::string_view member, const Options& options) {
  try {
    options.validate();
  } catch (const KeyedError& e) {
    throw KeyedError(std::string(member) + "." + e.key(), e.what());
  }
}

}  // namespace geartrib::core
