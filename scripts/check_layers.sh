#!/usr/bin/env bash
# The library layering (docs/developer.md, "Source layout"): the physics (src/core, material,
# asperity, gear, surface, contact, lubrication) and the solvers include nothing of case/, config/, topography/, output/,
# runs/ or app/. Prints each offending include and fails.
set -euo pipefail
src="${1:-$(dirname "$0")/../src}"
status=0
cd "$src"
for f in core/* material/* asperity/* gear/* surface/* contact/* contact/*/* lubrication/* solvers/*; do
  [[ -f "$f" ]] || continue
  while IFS= read -r line; do
    layer=$(sed -E 's/^#include "([a-z_]+)\/.*/\1/' <<<"$line")
    echo "$f: $line (the physics may not include $layer/)"
    status=1
  done < <(grep -E '^#include "(case|io|config|topography|output|runs|app|fit|fem)/' "$f" || true)
done
exit $status
