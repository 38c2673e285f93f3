#include "gear/mesh_analysis.hpp"

#include "asperity/cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace geartrib::gear {

MeshAnalysis::MeshAnalysis(const SpurPair& pair, const MeshStiffnessModel& stiffness, LoadSharing method,
                           double normal_force, double composite_modulus, const LoadedToothContact* contact)
    : pair_(pair),
      stiffness_(stiffness),
      method_(method),
      normal_force_(normal_force),
      composite_modulus_(composite_modulus),
      contact_(contact) {
  if (!(normal_force >= 0.0)) throw std::invalid_argument("normal force must be >= 0");
  if (method == LoadSharing::compatibility && !contact)
    throw std::invalid_argument("compatibility load sharing needs the loaded tooth contact");
}

PairLoad MeshAnalysis::pair_load(double s, double w) const {
  PairLoad l;
  l.s = s;
  l.line_load = w;
  const double r = pair_.flank(s).radius_equivalent;
  l.hertz_half_width = asperity::hertz_half_width(w, r, composite_modulus_);
  l.hertz_peak = l.hertz_half_width > 0.0 ? 2.0 * w / (std::numbers::pi * l.hertz_half_width) : 0.0;
  return l;
}

const PairLoad& MeshInstant::pair_at(double s) const {
  if (pairs.empty()) throw std::logic_error("mesh instant without a pair in contact");
  const PairLoad* own = &pairs.front();
  for (const auto& l : pairs)
    if (std::abs(l.s - s) < std::abs(own->s - s)) own = &l;
  return *own;
}

MeshInstant MeshAnalysis::at(double s, bool single_side, PairStiffness stiffness) const {
  const PathOfContact& p = pair_.path();
  std::vector<double> positions = pairs_in_contact(p, s);
  if (single_side) {
    const double tol = 1e-9 * p.line_length;
    const bool at_b = std::abs(s - p.b) <= tol, at_d = std::abs(s - p.d) <= tol;
    std::erase_if(positions, [&](double x) {
      return (at_b && std::abs(x - p.e) <= tol && std::abs(s - p.e) > tol) ||
             (at_d && std::abs(x - p.a) <= tol && std::abs(s - p.a) > tol);
    });
  }
  MeshInstant m;
  const double width = pair_.spec().face_width;
  if (method_ == LoadSharing::compatibility) {
    // A vanishing load (a millionth of a newton) stands for zero: the pairs nearest contact share it.
    const double force = normal_force_ > 0.0 ? normal_force_ : 1e-6;
    const std::vector<PairContact> contacts = contact_->pairs(positions);
    const CompatibilitySolution sol = solve_compatibility(contacts, force);
    double sum = 0.0;
    for (double f : sol.loads) sum += f;
    m.transmission_error = sol.approach;
    m.hertz_in_range = sol.hertz_in_range;
    m.mesh_stiffness = sol.tangent_stiffness;
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const double share = sol.loads[i] / sum;
      PairLoad l = pair_load(positions[i], share * normal_force_ / width);
      l.share = share;
      l.separation = contacts[i].separation;
      if (sol.loads[i] > 0.0)
        l.stiffness = 1.0 / (contacts[i].compliance + contacts[i].hertz.slope(sol.loads[i]));
      m.pairs.push_back(l);
    }
    return m;
  }
  const std::vector<double> shares = load_shares(p, positions, method_, &stiffness_);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    PairLoad l = pair_load(positions[i], shares[i] * normal_force_ / width);
    l.share = shares[i];
    if (stiffness == PairStiffness::computed || method_ == LoadSharing::stiffness)
      l.stiffness = stiffness_.pair(positions[i]).stiffness;
    m.mesh_stiffness += l.stiffness;
    m.pairs.push_back(l);
  }
  return m;
}

std::vector<MeshInstant> MeshAnalysis::cycle(int n) const {
  if (n < 1) throw std::invalid_argument("mesh cycle needs at least one position");
  std::vector<MeshInstant> out;
  out.reserve(static_cast<std::size_t>(n));
  const PathOfContact& p = pair_.path();
  for (int i = 0; i < n; ++i) out.push_back(at(p.a + p.base_pitch * i / n));
  return out;
}

MeshStiffnessStats MeshAnalysis::stiffness_stats(int n) const {
  const auto instants = cycle(n);
  MeshStiffnessStats s{0.0, instants.front().mesh_stiffness, instants.front().mesh_stiffness};
  for (const auto& m : instants) {
    s.mean += m.mesh_stiffness / n;
    s.min = std::min(s.min, m.mesh_stiffness);
    s.max = std::max(s.max, m.mesh_stiffness);
  }
  return s;
}

}  // namespace geartrib::gear
