// Topography files: point clouds of optical profilers (x y z with header lines and a missing-point
// marker such as "Bad" or NaN), plain whitespace or CSV height grids with a stated spacing, HDF5
// grids (/z with attributes dx, dy in metres; NaN for missing) and ISO 25178-72 X3P files (metres
// by the standard; topography/x3p_file.hpp says what is read and refused). Lengths in ASCII files are in
// micrometres unless a '# units: <unit>' line or the caller says otherwise.
//
// Every size and value is checked before it is used (docs/guide/surface.md#limits): the grid limits
// of surface/height_grid.hpp (points, spacing, heights, coordinates) against the declared sizes
// before allocating; a point cloud's lattice against the points given; an HDF5 /z against the
// bytes the file stores; an X3P's SizeX x SizeY against its data.bin; dx, dy one number each;
// heights finite (NaN only as the missing marker). Every refusal is an InputError naming the file
// and the field.
#pragma once

#include "output/table_writer.hpp"
#include "surface/height_grid.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

// A text topography file (xyz or grid) of more than this is refused before it is read: it would
// hold more than surface::kMaxGridPoints points at any usual number format (and its line numbers
// stay within an int).
inline constexpr std::uintmax_t kMaxTopographyTextBytes = (std::uintmax_t{1} << 31) - 1;  // 2 GiB
// Plausible for a measured gear flank, after the unit: outside these a warning names the unit
// the lengths were read in and the fix ('# units:' or --unit); the surface is still used.
inline constexpr double kPlausibleSpacing[2] = {1e-9, 1.0};  // [m]
inline constexpr double kPlausibleRq[2] = {1e-9, 1e-4};      // [m], of the cleaned surface

enum class TopographyFormat { xyz, grid, hdf5, x3p };
// By extension: .xyz .asc -> xyz; .csv .txt .grd -> grid; .h5 .hdf5 -> hdf5; .x3p -> x3p.
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
  std::vector<std::string> warnings;  // "FILE: warning: ..." (unit_warnings), for the caller to print
};
LoadedSurface load_surface(const std::filesystem::path& file, const TopographyReadOptions& read,
                           const surface::CleanupOptions& cleanup);

// The warnings of a surface read with lengths in `unit` metres (stated by the file or assumed):
// spacing outside kPlausibleSpacing (unless `check_spacing` is false: a resampled grid's spacing
// is the caller's), Rq of the valid heights outside kPlausibleRq.
std::vector<std::string> unit_warnings(const std::string& file, const surface::HeightGrid& g, double unit,
                                       bool unit_in_file, bool check_spacing = true);

// The checks every reader applies to what it read (x3p_file.cpp too), each an InputError naming
// file, line (0: none), key and value: a spacing within surface::kMinSpacing..kMaxSpacing, a
// height within +-surface::kMaxHeight (`hint`, when not empty, is appended to the rule: where the
// unit came from), and at least 9 valid points.
void check_grid_spacing(const std::string& file, int line, const std::string& key, const std::string& value, double h,
                        const std::string& hint = "");
void check_grid_height(const std::string& file, int line, const std::string& key, std::string_view value, double z,
                       const std::string& hint = "");
void check_valid_points(const surface::HeightGrid& g, const std::string& file, int line);

// Writes atomically in the format of the extension; ASCII lengths in `unit` metres, one of m, mm,
// um, nm (the file states it by symbol; std::invalid_argument otherwise). An X3P and an HDF5 file
// hold metres whatever `unit` says.
void write_topography(const std::filesystem::path& file, const surface::HeightGrid& g, double unit = 1e-6);
// The same into a command's output set (all outputs or none; committed by the caller).
void add_topography(OutputSet& outputs, const std::filesystem::path& file, const surface::HeightGrid& g,
                    double unit = 1e-6);

}  // namespace geartrib::io
