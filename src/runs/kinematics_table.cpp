#include "runs/kinematics_table.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geartrib::runs {

namespace {

// Under the compatibility sharing two more columns: the tracked pair's separation and the
// transmission error.
io::Table empty_table(const gear::GearMesh& mesh) {
  io::Table t;
  t.header = {"point",
              "s_m",
              "gamma",
              "rho1_m",
              "rho2_m",
              "r_eq_m",
              "load_share",
              "line_load_N_per_m",
              "hertz_p0_Pa",
              "hertz_halfwidth_m",
              "hertz_p0_single_pair_Pa",
              "v1_m_per_s",
              "v2_m_per_s",
              "entrainment_m_per_s",
              "sliding_m_per_s",
              "srr",
              "specific_sliding_pinion",
              "specific_sliding_wheel",
              "pair_stiffness_N_per_m",
              "mesh_stiffness_N_per_m",
              "pairs_in_contact"};
  if (mesh.tooth_contact()) {
    t.header.emplace_back("separation_m");
    t.header.emplace_back("transmission_error_m");
  }
  return t;
}

// The row of the tracked pair at s; at B and D `single_side` takes the single-tooth side of the jump.
void add_row(io::Table& t, const gear::GearMesh& mesh, const std::string& label, double s, bool single_side) {
  const auto& pair = mesh.pair();
  const auto& p = pair.path();
  const gear::MeshInstant m = mesh.analysis().at(s, single_side);
  const gear::PairLoad* own = nullptr;
  for (const auto& l : m.pairs)
    if (std::abs(l.s - s) <= 1e-9 * p.line_length) own = &l;
  if (!own) throw std::logic_error("tracked pair missing from the mesh instant");
  const gear::FlankGeometry f = pair.flank(s);
  const gear::FlankKinematics k = pair.kinematics(s, mesh.pinion_speed());
  const gear::PairLoad single = mesh.analysis().pair_load(s, mesh.normal_force() / pair.spec().face_width);
  std::vector<double> row{s,
                          f.roll_parameter,
                          f.radius_pinion,
                          f.radius_wheel,
                          f.radius_equivalent,
                          own->share,
                          own->line_load,
                          own->hertz_peak,
                          own->hertz_half_width,
                          single.hertz_peak,
                          k.rolling_pinion,
                          k.rolling_wheel,
                          k.entrainment,
                          k.sliding,
                          k.slide_to_roll,
                          k.specific_sliding_pinion,
                          k.specific_sliding_wheel,
                          own->stiffness,
                          m.mesh_stiffness,
                          static_cast<double>(m.pairs.size())};
  if (mesh.tooth_contact()) {
    row.push_back(own->separation);
    row.push_back(m.transmission_error);
  }
  t.add_row(label, row);
}

}  // namespace

io::Table kinematics_table(const gear::GearMesh& mesh, const std::vector<std::string>& points) {
  const auto& p = mesh.pair().path();
  io::Table t = empty_table(mesh);
  const std::vector<std::string> names = points.empty() ? std::vector<std::string>{"A", "B", "C", "D", "E"} : points;
  for (const auto& name : names) {
    double s = 0.0;
    if (name == "A") s = p.a;
    else if (name == "B") s = p.b;
    else if (name == "C") s = p.c;
    else if (name == "D") s = p.d;
    else if (name == "E") s = p.e;
    else throw std::invalid_argument("unknown point '" + name + "' (known: A, B, C, D, E)");
    add_row(t, mesh, name, s, true);
  }
  return t;
}

io::Table kinematics_table(const gear::GearMesh& mesh, int positions) {
  if (positions < 2 || positions > kMaxKinematicsPositions)
    throw std::invalid_argument("positions must lie in [2, " + std::to_string(kMaxKinematicsPositions) + "]");
  const auto& p = mesh.pair().path();
  io::Table t = empty_table(mesh);
  for (int i = 0; i < positions; ++i) add_row(t, mesh, std::to_string(i), p.a + p.length * i / (positions - 1), false);
  return t;
}

}  // namespace geartrib::runs
