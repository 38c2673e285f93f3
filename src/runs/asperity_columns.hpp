// The outputs of a single-asperity evaluation as named columns with their dimensions: the
// tables of `geartrib asperity` (CSV header = quantity + unit suffix) and the arrays of the
// Python module's geartrib.asperity.
#pragma once

#include "asperity/model.hpp"
#include "config/units.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace geartrib::runs {

using asperity::AsperityState;
using io::Dimension;

// The columns of the asperity table: CSV header = quantity + suffix (units in the name).
struct AsperityColumn {
  std::string_view quantity;
  std::string_view suffix;
  Dimension dimension;
  double (*get)(const AsperityState&);
};

inline constexpr AsperityColumn kAsperityColumns[] = {
    {"delta_star", "", Dimension::dimensionless, [](const AsperityState& s) { return s.delta_star; }},
    {"delta", "_m", Dimension::length, [](const AsperityState& s) { return s.delta; }},
    {"load", "_N", Dimension::force, [](const AsperityState& s) { return s.load; }},
    {"load_star", "", Dimension::dimensionless, [](const AsperityState& s) { return s.load_star; }},
    {"area", "_m2", Dimension::area, [](const AsperityState& s) { return s.area; }},
    {"area_star", "", Dimension::dimensionless, [](const AsperityState& s) { return s.area_star; }},
    {"contact_radius", "_m", Dimension::length, [](const AsperityState& s) { return s.contact_radius; }},
    {"plastic_radius", "_m", Dimension::length, [](const AsperityState& s) { return s.plastic_radius; }},
    {"mean_pressure", "_Pa", Dimension::pressure, [](const AsperityState& s) { return s.mean_pressure; }},
    {"max_pressure", "_Pa", Dimension::pressure, [](const AsperityState& s) { return s.max_pressure; }},
    {"plastic_fraction", "", Dimension::dimensionless, [](const AsperityState& s) { return s.plastic_fraction; }},
    {"max_von_mises", "_Pa", Dimension::pressure, [](const AsperityState& s) { return s.max_von_mises; }},
    {"von_mises_depth", "_m", Dimension::length, [](const AsperityState& s) { return s.von_mises_depth; }},
};

inline const AsperityColumn& asperity_column(const std::string& quantity) {
  for (const auto& c : kAsperityColumns)
    if (c.quantity == quantity) return c;
  std::string known;
  for (const auto& c : kAsperityColumns) known += (known.empty() ? "" : ", ") + std::string(c.quantity);
  throw std::invalid_argument("unknown quantity '" + quantity + "' (known: " + known + ")");
}

}  // namespace geartrib::runs
