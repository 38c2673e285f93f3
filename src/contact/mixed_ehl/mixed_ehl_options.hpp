// The mixed-EHL fidelity's options (contact.fidelity = "mixed_ehl", the [mixed_ehl] keys): the grid,
// the transient window and its time step, the lubricant's laws, and the line solver's own options
// held whole (contact/mixed_ehl/line_ehl.hpp: the domain, tolerance, film floor and boundary
// friction; the nodes and the pressure cap are set per run). Held whole in ContactSettings.
#pragma once

#include "contact/mixed_ehl/line_ehl.hpp"

namespace geartrib::contact::mixed_ehl {

struct MixedEhlOptions {
  // Nodes of the automatic grid over the largest contact's domain [-inlet b, outlet b].
  static constexpr int kAutomaticNodes = 1024;
  // At most this many nodes at any position (the solver's work grows as nodes x steps).
  static constexpr int kMaxNodes = 1 << 18;
  static constexpr double kMinWindow = 1.0, kMaxWindow = 1000.0;
  static constexpr double kMaxLeadIn = 100.0;
  // The node spacing [m]: every position's grid has it (its domain [-inlet b, outlet b] of its own
  // Hertz half-width b). 0: the largest contact's domain in kAutomaticNodes nodes, or the flank
  // profiles' finest spacing where that is finer (a grid is never coarser than a profile: it would
  // skip the profile's points between its nodes).
  double grid_spacing = 0.0;
  // The transient window at each position: this many contact widths 2b travelled by the slower
  // surface (its roughness then crosses the whole contact at least once), at least 1.
  double window = 2.0;
  // The window's lead-in: from the smooth contact's steady solution, time steps over this many
  // Hertz half-widths b travelled at the entrainment speed before the window, the roughness growing
  // from zero over its first half, so that the window starts from the state the moving surfaces
  // leave (its means then do not depend on the start: within 2 % from 4 on the shipped case). 0:
  // the window starts from the steady rough contact at t = 0 (its oil locked in the valleys).
  double lead_in = 4.0;
  // The time step as a Courant number: dt = time_step dx / max(u1, u2) (a roughness feature of the
  // faster surface moves time_step nodes a step).
  double time_step = 1.0;
  // One transient solve from A to E as well (the load and geometry changing each step, on the
  // largest contact's grid), its cost measured.
  bool whole_path = false;
  ViscosityLaw viscosity_law = Fluid{}.viscosity_law;
  FlowModel flow = Fluid{}.flow;
  bool compressible = Fluid{}.compressible;
  EhlOptions solver;      // inlet, outlet, tolerance, film_floor, boundary_friction (nodes, pressure_cap: per run)
  void validate() const;  // throws core::KeyedError naming the field ("solver.tolerance" for the solver's)
};

}  // namespace geartrib::contact::mixed_ehl
