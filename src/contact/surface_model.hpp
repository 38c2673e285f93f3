// The statistical model of a pair of rough flanks: the equivalent surface (seed section 4) and
// its Greenwood-Williamson pressure-separation table, built once for the path. The statistical
// fidelities solve their strips on it, the lubricated cycle shares the load with its asperities,
// and the deterministic fidelity builds one from its flanks' profiles to run beside it.
#pragma once

#include "asperity/model.hpp"
#include "contact/contact_options.hpp"
#include "contact/greenwood_williamson.hpp"
#include "material/material.hpp"
#include "surface/rough_surface.hpp"

#include <array>

namespace geartrib::contact {

// The flanks as the statistical model takes them (index 0 the pinion, 1 the wheel).
struct StatisticalFlanks {
  std::array<const Material*, 2> materials = {nullptr, nullptr};
  std::array<surface::FlankRoughness, 2> roughness;
  surface::HeightDistribution distribution = surface::HeightDistribution::gaussian;
  double eta_sigma_beta = surface::kTypicalEtaSigmaBeta;  // for flanks given by Ra or Rq
  const asperity::AsperityModel* model = nullptr;         // the asperity law, with the case's constants
  double friction = 0.0;  // mu of the asperities' side contact; the boundary coefficient when lubricated
};

// The equivalent rough surface of two flanks.
surface::EquivalentSurface equivalent_surface(const StatisticalFlanks& f);

// The flanks' statistical model, its table covering nominal pressures up to 1.5 max_pressure.
struct SurfaceModel {
  SurfaceModel(const StatisticalFlanks& flanks, const ContactSettings& cs, double max_pressure);
  StatisticalFlanks flanks;
  surface::EquivalentSurface surface;
  double plasticity_index = 0.0;
  GreenwoodWilliamson table;
};

}  // namespace geartrib::contact
