// Reference tables (validation/*/): CSV with '# key: value' provenance lines, then a header
// whose first column is the input (e.g. delta_star) and whose other columns are named
// quantity@label[unit] (e.g. contact_radius@seed-fem[um]), one row per observation.
#pragma once

#include "config/units.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::io {

struct ReferenceColumn {
  std::string quantity;        // e.g. contact_radius
  std::string label;           // e.g. seed-fem
  std::string unit;            // as written, e.g. um
  std::vector<double> values;  // SI
};

struct ReferenceTable {
  std::string file;
  std::vector<std::pair<std::string, std::string>> provenance;
  std::string input_name;
  std::vector<double> inputs;
  std::vector<ReferenceColumn> columns;
};

// `dimension_of(quantity)` gives the dimension a quantity name must carry, or throws
// std::invalid_argument for an unknown quantity. Throws InputError on any malformed line.
ReferenceTable read_reference_table(const std::filesystem::path& file,
                                    const std::function<Dimension(const std::string&)>& dimension_of);

}  // namespace geartrib::io
