// Example 1: one asperity.
//
// The smallest problem geartrib solves: one summit of the pinion's flank pressed into one summit
// of the wheel's flank. Both are 45 steel. Contact mechanics replaces the two curved summits by a
// sphere of radius R = R1 R2/(R1 + R2) against a rigid flat, with the composite modulus E_t of
// the two bodies and the strength (yield S_y, hardness H) of the softer one: a ContactPair.
//
// Each asperity model says how that sphere carries load as it is pressed deeper. The depth is
// counted in units of the critical interference delta_c, where the material first yields
// (delta* = delta/delta_c): below 1 the contact is elastic (Hertz), far above it the summit is
// flattened plastically. We compare two laws at a few delta*: geartrib's continuous model and
// Kogut-Etsion's finite-element fit, and print the load, the contact area and the share of the
// area that has yielded.
//
// Usage: single_asperity [materials/steel-45.toml]
#include "asperity/contact_pair.hpp"
#include "asperity/model.hpp"
#include "config/case_file.hpp"

#include <cstdio>
#include <string>

using namespace geartrib;

int main(int argc, char** argv) {
  // Step 1: read the material. load_material converts every "<number> <unit>" to SI and checks
  // it (E > 0, 0 < nu < 0.5, H >= S_y, ...); with no hardness given, H = 2.8 S_y (Tabor).
  const std::string file = argc > 1 ? argv[1] : GEARTRIB_DATA_DIR "/materials/steel-45.toml";
  const Material steel = io::load_material(file);

  // Step 2: the equivalent sphere-on-flat problem of two summits with tip radii 1.65 and 1.75 um
  // (the seed's pinion and wheel flanks): R = 0.8493 um, E_t = E/(2(1 - nu^2)) = 113.19 GPa.
  const asperity::ContactPair pair = asperity::make_contact_pair(steel, steel, 1.65e-6, 1.75e-6);
  std::printf("R = %.4f um, E_t = %.2f GPa, H = %.4f GPa\n", pair.radius * 1e6, pair.modulus * 1e-9,
              pair.hardness * 1e-9);

  // Step 3: for each model (by its registry name), its critical values, then the contact at a
  // few interferences. evaluate() takes the interference in metres; Detail::load_area skips the
  // stress field, which we do not print.
  for (const char* name : {"continuous", "kogut-etsion"}) {
    const auto model = asperity::make_asperity_model(name);
    const asperity::Critical crit = model->critical(pair);
    std::printf("\n%s (%s)\n", name, std::string(model->citation()).c_str());
    std::printf("  delta_c = %.4f nm, F_c = %.4g uN\n", crit.interference * 1e9, crit.load * 1e6);
    std::printf("  %8s %12s %12s %14s %10s\n", "delta*", "load uN", "F/F_c", "area um^2", "plastic");
    for (double delta_star : {0.5, 1.0, 6.0, 20.0, 110.0}) {
      const asperity::AsperityState s =
          model->evaluate(pair, delta_star * crit.interference, asperity::Detail::load_area);
      std::printf("  %8.1f %12.5g %12.4f %14.5g %10.3f\n", delta_star, s.load * 1e6, s.load_star, s.area * 1e12,
                  s.plastic_fraction);
    }
  }
  // Below delta* = 1 both laws are Hertz (F/F_c = delta*^1.5, no plastic share). Above it the
  // plastic share grows towards 1 and the load towards H times the area: the summit is flattened.
  return 0;
}
