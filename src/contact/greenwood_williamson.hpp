// Greenwood-Williamson summation of single-asperity contacts over the summit-height
// distribution of an equivalent rough surface, with any asperity model of the registry
// (Greenwood & Williamson 1966; elastic-plastic extensions after Chang-Etsion-Bogy 1987).
// Separation d: from the rigid flat to the mean of the summit heights [m].
#pragma once

#include <stdexcept>

#include "asperity/model.hpp"
#include "surface/rough_surface.hpp"

#include <vector>

namespace geartrib::contact {

// A nominal pressure the rough surface cannot carry at any separation the model allows (down to
// 10^4 sigma below the mean plane): the load is far beyond the surface's (an input problem).
class RoughSurfaceOverload : public std::invalid_argument {
 public:
  explicit RoughSurfaceOverload(double nominal_pressure);
};

// Contact of the rough surface per unit nominal area at one separation.
struct SurfaceContact {
  double separation = 0.0;          // d [m]
  double nominal_pressure = 0.0;    // p = eta int F(z - d) phi(z) dz [Pa]
  double real_area_ratio = 0.0;     // A_r/A_n = eta int A(z - d) phi(z) dz
  double contact_density = 0.0;     // contacts per nominal area, eta int_d phi [1/m^2]
  double plastic_area_ratio = 0.0;  // eta int A(z - d) phi_p(z - d) phi(z) dz, phi_p the plastic share of one contact
  double plastic_contact_density = 0.0;  // contacts with z - d > delta_c, per nominal area [1/m^2]
};

// The quantities of a point of the rough surface besides its nominal pressure, per nominal area.
struct ContactAtPressure {
  double real_area_ratio = 0.0;
  double contact_density = 0.0;  // [1/m^2]
  double plastic_area_ratio = 0.0;
  double plastic_contact_density = 0.0;  // [1/m^2]
};

struct GreenwoodWilliamsonOptions {
  // The resolutions' ranges (the case file's contact.height_points and contact.table_points).
  static constexpr int kMinHeightPoints = 8, kMaxHeightPoints = 100000;  // 8: one Gauss panel
  static constexpr int kMinTablePoints = 4, kMaxTablePoints = 10000;
  int height_points =
      128;  // quadrature points over the summit heights in contact (panel ends also at the model's breakpoints)
  int table_points_per_sigma = 32;  // separation table resolution
  bool plastic = true;              // tabulate the plastic area
  void validate() const;            // throws core::KeyedError naming the field
};

class GreenwoodWilliamson {
 public:
  // `pair` carries the materials; its radius is replaced by the surface's summit radius. The
  // pressure-separation table covers nominal pressures up to at least `max_pressure` [Pa].
  GreenwoodWilliamson(const surface::EquivalentSurface& surface, const asperity::AsperityModel& model,
                      const asperity::ContactPair& pair, double max_pressure,
                      const GreenwoodWilliamsonOptions& options);

  // Direct quadrature at a separation (what the table is built from); `plastic` sums the plastic
  // area whether or not the table does.
  SurfaceContact at_separation(double d) const { return at_separation(d, options_.plastic); }
  SurfaceContact at_separation(double d, bool plastic) const;
  // From the table: monotone log-linear interpolation in d.
  SurfaceContact interpolate(double d) const;
  // Nominal pressure at d and its derivative dp/dd (<= 0), from the table.
  double pressure(double d) const;
  double pressure_slope(double d) const;
  // The separation giving nominal pressure p >= 0 (bracketed inversion of the monotone table);
  // p = 0 gives the separation where contact begins.
  double separation_for_pressure(double p) const;
  // interpolate(separation_for_pressure(p)) without a logarithm or power: each table segment's
  // power law in p is split into cells of at most kCellRatio in pressure, each a cubic Hermite
  // polynomial in p with the law's values and slopes at its ends (error below 1e-8 of the value;
  // tests/test_rough_contact.cpp). Below kCellFloor of the table's top and above it: the exact
  // route.
  // `segment`: where the search starts and the segment found (a caller looking up ascending
  // pressures passes the same variable each time: a step or two per call instead of a bisection).
  ContactAtPressure at_pressure(double p) const {
    std::size_t segment = 0;
    return at_pressure(p, segment);
  }
  ContactAtPressure at_pressure(double p, std::size_t& segment) const;
  static constexpr double kCellRatio = 1.02, kCellFloor = 1e-7;
  // Height above the summit mean of the highest summit expected in a nominal area [m^2]:
  // the height exceeded by one summit of eta A on average (0 when eta A < 1).
  double highest_summit(double nominal_area) const;

  double contact_onset() const { return z_high_; }  // separation beyond which nothing touches [m]
  double max_pressure() const { return table_.back().nominal_pressure; }
  const surface::EquivalentSurface& surface() const { return surface_; }
  const asperity::AsperityModel& model() const { return model_; }
  const asperity::ContactPair& pair() const { return pair_; }
  double critical_interference() const { return delta_c_; }

 private:
  // The table row k at or above separation d (d < z_high_: k = floor((z_high - d)/step)) and the
  // fraction t of the step toward row k + 1; k + 1 may lie beyond the table.
  struct TablePosition {
    std::size_t k;
    double t;
  };
  TablePosition table_position(double d) const;
  double density(double z) const;               // summit-height probability density phi(z) [1/m]
  double contact_density(double d) const;       // summits above d per nominal area [1/m^2]
  void gaussian_table(int entries);             // table_[0 .. entries) on shared nodes
  static constexpr double kSharedDepth = 25.0;  // sigma: the shared-node table's reach below z_high
  surface::EquivalentSurface surface_;
  const asperity::AsperityModel& model_;
  asperity::ContactPair pair_;
  GreenwoodWilliamsonOptions options_;
  double delta_c_;
  double z_low_, z_high_;              // support of phi used in the quadrature
  std::vector<double> breaks_;         // interferences where the model jumps or kinks [m], ascending
  double step_;                        // table spacing in d [m]
  std::vector<SurfaceContact> table_;  // decreasing d from z_high_: table_[k].separation = z_high_ - k step
  // at_pressure's cells: the table segments from the first above kCellFloor of the top on (pressures in
  // segment_pressure_), segment k's cells from cell_start_[k] in cells_.
  struct Cell {
    double p_lo = 0.0, inv_width = 0.0;  // [Pa], [1/Pa]
    double c[4][4] = {};                 // per quantity, Horner coefficients in (p - p_lo)/width
  };
  void build_cells();
  std::vector<double> segment_pressure_;  // those segments' end pressures
  std::vector<std::size_t> cell_start_;   // per segment, and one past the last
  std::vector<Cell> cells_;
};

}  // namespace geartrib::contact
