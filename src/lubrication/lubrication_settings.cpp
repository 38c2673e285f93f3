#include "lubrication/lubrication_settings.hpp"

#include "core/keyed_error.hpp"

namespace geartrib::lubrication {

void LubricationSettings::validate() const {
  using core::KeyedError;
  if (!(wear_coefficient >= 0.0)) throw KeyedError("wear_coefficient", "must not be negative");
  if (!(scuffing_temperature >= 0.0)) throw KeyedError("scuffing_temperature", "must not be negative (0: no safety)");
  if (lubricated && traction == FilmTraction::curve && lubricant.traction.empty())
    throw KeyedError("traction", "\"curve\" needs the lubricant's measured traction curves");
  if (asperity_pressure == AsperityPressureModel::persson && film_gap != FilmGap::mean_gap)
    throw KeyedError("film_gap",
                     "asperity_pressure = \"persson\" takes the film's thickness as Persson's mean gap between the "
                     "deformed flanks (his interfacial separation): only \"mean-gap\" is that datum; the mean plane "
                     "and the dry-contact offset have no place in his law");
}

}  // namespace geartrib::lubrication
