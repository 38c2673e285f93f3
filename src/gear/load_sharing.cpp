#include "gear/load_sharing.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geartrib::gear {

namespace {
constexpr NamedChoice<LoadSharing> kLoadSharingNames[] = {
    {LoadSharing::iso, "iso"}, {LoadSharing::stiffness, "stiffness"}, {LoadSharing::compatibility, "compatibility"}};
}  // namespace

std::span<const NamedChoice<LoadSharing>> load_sharing_choices() { return kLoadSharingNames; }
std::string_view to_string(LoadSharing method) { return choice_name(load_sharing_choices(), method); }

double iso_load_sharing_factor(const PathOfContact& p, double s, bool single_side) {
  const double tol = 1e-12 * p.line_length;
  if (p.b <= p.a + tol || p.e <= p.d + tol) return 1.0;  // eps_alpha = 1: single contact throughout
  if (single_side && (std::abs(s - p.b) <= tol || std::abs(s - p.d) <= tol) && p.b <= p.d) return 1.0;
  if (s < p.b - tol || (std::abs(s - p.b) <= tol && !single_side)) return 1.0 / 3.0 + (s - p.a) / (3.0 * (p.b - p.a));
  if (s > p.d + tol || (std::abs(s - p.d) <= tol && !single_side)) return 2.0 / 3.0 - (s - p.d) / (3.0 * (p.e - p.d));
  return 1.0;
}

std::vector<double> pairs_in_contact(const PathOfContact& p, double s) {
  const double tol = 1e-12 * p.line_length;
  std::vector<double> out;
  double first = s;
  while (first - p.base_pitch >= p.a - tol) first -= p.base_pitch;
  for (double x = first; x <= p.e + tol; x += p.base_pitch)
    if (x >= p.a - tol) out.push_back(x);
  return out;
}

std::vector<double> load_shares(const PathOfContact& p, const std::vector<double>& positions, LoadSharing method,
                                const MeshStiffnessModel* stiffness) {
  std::vector<double> w;
  for (double s : positions) {
    if (method == LoadSharing::iso) {
      w.push_back(positions.size() == 1 ? 1.0 : iso_load_sharing_factor(p, s));
    } else if (method == LoadSharing::compatibility) {
      throw std::invalid_argument("load_shares: compatibility sharing is solved by LoadedToothContact");
    } else {
      if (!stiffness) throw std::invalid_argument("load_shares: stiffness sharing needs the mesh stiffness model");
      w.push_back(stiffness->pair(s).stiffness);
    }
  }
  double sum = 0.0;
  for (double x : w) sum += x;
  for (double& x : w) x /= sum;
  return w;
}

}  // namespace geartrib::gear
