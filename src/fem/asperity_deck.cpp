#include "fem/asperity_deck.hpp"
#include "fem/deck_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geartrib::fem {

void SingleAsperitySpec::validate() const {
  if (!(modulus > 0.0) || !(yield_strength > 0.0) || !(poisson_ratio > 0.0 && poisson_ratio < 0.5))
    throw std::invalid_argument("FEM material needs E' > 0, S_y > 0 and 0 < nu < 0.5");
  if (!(critical_interference_over_radius > 0.0 && critical_interference_over_radius < 0.01))
    throw std::invalid_argument("delta_c / R must lie in (0, 0.01) (small-slope asperity)");
  if (delta_star.empty()) throw std::invalid_argument("give at least one delta* level");
  for (std::size_t k = 0; k < delta_star.size(); ++k)
    if (!(delta_star[k] > 0.0) || (k && !(delta_star[k] > delta_star[k - 1])))
      throw std::invalid_argument("delta* levels must be positive and increasing");
  if (delta_star.back() * critical_interference_over_radius > 0.05)
    throw std::invalid_argument("the largest interference exceeds 5% of R: beyond the small-slope paraboloid");
  if (refine < 4 || refine > 400)
    throw std::invalid_argument("refine (elements across the contact radius) must lie in [4, 400]");
  if (std::sqrt(delta_star.back() / delta_star.front()) * refine > 400)
    throw std::invalid_argument(
        "levels too far apart for one mesh (more than 400 elements across the last contact): split the run");
  if (!(growth >= 1.0 && growth <= 2.0)) throw std::invalid_argument("mesh growth must lie in [1, 2]");
  if (!(size >= 5.0)) throw std::invalid_argument("body size must be at least 5 contact radii");
  if (material == FemMaterial::table && flow_table.empty())
    throw std::invalid_argument("material 'table' needs a flow table");
}

std::vector<std::vector<double>> plan_runs(const std::vector<double>& levels, double ratio) {
  std::vector<std::vector<double>> runs;
  for (double l : levels) {
    if (runs.empty() || l > ratio * runs.back().front()) runs.emplace_back();
    runs.back().push_back(l);
  }
  return runs;
}

