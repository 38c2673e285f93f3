// Loading materials/*.toml and gears/*.toml into SI structs, validating every field.
#pragma once

#include "core/case.hpp"
#include "material/material.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace geartrib::io {

// A change to a case from the command line (`--set key=value`, `geartrib sweep`): a dotted key
// of the case file (gear_pair.module) or a short alias (module) that stands for one or more keys.
struct CaseChange {
  std::string key;
  std::string value;  // as typed: "4mm", "30", "kogut-etsion", "0.1"
};

// The short aliases and the dotted keys each stands for (rq: both flanks' rq, ...).
struct CaseAlias {
  const char* name;
  std::vector<const char*> keys;
};
const std::vector<CaseAlias>& case_aliases();
// "name=value" into a change; throws std::invalid_argument naming `text` when there is no '='.
CaseChange parse_case_change(const std::string& text);

// Throws InputError (file, line, key, value, rule) on any problem; an error about a changed key
// names its --set. Setting one roughness form of a flank (ra, rq, summit_density, m0, topography)
// removes that flank's other forms.
Material load_material(const std::filesystem::path& file);
Case load_case(const std::filesystem::path& file, const std::vector<CaseChange>& changes = {});

}  // namespace geartrib::io
