// Example 2: one position of the mesh.
//
// A pair of spur gears touches along a straight line of action, from A (the wheel's tip) to E
// (the pinion's tip). At each point the two involute flanks act like two cylinders pressed
// together: a Hertzian strip of half-width b carries the tooth load. But the flanks are rough,
// so the load is really carried by the summits of the roughness inside that strip: the real
// contact area is a small fraction of the nominal one, and some summits yield.
//
// Here we take the seed's gear pair (gears/m6z30.toml: m = 6 mm, z = 30/30, 1000 N m) and look at
// one position, the pitch point C, where the flanks roll without sliding. We
//   1. load the case file (geometry, materials, roughness, operating point, model choices),
//   2. assemble the gear mesh and read off the load, curvature and Hertz pressure at C,
//   3. build the equivalent rough surface and the Greenwood-Williamson summation over its summits,
//   4. solve the rough line contact across the strip at C.
// `geartrib run` does the same at every position from A to E (runs::run_mesh_contact).
//
// Usage: mesh_position [gears/m6z30.toml]
#include "case/asperity_setup.hpp"
#include "case/contact_setup.hpp"
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/rough_line_contact.hpp"
#include "runs/mesh_cycle.hpp"

#include <cstdio>
#include <string>

using namespace geartrib;

int main(int argc, char** argv) {
  // Step 1: the case. Paths inside it (the materials) are relative to the case file.
  const std::string file = argc > 1 ? argv[1] : GEARTRIB_DATA_DIR "/gears/m6z30.toml";
  const Case c = io::prepare_case(io::load_case(file));

  // Step 2: the gear mesh: geometry, tooth stiffness and load sharing at the operating point.
  // Positions are distances s from T1 along the line of action; path().c is the pitch point.
  const gear::GearMesh mesh = gear::case_mesh(c);
  const double s = mesh.pair().path().c;
  const gear::MeshInstant instant = mesh.analysis().at(s);
  const gear::PairLoad load = instant.pairs.front();  // between B and D one pair carries it all
  const double radius = mesh.pair().flank(s).radius_equivalent;
  std::printf("pitch point C: s = %.3f mm, pairs in contact %zu\n", s * 1e3, instant.pairs.size());
  std::printf("line load %.1f N/mm, R = %.2f mm, Hertz p0 = %.0f MPa, b = %.1f um\n", load.line_load * 1e-3,
              radius * 1e3, load.hertz_peak * 1e-6, load.hertz_half_width * 1e6);

  // Step 3: the two flanks' roughness combined into one equivalent surface against a flat, the
  // summit contact pair, and the case's asperity model. GreenwoodWilliamson tabulates nominal
  // pressure against separation up to the pressure we will need.
  const surface::EquivalentSurface surf = contact::case_equivalent_surface(c);
  const asperity::ContactPair pair = asperity::contact_pair(c);
  const auto model = asperity::make_case_model(c, c.asperity.model);
  const contact::GreenwoodWilliamson gw(surf, *model, pair, 1.5 * load.hertz_peak, c.contact.greenwood_williamson);
  std::printf("surface: sigma_s = %.3f um, plasticity index %.2f, model %s\n", surf.summit_sigma * 1e6,
              surface::plasticity_index(surf, pair.modulus, pair.hardness), c.asperity.model.c_str());

  // Step 4: the strip. Uncoupled fidelity imposes the smooth Hertz pressure on the rough surface
  // and integrates the summits' contacts across the strip (the coupled one needs a Newton solver,
  // e.g. solvers::KinsolSolver from geartrib::solvers).
  const contact::RoughLineContact strip(gw, mesh.composite_modulus(), c.gear_pair.face_width, c.contact.strip, nullptr);
  const contact::StripResult r = strip.solve(load.line_load, radius);
  std::printf("real area ratio %.4f, plastic area fraction %.4f, mean real pressure %.2f GPa\n", r.real_area_ratio,
              r.plastic_area_fraction, r.mean_real_pressure * 1e-9);
  std::printf("contacts %.3g per mm, separation at the centre %.3f sigma_s\n", r.contacts_per_width * 1e-3,
              r.min_separation / surf.summit_sigma);
  return 0;
}
