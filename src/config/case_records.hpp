// A Case's load-time records read back (Case::parameters: each key's value, origin and text as
// written): errors and warnings located where a key's value came from, a component's refusal
// mapped from its option field to the case key, and the parameters as the Case now holds them.
// Used after loading by io::prepare_case, the mesh cycle (runs/), the commands and Python.
#pragma once

#include "case/case.hpp"
#include "config/input_error.hpp"
#include "core/keyed_error.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

// The record of a dotted key; nullptr when the case did not record it.
const ResolvedParameter* find_record(const Case& c, std::string_view key);

// The case file (from the records' origins); "the case" when none names one.
std::string case_file(const Case& c);

// Where a key's value came from, as a message locates it: the case file and line (a default: its
// table's line, when the file has the table), "FILE (--set KEY=VALUE)" for a change, a data file
// named whole (line 0); the case file when the case did not record the key.
struct Location {
  std::string file;
  int line = 0;
  std::string text() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};
Location location_of(const Case& c, std::string_view key);

// The key's value as the Case recorded it (SI unit), or `otherwise` when it did not record it.
std::string recorded_value(const Case& c, std::string_view key, const std::string& otherwise = "");

// An error at `key` with its `rule`, located where the key's value came from: the case file and
// line (a default: its table's line, when the file has the table), or the --set that gave it; with
// the value as the Case holds it (SI unit), or `value` when given (the text as written:
// ResolvedParameter::written). A key the case did not record: the case file.
InputError located_error(const Case& c, const std::string& key, const std::string& rule);
InputError located_error(const Case& c, const std::string& key, const std::string& value, const std::string& rule);
// The same quoting the value as the file or the --set wrote it (TomlReader's errors at load).
InputError located_error_as_written(const Case& c, const std::string& key, const std::string& rule);

// "where: warning: key 'KEY' = WRITTEN: message", the form of every located warning (as
// TomlReader::warning).
std::string located_warning(const Case& c, const std::string& key, const std::string& message);

// A component's refusal naming its option field (core::KeyedError): `prefix` + the field is the
// Case member's path, which the table maps to its case key (io::case_key_of_field); the error
// located at that key. A field no key sets (one the physics derives): the case file, unkeyed.
InputError refusal_error(const Case& c, const core::KeyedError& e, const std::string& prefix = "");

// The parameters as the Case holds them now, in the records' order: each recorded key's value
// read through its row (Parameter::get, formatted by Parameter::format) with its load-time origin.
// A Case changed in code after loading records its actual values. /parameters, `geartrib case`
// and Python's Case.parameters show these.
std::vector<ResolvedParameter> current_parameters(const Case& c);

}  // namespace geartrib::io
