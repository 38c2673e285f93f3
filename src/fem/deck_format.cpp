#include "fem/deck_format.hpp"

#include <fmt/format.h>

namespace geartrib::fem {

std::vector<double> graded_grid(double first, double h0, double fine, double total, double growth) {
  std::vector<double> x{0.0};
  if (first > 0.0) x.push_back(first);
  while (x.back() + 0.5 * h0 < fine) x.push_back(x.back() + h0);
  double h = h0;
  while (x.back() < total) {
    h *= growth;
    x.push_back(x.back() + h);
  }
  return x;
}

std::string deck_number(double v) { return fmt::format("{:.12e}", v); }

void write_id_lines(std::string& out, const std::vector<int>& ids) {
  for (std::size_t k = 0; k < ids.size(); ++k)
    out += fmt::format("{}{}", ids[k], (k + 1) % 10 == 0 || k + 1 == ids.size() ? "\n" : ", ");
}

void write_materials(std::string& out, const std::string& body_set, double youngs_modulus, double poisson_ratio,
                     FemMaterial material, double yield_strength,
                     const std::vector<std::pair<double, double>>& flow_table, const std::string& section_line) {
  const std::string elastic = fmt::format("*ELASTIC\n{}, {}\n", deck_number(youngs_modulus * 1e-6), poisson_ratio);
  out += "*MATERIAL, NAME=ASPERITY\n" + elastic;
  if (material == FemMaterial::perfectly_plastic)
    out += fmt::format("*PLASTIC\n{}, 0.\n", deck_number(yield_strength * 1e-6));
  if (material == FemMaterial::table) {
    out += "*PLASTIC\n";
    for (const auto& [stress, strain] : flow_table)
      out += fmt::format("{}, {}\n", deck_number(stress * 1e-6), deck_number(strain));
  }
  out += "*MATERIAL, NAME=FLAT\n" + elastic;
  out += "*SOLID SECTION, ELSET=" + body_set + ", MATERIAL=ASPERITY\n" + section_line;
  out += "*SOLID SECTION, ELSET=EFLAT, MATERIAL=FLAT\n" + section_line;
}

void write_rigid_flat_step(std::string& out, const RigidFlatStep& s) {
  out += fmt::format("*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{}\n",
                     deck_number(s.penalty));
  out += "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\n" + s.slave + ", SFLAT\n";
  // One step per level, the flat ramped from the previous level to this one; results are written
  // at every increment and read at each step's end (total time = level). (*TIME POINTS within
  // one step can stall ccx 2.20: an increment landing a rounding error short of a time point is
  // cut to zero and never converges.)
  double previous = 0.0;
  for (std::size_t k = 0; k < s.levels.size(); ++k) {
    const double span = s.levels[k] - previous;
    out += k == 0 && s.plastic ? "*STEP, NLGEOM, INC=2000\n" : "*STEP, INC=2000\n";
    out += fmt::format("*STATIC\n{}, {}, {}, {}\n",
                       deck_number(std::min(span, k == 0 ? s.initial_increment : 0.25 * span)), deck_number(span),
                       deck_number(1e-6 * span), deck_number(std::min(span, s.max_increment)));
    if (k == 0) out += "*BOUNDARY\n" + s.supports + "NFLAT, 1, 1, 0.\n";
    out += fmt::format("*BOUNDARY\nNFLAT, 2, 2, {}\n", deck_number(-s.displacement_per_level * s.levels[k]));
    out += "*NODE PRINT, NSET=NFLAT, TOTALS=ONLY\nRF\n";
    out += "*NODE PRINT, NSET=NCONTACT\nRF\n";
    out += "*NODE FILE\nU\n";
    out += s.plastic ? "*EL FILE\nS, PEEQ\n" : "*EL FILE\nS\n";
    out += "*END STEP\n";
    previous = s.levels[k];
  }
}

}  // namespace geartrib::fem
