// Finite-element decks (Abaqus/CalculiX format) for the seed's section 6 model: parallel
// parabolic-cylinder asperities y = t_k - (x - c_k)^2/(2 R_k) on a base, in plane strain, pressed
// by a rigid flat, frictionless, displacement-controlled to a list of approaches.
// Units in the deck: mm, N, MPa; forces are per mm of cylinder length.
#pragma once

#include "fem/asperity_deck.hpp"

#include <string>
#include <utility>
#include <vector>

namespace geartrib::fem {

struct DeckCylinder {
  double centre = 0.0;  // [m]
  double tip = 0.0;     // tip height, the highest at 0 [m]
  double radius = 0.0;  // R_m [m]
};

struct CylindersSpec {
  std::vector<DeckCylinder> cylinders;  // ordered by centre
  double asperity_height = 4e-6;        // base plane below the highest tip [m]
  double depth = 50e-6;                 // body depth below the highest tip; its bottom is fixed (the BEM's L_ref) [m]
  double youngs_modulus = 0.0;          // E [Pa]
  double poisson_ratio = 0.3;
  double yield_strength = 0.0;  // [Pa]
  FemMaterial material = FemMaterial::elastic;
  std::vector<std::pair<double, double>> flow_table;  // (stress [Pa], plastic strain [-])
  double unit = 0.0;                                  // approach unit, e.g. delta_pc [m]
  std::vector<double> levels;                         // approaches in `unit`, increasing
  int refine = 10;  // elements across the estimated contact half-width at the last level
  double growth = 1.25;
  void validate() const;  // throws std::invalid_argument
};

struct CylindersDeck {
  std::string text;
  int elements = 0;
  double tip_element = 0.0;                                        // [mm]
  std::vector<int> top_nodes;                                      // surface nodes of the fine region, by x
  std::vector<double> top_x, top_y;                                // their undeformed positions [mm]
  std::vector<std::pair<int, double>> flat_nodes;                  // flat contact nodes and their x [mm]
  std::vector<std::pair<int, std::pair<double, double>>> node_xy;  // every body node -> (x, y) [mm]
  std::vector<double> node_depth;  // below the local surface, same order as node_xy [mm]
};

CylindersDeck cylinders_deck(const CylindersSpec& s);

}  // namespace geartrib::fem
