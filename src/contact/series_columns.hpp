// Filling a result group's series (contact::Series) column by column: the mesh cycle's stages and
// the lubricated cycle add their outputs through these, one table of (name, unit, value) per stage.
#pragma once

#include "contact/mesh_contact.hpp"

#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace geartrib::contact {

// A series is filled through the reference add_series() returns: a group is reserved at its first
// series so that adding another never moves the earlier ones.
inline constexpr std::size_t kMaxSeries = 32;
inline std::vector<double>& add_series(std::vector<Series>& g, const char* name, const char* unit) {
  if (g.capacity() == 0) g.reserve(kMaxSeries);
  if (g.size() == g.capacity()) throw std::logic_error("mesh-cycle results: raise kMaxSeries");
  g.push_back({name, unit, {}});
  return g.back().values;
}

// One series per column, a value per row (a position's strip result, validity, lubrication, ...).
template <class Row>
struct Column {
  const char* name;
  const char* unit;
  double (*value)(const Row&);
};
template <class Row>
void add_columns(std::vector<Series>& g, const std::vector<Row>& rows, std::initializer_list<Column<Row>> columns) {
  for (const Column<Row>& column : columns) {
    std::vector<double>& v = add_series(g, column.name, column.unit);
    v.reserve(rows.size());
    for (const Row& row : rows) v.push_back(column.value(row));
  }
}

}  // namespace geartrib::contact
