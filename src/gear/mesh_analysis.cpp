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
      if (sol.loads[i] > 0.0) l.stiffness = 1.0 / (contacts[i].compliance + contacts[i].hertz.slope(sol.loads[i]));
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

namespace {
// Mean, least and largest of one member of a cycle's instants (in MeshStiffnessStats' three fields).
MeshStiffnessStats range_over(const std::vector<MeshInstant>& instants, double MeshInstant::*value) {
  MeshStiffnessStats s{0.0, instants.front().*value, instants.front().*value};
  for (const auto& m : instants) {
    s.mean += m.*value / static_cast<double>(instants.size());
    s.min = std::min(s.min, m.*value);
    s.max = std::max(s.max, m.*value);
  }
  return s;
}
}  // namespace

MeshStiffnessStats MeshAnalysis::stiffness_stats(int n) const {
  return range_over(cycle(n), &MeshInstant::mesh_stiffness);
}

TransmissionErrorStats MeshAnalysis::transmission_error_stats(int n) const {
  if (method_ != LoadSharing::compatibility)
    throw std::logic_error("the transmission error needs the compatibility load sharing");
  const auto instants = cycle(n);
  TransmissionErrorStats t;
  const MeshStiffnessStats error = range_over(instants, &MeshInstant::transmission_error);
  const MeshStiffnessStats stiffness = range_over(instants, &MeshInstant::mesh_stiffness);
  t.mean = error.mean, t.min = error.min, t.max = error.max, t.peak_to_peak = error.max - error.min;
  t.stiffness_mean = stiffness.mean, t.stiffness_min = stiffness.min, t.stiffness_max = stiffness.max;
  for (const MeshInstant& m : instants) t.hertz_in_range = t.hertz_in_range && m.hertz_in_range;
  // Where the tracked pair carries load: from each end of the path inwards to its first loaded
  // position, then bisected (its share rises from 0 where its separation meets the approach).
  const PathOfContact& p = pair_.path();
  auto loaded = [&](double s) { return at(s).pair_at(s).share > 0.0; };
  auto edge = [&](double from, double to) {
    if (loaded(from)) return from;
    double outside = from, inside = to;
    for (int i = 1; i <= n; ++i) {
      const double s = from + (to - from) * i / n;
      if (loaded(s)) {
        inside = s;
        break;
      }
      outside = s;
    }
    while (std::abs(inside - outside) > 1e-9 * p.line_length) {
      const double mid = 0.5 * (inside + outside);
      (loaded(mid) ? inside : outside) = mid;
    }
    return inside;
  };
  t.loaded_start = edge(p.a, p.c);
  t.loaded_end = edge(p.e, p.c);
  t.effective_contact_ratio = (t.loaded_end - t.loaded_start) / p.base_pitch;
  t.contact_lost = t.loaded_start > p.a || t.loaded_end < p.e;
  return t;
}

}  // namespace geartrib::gear
