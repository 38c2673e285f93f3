// Plane-strain half-plane boundary elements for rough line contact against a rigid flat:
// constant-pressure surface elements with exact influence coefficients, convolution by FFT
// (DC-FFT, or periodic), the constrained conjugate-gradient method of Polonsky & Keer (1999)
// for the contact complementarity, with an elastic-perfectly-plastic pressure cap, under load
// control (given line load) or displacement control (given approach of the flat).
//
// Reference of the displacements (plane strain needs one): non-periodic, the surface
// displacement under a line load P is u(x) = (2 P/(pi E*)) ln(L_ref/|x|), zero at the distance
// L_ref from the load (a substrate of depth ~L_ref on a rigid base behaves so); periodic, the
// mean surface displacement over the period is zero. The approach is the rigid flat's
// displacement in that reference.
#pragma once

#include "contact/toeplitz_convolution.hpp"

#include <limits>
#include <memory>
#include <vector>

namespace geartrib::contact {

struct HalfPlaneGrid {
  double start = 0.0;    // left edge of the first element [m]
  double spacing = 0.0;  // element width [m]
  int size = 0;          // number of elements
  double x(int i) const { return start + (i + 0.5) * spacing; }
};

struct BemOptions {
  double tolerance = 1e-10;  // complementarity error at convergence (relative to the profile relief)
  int max_iterations = 20000;
  double pressure_cap = std::numeric_limits<double>::infinity();  // [Pa]; H for an elastic-perfectly-plastic surface
  bool periodic = false;
  double reference_length = 20e-6;  // L_ref [m] (non-periodic)
  // Displacement control (and the capped load control, a sequence of them):
  // - precondition: conjugate gradients on the free set preconditioned by the inverse of the
  //   kernel's symbol (two more transforms per iteration, far fewer iterations);
  // - coarse_elements: start from the solution on the same domain with half the elements
  //   (interpolated), itself started so, while the coarser grid keeps at least this many
  //   elements (0: no coarser grid);
  // - overlap_start: start the coarsest grid from a pressure ~ sqrt of the rigid overlap, shrunk
  //   and scaled to the least energy (Hertz-like), instead of zero.
  bool precondition = true;
  int coarse_elements = 4096;
  bool overlap_start = true;
  void validate() const;  // throws core::KeyedError naming the field
};

struct BemSolution {
  std::vector<double> pressure;      // [Pa] per element
  std::vector<double> displacement;  // elastic surface displacement (positive away from the flat) [m]
  std::vector<double> gap;           // undeformed gap + displacement - approach [m]; < 0 only where capped (plastic)
  double approach = 0.0;             // [m]
  double line_load = 0.0;            // [N/m]
  int iterations = 0;                // on this grid
  int coarse_iterations = 0;         // on the coarser grids that started it (BemOptions::coarse_elements)
  double complementarity_error = 0.0;
  int contact_elements = 0;
  int capped_elements = 0;
  // Cost: FFTs executed (one r2c or c2r of the convolution's length each; coarse grids'
  // shorter ones included), the time spent in them and the whole solve's wall time [s].
  long transforms = 0;
  double transform_seconds = 0.0;
  double seconds = 0.0;
};

class HalfPlaneBem {
 public:
  // plane_strain_modulus: E* = E/(1 - nu^2) of the elastic body (the flat is rigid).
  HalfPlaneBem(const HalfPlaneGrid& grid, double plane_strain_modulus, const BemOptions& options);

  // gap0: undeformed gap between flat and surface per element. Throw std::runtime_error if
  // the tolerance is not reached (never an unconverged answer). Load control is Polonsky-Keer's
  // without a cap; with a cap, the approach is bracketed over displacement-controlled solves.
  BemSolution solve_load(const std::vector<double>& gap0, double line_load) const;
  BemSolution solve_approach(const std::vector<double>& gap0, double approach) const;

  // Elastic surface displacement of a pressure distribution.
  void displacement(const std::vector<double>& pressure, std::vector<double>& u) const;
  const HalfPlaneGrid& grid() const { return grid_; }

 private:
  BemSolution solve(const std::vector<double>& gap0, bool load_control, double target,
                    const std::vector<double>* initial) const;
  BemSolution solve_load_capped(const std::vector<double>& gap0, double line_load) const;
  BemSolution solve_box(const std::vector<double>& gap0, double approach, const std::vector<double>* initial) const;
  // A displacement-controlled solve's starting pressure (empty: zero): from the coarser grids
  // (adding their iterations to coarse_iterations), else from the rigid overlap.
  std::vector<double> start(const std::vector<double>& gap0, double approach, int& coarse_iterations) const;
  std::vector<double> overlap_start(const std::vector<double>& gap0, double approach) const;
  // The gap's range, the length the displacement-controlled complementarity error is relative to
  // (a flat gap: the approach's depth below it) [m].
  double relief(const std::vector<double>& gap0, double approach) const;
  // Packs a solution, or throws when the complementarity error is above the tolerance.
  BemSolution finish(std::vector<double> p, std::vector<double> u, std::vector<double> g, double approach,
                     int iterations, double error) const;
  HalfPlaneGrid grid_;
  double modulus_;
  BemOptions options_;
  std::unique_ptr<ToeplitzConvolution> conv_;
  double kernel_norm_ = 0.0;            // largest absolute row sum of K, >= ||K||
  std::vector<double> inverse_symbol_;  // the preconditioner's spectral factor (ToeplitzConvolution::apply_spectral)
};

// Subsurface stresses (plane strain) at (x, depth z > 0) by superposing the uniform-strip
// solutions of the elements (Johnson, Contact Mechanics, eq. 2.25): compression negative.
struct PlaneStrainStress {
  double xx = 0.0, zz = 0.0, xz = 0.0, yy = 0.0;
  double von_mises() const;
};
PlaneStrainStress uniform_strip_stress(double x, double z, double half_width, double pressure, double nu);
PlaneStrainStress subsurface_stress(const HalfPlaneGrid& grid, const std::vector<double>& pressure, double x, double z,
                                    double nu);

// The same field for many points: the strips' sum regrouped by element edges e_k,
// sum_j p_j (F(x - e_j) - F(x - e_{j+1})) = sum_k (p_k - p_{k-1}) F(x - e_k), keeping only the
// nonzero pressure jumps (one arctangent per loaded edge instead of two per loaded element), and
// clusters of edges far from the point summed at 20 Chebyshev points (a one-sided fast multipole
// scheme, error ~1e-16 of the summed jumps): equal to subsurface_stress to its rounding (closer
// to a long-double sum than it), 20 to 40 times as fast on 2^14 to 2^16 elements.
class SubsurfaceStressField {
 public:
  SubsurfaceStressField(const HalfPlaneGrid& grid, const std::vector<double>& pressure);
  PlaneStrainStress at(double x, double z, double nu) const;

 private:
  struct Cluster {
    std::size_t lo = 0, hi = 0;  // edges [lo, hi)
    double centre = 0.0, half = 0.0;
    std::size_t left = 0;     // children at left and left + 1; 0: a leaf, summed edge by edge
    std::size_t weights = 0;  // offset of its Chebyshev weights in weight_
  };
  std::vector<double> edge_, jump_, weight_;
  std::vector<Cluster> cluster_;
};

}  // namespace geartrib::contact
