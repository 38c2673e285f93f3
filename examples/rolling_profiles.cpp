// Example 4: the flanks themselves in contact, rolling past each other.
//
// The statistical model of example 2 asks how an average patch of flank carries the load. Here we
// press the two flanks' own profiles together at a few positions of the seed's pair and watch the
// composite roughness change as the flanks slide past each other. We
//   1. load the case, assemble the mesh and read the load, curvature and contact point on each
//      flank (its involute arc length sigma = rho^2 / (2 r_b)) at four positions,
//   2. generate a ground profile for each flank long enough for the whole path,
//   3. solve the strip at each position with the boundary elements (elastic-perfectly-plastic at
//      the hardness), and print what the contact looks like.
// `geartrib run gears/m6z30-deterministic.toml` does the same at every position, beside the
// statistical model, and can run the flanks in (docs/theory/deterministic-contact.md).
//
// Usage: rolling_profiles [gears/m6z30-dry.toml]
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "contact/deterministic_contact.hpp"
#include "surface/flank_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace geartrib;

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : std::string(GEARTRIB_DATA_DIR) + "/gears/m6z30-dry.toml";
  const Case c = io::prepare_case(io::load_case(file));
  const gear::GearMesh mesh = gear::case_mesh(c);
  const gear::PathOfContact& path = mesh.pair().path();
  const double rb1 = mesh.pair().pinion().base_radius, rb2 = mesh.pair().wheel().base_radius;

  // 1. Four positions: A, the pitch point, D and E; where each flank's contact point is.
  const double at[] = {path.a, path.c, path.d, path.e};
  std::vector<contact::StripPosition> positions;
  std::vector<double> hertz_p0;
  for (double s : at) {
    const gear::FlankGeometry f = mesh.pair().flank(s);
    // The pair at s (at B and D two pairs are in contact: take this one's load).
    const gear::MeshInstant m = mesh.analysis().at(s);
    const gear::PairLoad& load = m.pair_at(s);
    hertz_p0.push_back(load.hertz_peak);
    positions.push_back({load.line_load, f.radius_equivalent, load.hertz_half_width,
                         f.radius_pinion * f.radius_pinion / (2.0 * rb1),
                         f.radius_wheel * f.radius_wheel / (2.0 * rb2)});
  }

  // 2. Ground flanks (Rq 0.3 um, correlation length 10 um), each covering its contact points and
  // half a millimetre either side (the strip below reaches 0.25 mm).
  contact::FlankTrack flank[2];
  for (int g = 0; g < 2; ++g) {
    surface::GeneratedProfileSpec spec;
    spec.rq = 0.3e-6;
    spec.seed = 1 + g;
    double lo = 1e9, hi = 0.0;
    for (const auto& p : positions) {
      const double sigma = g == 0 ? p.sigma_pinion : p.sigma_wheel;
      lo = std::min(lo, sigma), hi = std::max(hi, sigma);
    }
    flank[g] = {surface::generate_profile(spec, hi - lo + 1e-3), lo - 0.5e-3};
  }

  // 3. The strip: 0.5 um elements over +-0.25 mm, the pressure capped at the hardness.
  contact::DeterministicOptions o;
  o.pressure_cap = std::min(c.pinion.material.hardness, c.wheel.material.hardness);
  o.poisson_ratio = c.pinion.material.poisson_ratio;
  const contact::StripSolver strip(mesh.composite_modulus(), 0.25e-3, o);
  std::printf("%-6s %10s %10s %8s %10s %10s %12s\n", "point", "w N/mm", "p0 MPa", "spots", "A_r/2b", "plastic",
              "p_max MPa");
  const char* name[] = {"A", "C", "D", "E"};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const contact::DeterministicStrip r = strip.solve(flank[0], flank[1], positions[i], false);
    std::printf("%-6s %10.1f %10.0f %8d %10.3f %10.3f %12.0f\n", name[i], positions[i].line_load * 1e-3,
                hertz_p0[i] * 1e-6, r.contact_spots, r.real_area_ratio, r.plastic_area_fraction,
                r.peak_pressure * 1e-6);
  }
  std::printf(
      "The peaks sit at the hardness (%.0f MPa): the flanks' summits yield, two to three times the\n"
      "smooth Hertz pressure; about a third of the Hertz strip touches.\n",
      o.pressure_cap * 1e-6);
  return 0;
}
