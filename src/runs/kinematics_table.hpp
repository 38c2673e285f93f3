// The pair along its line of action at named points or evenly spaced positions: curvature, load
// share, Hertz line contact, speeds, stiffness. `geartrib kinematics` prints it, the Python
// module's geartrib.kinematics returns it. Column names carry their units (s_m, hertz_p0_Pa).
#pragma once

#include "gear/gear_mesh.hpp"
#include "output/table_writer.hpp"

#include <string>
#include <vector>

namespace geartrib::runs {

// Rows labelled by point: A, B, C, D, E (empty: all five); at B and D the single-tooth side of
// the jump. Throws std::invalid_argument for another name.
io::Table kinematics_table(const gear::GearMesh& mesh, const std::vector<std::string>& points);
// `positions` (2 to kMaxKinematicsPositions) evenly spaced from A to E, rows labelled 0, 1, ...;
// std::invalid_argument outside.
inline constexpr int kMaxKinematicsPositions = 100000;
io::Table kinematics_table(const gear::GearMesh& mesh, int positions);

}  // namespace geartrib::runs
