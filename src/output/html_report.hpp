// A calculation report of a run's result file: one self-contained HTML page (no scripts, no
// external resources; the plots inline SVG) that a reviewer can read: the case, the gear data with
// the diameters of A..E and the active profile, the operating point, every rating factor with its
// clause and the assumed ones marked, the path quantities at the named points in engineering units
// (MPa, um, degC, 1/min), plots along the path, the validity verdict and the warnings, and the
// scene as run. Everything is read from the file `geartrib run` wrote (docs/reference/hdf5-layout.md).
#pragma once

#include <filesystem>
#include <string>

namespace geartrib::io {

// The report of `result` (a `geartrib run` HDF5 file) as HTML text, naming the file `name` (the
// result's own name when `result` is a temporary copy). Throws std::runtime_error naming the file and
// what is missing when it is not a run's result.
std::string html_report(const std::filesystem::path& result, const std::string& name);

}  // namespace geartrib::io
