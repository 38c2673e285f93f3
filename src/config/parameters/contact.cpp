// The mesh-cycle contact run's keys, declared beside ContactSettings and RunningInSettings: the
// resolutions' accessors name the physics' option fields (contact::StripOptions,
// GreenwoodWilliamsonOptions, DeterministicOptions) held whole in ContactSettings.
#include "config/parameters/declare.hpp"

#include "asperity/model.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/greenwood_williamson.hpp"
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
          "Deterministic: the pressure profiles kept in the HDF5 file: at the positions nearest A, B, C, D, E "
          "(points), at every position (all) or none");
  add(integer(
          "contact.threads", [](auto& c, int) -> auto& { return c.contact.threads; }))
      .range(0, 1024)
      .alias({"threads"})
      .doc("Deterministic: threads solving the positions of a mesh (0: all cores)");
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
