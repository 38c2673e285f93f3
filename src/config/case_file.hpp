// Loading materials/*.toml and gears/*.toml into SI structs, validating every field. A case's
// keys are those of the declared parameter table (config/case_parameters.hpp).
#pragma once

#include "case/case.hpp"
#include "config/case_parameters.hpp"
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
// "name=value" into a change; throws std::invalid_argument naming `text` when there is no '='.
CaseChange parse_case_change(const std::string& text);
// The dotted keys (or tables) a change of the dotted key `key` to `value` removes besides setting
// `key`: the forms it replaces (a torque and an FZG load stage with its test; a flank's roughness
// forms; the lubricant's file and its fixed values; lubricant.file = none the whole [lubricant]
// table, setting nothing).
std::vector<std::string> keys_replaced_by(const std::string& key, const std::string& value);

// Throws InputError (file, line, key, value, rule) on any problem; an error about a changed key
// names its --set. Setting one roughness form of a flank (ra, rq, summit_density, m0, topography)
// removes that flank's other forms. `parts` (io::CasePart bits): what the caller uses (default:
// the mesh cycle's); a key without a default is required only when one of them needs it. Every
// key's value and origin is recorded in Case::parameters.
Material load_material(const std::filesystem::path& file);
// The same, appending located warnings (a value outside the plausible band of gear materials) to
// `warnings` when it is not null. Youngs's modulus lies in [1e6, 1e13] Pa, the density in
// [1, 1e5] kg/m^3 (docs/reference/units.md).
Material load_material(const std::filesystem::path& file, std::vector<std::string>* warnings);
// lubricants/*.toml: every value required (lubricants/README.md), the pressure-viscosity
// coefficient optional (the ISO/TR 15144-1 correlation without it).
lubrication::Lubricant load_lubricant(const std::filesystem::path& file);
Case load_case(const std::filesystem::path& file, const std::vector<CaseChange>& changes = {},
               unsigned parts = kMeshCycleParts);
// The same from a case's text in memory (the Python module's cases, on whichever machine runs
// them): `name` stands for the file in messages; `directory` resolves the material, lubricant
// and topography files (empty: name's folder).
Case load_case_text(const std::string& text, const std::filesystem::path& name,
                    const std::vector<CaseChange>& changes = {}, unsigned parts = kMeshCycleParts,
                    const std::filesystem::path& directory = {});

}  // namespace geartrib::io
