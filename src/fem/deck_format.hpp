// Pieces shared by the CalculiX deck writers: graded 1-D grids and the number and id formats
// ccx reads safely.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace geartrib::fem {

enum class FemMaterial { elastic, perfectly_plastic, table };

// Graded 1-D grid from 0: a first cell `first` (0: none; a tiny axis cell for axisymmetric
// models, whose axis face collapses in ccx's wedge expansion), uniform cells h0 up to `fine`,
// then cells growing by `growth` until `total` is passed.
std::vector<double> graded_grid(double first, double h0, double fine, double total, double growth);

// 13 significant digits in 19 characters: ccx silently cuts fields longer than 20.
std::string deck_number(double v);

// Node or element ids, ten per line.
void write_id_lines(std::string& out, const std::vector<int>& ids);

// Materials ASPERITY (elastic; perfectly plastic at S_y, or the flow table of (stress [Pa],
// plastic strain)) on `body_set` and FLAT (elastic) on EFLAT, with their solid sections
// (`section_line`: "1.\n" for the plane-strain thickness, empty for axisymmetric).
void write_materials(std::string& out, const std::string& body_set, double youngs_modulus, double poisson_ratio,
                     FemMaterial material, double yield_strength,
                     const std::vector<std::pair<double, double>>& flow_table, const std::string& section_line);

// The rigid flat's frictionless penalty contact with the `slave` surface (master SFLAT) and one
// static step per level (total time = level): `supports` (*BOUNDARY lines), the flat (NFLAT)
// moved down to `displacement_per_level` x level, reactions of NFLAT (totals) and of NCONTACT
// (per node), U, S and, for plastic runs, PEEQ at every increment.
struct RigidFlatStep {
  std::string slave;
  double penalty = 0.0;        // [MPa/mm]
  std::vector<double> levels;  // increasing
  double initial_increment = 0.0, max_increment = 0.0;
  bool plastic = false;  // NLGEOM and PEEQ output
  std::string supports;
  double displacement_per_level = 0.0;  // [mm]
};
void write_rigid_flat_step(std::string& out, const RigidFlatStep& step);

}  // namespace geartrib::fem
