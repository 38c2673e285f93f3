// Subcommands of the geartrib command line. Each adds itself to the CLI11 app; its callback
// runs the command and throws on bad input (main maps the exception to the exit status).
#pragma once

#include <CLI/CLI.hpp>

#include "core/case.hpp"

#include <filesystem>
#include <string>

namespace geartrib::app {

void add_asperity_command(CLI::App& app);
void add_kinematics_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_multi_asperity_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_dynamics_command(CLI::App& app);
void add_version_command(CLI::App& app);

// The --csv and -o/--output options every table-printing command takes.
void add_table_options(CLI::App* cmd, bool& csv, std::string& output);

// gears/m6z30.toml in the working directory, else in the source tree the tool was built from.
std::filesystem::path default_case_file();
// Loads the case (the default one when `file` is empty), printing its warnings to stderr.
Case load_case_reporting(const std::string& file);

}  // namespace geartrib::app
