#include "io/hdf5_results.hpp"

#include "io/case_records.hpp"
#include "io/hdf5_handles.hpp"
#include "io/table_writer.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <vector>

namespace geartrib::io {

namespace {

using hdf5::Handle;
using hdf5::number_attribute;
using hdf5::string_attribute;

void write_file(const std::string& path, const contact::MeshContactResult& r, const std::string& case_file,
                const Case& c) {
  hdf5::NewFile file(path);
  {
    Handle mesh(H5Gcreate2(file, "/mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /mesh");
    for (const auto& s : r.mesh) hdf5::number_dataset(mesh, s.name, s.values, s.unit);
    number_attribute(mesh, "s_A_m", r.path.a);
    number_attribute(mesh, "s_B_m", r.path.b);
    number_attribute(mesh, "s_C_m", r.path.c);
    number_attribute(mesh, "s_D_m", r.path.d);
    number_attribute(mesh, "s_E_m", r.path.e);
    number_attribute(mesh, "base_pitch_m", r.path.base_pitch);
    number_attribute(mesh, "contact_ratio", r.path.contact_ratio);
  }
  {
    Handle contact(H5Gcreate2(file, "/contact", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /contact");
    for (const auto& s : r.contact) hdf5::number_dataset(contact, s.name, s.values, s.unit);
    if (!r.validity.empty()) {
      Handle validity(H5Gcreate2(contact, "validity", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                      "group /contact/validity");
      for (const auto& s : r.validity) hdf5::number_dataset(validity, s.name, s.values, s.unit);
      string_attribute(validity, "regime", r.regime);
      string_attribute(validity, "verdict", r.verdict);
      for (const auto& f : r.flag_counts) number_attribute(validity, "positions_" + f.name, f.positions);
    }
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
    string_attribute(group, "meaning",
                     "the statistical model (uncoupled) on the same flanks: their spectral moments from the profiles");
    for (const auto& s : r.statistical) hdf5::number_dataset(group, s.name, s.values, s.unit);
  }
  if (r.running_in) {
    const auto& ri = *r.running_in;
    Handle group(H5Gcreate2(file, "/running_in", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /running_in");
    for (const auto& s : ri.history) hdf5::number_dataset(group, s.name, s.values, s.unit);
    string_attribute(group, "teeth", ri.teeth);
    number_attribute(group, "meshes", ri.meshes);
    number_attribute(group, "shakedown_mesh", ri.shakedown_mesh);
    number_attribute(group, "tolerance_m", ri.tolerance);
    const char* gear[2] = {"pinion", "wheel"};
    for (int g = 0; g < 2; ++g) {
      hdf5::number_dataset(group, std::string(gear[g]) + "_profile_initial_m", ri.initial[g], "m");
      hdf5::number_dataset(group, std::string(gear[g]) + "_profile_final_m", ri.final[g], "m");
      number_attribute(group, std::string(gear[g]) + "_profile_spacing_m", ri.spacing[g]);
    }
  }
  if (!r.synthesis.empty()) {
    // Deterministic: flanks synthesised from a measured patch, and how (attributes only).
    Handle group(H5Gcreate2(file, "/synthesis", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /synthesis");
    string_attribute(group, "meaning",
                     "flank profiles synthesised from a measured patch's profile spectrum (random phases; iaaft: its "
                     "height distribution kept); tooth t's seed is seed + t");
    for (const auto& f : r.synthesis) {
      Handle g(H5Gcreate2(group, f.gear.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               "group /synthesis/" + f.gear);
      string_attribute(g, "patch", f.patch);
      string_attribute(g, "method", f.method);
      number_attribute(g, "seed", f.seed);
      number_attribute(g, "teeth", f.teeth);
      number_attribute(g, "patch_lines", f.patch_lines);
      number_attribute(g, "patch_points", f.patch_points);
      number_attribute(g, "patch_spacing_m", f.patch_spacing);
      number_attribute(g, "patch_rq_m", f.patch_rq);
      number_attribute(g, "rolled_off_fraction", f.rolled_off_fraction);
      number_attribute(g, "profile_length_m", f.profile_length);
      number_attribute(g, "profile_rq_m", f.profile_rq);
      if (f.method == "iaaft") {
        number_attribute(g, "iaaft_iterations", f.iterations);
        number_attribute(g, "iaaft_spectrum_misfit", f.spectrum_misfit);
        number_attribute(g, "iaaft_curvature_ratio", f.curvature_ratio);
        number_attribute(g, "iaaft_converged", f.converged ? 1.0 : 0.0);
      }
    }
  }
  if (r.lubrication_summary) {
    const auto& l = *r.lubrication_summary;
    Handle lub(H5Gcreate2(file, "/lubrication", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /lubrication");
    for (const auto& s : r.lubrication) hdf5::number_dataset(lub, s.name, s.values, s.unit);
    for (const auto& t : contact::summary_texts(l)) string_attribute(lub, t.name, t.value);
    string_attribute(lub, "ehl_regime_codes",
                     "0 rigid-isoviscous, 1 rigid-piezoviscous, 2 elastic-isoviscous, 3 elastic-piezoviscous");
    for (const auto& v : contact::summary_values(l)) number_attribute(lub, v.name, v.value);
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
    string_attribute(meta, "asperity_model", r.asperity_model);
    string_attribute(meta, "fidelity", r.fidelity);
    number_attribute(meta, "summit_density_per_m2", r.surface.summit_density);
    number_attribute(meta, "summit_radius_m", r.surface.summit_radius);
    number_attribute(meta, "summit_sigma_m", r.surface.summit_sigma);
    number_attribute(meta, "surface_sigma_m", r.surface.surface_sigma);
    number_attribute(meta, "summit_mean_height_m", r.surface.summit_mean_height);
    number_attribute(meta, "plasticity_index", r.plasticity_index);
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
