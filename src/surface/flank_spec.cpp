#include "surface/flank_spec.hpp"

#include "core/keyed_error.hpp"

namespace geartrib::surface {

void TopographySpec::validate() const {
  using core::KeyedError;
  if (!(unit > 0.0)) throw KeyedError("unit", "the length unit must be positive");
  if (!(spacing >= 0.0)) throw KeyedError("spacing", "must not be negative (0: from the file)");
  if (!(resample >= 0.0)) throw KeyedError("resample", "must not be negative (0: as measured)");
  if (!(profile_at >= 0.0 && profile_at <= 1.0)) throw KeyedError("profile_at", "must lie in [0, 1]");
  if (!(synthesis_length >= 0.0)) throw KeyedError("synthesis_length", "must not be negative");
  core::validate_member("clean", clean);
}

void RoughnessSettings::validate() const {
  if (!(eta_sigma_beta > 0.0)) throw core::KeyedError("eta_sigma_beta", "must be positive");
}

}  // namespace geartrib::surface
