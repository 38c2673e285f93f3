// The summaries of a mesh cycle's result: named texts and named scalars with their units, each
// defined once here beside the results they summarise (mesh_contact.hpp). Every sink iterates
// them and copies no name: the HDF5 attributes (output/hdf5_results.cpp; its names are the reference),
// the Python module's dicts, the sweep's columns and the finite-output check (runs/).
#pragma once

#include "contact/mesh_contact.hpp"

#include <string>
#include <vector>

namespace geartrib::contact {

// One scalar of a summary, with its unit ("1": a number or a count).
struct SummaryValue {
  std::string name, unit;
  double value = 0.0;
};
// One text of a summary.
struct SummaryText {
  std::string name, value;
};
// A summary: its texts, then its values, each in one order.
struct Summary {
  std::vector<SummaryText> texts;
  std::vector<SummaryValue> values;
};

// The path of contact: s_A_m .. s_E_m, base_pitch_m, contact_ratio (/mesh's attributes).
Summary path_summary(const gear::PathOfContact& p);
// The gears' circles and the diameters where A..E lie on each (/mesh's attributes): the line of
// action T1T2 line_of_action_m; <gear>_reference_diameter_m, _base_, _tip_, _root_; <gear>_diameter_at_A_m .. _E_m; the
// start and end of the active profile <gear>_sap_diameter_m, _eap_diameter_m (the pinion's at A and E, the wheel's at E
// and A).
Summary gear_summary(const MeshContactResult& r);
// The loaded tooth contact over one base pitch (compatibility sharing; /mesh's attributes):
// transmission_error_mean_m, _peak_to_peak_m, _min_m, _max_m, the effective mesh stiffness's
// mean, min and max, loaded_start_m, loaded_end_m, effective_contact_ratio, contact_lost,
// hertz_approach_in_range.
Summary tooth_contact_summary(const gear::TransmissionErrorStats& t);
// The ratings' verdict (/rating's attributes, the sweep's columns): methods; S_H_min, S_F_min (the
// lower gear's), S_H_pinion/_wheel, S_F_pinion/_wheel, S_S_min (the lower of the flash and the
// integral method's), S_B, S_intS, lambda_GF_min, S_lambda, NaN where not rated (the same names always);
// assumed_inputs, findings_count.
Summary rating_summary(const rating::RatingResult& r);
// The models run and the equivalent surface: asperity_model, fidelity; the summits' density,
// radius and sigma, the surface's sigma, the summits' mean height, the plasticity index (/meta's).
Summary surface_summary(const MeshContactResult& r);
// Where the models hold: regime, verdict; positions_<flag>, the positions where each validity flag
// is set (/contact/validity's).
Summary validity_summary(const MeshContactResult& r);
// The running-in's record: teeth; meshes, shakedown_mesh, tolerance_m, <gear>_profile_spacing_m
// (/running_in's).
Summary running_in_summary(const RunningInResult& ri);
// A synthesised flank's record: patch, method; seed, teeth, the patch's and the profile's figures,
// and with IAAFT its convergence (/synthesis/<gear>'s).
Summary synthesis_summary(const FlankSynthesis& f);
// The lubricated cycle's findings: the lubricant and the models chosen, the meaning of the
// ehl_regime codes; the oil, the roughness, friction, losses, temperatures, lambda, safeties
// (/lubrication's; the safeties only with a scuffing temperature).
Summary lubrication_summary(const LubricationSummary& l);
// A mixed-EHL run's settings as run, its cost and the path's extremes: viscosity_law, flow; the
// grid, window, solver and oil as run, the steps and their wall time, the least film, the largest
// asperity share, peak pressure, flash temperature, von Mises stress and load error, the path
// means of the asperity share and friction, and the whole path's solve (/mixed_ehl's).
Summary mixed_ehl_summary(const MixedEhlSummary& m);
// The named points' values as series over the points (in the order of l.points; the names are
// l.points[i].name): /lubrication/points in HDF5, the Python module's table.
std::vector<Series> named_point_series(const LubricationSummary& l);

}  // namespace geartrib::contact
