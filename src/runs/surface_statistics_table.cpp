#include "runs/surface_statistics_table.hpp"

#include <numbers>

namespace geartrib::runs {

io::Table surface_statistics_table(const surface::SurfaceStatistics& s, const surface::CleanupReport* report) {
  io::Table t;
  t.header = {"quantity", "value"};
  t.add_row("points", {static_cast<double>(s.points)});
  if (report) {
    t.add_row("missing_in_file", {static_cast<double>(report->missing_in)});
    t.add_row("outliers_masked", {static_cast<double>(report->outliers)});
    t.add_row("points_filled", {static_cast<double>(report->filled)});
  }
  t.add_row("missing", {static_cast<double>(s.missing)});
  t.add_row("Ra_m", {s.ra});
  t.add_row("Rq_m", {s.rq});
  t.add_row("Rsk", {s.rsk});
  t.add_row("Rku", {s.rku});
  t.add_row("Rz_m", {s.rz});
  t.add_row("lay_angle_deg", {s.lay_angle * 180.0 / std::numbers::pi});
  t.add_row("m0_m2", {s.m0});
  t.add_row("m2_along_lay", {s.m2_along});
  t.add_row("m4_along_lay_1_per_m2", {s.m4_along});
  t.add_row("m2_across_lay", {s.m2_across});
  t.add_row("m4_across_lay_1_per_m2", {s.m4_across});
  t.add_row("summits", {static_cast<double>(s.summits)});
  t.add_row("summit_density_1_per_m2", {s.summit_density});
  t.add_row("summit_radius_m", {s.summit_radius});
  t.add_row("summit_mean_height_m", {s.summit_mean_height});
  t.add_row("summit_sigma_m", {s.summit_sigma});
  t.add_row("mccool_summit_density_1_per_m2", {s.mccool_density});
  t.add_row("mccool_summit_radius_m", {s.mccool_radius});
  t.add_row("mccool_summit_sigma_m", {s.mccool_summit_sigma});
  return t;
}

}  // namespace geartrib::runs
