// A surface's statistics as rows of (quantity, value), names carrying units (Ra_m, lay_angle_deg,
// summit_density_1_per_m2): what `geartrib surface stats` prints and geartrib.surface_statistics
// returns in Python.
#pragma once

#include "output/table_writer.hpp"
#include "surface/height_grid.hpp"
#include "surface/surface_statistics.hpp"

namespace geartrib::runs {

// With a clean-up report (not null): the points missing in the file, masked and filled too.
io::Table surface_statistics_table(const surface::SurfaceStatistics& s, const surface::CleanupReport* report);

}  // namespace geartrib::runs
