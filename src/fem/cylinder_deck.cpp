#include "fem/cylinder_deck.hpp"

#include "fem/deck_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geartrib::fem {

void CylindersSpec::validate() const {
  if (cylinders.empty()) throw std::invalid_argument("give at least one cylinder");
  double top = -1e300;
  for (std::size_t k = 0; k < cylinders.size(); ++k) {
    if (!(cylinders[k].radius > 0.0)) throw std::invalid_argument("cylinder tip radii must be positive");
    if (k && !(cylinders[k].centre > cylinders[k - 1].centre))
      throw std::invalid_argument("cylinders must be ordered by centre");
    top = std::max(top, cylinders[k].tip);
  }
  if (std::abs(top) > 1e-15) throw std::invalid_argument("the highest tip must be at 0");
  if (!(asperity_height > 0.0) || !(depth > 2.0 * asperity_height))
    throw std::invalid_argument("need 0 < asperity height < depth / 2");
  if (!(youngs_modulus > 0.0) || !(yield_strength > 0.0) || !(poisson_ratio > 0.0 && poisson_ratio < 0.5))
    throw std::invalid_argument("FEM material needs E > 0, S_y > 0 and 0 < nu < 0.5");
  if (!(unit > 0.0) || levels.empty()) throw std::invalid_argument("give the approach unit and at least one level");
  for (std::size_t k = 0; k < levels.size(); ++k)
    if (!(levels[k] > 0.0) || (k && !(levels[k] > levels[k - 1])))
      throw std::invalid_argument("levels must be positive and increasing");
  if (!(levels.back() * unit < 0.5 * asperity_height))
    throw std::invalid_argument("the approach must stay below half the asperity height");
  if (refine < 4 || refine > 200) throw std::invalid_argument("refine must lie in [4, 200]");
  if (!(growth >= 1.0 && growth <= 2.0)) throw std::invalid_argument("mesh growth must lie in [1, 2]");
  if (material == FemMaterial::table && flow_table.empty())
    throw std::invalid_argument("material 'table' needs a flow table");
}

