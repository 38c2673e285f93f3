// The seed's multi-asperity study (sections 5-7): parallel parabolic-cylinder asperities
// y = t_k - (x - c_k)^2/(2 R_m) standing on a base plane, pressed by a rigid flat, solved with
// the plane-strain boundary elements of half_plane_bem.hpp (half-plane approximation of the
// asperities: the elastic field is that of a flat surface loaded by the contact pressure).
#pragma once

#include "contact/half_plane_bem.hpp"

#include <optional>
#include <string>
#include <vector>

namespace geartrib::contact {

// One asperity of a measured profile (surface::reduce_to_cylinders): axis, tip height and radius.
struct ProfileAsperity {
  double centre = 0.0;      // across the lay [m]
  double height = 0.0;      // tip height [m] (any datum; the highest tip first touches the flat)
  double tip_radius = 0.0;  // [m]
};

struct MultiAsperitySpec {
  std::string layout = "HLH";       // one letter per asperity: H high, L low by height_step
  double tip_radius = 6.6e-6;       // R_m [m]
  double height_step = 0.0;         // h_m [m]
  double spacing = 0.5e-6;          // d_m: distance between neighbouring asperity axes [m]
  double asperity_height = 4e-6;    // base plane (floor of the profile) below the high tips [m]
  double length = 10e-6;            // cylinder length, for the contact areas [m]
  double approach = 0.0;            // approach of the flat after it touches the high tips [m] (if no load)
  std::optional<double> line_load;  // load control [N/m]
  double modulus = 0.0;  // plane-strain modulus against a rigid flat [Pa]: E_t (composite) or E/(1 - nu^2) (one body)
  double poisson_ratio = 0.3;
  double pressure_cap = 0.0;        // [Pa]; infinity for elastic
  int elements = 4096;              // boundary elements over the domain
  double reference_length = 50e-6;  // displacement reference L_ref (a rigid base ~L_ref deep) [m]
  double tolerance = 1e-10;
  // The solver (BemOptions): preconditioned, started from coarser grids of the same domain down
  // to coarse_elements (0: none) and, on the coarsest, from the rigid overlap. Any choice
  // converges to the same answer within the tolerance; these are the fastest.
  bool precondition = true;
  int coarse_elements = 4096;
  bool overlap_start = true;
  // Measured asperities in order across the lay; when not empty they replace layout, tip_radius,
  // height_step and spacing (kind 'H' marks the highest tip, 'L' the others).
  std::vector<ProfileAsperity> profile;
  void validate() const;  // throws std::invalid_argument
};

struct AsperityLoad {
  char kind = 'H';
  double centre = 0.0;                 // [m]
  double load = 0.0;                   // [N/m]
  double contact_width = 0.0;          // [m]
  double max_pressure = 0.0;           // [Pa]
  double max_surface_von_mises = 0.0;  // just below the surface (half an element deep) [Pa]
  double max_deformation = 0.0;        // largest downward surface displacement, elastic + plastic [m]
};

struct MultiAsperityResult {
  std::vector<AsperityLoad> asperities;
  double total_contact_area = 0.0;         // sum of widths x length [m^2]
  std::vector<double> midpoint_von_mises;  // at the surface midway between neighbours (half an element deep) [Pa]
  double inflection_depth = 0.0;           // below the middle asperity: depth of the inflection point [m]
  double inflection_von_mises = 0.0;       // ... and the von Mises stress there [Pa]
  double approach = 0.0;                   // [m]
  double line_load = 0.0;                  // [N/m]
  int iterations = 0;                      // on the grid of `elements`
  int coarse_iterations = 0;               // on the coarser grids that started it
  double complementarity_error = 0.0;
  // Cost: the boundary-element solve's FFTs (count, time in them), its wall time, and the whole
  // study's (solve, loads, stresses) [s].
  long transforms = 0;
  double transform_seconds = 0.0;
  double solve_seconds = 0.0;
  double seconds = 0.0;
  HalfPlaneGrid grid;
  std::vector<double> pressure;
};

MultiAsperityResult solve_multi_asperity(const MultiAsperitySpec& spec);

}  // namespace geartrib::contact
