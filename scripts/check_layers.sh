#!/usr/bin/env bash
# The library layering (docs/developer.md, "Source layout"): the physics (src/core, material,
# asperity, gear, surface, contact, lubrication) and the solvers include nothing of case/, io/,
# runs/ or app/. Prints each offending include and fails. The mesh-cycle runs of contact/ that
# still take a Case (built in geartrib_case, CMakeLists.txt) are listed in kTakesCase until they
# take typed options (issue 31).
set -euo pipefail
src="${1:-$(dirname "$0")/../src}"
takes_case=(contact/mesh_contact.hpp contact/mesh_contact.cpp contact/mesh_deterministic.hpp
  contact/mesh_deterministic.cpp contact/mesh_lubrication.hpp contact/mesh_lubrication.cpp)
status=0
cd "$src"
for f in core/* material/* asperity/* gear/* surface/* contact/* lubrication/* solvers/*; do
  allowed=""
  for t in "${takes_case[@]}"; do [[ "$f" == "$t" ]] && allowed=case; done
  while IFS= read -r line; do
    layer=$(sed -E 's/^#include "([a-z_]+)\/.*/\1/' <<<"$line")
    [[ "$layer" == "$allowed" ]] && continue
    echo "$f: $line (the physics may not include $layer/)"
    status=1
  done < <(grep -E '^#include "(case|io|runs|app|fit|fem)/' "$f" || true)
done
exit $status
