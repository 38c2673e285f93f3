// Subcommands of the geartrib command line. Each adds itself to the CLI11 app; its callback
// runs the command and throws on bad input (main maps the exception to the exit status).
#pragma once

#include <CLI/CLI.hpp>

#include "contact/mesh_contact.hpp"
#include "core/case.hpp"
#include "io/topography_files.hpp"
#include "io/units.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace geartrib::app {

void add_asperity_command(CLI::App& app);
void add_kinematics_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_multi_asperity_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_dynamics_command(CLI::App& app);
void add_surface_command(CLI::App& app);
void add_fem_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_tradeoff_command(CLI::App& app);
void add_version_command(CLI::App& app);

// The --csv and -o/--output options every table-printing command takes.
void add_table_options(CLI::App* cmd, bool& csv, std::string& output);

// A command-line quantity with a unit ("0.5 um", "1000 rpm"), SI; the error names the option.
double quantity_option(const std::string& option, const std::string& text, io::Dimension d);

// Reading and cleaning a topography file from the command line (surface, multi-asperity).
struct SurfaceInputOptions {
  std::string unit = "um";   // ASCII length unit when the file does not state one
  std::string spacing;       // grid files without '# spacing:'
  std::string resample;      // regrid spacing
  int form_degree = 2;       // polynomial form removed
  std::string cutoff;        // Gaussian waviness cut-off
  double outliers = 0.0;     // k robust standard deviations; 0 off
  bool fill = false;
};
void add_surface_input_options(CLI::App* cmd, SurfaceInputOptions& o);
// Loads and cleans, printing the clean-up report to stderr.
io::LoadedSurface load_surface_reporting(const std::string& file, const SurfaceInputOptions& o);

// gears/m6z30.toml in the working directory, else in the source tree the tool was built from.
std::filesystem::path default_case_file();
// Loads the case (the default one when `file` is empty) with the command line's key=value
// changes (io::CaseChange), printing its warnings to stderr.
Case load_case_reporting(const std::string& file, const std::vector<std::string>& changes = {});
// The mesh cycle of a case as the case asks for it (KINSOL when coupled, the case's integrator
// when it asks for dynamics); throws std::runtime_error on a non-finite output. Thread-safe.
contact::MeshContactResult run_mesh_cycle(const Case& c, const std::function<void(int, int)>& progress = {},
                                          int positions = 0);

}  // namespace geartrib::app
