// `geartrib contact`'s result file (HDF5, readable with h5py):
//   /curve/<name>    the area-load curve, a row per load: 1-D float64 with attribute "units"
//   /fields/<name>   the last load's fields on the grid, 2-D float64 (ny x nx, row-major: y rows of
//                    x) with "units": heights_m, pressure_Pa, gap_m, spot (the spot's index from 0,
//                    largest first; -1 out of contact); attributes dx_m, dy_m, periodic_x, periodic_y
//   /spots/<name>    the last load's spots, largest first: area_m2, load_N
//   /stress/<name>   the last load's planes under the surface: depth_m, max_von_mises_Pa, x_m, y_m
//   /summary         one float64 attribute per number (its name carries the unit) and the run's
//                    choices as string attributes
//   /scene           the command line that made the file; /meta: attribute version
// Writes `path` as it is: a command writes it through an io::OutputSet (all outputs or none).
#pragma once

#include "output/column_table.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace geartrib::io {

struct ArealContactFile {
  ColumnTable curve;
  int nx = 0, ny = 0;
  double dx = 0.0, dy = 0.0;
  bool periodic_x = true, periodic_y = true;
  std::vector<double> heights, pressure, gap, spot;  // nx * ny each
  ColumnTable spots, stress;
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::string>> texts;
  std::string scene;
};
void write_areal_contact_hdf5(const std::filesystem::path& path, const ArealContactFile& f);

}  // namespace geartrib::io
