// The loaded mesh at any instant: the pairs in contact, their load shares, line loads and
// Hertz line-contact pressures, and the mesh stiffness; and the mesh cycle of one base pitch.
#pragma once

#include "gear/load_sharing.hpp"
#include "gear/spur_pair.hpp"
#include "gear/tooth_contact.hpp"
#include "gear/tooth_stiffness.hpp"

#include <vector>

namespace geartrib::gear {

struct PairLoad {
  double s = 0.0;                 // position on the line of action [m]
  double share = 0.0;             // share of the transmitted normal load
  double line_load = 0.0;         // normal load per unit face width [N/m]
  double hertz_peak = 0.0;        // Hertz line-contact peak pressure p0 = 2 w/(pi b_H) [Pa]
  double hertz_half_width = 0.0;  // b_H = sqrt(4 w R/(pi E_t)) [m]
  double stiffness = 0.0;         // tooth-pair stiffness [N/m]; under compatibility its tangent at the load
  double separation = 0.0;        // e_j: the flanks' modifications at the contact (compatibility) [m]
};

struct MeshInstant {
  std::vector<PairLoad> pairs;  // every pair in contact, in order of s
  double mesh_stiffness = 0.0;  // sum of the pair stiffnesses [N/m]
  // Under compatibility: the common approach delta, the static transmission error along the line
  // of action [m]; and whether every loaded pair's Hertzian approach was within its model's range.
  double transmission_error = 0.0;
  bool hertz_in_range = true;
  // The pair whose contact is at s (nearest it): the one `at(s)` was asked about.
  const PairLoad& pair_at(double s) const;
};

// The mesh stiffness over one base pitch: its mean, least and largest [N/m].
struct MeshStiffnessStats {
  double mean = 0.0, min = 0.0, max = 0.0;
};

// The loaded tooth contact over one base pitch (compatibility sharing).
struct TransmissionErrorStats {
  double mean = 0.0, min = 0.0, max = 0.0, peak_to_peak = 0.0;            // static transmission error delta [m]
  double stiffness_mean = 0.0, stiffness_min = 0.0, stiffness_max = 0.0;  // effective (tangent) mesh stiffness [N/m]
  double loaded_start = 0.0, loaded_end = 0.0;  // s where a pair begins and ends carrying load [m]
  double effective_contact_ratio = 0.0;         // (loaded_end - loaded_start)/p_b
  bool contact_lost = false;                    // a pair within A..E carries nothing at some position
  bool hertz_in_range = true;                   // every loaded pair's Hertzian approach within its model's range
};

class MeshAnalysis {
 public:
  // normal_force: the total normal tooth force F_bn = T1/r_b1 [N]; composite_modulus E_t [Pa];
  // `contact` the loaded tooth contact, needed by (and only read under) LoadSharing::compatibility.
  MeshAnalysis(const SpurPair& pair, const MeshStiffnessModel& stiffness, LoadSharing method, double normal_force,
               double composite_modulus, const LoadedToothContact* contact = nullptr);

  // The mesh when one pair is at s. single_side: at B and D take the single-pair side of the
  // jump (the neighbour at E or A has just left or not yet arrived). PairStiffness::omitted
  // leaves the stiffnesses 0 unless the load sharing needs them (ISO sharing does not). Under
  // compatibility a pair whose separation exceeds the approach carries nothing (share 0); at zero
  // load the shares are those of a vanishing load.
  enum class PairStiffness { computed, omitted };
  MeshInstant at(double s, bool single_side = false, PairStiffness stiffness = PairStiffness::computed) const;
  // Hertz values of a pair at s carrying line load w.
  PairLoad pair_load(double s, double line_load) const;
  // One base pitch of pinion rotation, n positions s0 = A + i p_b/n, i = 0..n-1.
  std::vector<MeshInstant> cycle(int n) const;
  // The mesh stiffness over cycle(n).
  MeshStiffnessStats stiffness_stats(int n) const;
  // Under compatibility: the transmission error and effective stiffness over cycle(n), and where
  // a pair carries load (its ends bisected to 1e-9 of the path); throws under another sharing.
  TransmissionErrorStats transmission_error_stats(int n) const;

  double normal_force() const { return normal_force_; }
  LoadSharing method() const { return method_; }

 private:
  const SpurPair& pair_;
  const MeshStiffnessModel& stiffness_;
  LoadSharing method_;
  double normal_force_;
  double composite_modulus_;
  const LoadedToothContact* contact_;
};

}  // namespace geartrib::gear
