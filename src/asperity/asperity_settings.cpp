#include "asperity/asperity_settings.hpp"

#include "asperity/model.hpp"
#include "core/keyed_error.hpp"

#include <algorithm>

namespace geartrib::asperity {

void AsperitySettings::validate() const {
  using core::KeyedError;
  const auto names = asperity_model_names();
  if (std::find(names.begin(), names.end(), model) == names.end())
    throw KeyedError("model", "unknown asperity model '" + model + "'");
  if (!(measured_axis_offset >= 0.0)) throw KeyedError("measured_axis_offset", "must not be negative (0: none)");
  if (!(measured_tip_gap >= 0.0)) throw KeyedError("measured_tip_gap", "must not be negative (0: none)");
  if (!(cylinder_tip_radius >= 0.0)) throw KeyedError("cylinder_tip_radius", "must not be negative (0: not given)");
  if (!(cylinder_yield_constant > 0.0)) throw KeyedError("cylinder_yield_constant", "must be positive");
}

}  // namespace geartrib::asperity
