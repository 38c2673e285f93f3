// Reduction of a surface to the seed's model (section 4): its profile across the lay, averaged
// along the lay, cut into parallel parabolic-cylinder asperities y = h - (x - c)^2/(2 R_m).
#pragma once

#include "surface/height_grid.hpp"

#include <vector>

namespace geartrib::surface {

struct CylinderAsperityFit {
  double centre = 0.0;      // across the lay [m]
  double height = 0.0;      // tip height above the mean line [m]
  double tip_radius = 0.0;  // R_m [m]
  double spacing = 0.0;     // to the next asperity [m] (0 for the last)
};

struct CylinderReduction {
  bool lay_along_y = true;      // the lay snapped to the nearer grid axis
  std::vector<double> profile;  // mean profile across the lay [m]
  double spacing_step = 0.0;    // its sampling step [m]
  std::vector<CylinderAsperityFit> asperities;
  double mean_tip_radius = 0.0, sd_tip_radius = 0.0;
  double mean_spacing = 0.0, sd_spacing = 0.0;
  double mean_height = 0.0, sd_height = 0.0;
};

// Peaks of the mean profile with a prominence of at least `min_prominence` x its Rq, each fitted
// by least squares with a parabola over the points within its top `cap` fraction of prominence.
CylinderReduction reduce_to_cylinders(const HeightGrid& g, double lay_angle, double min_prominence = 0.5,
                                      double cap = 0.3);

}  // namespace geartrib::surface
