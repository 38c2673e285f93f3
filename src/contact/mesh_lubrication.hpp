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
  // The asperities' share of the load at position i, for the strip contact.
  double asperity_share(std::size_t i) const { return positions_[i].asperity_share; }
  // Friction, temperatures, wear and losses; fills r.lubrication and r.lubrication_summary.
  void finish(MeshContactResult& r);

  // One position's lubricated state (SI); the constructor fills the film and the shares, finish()
  // the rest. Each field is one /lubrication series.
  struct Position {
    double film_isothermal = 0.0, heating_factor = 1.0, film = 0.0, regime = 0.0;
    double asperity_share = 0.0;
    double separation = 0.0;    // mean planes' separation [m]
    double film_gap = 0.0;      // the film's gap: the separation, or above the dry contact's [m]
    double gap_from_dry = 0.0;  // 1 where the dry contact's separation is negative
    double iso_flash = 0.0;     // flash temperature with the ISO mean coefficient [K]
    double friction = 0.0, film_traction = 0.0, flash = 0.0, contact_temperature = 0.0, iso_contact_temperature = 0.0,
           power_loss = 0.0, wear_pinion = 0.0, wear_wheel = 0.0, iso_film = 0.0, iso_lambda = 0.0, lambda = 0.0,
           low_peclet = 0.0;
  };

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
  std::vector<Position> positions_;
};

// (Ra1 + Ra2)/2 of a case's flanks [m]: the given Ra, or Rq/1.2533 (Gaussian), or for summit and
// spectral forms the equivalent surface's sigma shared equally.
double mean_arithmetic_roughness(const Case& c, const surface::EquivalentSurface& s);

}  // namespace geartrib::contact
