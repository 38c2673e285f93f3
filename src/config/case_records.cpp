#include "config/case_records.hpp"

#include "config/case_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace geartrib::io {

const ResolvedParameter* find_record(const Case& c, std::string_view key) {
  for (const auto& p : c.parameters)
    if (p.key == key) return &p;
  return nullptr;
}

std::string case_file(const Case& c) {
  // A key of the case (its required title first) names the file; a data file's origin does not.
  const auto of_case = [](const ResolvedParameter& p) {
    return !p.origin.file.empty() && (p.origin.kind != Origin::Kind::file || p.origin.line > 0);
  };
  if (const auto* t = find_record(c, "title"); t && of_case(*t)) return t->origin.file;
  for (const auto& p : c.parameters)
    if (of_case(p)) return p.origin.file;
  return "the case";
}

Location location_of(const Case& c, std::string_view key) {
  const ResolvedParameter* p = find_record(c, key);
  if (!p || p->origin.file.empty()) return {case_file(c), 0};
  return {p->origin.where_file(), p->origin.where_line()};
}

std::string recorded_value(const Case& c, std::string_view key, const std::string& otherwise) {
  const ResolvedParameter* p = find_record(c, key);
  return p ? p->value : otherwise;
}

InputError located_error(const Case& c, const std::string& key, const std::string& value, const std::string& rule) {
  const auto [file, line] = location_of(c, key);
  return InputError(file, line, key, value, rule);
}

InputError located_error(const Case& c, const std::string& key, const std::string& rule) {
  return located_error(c, key, recorded_value(c, key), rule);
}

InputError located_error_as_written(const Case& c, const std::string& key, const std::string& rule) {
  const ResolvedParameter* p = find_record(c, key);
  return located_error(c, key, p ? p->written : std::string(), rule);
}

std::string located_warning(const Case& c, const std::string& key, const std::string& message) {
  const ResolvedParameter* p = find_record(c, key);
  const std::string written = p ? p->written : std::string();
  return fmt::format("{}: warning: key '{}'{}: {}", location_of(c, key).text(), key,
                     written.empty() ? "" : " = " + written, message);
}

InputError refusal_error(const Case& c, const core::KeyedError& e, const std::string& prefix) {
  const std::string key = case_key_of_field(prefix + e.key());
  const auto [row, gear] = find_parameter(key);
  // A field no key sets (one the physics derives, as the boundary elements' pressure cap from the
  // flanks' hardness): the case file, unkeyed, rather than a key the file cannot have.
  if (!find_record(c, key) && !row) return InputError(case_file(c), 0, "", "", e.what());
  // The value refused is the one the Case holds now (a Case changed in code: not its record's).
  if (row && row->kind != ParameterKind::model_constants)
    return located_error(c, key, row->format(row->get(c, gear)), e.what());
  return located_error(c, key, e.what());
}

std::vector<ResolvedParameter> current_parameters(const Case& c) {
  std::vector<ResolvedParameter> out = c.parameters;
  for (ResolvedParameter& r : out) {
    const auto [row, gear] = find_parameter(r.key);
    if (!row) continue;
    if (row->kind == ParameterKind::model_constants) {
      // asperity.constants.MODEL.NAME: the model's overridden constant as the Case holds it.
      const std::string rest = r.key.substr(std::string_view("asperity.constants.").size());
      const auto dot = rest.find('.');
      const auto model = c.asperity.constants.find(rest.substr(0, dot));
      if (dot == std::string::npos || model == c.asperity.constants.end()) continue;
      for (const auto& [name, value] : model->second)
        if (name == rest.substr(dot + 1)) r.value = fmt::format("{:g}", value);
      continue;
    }
    // A number given by its rule's name (green-2005) keeps the name: the rule is what ran.
    if (row->kind == ParameterKind::number &&
        std::find(row->choices.begin(), row->choices.end(), r.value) != row->choices.end())
      continue;
    r.value = row->format(row->get(c, gear));
  }
  return out;
}

}  // namespace geartrib::io
