// The case a command runs: loaded with its --set changes, warnings printed (the mesh cycle it
// runs: runs/mesh_cycle.hpp).
#pragma once

#include "app/cli_options.hpp"
#include "case/case.hpp"
#include "config/case_file.hpp"
#include "config/case_parameters.hpp"
#include "config/case_prepare.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace geartrib::app {

// gears/m6z30.toml in the working directory, else beside an installed tool (<prefix>/share/geartrib),
// else in the source tree the tool was built from.
std::filesystem::path default_case_file();
// The case file a command reads (the default one when none is given), and its --set changes.
std::filesystem::path case_path(const CaseOptions& o);
std::vector<io::CaseChange> case_changes(const CaseOptions& o);
// Loads the case (the default one when the file is empty) with the command line's key=value
// changes, requiring the keys of `parts` (io::CasePart; default: what the mesh cycle uses),
// prepares its derived data (io::prepare_case), printing its warnings to stderr.
Case load_case_reporting(const CaseOptions& o, unsigned parts = io::kMeshCycleParts);

}  // namespace geartrib::app
