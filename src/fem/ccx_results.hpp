// Running CalculiX (`ccx`) on a deck and reading its results: the reaction totals of the .dat
// file and the nodal displacements, stresses and equivalent plastic strains of the .frd file.
#pragma once

#include "fem/asperity_deck.hpp"
#include "fem/cylinder_deck.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace geartrib::fem {

// `s` as one single-quoted word for /bin/sh (embedded quotes escaped), for commands run through
// std::system or popen.
std::string shell_quoted(const std::string& s);

// The ccx executable: $GEARTRIB_CCX when set (empty if that file does not exist), else ccx on
// PATH; empty when there is none.
std::filesystem::path find_ccx();
// "CalculiX 2.20" or the like, from `ccx -v`.
std::string ccx_version(const std::filesystem::path& ccx);

// Runs `ccx -i <job>` in `dir` (job.inp must be there), one thread; throws std::runtime_error
// with the tail of ccx's output when it fails or writes no results.
void run_ccx(const std::filesystem::path& ccx, const std::filesystem::path& dir, const std::string& job);

// One nodal field at one output time: node -> values.
struct FrdField {
  double time = 0.0;
  std::string name;  // DISP, STRESS, PE, ...
  std::map<int, std::vector<double>> values;
};
std::vector<FrdField> read_frd(const std::filesystem::path& file);
// The "total force" lines of the .dat file for a node set: (time, fx, fy, fz).
std::vector<std::vector<double>> read_dat_totals(const std::filesystem::path& file);

// Per-node forces printed by *NODE PRINT (no totals) for one node set at one time.
struct DatForces {
  std::string set;
  double time = 0.0;
  std::map<int, std::array<double, 3>> forces;
};
std::vector<DatForces> read_dat_forces(const std::filesystem::path& file);

// Contact zones along a surface: the intervals of touching nodes (gap below a tenth of the
// largest penetration), each edge placed where the gap of the first two open nodes, opening as
// (x - edge)^(3/2), extrapolates to zero (kept between the last touching node and the first open
// node used). Open nodes whose gap is below a tenth of the next one's are taken as on the rim
// (within the discretisation of the edge) and skipped.
// `min_touch`: gaps below it count as touching too (1e-3 of the interference: a plastic contact
// meets the flat tangentially, leaving a band of near-zero gaps at its rim).
std::vector<std::pair<double, double>> contact_intervals(const std::vector<double>& x, const std::vector<double>& gap,
                                                         double min_touch = 0.0);

// Normalised single-asperity results at each level.
struct SingleAsperityResult {
  double delta_star = 0.0;
  double load_star = 0.0;                 // F / F_c
  double area_star = 0.0;                 // pi a^2 / A_c
  double contact_radius = 0.0;            // a / a_c
  double mean_pressure_over_yield = 0.0;  // F / (pi a^2 S_y)
  double max_pressure_over_yield =
      0.0;  // largest nodal reaction of the flat over its ring area, / S_y (axis node excluded)
  double max_von_mises_over_yield = 0.0;  // largest nodal von Mises / S_y
  double max_von_mises_depth = 0.0;       // its depth below the apex / a
  double plastic_depth = 0.0;             // deepest node with PEEQ > 0, / a_c (0: elastic)
  double plastic_surface_radius = 0.0;    // outermost surface node with PEEQ > 0, / a_c
  // The yielded share of the contact disc at the surface (surface_yield_share of the
  // surface_yielded_nodes, deformed radii): 0..1; its standard deviation from the mesh, and the
  // innermost yielded surface node (deformed) / a_c (0 if none or from the axis), which shows an annulus.
  double plastic_surface_area_fraction = 0.0;
  double plastic_surface_area_fraction_sd = 0.0;
  double plastic_surface_inner_radius = 0.0;
};

// A surface node counts as yielded when its equivalent plastic strain exceeds this (1e-6: 1/4000
// of the yield strain S_y/E ~ 4e-3 of the project's steel, above the 5-digit print of zero).
inline constexpr double surface_yield_threshold = 1e-6;

// Which surface nodes have yielded, from ccx's nodal PE along the surface (outward): the median
// of each node's value and its two neighbours' (the end nodes their own) above `threshold`.
// ccx extrapolates PEEQ from the integration points to the nodes; where it varies steeply within
// an element single nodes come out negative (down to -1.5e-3 inside the yielded zone at
// delta* = 20) or spuriously positive. The median drops such one-node flips and keeps the
// boundaries of any run of two or more nodes in place.
std::vector<bool> surface_yielded_nodes(const std::vector<double>& peeq, double threshold = surface_yield_threshold);

// The yielded share of a contact disc of radius `contact_radius`: the integral of the yielded
// indicator times 2 pi r dr over 0 <= r <= contact_radius, divided by pi contact_radius^2. Each
// surface node stands for the ring between the midpoints to its neighbours (the first from the
// axis, the last outward without end), so a yielded/unyielded boundary lies halfway between the
// two nodes, and the ring that contains the contact edge is cut there. `radius` increasing and
// as long as `yielded`; 0 when contact_radius <= 0. The yielded set may be an annulus or several.
double surface_yield_share(const std::vector<double>& radius, const std::vector<bool>& yielded, double contact_radius);

// Reads a finished single-asperity run (job.dat, job.frd in `dir`). F_c, A_c, a_c are the
// Hertz values at delta_c for E_t (R = 1 mm); the contact radius is where the deformed surface
// meets the flat, from the opening of the gap at the first two open surface nodes.
std::vector<SingleAsperityResult> read_single_asperity(const SingleAsperitySpec& spec, const SingleAsperityDeck& deck,
                                                       const std::filesystem::path& dir, const std::string& job);

// Three-cylinder results per level and asperity (SI).
struct CylinderLevelResult {
  double level = 0.0;      // approach in the spec's unit
  double line_load = 0.0;  // total [N/m]
  struct Asperity {
    double load = 0.0;                // [N/m], from the flat's nodal reactions over its share
    double contact_width = 0.0;       // [m]
    double max_von_mises = 0.0;       // within one contact width (at least one element) of its surface [Pa]
    double max_plastic_strain = 0.0;  // equivalent plastic strain in its share
  };
  std::vector<Asperity> asperities;
};
std::vector<CylinderLevelResult> read_cylinders(const CylindersSpec& spec, const CylindersDeck& deck,
                                                const std::filesystem::path& dir, const std::string& job);

}  // namespace geartrib::fem
