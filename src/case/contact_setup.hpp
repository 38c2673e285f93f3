// The case's rough contact (a translator, case/ above the physics): the equivalent surface of its
// two flanks, the Greenwood-Williamson table's options, the strip's and the boundary elements'.
#pragma once

#include "case/case.hpp"
#include "contact/deterministic/mesh_deterministic.hpp"
#include "contact/statistical/strip_fidelities.hpp"
#include "contact/surface_model.hpp"
#include "surface/rough_surface.hpp"

namespace geartrib::contact {

// Both flanks' roughness with the case's height distribution and eta sigma beta.
surface::EquivalentSurface case_equivalent_surface(const Case& c);
// contact.height_points, contact.table_points; the plastic area when an output asks for it.
GreenwoodWilliamsonOptions greenwood_williamson_options(const Case& c);
// contact.fidelity (coupled or not), strip_points, strip_lookup, coupled_nodes.
StripOptions strip_options(const Case& c);
// The deterministic fidelity's strip: contact.element_size and strip_halfwidths, the softer flank's
// hardness capping the pressure and taking the plastic deformation (equal hardness: half each),
// the subsurface stress when asked for, running_in.tolerance as the plastic overlap.
DeterministicOptions deterministic_options(const Case& c);

}  // namespace geartrib::contact
