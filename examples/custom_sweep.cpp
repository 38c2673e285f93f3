// Example 3: a sweep of your own, in code.
//
// `geartrib sweep` varies the keys of a case file from the command line. In a program you can
// do the same by changing the Case struct itself, then running the mesh-cycle contact for each
// variant. Here we ask a design question about the seed's gear pair dry (gears/m6z30-dry.toml, the seed's scene): how
// does the real contact area respond to the transmitted torque, and to a finer flank finish?
//
// For every (torque, Ra) we
//   1. copy the loaded case and change its operating point and both flanks' roughness,
//   2. assemble the gear mesh for that operating point,
//   3. run the rough contact at every position from A to E (runs::run_mesh_contact, the same
//      call `geartrib run` makes),
//   4. pick a few numbers out of the result's named series and print one table row.
//
// Usage: custom_sweep [gears/m6z30-dry.toml]
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "contact/mesh_contact.hpp"
#include "runs/mesh_cycle.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

using namespace geartrib;

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : GEARTRIB_DATA_DIR "/gears/m6z30-dry.toml";
  const Case base = io::prepare_case(io::load_case(file));

  std::printf("%10s %8s %8s %11s %11s %10s %14s\n", "torque Nm", "Ra um", "psi", "max p0 MPa", "mean Ar/An",
              "max Ar/An", "real p GPa");
  for (double torque : {250.0, 1000.0, 2000.0}) {
    for (double ra : {0.8e-6, 0.4e-6}) {
      // Step 1: a variant of the case. All fields are SI. A flank's roughness has one form;
      // the file gives Ra, so we change Ra (set form = rq and rq = ... to give Rq instead).
      Case c = base;
      c.operating.pinion_torque = torque;
      c.pinion.flank.roughness.ra = ra;
      c.wheel.flank.roughness.ra = ra;
      io::prepare_case(c);  // its derived data (summit radii, the pair's findings) for the variant

      // Step 2: the mesh depends on the torque (load sharing, Hertz pressures), so it is built
      // for each variant.
      const gear::GearMesh mesh = gear::case_mesh(c);

      // Step 3: the contact along A -> E. No solver is needed for the uncoupled fidelity the case
      // asks for, and no integrator since the case's dynamics are "none". 41 positions are
      // plenty for a table (the case file asks for 201).
      const contact::MeshContactResult r = runs::run_mesh_contact(c, mesh, nullptr, {}, 41);

      // Step 4: results are series over the positions, found by name (the names of the HDF5
      // file's /mesh and /contact groups: README.md, "The main job"), plus a few scalars.
      const auto& p0 = r.find("hertz_p0_Pa")->values;
      const auto& area = r.find("real_area_ratio")->values;
      const auto& pressure = r.find("mean_real_pressure_Pa")->values;
      std::printf("%10.0f %8.2f %8.1f %11.0f %11.4f %10.4f %14.3f\n", torque, ra * 1e6, r.plasticity_index,
                  *std::max_element(p0.begin(), p0.end()) * 1e-6, contact::path_mean(area),
                  *std::max_element(area.begin(), area.end()),
                  *std::max_element(pressure.begin(), pressure.end()) * 1e-9);
    }
  }
  // Reading the table: the plasticity index psi is far above 1 for both finishes, so every summit
  // that touches is flattened plastically and carries the hardness H = 1.17 GPa. The real area is
  // then the load over H, whatever the finish. Its ratio to the Hertz strip 2b, which widens as the
  // square root of the load, grows as the square root of the torque (x1.41 from 1000 to 2000 N m).
  return 0;
}
