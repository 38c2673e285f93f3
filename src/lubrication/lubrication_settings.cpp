#include "lubrication/lubrication_settings.hpp"

#include "core/keyed_error.hpp"

namespace geartrib::lubrication {

void LubricationSettings::validate() const {
  using core::KeyedError;
  if (!(wear_coefficient >= 0.0)) throw KeyedError("wear_coefficient", "must not be negative");
  if (!(scuffing_temperature >= 0.0)) throw KeyedError("scuffing_temperature", "must not be negative (0: no safety)");
  if (lubricated && traction == FilmTraction::curve && lubricant.traction.empty())
    throw KeyedError("traction", "\"curve\" needs the lubricant's measured traction curves");
}

}  // namespace geartrib::lubrication
