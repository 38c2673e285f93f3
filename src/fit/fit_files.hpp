// Files of the fitting: reference-data CSV in, report, TOML fragment and generated C++ out.
//
// Reference data: '# key: value' provenance lines, then a header whose first column is
// delta_star and whose other columns are observed quantities (load_star, area_star,
// mean_pressure_over_yield, plastic_area_fraction), optional sd_<quantity> standard deviations
// and an optional per-row weight. An empty cell is a missing observation; "nan" or "inf" are errors.
#pragma once

#include "fit/model_fit.hpp"

#include <filesystem>
#include <string>

namespace geartrib::io {

fit::FitData read_fit_data(const std::filesystem::path& file);  // throws InputError

std::string format_fit_report(const fit::FitResult& r);
// [asperity.constants.<model>] with the free constants (their standard errors as comments).
std::string format_fit_toml(const fit::FitResult& r, const std::string& provenance);
// A C++ header of every constant as `inline constexpr double <model>_<name>` in
// geartrib::asperity::fitted (the continuous model's defaults are such a header).
std::string format_fit_cpp(const fit::FitResult& r, const std::string& provenance);

}  // namespace geartrib::io
