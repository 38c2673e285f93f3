// The mesh-cycle results as HDF5 (readable with h5py):
//   /mesh/<name>, /contact/<name>   1-D float64 datasets over the positions, attribute "units"
//   /mesh attributes                s_A_m .. s_E_m, base_pitch_m, contact_ratio
//   /scene                          the case file's text as run (string), attribute "file"
//   /meta                           attributes version, asperity_model, fidelity, equivalent
//                                   surface; datasets stage_names, stage_seconds (units "s"),
//                                   warnings (findings that make the result doubtful)
// Written to a temporary name in the same folder and renamed when complete.
#pragma once

#include "contact/mesh_contact.hpp"

#include <filesystem>
#include <string>

namespace geartrib::io {

void write_mesh_contact_hdf5(const std::filesystem::path& path, const contact::MeshContactResult& result,
                             const std::string& case_file, const std::string& case_text);

}  // namespace geartrib::io
