// The mesh-cycle results as HDF5 (readable with h5py):
//   /mesh/<name>, /contact/<name>   1-D float64 datasets over the positions, attribute "units"
//   /mesh attributes                s_A_m .. s_E_m, base_pitch_m, contact_ratio; under the
//                                   compatibility sharing the transmission error's and the
//                                   loaded contact's (contact::tooth_contact_summary)
//   /scene                          the case file's text with the --set changes (string), attribute "file"
//   /parameters/key, value, origin  every declared key as it ran (value with SI unit; origin
//                                   "file:line", "--set" or "default")
//   /meta                           attributes version, asperity_model, fidelity, equivalent
//                                   surface; datasets stage_names, stage_seconds (units "s"),
//                                   warnings (findings that make the result doubtful)
// Writes `path` as it is: a command writes it through an io::OutputSet (all outputs or none).
#pragma once

#include "case/case.hpp"
#include "contact/mesh_contact.hpp"

#include <filesystem>
#include <string>

namespace geartrib::io {

// Initialises the HDF5 library (~0.5 ms) and turns its error printing off (every HDF5 error
// becomes an exception with a message of ours). Idempotent; every HDF5 reader and writer calls it,
// and a command may call it early, off its critical path (the sweep, while its points run).
void start_hdf5();

void write_mesh_contact_hdf5(const std::filesystem::path& path, const contact::MeshContactResult& result,
                             const std::string& case_file, const Case& c);

}  // namespace geartrib::io
