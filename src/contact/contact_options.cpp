#include "contact/contact_options.hpp"

#include "core/keyed_error.hpp"

namespace geartrib {

void ContactSettings::validate() const {
  core::validate_member("greenwood_williamson", greenwood_williamson);
  core::validate_member("strip", strip);
  core::validate_member("boundary_elements", boundary_elements);
}

}  // namespace geartrib
