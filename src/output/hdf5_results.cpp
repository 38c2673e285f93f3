#include "output/hdf5_results.hpp"

#include "config/case_records.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/run_summary.hpp"
#include "output/hdf5_handles.hpp"
#include "output/table_writer.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <vector>

namespace geartrib::io {

namespace {

using hdf5::Handle;
using hdf5::number_attribute;
using hdf5::string_attribute;

// A summary as its group's attributes: its texts, then its values.
void summary_attributes(hid_t group, const contact::Summary& s) {
  for (const auto& t : s.texts) string_attribute(group, t.name, t.value);
  for (const auto& v : s.values) number_attribute(group, v.name, v.value);
}

void write_file(const std::string& path, const contact::MeshContactResult& r, const std::string& case_file,
                const Case& c) {
  hdf5::NewFile file(path);
  {
    Handle mesh(H5Gcreate2(file, "/mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /mesh");
    for (const auto& s : r.mesh) hdf5::number_dataset(mesh, s.name, s.values, s.unit);
    summary_attributes(mesh, contact::path_summary(r.path));
    summary_attributes(mesh, contact::gear_summary(r));
    if (r.tooth_contact) summary_attributes(mesh, contact::tooth_contact_summary(*r.tooth_contact));
  }
  {
    Handle contact(H5Gcreate2(file, "/contact", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /contact");
    for (const auto& s : r.contact) hdf5::number_dataset(contact, s.name, s.values, s.unit);
    if (!r.validity.empty()) {
      Handle validity(H5Gcreate2(contact, "validity", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                      "group /contact/validity");
      for (const auto& s : r.validity) hdf5::number_dataset(validity, s.name, s.values, s.unit);
      summary_attributes(validity, contact::validity_summary(r));
    }
  }
  if (r.rating) {
    // The ratings: one row per factor (symbol, gear, value in SI with its unit, clause, assumed,
    // note), the verdict as attributes, the findings.
    Handle group(H5Gcreate2(file, "/rating", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /rating");
    std::vector<std::string> symbol, gear, unit, clause, note, findings = r.rating->findings;
    std::vector<double> value, assumed;
    for (const auto& f : r.rating->factors) {
      symbol.push_back(f.symbol);
      gear.emplace_back(f.gear == 0 ? "pinion" : f.gear == 1 ? "wheel" : "pair");
      value.push_back(f.value);
      unit.push_back(f.unit);
      clause.push_back(f.clause);
      note.push_back(f.note);
      assumed.push_back(f.assumed ? 1.0 : 0.0);
    }
    hdf5::strings_dataset(group, "symbol", symbol);
    hdf5::strings_dataset(group, "gear", gear);
    hdf5::number_dataset(group, "value", value, "SI (see unit)");
    hdf5::strings_dataset(group, "unit", unit);
    hdf5::strings_dataset(group, "clause", clause);
    hdf5::number_dataset(group, "assumed", assumed, "1");
    hdf5::strings_dataset(group, "note", note);
    hdf5::strings_dataset(group, "findings", findings);
    contact::Summary verdict = contact::rating_summary(*r.rating);  // not rated (NaN): no attribute
    std::erase_if(verdict.values, [](const contact::SummaryValue& v) { return std::isnan(v.value); });
    summary_attributes(group, verdict);
  }
  if (!r.pressure_profiles.empty()) {
    // Deterministic: the pressure across the strip at the positions kept (one x for all).
    Handle group(H5Gcreate2(file, "/contact/pressure", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "group /contact/pressure");
    hdf5::number_dataset(group, "x_m", r.pressure_profiles.front().x, "m");
    for (const auto& p : r.pressure_profiles) {
      const std::string name = "position_" + std::to_string(p.position);
      hdf5::number_dataset(group, name, p.pressure, "Pa");
      Handle d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, name);
      number_attribute(d, "s_m", p.s);
      number_attribute(d, "position", p.position);
      if (!p.point.empty()) string_attribute(d, "point", p.point);
    }
  }
  if (!r.statistical.empty()) {
    Handle group(H5Gcreate2(file, "/statistical", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "group /statistical");
    string_attribute(group, "meaning", std::string(contact::group_description(r.fidelity, "/statistical")));
    for (const auto& s : r.statistical) hdf5::number_dataset(group, s.name, s.values, s.unit);
  }
  if (r.running_in) {
    const auto& ri = *r.running_in;
    Handle group(H5Gcreate2(file, "/running_in", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /running_in");
    for (const auto& s : ri.history) hdf5::number_dataset(group, s.name, s.values, s.unit);
    summary_attributes(group, contact::running_in_summary(ri));
    const char* gear[2] = {"pinion", "wheel"};
    for (int g = 0; g < 2; ++g) {
      hdf5::number_dataset(group, std::string(gear[g]) + "_profile_initial_m", ri.initial[g], "m");
      hdf5::number_dataset(group, std::string(gear[g]) + "_profile_final_m", ri.final[g], "m");
    }
  }
  if (!r.synthesis.empty()) {
    // Deterministic: flanks synthesised from a measured patch, and how (attributes only).
    Handle group(H5Gcreate2(file, "/synthesis", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /synthesis");
    string_attribute(group, "meaning",
                     "flank profiles synthesised from a measured patch's profile spectrum (random phases; iaaft: its "
                     "height distribution kept); areal-synthesis, areal-tiled: the areal fidelity's height maps from "
                     "the patch's areal spectrum, or the patch tiled by mirror images (profile_length_m, profile_rq_m: "
                     "tooth 0's map along the involute, and its Rq); tooth t's seed is seed + t");
    for (const auto& f : r.synthesis) {
      Handle g(H5Gcreate2(group, f.gear.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               "group /synthesis/" + f.gear);
      summary_attributes(g, contact::synthesis_summary(f));
    }
  }
  if (r.mixed_ehl_summary) {
    // Mixed EHL: the windows' series, the run's summary and the profiles through the contact kept.
    Handle group(H5Gcreate2(file, "/mixed_ehl", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /mixed_ehl");
    string_attribute(group, "meaning", std::string(contact::group_description(r.fidelity, "/mixed_ehl")));
    for (const auto& s : r.mixed_ehl) hdf5::number_dataset(group, s.name, s.values, s.unit);
    summary_attributes(group, contact::mixed_ehl_summary(*r.mixed_ehl_summary));
    if (!r.ehl_profiles.empty()) {
      Handle profiles(H5Gcreate2(group, "profiles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                      "group /mixed_ehl/profiles");
      string_attribute(profiles, "meaning",
                       std::string(contact::group_description(r.fidelity, "/mixed_ehl/profiles")) +
                           "; state: 0 fluid, 1 cavitated, 2 asperity contact");
      for (const auto& p : r.ehl_profiles) {
        const std::string name = "position_" + std::to_string(p.position);
        Handle g(H5Gcreate2(profiles, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "group /mixed_ehl/profiles/" + name);
        number_attribute(g, "s_m", p.s);
        number_attribute(g, "position", p.position);
        if (!p.point.empty()) string_attribute(g, "point", p.point);
        hdf5::number_dataset(g, "x_m", p.x, "m");
        for (const auto& [instant, q] : {std::pair{"peak", &p.peak}, std::pair{"middle", &p.middle}}) {
          const std::string at = instant;
          number_attribute(g, at + "_time_s", q->time);
          hdf5::number_dataset(g, at + "_pressure_Pa", q->pressure, "Pa");
          hdf5::number_dataset(g, at + "_film_m", q->film, "m");
          hdf5::number_dataset(g, at + "_shear_Pa", q->shear, "Pa");
          hdf5::number_dataset(g, at + "_state", q->state, "1");
        }
      }
    }
  }
  if (r.lubrication_summary) {
    const auto& l = *r.lubrication_summary;
    Handle lub(H5Gcreate2(file, "/lubrication", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /lubrication");
    for (const auto& s : r.lubrication) hdf5::number_dataset(lub, s.name, s.values, s.unit);
    summary_attributes(lub, contact::lubrication_summary(l));
    // The named points, each evaluated where it stands (B and D on the single pair's side).
    Handle points(H5Gcreate2(lub, "points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                  "group /lubrication/points");
    std::vector<std::string> names;
    for (const auto& p : l.points) names.push_back(p.name);
    hdf5::strings_dataset(points, "point", names);
    for (const auto& q : contact::named_point_series(l)) hdf5::number_dataset(points, q.name, q.values, q.unit);
  }
  {
    hdf5::string_dataset(file, "/scene", c.source_text);
    Handle scene(H5Dopen2(file, "/scene", H5P_DEFAULT), H5Dclose, "/scene");
    string_attribute(scene, "file", case_file);
    // Every declared key as it ran: value with its SI unit, and where it came from.
    Handle parameters(H5Gcreate2(file, "/parameters", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                      "group /parameters");
    std::vector<std::string> keys, values, origins;
    for (const auto& p : current_parameters(c)) {
      keys.push_back(p.key);
      values.push_back(p.value);
      origins.push_back(p.origin.text());
    }
    hdf5::strings_dataset(parameters, "key", keys);
    hdf5::strings_dataset(parameters, "value", values);
    hdf5::strings_dataset(parameters, "origin", origins);
  }
  {
    Handle meta(H5Gcreate2(file, "/meta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /meta");
    string_attribute(meta, "version", GEARTRIB_VERSION);
    summary_attributes(meta, contact::surface_summary(r));
    std::vector<double> seconds;
    std::vector<std::string> names;
    for (const auto& s : r.stages) {
      seconds.push_back(s.seconds);
      names.push_back(s.name);
    }
    hdf5::number_dataset(meta, "stage_seconds", seconds, "s");
    hdf5::strings_dataset(meta, "stage_names", names);
    hdf5::strings_dataset(meta, "warnings", r.warnings);
  }
  file.close();
}

}  // namespace

void start_hdf5() {
  H5open();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

void write_mesh_contact_hdf5(const std::filesystem::path& path, const contact::MeshContactResult& result,
                             const std::string& case_file, const Case& c) {
  start_hdf5();
  write_file(path.string(), result, case_file, c);
}

}  // namespace geartrib::io
