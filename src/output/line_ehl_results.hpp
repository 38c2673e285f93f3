// `geartrib ehl`'s result file (HDF5, readable with h5py):
//   /profile/<name>   the last instant over the nodes: 1-D float64 with attribute "units"; text
//                     columns (the node's state) as 1-D UTF-8 strings
//   /series/<name>    the transient's instants, the same way (transient runs only)
//   /summary          one float64 attribute per summary row (its name carries the unit), and the
//                     run's choices as string attributes (viscosity_law, flow, roughness, ...)
//   /meta             attribute version
// Writes `path` as it is: a command writes it through an io::OutputSet (all outputs or none).
#pragma once

#include "output/column_table.hpp"
#include "output/table_writer.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::io {

struct LineEhlFile {
  ColumnTable profile;
  ColumnTable series;  // empty: a steady run
  Table summary;       // labelled rows of one value
  std::vector<std::pair<std::string, std::string>> texts;
};
void write_line_ehl_hdf5(const std::filesystem::path& path, const LineEhlFile& f);

}  // namespace geartrib::io
