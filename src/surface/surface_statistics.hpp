// Areal roughness statistics of a height grid: amplitude parameters, spectral moments along and
// across the lay, the lay direction, summits (eight-neighbour peaks) and McCool's predictions.
#pragma once

#include "surface/height_grid.hpp"
#include "surface/rough_surface.hpp"

#include <vector>

namespace geartrib::surface {

struct SurfaceStatistics {
  std::size_t points = 0, missing = 0;
  double ra = 0, rq = 0, rsk = 0, rku = 0;  // about the mean plane [m], [-]
  double rz = 0;         // mean over the profiles across the lay of ISO 4287 Rz (5 sampling lengths) [m]
  double lay_angle = 0;  // direction of the lay (smallest slope variance) from the x axis [rad], in (-pi/2, pi/2]
  double m0 = 0;         // variance of heights [m^2]
  double m2_along = 0, m4_along = 0;    // slope and curvature variances along the lay [-], [1/m^2]
  double m2_across = 0, m4_across = 0;  // ... across the lay
  // Summits: interior points higher than their eight neighbours.
  std::size_t summits = 0;
  double summit_density = 0;      // [1/m^2]
  double summit_radius = 0;       // 1 / mean summit curvature, curvature -(z_xx + z_yy)/2 [m]
  double summit_mean_height = 0;  // above the mean plane [m]
  double summit_sigma = 0;        // standard deviation of summit heights [m]
  // McCool (1986) from m0 and the direction-averaged m2, m4: density, radius, sigma_s.
  double mccool_density = 0, mccool_radius = 0, mccool_summit_sigma = 0;
};

SurfaceStatistics surface_statistics(const HeightGrid& g);

// A summit: an interior valid point strictly higher than its eight neighbours (all valid).
struct Summit {
  double x = 0, y = 0;  // position [m]
  double height = 0;    // above `mean_plane` [m]
  double radius = 0;    // 1 / mean curvature -(z_xx + z_yy)/2 by central differences [m]
};
std::vector<Summit> find_summits(const HeightGrid& g, double mean_plane);

// The rms gradient |grad z| of a grid taken as one period of a periodic surface (all points valid),
// by its Fourier transform: sqrt(sum |q|^2 |z_q|^2), exact for a band-limited periodic surface (a
// generated one; the one the areal boundary elements' spectral kernel sees) [1].
double spectral_rms_gradient(const HeightGrid& g);

// The flank roughness the contact models take, from the measured summits.
FlankRoughness measured_roughness(const SurfaceStatistics& s);

}  // namespace geartrib::surface
