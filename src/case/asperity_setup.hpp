// The case's single-asperity problem (a translator, case/ above the physics): its contact pair,
// its models with the case's constant overrides, and its cylinder asperity.
#pragma once

#include "asperity/contact_pair.hpp"
#include "asperity/cylinder.hpp"
#include "asperity/model.hpp"
#include "case/case.hpp"

#include <memory>
#include <string_view>

namespace geartrib::asperity {

// Pinion and wheel bodies with their flanks' summit radii (seed: R = 0.8493 um).
ContactPair contact_pair(const Case& c);
// The named model with the case's [asperity.constants.<name>] applied.
std::unique_ptr<AsperityModel> make_case_model(const Case& c, std::string_view name);
// The material of the softer flank (the pinion's at equal hardness): what yields first.
const Material& softer_material(const Case& c);
// The parabolic-cylinder asperity of seed section 5 on the softer body.
CylinderAsperity cylinder_asperity(const Case& c);

}  // namespace geartrib::asperity
