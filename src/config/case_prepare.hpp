// The data a case derives from its inputs, computed once after loading (io::load_case only reads
// and validates): each measured flank's topography read and reduced to its summit statistics (or
// a profile trace's spectral moments), the line the deterministic fidelity rolls and the spectrum a
// synthesis draws on; a generated profile's spectral moments from a 65,536-point sample; the
// flanks' summit radii made consistent with their equivalent surface; the gear pair built, its
// findings (undercut) kept as located warnings. Refusals are located at the key whose value
// they are about (config/case_records.hpp). Called by the commands, the sweeps and Python after
// loading (with the --set changes) and again after a Case is changed in code; idempotent.
#pragma once

#include "case/case.hpp"

namespace geartrib::io {

void prepare_case(Case& c);
// The same on a copy: io::prepare_case(io::load_case(file)).
Case prepare_case(Case&& c);

}  // namespace geartrib::io
