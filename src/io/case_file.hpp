// Loading materials/*.toml and gears/*.toml into SI structs, validating every field.
#pragma once

#include "core/case.hpp"
#include "material/material.hpp"

#include <filesystem>

namespace geartrib::io {

// Throws InputError (file, line, key, value, rule) on any problem.
Material load_material(const std::filesystem::path& file);
Case load_case(const std::filesystem::path& file);

}  // namespace geartrib::io