SingleAsperityDeck single_asperity_deck(const SingleAsperitySpec& s) {
  s.validate();
  SingleAsperityDeck d;
  const double radius = 1.0;  // [mm]
  d.critical_interference = s.critical_interference_over_radius * radius;
  const double a_max =
      std::sqrt(radius * d.critical_interference * s.delta_star.back());  // Hertz radius at the last level
  const double a_min = std::sqrt(radius * d.critical_interference * s.delta_star.front());
  const double h0 = a_min / s.refine;
  d.tip_element = h0;
  const std::vector<double> r =
      graded_grid(std::min(2e-5 * radius, 0.2 * h0), h0, 1.6 * a_max, s.size * a_max, s.growth);
  const std::vector<double> depth = graded_grid(0.0, h0, 1.6 * a_max, s.size * a_max, s.growth);
  const int nr = static_cast<int>(r.size()) - 1, nz = static_cast<int>(depth.size()) - 1;
  const int ni = 2 * nr + 1;  // lattice points across (corners and midsides)
  auto lattice = [](const std::vector<double>& x, int i) {
    return i % 2 == 0 ? x[i / 2] : 0.5 * (x[i / 2] + x[i / 2 + 1]);
  };
  auto id = [&](int i, int j) { return j * ni + i + 1; };  // j = 0 at the surface, downward
  std::string& out = d.text;
  out += "** geartrib: single asperity (paraboloid y = -r^2/(2R), R = 1 mm) against a rigid flat\n";
  out += fmt::format("** units mm N MPa; delta_c = {} mm; tip element {} mm; {} x {} CAX8\n",
                     deck_number(d.critical_interference), deck_number(h0), nr, nz);
  out += "** delta* levels:";
  for (double l : s.delta_star) out += fmt::format(" {}", l);
  out += "\n";
  out += "*NODE, NSET=NASP\n";
  for (int j = 0; j <= 2 * nz; ++j)
    for (int i = 0; i < ni; ++i) {
      if (i % 2 == 1 && j % 2 == 1) continue;  // element centres are not nodes of CAX8
      const double rr = lattice(r, i), dd = lattice(depth, j);
      out += fmt::format("{}, {}, {}\n", id(i, j), deck_number(rr), deck_number(-rr * rr / (2.0 * radius) - dd));
      d.node_depth.emplace_back(id(i, j), dd);
      d.node_r.emplace_back(id(i, j), rr);
      if (j == 0) d.top_nodes.push_back(id(i, j)), d.top_node_r.push_back(rr);
    }
  // The rigid flat: one row of CAX4 over the contact zone, touching the apex.
  const int flat0 = id(ni - 1, 2 * nz) + 1;
  std::vector<double> rf;
  for (double x : r)
    if (rf.empty() || rf.back() < 2.0 * a_max) rf.push_back(x);
  const double thickness = 1.6 * a_max;
  out += "*NODE, NSET=NFLAT\n";
  for (std::size_t i = 0; i < rf.size(); ++i) d.flat_nodes.emplace_back(flat0 + static_cast<int>(i), rf[i]);
  for (int row = 0; row < 2; ++row)
    for (std::size_t i = 0; i < rf.size(); ++i)
      out += fmt::format("{}, {}, {}\n", flat0 + row * static_cast<int>(rf.size()) + static_cast<int>(i),
                         deck_number(rf[i]), deck_number(row * thickness));
  out += "*ELEMENT, TYPE=CAX8, ELSET=EASP\n";
  int e = 0;
  std::vector<int> top_elements;
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nr; ++i) {
      const int I = 2 * i, J = 2 * j;
      ++e;
      out += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, id(I, J + 2), id(I + 2, J + 2), id(I + 2, J),
                         id(I, J), id(I + 1, J + 2), id(I + 2, J + 1), id(I + 1, J), id(I, J + 1));
      if (j == 0 && r[i] < 2.0 * a_max) top_elements.push_back(e);
    }
  d.elements = e;
  out += "*ELEMENT, TYPE=CAX4, ELSET=EFLAT\n";
  const int nf = static_cast<int>(rf.size());
  for (int i = 0; i + 1 < nf; ++i)
    out += fmt::format("{}, {}, {}, {}, {}\n", e + 1 + i, flat0 + i, flat0 + i + 1, flat0 + nf + i + 1, flat0 + nf + i);
  // Node sets for the supports.
  std::vector<int> axis, bottom;
  for (int j = 0; j <= 2 * nz; ++j) axis.push_back(id(0, j));
  for (int i = 0; i < ni; ++i) bottom.push_back(id(i, 2 * nz));
  out += "*NSET, NSET=NAXIS\n";
  write_id_lines(out, axis);
  out += "*NSET, NSET=NBOTTOM\n";
  write_id_lines(out, bottom);
  out += "*NSET, NSET=NCONTACT\n";
  std::vector<int> contact_nodes;
  for (const auto& fn : d.flat_nodes) contact_nodes.push_back(fn.first);
  write_id_lines(out, contact_nodes);
  out += "*SURFACE, NAME=SASP, TYPE=ELEMENT\n";
  for (int t : top_elements) out += fmt::format("{}, S3\n", t);
  out += "*SURFACE, NAME=SFLAT, TYPE=ELEMENT\n";
  for (int i = 0; i + 1 < nf; ++i) out += fmt::format("{}, S1\n", e + 1 + i);
  // Materials: the asperity's E = E_t (1 - nu^2), so that E/(1 - nu^2) is the pair's E_t.
  const double nu = s.poisson_ratio, sy = s.yield_strength * 1e-6;
  write_materials(out, "EASP", s.modulus * (1.0 - nu * nu), nu, s.material, s.yield_strength, s.flow_table, "");
  RigidFlatStep step;
  step.slave = "SASP";
  step.penalty =
      1e3 * 1.6 * sy / d.critical_interference;  // penetration ~0.1% of delta_c at the first-yield pressure ~1.6 S_y
  step.levels = s.delta_star;
  // Increments: from a quarter of the first level (at most delta* = 0.5, before first yield), at
  // most half the first level or a fiftieth of the last, whichever is larger; ccx adapts between.
  step.initial_increment = std::min(0.25 * s.delta_star.front(), 0.5);
  step.max_increment = std::max(0.5 * s.delta_star.front(), s.delta_star.back() / 50.0);
  step.plastic = s.material != FemMaterial::elastic;
  step.supports = "NAXIS, 1, 1, 0.\nNBOTTOM, 2, 2, 0.\n";
  step.displacement_per_level = d.critical_interference;
  write_rigid_flat_step(out, step);
  return d;
}

}  // namespace geartrib::fem
