// The mesh-cycle contact run's keys, declared beside ContactSettings and RunningInSettings: the
// resolutions' accessors name the physics' option fields (contact::StripOptions,
// GreenwoodWilliamsonOptions, DeterministicOptions, mixed_ehl::MixedEhlOptions) held whole in
// ContactSettings.
#include "config/parameters/declare.hpp"

#include "asperity/model.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mixed_ehl/mixed_ehl_options.hpp"
#include "contact/rough_line_contact.hpp"

namespace geartrib::io::parameters {

// [contact]: fidelity, outputs, resolutions; [running_in].
void declare_contact(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  using K = ParameterKind;
  using contact::GreenwoodWilliamsonOptions;
  using contact::StripOptions;
  // [contact]: the mesh cycle's fidelity, outputs and resolutions.
  add(mapped_choice(
          "contact.fidelity", contact::fidelity_names(), [](auto& c, int) -> auto& { return c.contact.fidelity; },
          [](const std::string& t) { return contact::find_fidelity(t).id(); },
          [](ContactFidelity f) { return std::string(f.name()); }))
      .alias({"fidelity"})
      .doc(contact::fidelity_descriptions());
  {
    Parameter outputs;
    outputs.key = "contact.outputs";
    outputs.kind = K::choice_list;
    outputs.choices = {"real_area", "plastic_fraction", "asperity_stress", "mesh_stiffness"};
    outputs.get = [](const Case& c, int) {
      ParameterValue v;
      if (c.contact.real_area) v.list.emplace_back("real_area");
      if (c.contact.plastic_fraction) v.list.emplace_back("plastic_fraction");
      if (c.contact.asperity_stress) v.list.emplace_back("asperity_stress");
      if (c.contact.mesh_stiffness) v.list.emplace_back("mesh_stiffness");
      return v;
    };
    outputs.set = [](Case& c, int, const ParameterValue& v) {
      auto has = [&](const char* n) { return std::find(v.list.begin(), v.list.end(), n) != v.list.end(); };
      c.contact.real_area = has("real_area");
      c.contact.plastic_fraction = has("plastic_fraction");
      c.contact.asperity_stress = has("asperity_stress");
      c.contact.mesh_stiffness = has("mesh_stiffness");
    };
    add(std::move(outputs))
        .doc(
            "The outputs computed (a run computes only these; mesh_stiffness: the tooth-pair stiffness along the "
            "path, computed anyway with stiffness load sharing)");
  }
  add(integer(
          "contact.positions", [](auto& c, int) -> auto& { return c.contact.positions; }))
      .range(2, 100000)
      .alias({"positions"})
      .ladder({"11", "21", "41", "81", "101", "201", "401", "801"})
      .doc("Positions along the path of contact A -> E");
  add(integer(
          "contact.strip_points", [](auto& c, int) -> auto& { return c.contact.strip.strip_points; }))
      .range(StripOptions::kMinStripPoints, StripOptions::kMaxStripPoints)
      .field("contact.strip.strip_points")
      .alias({"strip_points"})
      .ladder({"8", "16", "32", "64", "128", "256", "512"})
      .doc("Uncoupled: quadrature points across the Hertz strip");
  add(integer(
          "contact.height_points", [](auto& c, int) -> auto& { return c.contact.greenwood_williamson.height_points; }))
      .range(GreenwoodWilliamsonOptions::kMinHeightPoints, GreenwoodWilliamsonOptions::kMaxHeightPoints)
      .field("contact.greenwood_williamson.height_points")
      .alias({"height_points"})
      .ladder({"8", "16", "32", "64", "128", "256", "512", "1024"})
      .doc("Quadrature points over the summit heights in contact");
  add(integer(
          "contact.table_points",
          [](auto& c, int) -> auto& { return c.contact.greenwood_williamson.table_points_per_sigma; }))
      .range(GreenwoodWilliamsonOptions::kMinTablePoints, GreenwoodWilliamsonOptions::kMaxTablePoints)
      .field("contact.greenwood_williamson.table_points_per_sigma")
      .alias({"table_points"})
      .ladder({"4", "8", "16", "32", "64", "128", "256"})
      .doc("Pressure-separation table points per summit sigma");
  add(integer(
          "contact.coupled_nodes", [](auto& c, int) -> auto& { return c.contact.strip.coupled_nodes; }))
      .range(StripOptions::kMinCoupledNodes, StripOptions::kMaxCoupledNodes)
      .field("contact.strip.coupled_nodes")
      .alias({"coupled_nodes"})
      .ladder({"32", "64", "128", "256"})
      .doc("Coupled: pressure elements across the contact");
  add(mapped_choice(
          "contact.strip_lookup", {"cubic", "exact"}, [](auto& c, int) -> auto& { return c.contact.strip.lookup; },
          [](const std::string& t) { return t == "exact" ? contact::StripLookup::exact : contact::StripLookup::cubic; },
          [](contact::StripLookup l) { return std::string(l == contact::StripLookup::exact ? "exact" : "cubic"); }))
      .alias({"strip_lookup"})
      .ladder({"cubic", "exact"})
      .field("contact.strip.lookup")
      .doc(
          "Uncoupled: the rough surface at each strip point from cubic cells in the pressure (no transcendental "
          "call per point) or exact: the pressure table's inversion and log-linear interpolation, the reference");
  add(integer(
          "contact.stress_table", [](auto& c, int) -> auto& { return c.contact.stress_table; }))
      .range(0, asperity::VonMisesTable::kMaxIntervals)
      .alias({"stress_table"})
      .ladder({"4", "8", "16", "32", "64", "0"})
      .doc(
          "Asperity stresses: intervals of the normalised von Mises table over the square root of the plastic share "
          "(0: the exact maximisation at every position, the reference)");

  // Deterministic fidelity: the boundary elements across the strip.
  add(quantity(
          "contact.element_size", D::length,
          [](auto& c, int) -> auto& { return c.contact.boundary_elements.element_size; }))
      .range(1e-9, 1e-3)
      .field("contact.boundary_elements.element_size")
      .plausible(0.01 * kUm, 10.0 * kUm)
      .alias({"element_size"})
      .ladder({"4 um", "2 um", "1 um", "0.5 um", "0.25 um", "0.125 um"})
      .doc(
          "Deterministic: boundary-element width across the strip; not below a flank profile's spacing (the profile "
          "is averaged over each element)");
  add(number(
          "contact.strip_halfwidths",
          [](auto& c, int) -> auto& { return c.contact.boundary_elements.strip_halfwidths; }))
      .range(contact::DeterministicOptions::kMinStripHalfwidths, contact::DeterministicOptions::kMaxStripHalfwidths)
      .field("contact.boundary_elements.strip_halfwidths")
      .alias({"strip_halfwidths"})
      .ladder({"1.1", "1.25", "1.5", "2", "3"})
      .doc(
          "Deterministic: the strip's half-length in the path's largest Hertz half-width (a rough contact spreads "
          "beyond the smooth one's)");
  add(mapped_choice(
          "contact.pressure_profiles", {"points", "all", "none"},
          [](auto& c, int) -> auto& { return c.contact.pressure_profiles; },
          [](const std::string& t) {
            return t == "all" ? PressureProfiles::all : t == "none" ? PressureProfiles::none : PressureProfiles::points;
          },
          [](PressureProfiles p) {
            return std::string(p == PressureProfiles::all ? "all" : p == PressureProfiles::none ? "none" : "points");
          }))
      .doc(
          "Deterministic and mixed EHL: the pressure profiles kept in the HDF5 file (mixed EHL: with the film) at "
          "the positions nearest A, B, C, D, E (points), at every position (all) or none");
  add(integer(
          "contact.threads", [](auto& c, int) -> auto& { return c.contact.threads; }))
      .range(0, 1024)
      .alias({"threads"})
      .doc("Deterministic and mixed EHL: threads solving the positions of a mesh (0: all cores)");
  // [mixed_ehl]: the mixed-EHL fidelity's grid, window and line solver (contact::mixed_ehl::MixedEhlOptions).
  using contact::mixed_ehl::MixedEhlOptions;
  add(quantity(
          "mixed_ehl.grid_spacing", D::length, [](auto& c, int) -> auto& { return c.contact.mixed_ehl.grid_spacing; }))
      .range(0.0, 1e-3)
      .field("contact.mixed_ehl.grid_spacing")
      .ladder({"2 um", "1 um", "0.5 um", "0.25 um"})
      .doc(
          "Mixed EHL: the nodes' spacing at every position (its domain from -inlet to outlet Hertz half-widths); "
          "not coarser than a flank profile's spacing (the nodes would skip its points). 0: the largest contact's "
          "domain in 1024 nodes, or the profiles' spacing where that is finer");
  add(number(
          "mixed_ehl.inlet", [](auto& c, int) -> auto& { return c.contact.mixed_ehl.solver.inlet; }))
      .range(1.5, 100.0)
      .field("contact.mixed_ehl.solver.inlet")
      .doc("Mixed EHL: the domain's start, this many Hertz half-widths before the contact point (the inlet)");
  add(number(
          "mixed_ehl.outlet", [](auto& c, int) -> auto& { return c.contact.mixed_ehl.solver.outlet; }))
      .range(1.05, 100.0)
      .field("contact.mixed_ehl.solver.outlet")
      .doc("Mixed EHL: the domain's end, this many Hertz half-widths after the contact point (the outlet)");
  add(number(
          "mixed_ehl.window", [](auto& c, int) -> auto& { return c.contact.mixed_ehl.window; }))
      .range(MixedEhlOptions::kMinWindow, MixedEhlOptions::kMaxWindow)
      .field("contact.mixed_ehl.window")
      .ladder({"1", "2", "4", "8"})
      .doc(
          "Mixed EHL: the transient window at each position, in contact widths 2b travelled by the slower surface "
          "(at least 1: its roughness crosses the whole contact); the time means and extremes are over it");
  add(number(
          "mixed_ehl.lead_in", [](auto& c, int) -> auto& { return c.contact.mixed_ehl.lead_in; }))
      .range(0.0, MixedEhlOptions::kMaxLeadIn)
      .field("contact.mixed_ehl.lead_in")
      .ladder({"0", "1", "2", "4", "8"})
      .doc(
          "Mixed EHL: the window's lead-in, in Hertz half-widths b travelled at the entrainment speed: time steps from "
          "the smooth contact with the roughness growing over its first half, so that the window starts from the "
          "state the moving surfaces leave (0: from the steady rough contact at the window's start)");
  add(number(
          "mixed_ehl.time_step", [](auto& c, int) -> auto& { return c.contact.mixed_ehl.time_step; }))
      .range(0.0, 100.0, true, false)
      .field("contact.mixed_ehl.time_step")
      .ladder({"4", "2", "1", "0.5", "0.25"})
      .doc(
          "Mixed EHL: the time step as a Courant number, dt = time_step x node spacing / the faster surface's speed "
          "(the faster surface's roughness moves this many nodes a step)");
  add(number(
          "mixed_ehl.tolerance", [](auto& c, int) -> auto& { return c.contact.mixed_ehl.solver.tolerance; }))
      .range(0.0, 0.1, true, true)
      .field("contact.mixed_ehl.solver.tolerance")
      .ladder({"1e-4", "1e-5", "1e-6", "1e-7", "1e-8"})
      .doc(
          "Mixed EHL: converged when the largest Newton update of the pressure is below this times the Hertz "
          "pressure and the load within this of the line load");
  add(named_choice(
          "mixed_ehl.viscosity_law", contact::mixed_ehl::viscosity_law_choices(), "viscosity law",
          [](auto& c, int) -> auto& { return c.contact.mixed_ehl.viscosity_law; }))
      .doc(
          "Mixed EHL: the viscosity's rise with pressure: roelands (Roelands 1966, Z from alpha) or barus "
          "(exp(alpha p)); eta and alpha are the oil's at the flanks' bulk temperature");
  add(named_choice(
          "mixed_ehl.flow", contact::mixed_ehl::flow_model_choices(), "flow model",
          [](auto& c, int) -> auto& { return c.contact.mixed_ehl.flow; }))
      .doc(
          "Mixed EHL: newtonian, or eyring: the Ree-Eyring Poiseuille flow factor of the mid-film shear with the "
          "oil's Eyring stress (Conry, Wang & Cusano 1987)");
  add(numeric(
          "mixed_ehl.compressible", K::flag, D::dimensionless,
          [](auto& c, int) -> auto& { return c.contact.mixed_ehl.compressible; }))
      .field("contact.mixed_ehl.compressible")
      .doc("Mixed EHL: the oil's density rising with pressure (Dowson & Higginson 1966); false: constant");
  add(quantity(
          "mixed_ehl.film_floor", D::length,
          [](auto& c, int) -> auto& { return c.contact.mixed_ehl.solver.film_floor; }))
      .range(0.0, 1e-6, true, false)
      .field("contact.mixed_ehl.solver.film_floor")
      .doc(
          "Mixed EHL: the film below which a node counts as in asperity contact (its load the asperity share, its "
          "friction mixed_ehl.boundary_friction)");
  add(number(
          "mixed_ehl.boundary_friction",
          [](auto& c, int) -> auto& { return c.contact.mixed_ehl.solver.boundary_friction; }))
      .range(0.0, 1.0)
      .field("contact.mixed_ehl.solver.boundary_friction")
      .doc(
          "Mixed EHL: the friction coefficient in the asperity contacts (the statistical cycle beside it takes "
          "friction.mu)");
  add(numeric(
          "mixed_ehl.whole_path", K::flag, D::dimensionless,
          [](auto& c, int) -> auto& { return c.contact.mixed_ehl.whole_path; }))
      .field("contact.mixed_ehl.whole_path")
      .doc(
          "Mixed EHL: also one transient solve from A to E on the largest contact's grid, the load, curvature and "
          "speeds changing every step (the squeeze they cause), its cost measured");
  // [areal]: the areal fidelity's window across the face and its flanks.
  add(quantity(
          "areal.window", D::length, [](auto& c, int) -> auto& { return c.contact.areal.window; }))
      .range(1e-6, 1e-2)
      .field("contact.areal.window")
      .plausible(10.0 * kUm, 1000.0 * kUm)
      .ladder({"16 um", "32 um", "64 um", "128 um"})
      .doc(
          "Areal: the window's width across the face, periodic across it: at least four of the roughness' "
          "correlation lengths (fewer is refused at one), so that the window holds a fair sample of its spots");
  add(integer(
          "areal.points", [](auto& c, int) -> auto& { return c.contact.areal.points; }))
      .range(contact::areal::ArealMeshOptions::kMinPoints, contact::areal::ArealMeshOptions::kMaxPoints)
      .field("contact.areal.points")
      .ladder({"32", "64", "128", "256"})
      .doc(
          "Areal: the window's points across the face (its spacing window/points; along the involute the "
          "elements are contact.element_size)");
  add(named_choice(
          "areal.lay", contact::areal::areal_lay_choices(), "lay",
          [](auto& c, int) -> auto& { return c.contact.areal.lay; }))
      .doc(
          "Areal: each flank's height map across the face: isotropic (a random surface with the flank profile's "
          "Gaussian correlation in every direction: superfinished, vibratory-finished or shot-peened flanks; a "
          "generated ground profile), directional (the same with areal.lay_ratio times the correlation across "
          "the face: a ground flank's lay), extruded (the profile repeated across the face: the deterministic "
          "fidelity's flank, an endless lay across the profile) or patch (the flank's measured topography, "
          "synthesised from its areal spectrum or tiled: areal.patch)");
  add(number(
          "areal.lay_ratio", [](auto& c, int) -> auto& { return c.contact.areal.lay_ratio; }))
      .range(1.0, contact::areal::ArealMeshOptions::kMaxLayRatio)
      .field("contact.areal.lay_ratio")
      .plausible(1.0, 50.0)
      .doc(
          "Areal, directional lay: the correlation length across the face over that along the involute "
          "(Peklenik's gamma; ground flanks about 3 to over 10): 1 is isotropic, and large ratios approach the "
          "extruded lay");
  add(named_choice(
          "areal.patch", contact::areal::areal_patch_choices(), "patch method",
          [](auto& c, int) -> auto& { return c.contact.areal.patch; }))
      .doc(
          "Areal, patch lay: how the measured patch (smaller than the flank) makes each flank's map: synthesis "
          "(its areal power spectrum with random phases seeded by the topography's synthesis_seed: the lay "
          "kept, no wavelength longer than the patch) or tiled (the patch itself repeated by mirror images)");
  add(number(
          "areal.tolerance", [](auto& c, int) -> auto& { return c.contact.areal.tolerance; }))
      .range(1e-12, 1e-2)
      .field("contact.areal.tolerance")
      .ladder({"1e-3", "1e-4", "1e-5", "1e-6", "1e-8"})
      .doc(
          "Areal: the solver's stop, the contact conditions' rms residual over the heights' rms (Polonsky & "
          "Keer's conjugate gradients)");
  // [running_in]
  add(integer(
          "running_in.meshes", [](auto& c, int) -> auto& { return c.running_in.meshes; }))
      .range(0, 100000)
      .alias({"meshes"})
      .doc(
          "Deterministic: meshes of running-in, each flank's plastic deformation carried to its next mesh (0: the "
          "new flanks only); stops earlier at shakedown");
  add(quantity(
          "running_in.tolerance", D::length,
          [](auto& c, int) -> auto& { return c.contact.boundary_elements.plastic_overlap; }))
      .range(1e-15, 1e-3, true, false)
      .field("contact.boundary_elements.plastic_overlap")
      .doc(
          "Deterministic: plastic deformation below this counts as none (the plastic area's threshold); a mesh that "
          "deforms no flank point by more ends the running-in (shakedown)");
  add(named_choice(
          "running_in.teeth", tooth_order_choices(), "tooth order",
          [](auto& c, int) -> auto& { return c.running_in.teeth; }))
      .doc(
          "pair: one pinion tooth meets one wheel tooth every mesh (the 1:1 pair's order); hunting: every tooth, "
          "in the order they mesh (pinion tooth k meets wheel tooth k mod z2)");
}

}  // namespace geartrib::io::parameters