CylindersDeck cylinders_deck(const CylindersSpec& s) {
  s.validate();
  CylindersDeck d;
  const double mm = 1e3;  // metres -> millimetres
  const double approach = s.levels.back() * s.unit * mm;
  double r_min = 1e300;
  for (const auto& c : s.cylinders) r_min = std::min(r_min, c.radius * mm);
  // Contact half-width estimate: the flat's chord through the highest tip, sqrt(2 R delta).
  const double b = std::sqrt(2.0 * r_min * approach);
  const double h0 = b / s.refine;
  d.tip_element = h0;
  const double x_lo = s.cylinders.front().centre * mm - 1.6 * b, x_hi = s.cylinders.back().centre * mm + 1.6 * b;
  const double depth = s.depth * mm, base = -s.asperity_height * mm;
  // x: uniform h0 over the contacts, growing outward to depth on each side.
  std::vector<double> x;
  const int n_fine = std::max(1, static_cast<int>(std::ceil((x_hi - x_lo) / h0)));
  const std::vector<double> out = graded_grid(0.0, h0, 0.0, depth, s.growth);
  // NOLINTNEXTLINE(modernize-loop-convert): std::views::reverse is beyond clang(-tidy) 14 with libstdc++ 12
  for (auto it = out.rbegin(); it != out.rend(); ++it)
    if (*it > 0.0) x.push_back(x_lo - *it);
  for (int i = 0; i <= n_fine; ++i) x.push_back(x_lo + (x_hi - x_lo) * i / n_fine);
  for (double o : out)
    if (o > 0.0) x.push_back(x_hi + o);
  // depth below the surface: uniform h0 over 1.6 b, then growing to the bottom.
  std::vector<double> z = graded_grid(0.0, h0, 1.6 * b, depth, s.growth);
  z.back() = depth;  // the last layer ends on the bottom
  auto top = [&](double xx) {
    double y = base;
    for (const auto& c : s.cylinders)
      y = std::max(y, c.tip * mm - std::pow(xx - c.centre * mm, 2) / (2.0 * c.radius * mm));
    return y;
  };
  const int nx = static_cast<int>(x.size()) - 1, nz = static_cast<int>(z.size()) - 1, ni = 2 * nx + 1;
  auto lattice = [](const std::vector<double>& v, int i) {
    return i % 2 == 0 ? v[i / 2] : 0.5 * (v[i / 2] + v[i / 2 + 1]);
  };
  auto id = [&](int i, int j) { return j * ni + i + 1; };
  std::string& t = d.text;
  t += fmt::format("** geartrib: {} parabolic cylinders in plane strain against a rigid flat; units mm N MPa\n",
                   s.cylinders.size());
  t += fmt::format("** tip element {} mm; {} x {} CPE8; approach levels in units of {} m:", deck_number(h0), nx, nz,
                   s.unit);
  for (double l : s.levels) t += fmt::format(" {}", l);
  t += "\n*NODE, NSET=NBODY\n";
  for (int j = 0; j <= 2 * nz; ++j)
    for (int i = 0; i < ni; ++i) {
      if (i % 2 == 1 && j % 2 == 1) continue;
      const double xx = lattice(x, i), yt = top(xx);
      // Depth scaled so that every column ends on the flat bottom y = -depth.
      const double yy = yt - lattice(z, j) * (yt + depth) / depth;
      t += fmt::format("{}, {}, {}\n", id(i, j), deck_number(xx), deck_number(yy));
      d.node_xy.push_back({id(i, j), {xx, yy}});
      d.node_depth.push_back(yt - yy);
      if (j == 0 && xx >= x_lo - 1e-12 && xx <= x_hi + 1e-12)
        d.top_nodes.push_back(id(i, j)), d.top_x.push_back(xx), d.top_y.push_back(yt);
    }
  const int flat0 = id(ni - 1, 2 * nz) + 1;
  std::vector<double> xf;
  for (double xx : x)
    if (xx >= x_lo - 2.0 * h0 && xx <= x_hi + 2.0 * h0) xf.push_back(xx);
  const int nf = static_cast<int>(xf.size());
  t += "*NODE, NSET=NFLAT\n";
  for (int row = 0; row < 2; ++row)
    for (int i = 0; i < nf; ++i) {
      t += fmt::format("{}, {}, {}\n", flat0 + row * nf + i, deck_number(xf[i]), deck_number(row * 10.0 * h0));
      if (row == 0) d.flat_nodes.emplace_back(flat0 + i, xf[i]);
    }
  t += "*ELEMENT, TYPE=CPE8, ELSET=EBODY\n";
  int e = 0;
  std::vector<int> top_elements;
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) {
      const int I = 2 * i, J = 2 * j;
      ++e;
      t += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, id(I, J + 2), id(I + 2, J + 2), id(I + 2, J),
                       id(I, J), id(I + 1, J + 2), id(I + 2, J + 1), id(I + 1, J), id(I, J + 1));
      if (j == 0 && x[i] >= x_lo - 1.6 * b && x[i + 1] <= x_hi + 1.6 * b) top_elements.push_back(e);
    }
  d.elements = e;
  t += "*ELEMENT, TYPE=CPE4, ELSET=EFLAT\n";
  for (int i = 0; i + 1 < nf; ++i)
    t += fmt::format("{}, {}, {}, {}, {}\n", e + 1 + i, flat0 + i, flat0 + i + 1, flat0 + nf + i + 1, flat0 + nf + i);
  std::vector<int> bottom;
  bottom.reserve(static_cast<std::size_t>(ni));
  for (int i = 0; i < ni; ++i) bottom.push_back(id(i, 2 * nz));
  t += "*NSET, NSET=NBOTTOM\n";
  write_id_lines(t, bottom);
  t += "*NSET, NSET=NCONTACT\n";
  std::vector<int> contact_flat;
  contact_flat.reserve(static_cast<std::size_t>(nf));
  for (int i = 0; i < nf; ++i) contact_flat.push_back(flat0 + i);
  write_id_lines(t, contact_flat);
  t += "*SURFACE, NAME=SBODY, TYPE=ELEMENT\n";
  for (int el : top_elements) t += fmt::format("{}, S3\n", el);
  t += "*SURFACE, NAME=SFLAT, TYPE=ELEMENT\n";
  for (int i = 0; i + 1 < nf; ++i) t += fmt::format("{}, S1\n", e + 1 + i);
  write_materials(t, "EBODY", s.youngs_modulus, s.poisson_ratio, s.material, s.yield_strength, s.flow_table, "1.\n");
  RigidFlatStep step;
  step.slave = "SBODY";
  step.penalty = 1e3 * 1.8 * s.yield_strength * 1e-6 /
                 approach;  // penetration ~0.1% of the approach at ~1.8 S_y (plane-strain yield)
  step.levels = s.levels;
  step.initial_increment = std::min(0.1 * s.levels.back(), 0.25 * s.levels.front());
  step.max_increment = std::max(0.5 * s.levels.front(), s.levels.back() / 20.0);
  step.plastic = s.material != FemMaterial::elastic;
  step.supports = "NBOTTOM, 1, 2, 0.\n";
  step.displacement_per_level = s.unit * mm;
  write_rigid_flat_step(t, step);
  return d;
}

}  // namespace geartrib::fem
