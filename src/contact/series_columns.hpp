// Filling a result group's series (contact::Series) column by column: the mesh cycle's output
// stage builds every series once, from the stages' typed results, one table of (name, unit,
// value) per result.
#pragma once

#include "contact/mesh_contact.hpp"

#include <initializer_list>
#include <vector>

namespace geartrib::contact {

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
    Series s{column.name, column.unit, {}};
    s.values.reserve(rows.size());
    for (const Row& row : rows) s.values.push_back(column.value(row));
    g.push_back(std::move(s));
  }
}

}  // namespace geartrib::contact
