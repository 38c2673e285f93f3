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
  void validate() const;
};

struct BemSolution {
  std::vector<double> pressure;      // [Pa] per element
  std::vector<double> displacement;  // elastic surface displacement (positive away from the flat) [m]
  std::vector<double> gap;           // undeformed gap + displacement - approach [m]; < 0 only where capped (plastic)
  double approach = 0.0;             // [m]
  double line_load = 0.0;            // [N/m]
  int iterations = 0;
  double complementarity_error = 0.0;
  int contact_elements = 0;
  int capped_elements = 0;
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
  BemSolution solve_box(const std::vector<double>& gap0, double approach, const std::vector<double>* initial) const;
  // Packs a solution, or throws when the complementarity error is above the tolerance.
  BemSolution finish(std::vector<double> p, std::vector<double> u, std::vector<double> g, double approach,
                     int iterations, double error) const;
  HalfPlaneGrid grid_;
  double modulus_;
  BemOptions options_;
  std::unique_ptr<ToeplitzConvolution> conv_;
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

}  // namespace geartrib::contact
