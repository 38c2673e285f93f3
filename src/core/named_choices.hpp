// A model choice by name: one table of (value, name) per enum gives the name of a value, the value
// of a name (with the error a case reader or the command line passes on) and the list of names
// (the case schema's choices).
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib {

template <class E>
struct NamedChoice {
  E value;
  const char* name;
};

// The value named `name`; std::invalid_argument "unknown <noun> 'name'" when none is.
template <class E>
E choice_from_name(std::span<const NamedChoice<E>> table, std::string_view name, std::string_view noun) {
  for (const auto& c : table)
    if (name == c.name) return c.value;
  throw std::invalid_argument("unknown " + std::string(noun) + " '" + std::string(name) + "'");
}

template <class E>
const char* choice_name(std::span<const NamedChoice<E>> table, E value) {
  for (const auto& c : table)
    if (c.value == value) return c.name;
  return "?";
}

template <class E>
std::vector<std::string> choice_names(std::span<const NamedChoice<E>> table) {
  std::vector<std::string> names;
  names.reserve(table.size());
  for (const auto& c : table) names.emplace_back(c.name);
  return names;
}

}  // namespace geartrib
