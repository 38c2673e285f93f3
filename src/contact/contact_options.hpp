// The mesh cycle's contact options: the fidelity (one of the registered ones,
// contact/fidelity_registry.hpp), the outputs asked for, the resolution knobs and running-in.
#pragma once

#include "contact/areal/mesh_areal_options.hpp"
#include "contact/deterministic_contact.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mixed_ehl/mixed_ehl_options.hpp"
#include "contact/rough_line_contact.hpp"
#include "core/named_choices.hpp"

#include <span>
#include <string>
#include <string_view>

namespace geartrib {

// A contact fidelity, by the name it is registered under (contact/fidelities.hpp lists them):
// uncoupled, coupled, deterministic, ... The case table's choices are the registry's names, so
// a value always names a registered fidelity (its name points into the registry's entry).
class ContactFidelity {
 public:
  constexpr ContactFidelity() = default;
  constexpr explicit ContactFidelity(std::string_view name) : name_(name) {}
  constexpr std::string_view name() const { return name_; }
  friend constexpr bool operator==(ContactFidelity a, ContactFidelity b) { return a.name_ == b.name_; }
  // The built-in ones, for code and tests that name them.
  static const ContactFidelity uncoupled, coupled, deterministic, mixed_ehl;

 private:
  std::string_view name_ = "uncoupled";
};
inline constexpr ContactFidelity ContactFidelity::uncoupled{"uncoupled"};
inline constexpr ContactFidelity ContactFidelity::coupled{"coupled"};
inline constexpr ContactFidelity ContactFidelity::deterministic{"deterministic"};
inline constexpr ContactFidelity ContactFidelity::mixed_ehl{"mixed_ehl"};

// Which pressure profiles a deterministic or mixed-EHL run keeps: at the path's points A, B, C, D,
// E, at every position, or none.
enum class PressureProfiles { points, all, none };

// The mesh-cycle contact run: fidelity, the outputs asked for, the run's own knobs, and the
// physics' options whole (each default stated once, in its struct). The fidelity sets the members
// that follow from the rest of the case: the strip's fidelity, the table's plastic area (the
// plastic_fraction output), the boundary elements' cap, Poisson ratio and plastic share (the
// flanks' materials) and subsurface stress (the asperity_stress output).
struct ContactSettings {
  ContactFidelity fidelity;
  bool real_area = true;  // outputs asked for
  bool plastic_fraction = true;
  bool asperity_stress = true;
  bool mesh_stiffness = false;  // the tooth-pair stiffness along the path (needed anyway by stiffness load sharing)
  int positions = 201;          // along A -> E of one tooth pair
  // Statistical fidelities: the summit-height quadrature and the pressure-separation table
  // (contact.height_points, table_points); the strip (strip_points, strip_lookup, coupled_nodes).
  contact::GreenwoodWilliamsonOptions greenwood_williamson;
  contact::StripOptions strip;
  int stress_table = 64;  // von Mises table intervals over sqrt(plastic share); 0: exact maximisation each time
  // Deterministic: the boundary elements (contact.element_size, strip_halfwidths; running_in.tolerance
  // as the plastic overlap), the pressure profiles kept and the threads (0: all cores).
  contact::DeterministicOptions boundary_elements;
  PressureProfiles pressure_profiles = PressureProfiles::points;
  int threads = 0;
  // Mixed EHL: the grid, the transient window and the line solver (the pressure profiles kept and
  // the threads as above).
  contact::mixed_ehl::MixedEhlOptions mixed_ehl;
  // Areal: the window across the face, the flanks' lay, the solver's tolerance (the strip along the
  // involute as the deterministic fidelity's; its positions are solved on one thread).
  contact::areal::ArealMeshOptions areal;
  // The option structs' validate(): throws core::KeyedError naming the field by its path from here
  // ("strip.strip_points", "boundary_elements.element_size", "mixed_ehl.solver.tolerance").
  void validate() const;
};

// Running-in (deterministic fidelity): the plastic deformation of each flank point carried from
// one mesh of the same teeth to the next, until shakedown or `meshes` meshes. Its threshold, below
// which a plastic deformation counts as none (shakedown: a mesh that deforms no flank point by
// more), is the boundary elements' plastic_overlap (ContactSettings::boundary_elements).
// The teeth that meet from mesh to mesh: pair, one pinion and one wheel tooth (the 1:1 pair's order);
// hunting, every tooth in the order they mesh (pinion tooth k meets wheel tooth k mod z2).
enum class ToothOrder { pair, hunting };
std::span<const NamedChoice<ToothOrder>> tooth_order_choices();  // running_in.teeth
const char* tooth_order_name(ToothOrder o);

struct RunningInSettings {
  int meshes = 0;  // 0: one mesh, no running-in
  ToothOrder teeth = ToothOrder::pair;
  bool hunting() const { return teeth == ToothOrder::hunting && meshes > 0; }  // more than one mesh, every tooth
};

}  // namespace geartrib
