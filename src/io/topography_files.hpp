// Topography files: point clouds of optical profilers (x y z with header lines and a missing-point
// marker such as "Bad" or NaN), plain whitespace or CSV height grids with a stated spacing, and
// HDF5 grids (/z with attributes dx, dy in metres; NaN for missing). Lengths in ASCII files are
// in micrometres unless a '# units: <unit>' line or the caller says otherwise.
#pragma once

#include "surface/height_grid.hpp"

#include <filesystem>
#include <string>

namespace geartrib::io {

enum class TopographyFormat { xyz, grid, hdf5 };
// By extension: .xyz .asc -> xyz; .csv .txt .grd -> grid; .h5 .hdf5 -> hdf5.
TopographyFormat topography_format(const std::filesystem::path& file);

struct TopographyReadOptions {
  double unit = 1e-6;     // metres per file length unit (ASCII), unless the file states it
  double spacing = 0.0;   // grid files: spacing in file units when the file does not state it
  double resample = 0.0;  // > 0: regrid at this spacing [m] (point clouds off a lattice: binned;
                          // grids: bilinear); 0: keep the file's lattice
};

// Throws InputError naming the file and line for malformed content.
surface::HeightGrid read_topography(const std::filesystem::path& file, const TopographyReadOptions& options = {});
// Reads and cleans (surface::clean_surface) a topography file; errors in either name the file.
struct LoadedSurface {
  surface::HeightGrid grid;
  surface::CleanupReport cleanup;
};
LoadedSurface load_surface(const std::filesystem::path& file, const TopographyReadOptions& read,
                           const surface::CleanupOptions& cleanup);

// Writes atomically in the format of the extension; ASCII lengths in `unit` metres.
void write_topography(const std::filesystem::path& file, const surface::HeightGrid& g, double unit = 1e-6);

}  // namespace geartrib::io
