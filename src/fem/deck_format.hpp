// Pieces shared by the CalculiX deck writers: graded 1-D grids and the number and id formats
// ccx reads safely.
#pragma once

#include <string>
#include <vector>

namespace geartrib::fem {

// Graded 1-D grid from 0: a first cell `first` (0: none; a tiny axis cell for axisymmetric
// models, whose axis face collapses in ccx's wedge expansion), uniform cells h0 up to `fine`,
// then cells growing by `growth` until `total` is passed.
std::vector<double> graded_grid(double first, double h0, double fine, double total, double growth);

// 13 significant digits in 19 characters: ccx silently cuts fields longer than 20.
std::string deck_number(double v);

// Node or element ids, ten per line.
void write_id_lines(std::string& out, const std::vector<int>& ids);

}  // namespace geartrib::fem
