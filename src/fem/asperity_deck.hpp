// Finite-element input decks (Abaqus/CalculiX format) for the single-asperity verification of
// seed section 3: an axisymmetric paraboloid y = -r^2/(2R) pressed by a rigid flat, frictionless,
// displacement-controlled to a list of delta* = delta/delta_c levels.
// Units in the deck: mm, N, MPa, with R = 1 mm; the problem is self-similar in R for elastic and
// rate-independent plastic materials, so the normalised results (F/F_c, A/A_c) hold for any R.
#pragma once

#include "fem/deck_format.hpp"

#include <string>
#include <utility>
#include <vector>

namespace geartrib::fem {

struct SingleAsperitySpec {
  double modulus = 0.0;  // E/(1 - nu^2) of the deformable asperity = the pair's E_t (Johnson's E*) [Pa]
  double poisson_ratio = 0.3;
  double yield_strength = 0.0;                     // S_y [Pa]
  double critical_interference_over_radius = 0.0;  // delta_c / R [-] (Kogut-Etsion's, from the case)
  FemMaterial material = FemMaterial::elastic;
  std::vector<std::pair<double, double>> flow_table;  // (stress [Pa], plastic strain [-]) from S_y at 0
  std::vector<double> delta_star;                     // levels, increasing, > 0
  // Mesh: the element size at the tip is the Hertz contact radius at the smallest level over
  // `refine` (n elements across the first contact), uniform to 1.6 times the contact radius at
  // the largest level, then growing geometrically by `growth` to a body `size` such radii wide
  // and deep. Levels far apart are better run in groups (plan_runs).
  int refine = 20;
  double growth = 1.25;
  double size = 60.0;
  void validate() const;  // throws std::invalid_argument
};

struct SingleAsperityDeck {
  std::string text;                                // the .inp deck
  int elements = 0;                                // CAX8 elements of the asperity
  double tip_element = 0.0;                        // element size near the tip [mm]
  double critical_interference = 0.0;              // delta_c [mm] (R = 1 mm)
  std::vector<double> top_node_r;                  // radial positions of the surface nodes, outward [mm]
  std::vector<int> top_nodes;                      // their node numbers
  std::vector<std::pair<int, double>> node_depth;  // node -> depth below the apex (undeformed) [mm], for stresses
  std::vector<std::pair<int, double>> node_r;      // node -> radial position [mm]
  std::vector<std::pair<int, double>> flat_nodes;  // the flat's contact-face nodes and their radii [mm]
};

SingleAsperityDeck single_asperity_deck(const SingleAsperitySpec& s);

// Splits increasing levels into runs whose largest level is at most `ratio` times the smallest
// (ratio 4: contact radii within a factor 2), so that each run's mesh resolves its first contact
// with `refine` elements without a needlessly fine mesh at the last.
std::vector<std::vector<double>> plan_runs(const std::vector<double>& levels, double ratio = 4.0);

}  // namespace geartrib::fem
