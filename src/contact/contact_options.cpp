#include "contact/contact_options.hpp"

#include "core/keyed_error.hpp"

namespace geartrib {

namespace {
constexpr NamedChoice<ToothOrder> kToothOrders[] = {{ToothOrder::pair, "pair"}, {ToothOrder::hunting, "hunting"}};
}  // namespace

std::span<const NamedChoice<ToothOrder>> tooth_order_choices() { return kToothOrders; }
const char* tooth_order_name(ToothOrder o) { return choice_name(tooth_order_choices(), o); }

void ContactSettings::validate() const {
  core::validate_member("greenwood_williamson", greenwood_williamson);
  core::validate_member("strip", strip);
  core::validate_member("boundary_elements", boundary_elements);
  core::validate_member("mixed_ehl", mixed_ehl);
  core::validate_member("areal", areal);
}

}  // namespace geartrib
