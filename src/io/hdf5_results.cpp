#include "io/hdf5_results.hpp"

#include "io/hdf5_handles.hpp"
#include "io/table_writer.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <vector>

namespace geartrib::io {

namespace {

using hdf5::Handle;
using hdf5::check;
using hdf5::number_attribute;
using hdf5::string_attribute;

void vector_dataset(hid_t group, const std::string& name, const std::vector<double>& values, const std::string& units) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "dataspace");
  Handle set(H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "dataset " + name);
  check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + name);
  string_attribute(set, "units", units);
}

void write_file(const std::string& path, const contact::MeshContactResult& r, const std::string& case_file,
                const std::string& case_text) {
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "file " + path);
  {
    Handle mesh(H5Gcreate2(file, "/mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /mesh");
    for (const auto& s : r.mesh) vector_dataset(mesh, s.name, s.values, s.unit);
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
    for (const auto& s : r.contact) vector_dataset(contact, s.name, s.values, s.unit);
  }
  {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
    check(H5Tset_size(type, std::max<std::size_t>(1, case_text.size())), "H5Tset_size");
    check(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
    Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
    Handle scene(H5Dcreate2(file, "/scene", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, "/scene");
    check(H5Dwrite(scene, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, case_text.c_str()), "write /scene");
    string_attribute(scene, "file", case_file);
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
    number_attribute(meta, "plasticity_index", r.plasticity_index);
    std::vector<double> seconds;
    std::vector<const char*> names;
    for (const auto& s : r.stages) {
      seconds.push_back(s.seconds);
      names.push_back(s.name.c_str());
    }
    vector_dataset(meta, "stage_seconds", seconds, "s");
    const hsize_t n = names.size();
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
    check(H5Tset_size(type, H5T_VARIABLE), "H5Tset_size");
    check(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
    Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "dataspace");
    Handle set(H5Dcreate2(meta, "stage_names", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, "stage_names");
    check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, names.data()), "write stage_names");
  }
}

}  // namespace

void write_mesh_contact_hdf5(const std::filesystem::path& path, const contact::MeshContactResult& result,
                             const std::string& case_file, const std::string& case_text) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions, not stderr dumps
  write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp.string(), result, case_file, case_text); });
}

}  // namespace geartrib::io
