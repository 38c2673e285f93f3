// A measured or generated surface: heights on a regular grid (row-major, y rows of x), with a
// mask of valid points, SI units; and the clean-up operations of section 4 of the seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace geartrib::surface {

// Limits on every height grid, whether read, resampled or generated (docs/guide/surface.md#limits).
// The readers check them against the file's declared sizes before allocating and refuse beyond
// them with the file and field named; make_grid and validate() throw std::invalid_argument.
inline constexpr std::size_t kMaxGridPoints = std::size_t{1} << 25;  // 33 554 432 (8192 x 4096): ~0.3 GB a copy
inline constexpr double kMinSpacing = 1e-12;                         // [m], 1 pm
inline constexpr double kMaxSpacing = 1e3;                           // [m], 1 km
inline constexpr double kMaxHeight = 1.0;                            // |z| [m]
inline constexpr double kMaxCoordinate = 1e3;                        // |x|, |y| of a point cloud [m]
inline constexpr std::size_t kMinValidPoints = 9;                    // valid points a surface needs

struct HeightGrid {
  int nx = 0, ny = 0;
  double dx = 0.0, dy = 0.0;        // spacing [m]
  std::vector<double> z;            // heights [m], z[j * nx + i] at x = i dx, y = j dy
  std::vector<std::uint8_t> valid;  // 1 where measured, 0 where missing

  double& at(int i, int j) { return z[static_cast<std::size_t>(j) * nx + i]; }
  double at(int i, int j) const { return z[static_cast<std::size_t>(j) * nx + i]; }
  bool ok(int i, int j) const { return valid[static_cast<std::size_t>(j) * nx + i] != 0; }
  std::size_t size() const { return z.size(); }
  std::size_t missing() const;
  void validate() const;  // throws std::invalid_argument (sizes, spacing in [kMinSpacing, kMaxSpacing])
};

// Throws std::invalid_argument beyond kMaxGridPoints (before allocating) or the spacing limits.
HeightGrid make_grid(int nx, int ny, double dx, double dy);

// The first rule of the topography files a grid's heights break, or empty: a valid height beyond
// +-kMaxHeight ("z[row, column] = ..."), fewer than kMinValidPoints valid points. What every reader
// refuses (io::check_grid_height, io::check_valid_points) and so what no writer may write.
std::string height_rule(const HeightGrid& g);

// Heights in the form files and arrays hold them, NaN marking a missing point: into a grid of
// their size (z[j * nx + i]; std::invalid_argument for another size), and out of one.
void set_heights(HeightGrid& g, std::span<const double> z);
std::vector<double> heights_or_nan(const HeightGrid& g);

// Removes the least-squares polynomial form of total degree `degree` (1: plane; 2 or more for a
// curved flank) fitted to the valid points.
void remove_form(HeightGrid& g, int degree);
// Splits roughness from waviness: subtracts the areal Gaussian filter of cut-off lambda_c
// (ISO 16610-61 weighting, alpha = sqrt(ln 2/pi)), applied separably, renormalised at the edges
// and over missing points. Returns the waviness that was removed. The cut-off must lie between two
// of the smaller spacing and the surface's longer side (std::invalid_argument otherwise); long
// kernels are applied by FFT, so the cost is O(points log points) whatever the cut-off.
HeightGrid remove_waviness(HeightGrid& g, double cutoff);
// Marks points farther than k robust standard deviations (1.4826 x MAD) from the median as
// missing; returns how many.
std::size_t remove_outliers(HeightGrid& g, double k);
// Fills missing points by the mean of their valid neighbours, repeated until none is left
// (a missing region is filled from its edge inward, one ring a pass; O(points) in all). Throws if
// no point is valid.
void fill_missing(HeightGrid& g);
// Scattered points (x, y, z) [m] binned onto a regular grid of cell size `spacing` starting at the
// smallest x and y: each cell holds the mean of its points (NaN z: not counted); cells without a
// point are missing. For point clouds that are not on a lattice (stitched or rotated exports).
// Throws std::invalid_argument when the grid would exceed kMaxGridPoints.
HeightGrid grid_from_points(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                            double spacing);
// Bilinear resampling onto spacing `spacing` in both directions over the same extent; a new point
// is missing when any of its four neighbours is. Throws std::invalid_argument when the grid would
// exceed kMaxGridPoints.
HeightGrid resample(const HeightGrid& g, double spacing);

// The clean-up pipeline of seed section 4, in this order: outliers masked, missing points filled
// (optional), polynomial form removed, waviness split off by the Gaussian filter (optional).
struct CleanupOptions {
  int form_degree = 2;         // 0: none, 1: plane, 2+: polynomial (an involute flank is curved)
  double waviness_cutoff = 0;  // Gaussian cut-off lambda_c [m]; 0: no filter
  double outlier_limit = 0;    // k robust standard deviations; 0: keep all points
  bool fill = false;           // fill missing points (else they stay masked)
  void validate() const;       // throws core::KeyedError naming the field
};
struct CleanupReport {
  std::size_t missing_in = 0;   // points missing in the input
  std::size_t outliers = 0;     // points masked as outliers
  std::size_t filled = 0;       // points filled
  std::size_t missing_out = 0;  // points still missing
};
CleanupReport clean_surface(HeightGrid& g, const CleanupOptions& o);

// The equivalent rough surface of two facing flanks (seed section 4): y_e = y_u mirrored + y_d.
// A surface turned over to face the other is seen mirrored about one in-plane axis: x by
// default; `none` when the upper export is already in the lower one's frame. Grids must align.
enum class Mirror { x, y, none };
HeightGrid equivalent_surface(const HeightGrid& upper, const HeightGrid& lower, Mirror mirror = Mirror::x);

}  // namespace geartrib::surface
