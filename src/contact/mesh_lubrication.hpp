// The lubricated mesh cycle along A -> E: the smooth film and its inlet-heating correction, the
// load shared between film and asperities (the asperity side from the run's own
// Greenwood-Williamson table), friction, flash and contact temperature, Archard wear, power loss
// and the ISO/TS 6336-20/22 rating quantities beside them. Used by run_mesh_contact.
#pragma once

#include "case/case.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "lubrication/ehl_film.hpp"
#include "lubrication/lubricant.hpp"

#include <vector>

namespace geartrib::contact {

// The path's loading and kinematics, one value per position (the run's /mesh series).
struct PathState {
  std::vector<double> s, line_load, half_width, hertz_p0, radius, v1, v2;
};

class MeshLubrication {
 public:
  // Film, regime and load shares at every position (before the strips are solved).
  MeshLubrication(const Case& c, const gear::GearMesh& mesh, const PathState& path, const GreenwoodWilliamson& gw);
  // The asperities' share of the load at each position, for the strip contact.
  const std::vector<double>& asperity_shares() const { return asperity_share_; }
  // Friction, temperatures, wear and losses; fills r.lubrication and r.lubrication_summary.
  void finish(MeshContactResult& r) const;

 private:
  const Case& case_;
  const gear::GearMesh& mesh_;
  const PathState& path_;
  lubrication::FilmFormula formula_;
  lubrication::InletHeating inlet_;
  lubrication::OilState oil_at_inlet_, oil_at_bulk_;
  double reduced_modulus_ = 0.0;                // E' = 2 E* [Pa]
  double thermal_coefficient_[2] = {0.0, 0.0};  // B_M of pinion and wheel
  double iso_friction_ = 0.0;
  double bulk_temperature_ = 0.0;
  bool bulk_estimated_ = false;
  double composite_rq_ = 0.0, mean_ra_ = 0.0;
  std::vector<double> film_isothermal_, heating_factor_, film_, regime_, iso_flash_;
  std::vector<double> asperity_share_;
  std::vector<double> separation_;    // mean planes' separation [m]
  std::vector<double> film_gap_;      // the film's gap: the separation, or above the dry contact's (flag) [m]
  std::vector<double> gap_from_dry_;  // 1 where the dry contact's separation is negative
};

// (Ra1 + Ra2)/2 of a case's flanks [m]: the given Ra, or Rq/1.2533 (Gaussian), or for summit and
// spectral forms the equivalent surface's sigma shared equally.
double mean_arithmetic_roughness(const Case& c, const surface::EquivalentSurface& s);

}  // namespace geartrib::contact
