// The case's rough contact (a translator, case/ above the physics): the equivalent surface of its
// two flanks. The contact's options are the physics' own structs, held whole in the Case
// (ContactSettings: strip, greenwood_williamson, boundary_elements).
#pragma once

#include "case/case.hpp"
#include "surface/rough_surface.hpp"

namespace geartrib::contact {

// Both flanks' roughness with the case's height distribution and eta sigma beta.
surface::EquivalentSurface case_equivalent_surface(const Case& c);

}  // namespace geartrib::contact
