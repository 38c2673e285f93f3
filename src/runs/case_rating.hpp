// A case's ISO ratings (rating/load_capacity.hpp, rating/scuffing.hpp) on its mesh and, for
// scuffing and micropitting, on its lubricated cycle's path: what `geartrib run` records in
// /rating and `geartrib rate` prints.
#pragma once

#include "case/case.hpp"
#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"

namespace geartrib::runs {

// The methods `geartrib rate` runs on a case that names none: all four (a dry case rates bending and
// says why not the others). Scuffing without a scuffing temperature reports the temperatures alone.
RatingRequest default_rating_request(const Case& c);

// The ratings c.rating asks for, on the cycle's result (its lubricated path: scuffing by the flash
// temperature, micropitting). On a dry case the methods that need the oil are left out, each with a
// finding. Throws core::KeyedError naming the case key a method needs ("pinion.material",
// "pinion.flank_rz") when its data are missing.
rating::RatingResult rate_case(const Case& c, const gear::GearMesh& mesh, const contact::MeshContactResult& cycle);

}  // namespace geartrib::runs
