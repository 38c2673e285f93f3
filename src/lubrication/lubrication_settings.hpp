// The lubricated mesh cycle's settings: the oil (a lubricant file, or eta and alpha at the oil
// temperature given in the case) and the models along the path, each a choice of its own header.
#pragma once

#include "lubrication/ehl_film.hpp"
#include "lubrication/film_closure.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/lubricant.hpp"
#include "lubrication/mixed_lubrication.hpp"

#include <string>

namespace geartrib::lubrication {

struct LubricationSettings {
  bool lubricated = false;     // the case has a [lubricant] table; false: a dry run
  std::string lubricant_file;  // as written in the case (relative to it); empty: the fixed form
  Lubricant lubricant;
  FilmFormula film_formula = FilmFormula::dowson_higginson;
  InletHeating inlet_heating = InletHeating::gupta;
  FilmGap film_gap = FilmGap::mean_gap;
  AsperityPressureModel asperity_pressure = AsperityPressureModel::automatic;
  PerssonSpectrum persson_spectrum = PerssonSpectrum::flanks;  // Persson's spectrum (asperity_pressure = persson)
  FilmTraction traction = FilmTraction::thermal_eyring;
  MeanFrictionLaw mean_friction = MeanFrictionLaw::iso_flash;  // the bulk-temperature estimate's law
  double wear_coefficient = 1e-17;    // Archard's dimensional k [m^2/N = m^3/(N m)] (assumed order, mild wear)
  double scuffing_temperature = 0.0;  // theta_S [K]; 0: no scuffing safety
  // Throws core::KeyedError naming the field (traction: curve needs the lubricant's curves).
  void validate() const;
};

}  // namespace geartrib::lubrication
