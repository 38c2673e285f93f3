// geartrib: spur-gear mesh tribology along the line of action. Thin command line over the
// geartrib_physics and geartrib_io libraries.
#include "app/commands.hpp"

#include <CLI/CLI.hpp>

#include "config/input_error.hpp"
#include "output/table_writer.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace {

// `geartrib fit` is a module (geartrib-fit.so, CMakeLists.txt), loaded only when that command runs:
// Ceres and its solvers' 21 shared libraries would otherwise cost every command a few milliseconds
// of start-up. The list of commands shows it with this description, that of src/app/fit_command.cpp
// (ctest cli.fit-module checks that the two agree).
constexpr const char* kFitDescription =
    "Fit a registered asperity model's named constants to reference data (validation/fem-reference/*.csv)\n"
    "with Ceres: automatic differentiation through the model's own law, bounds from each constant's range,\n"
    "relative residuals (or residuals over sd_<quantity> columns), optional robust loss. Prints each\n"
    "constant with its standard error, the correlation matrix, the rms relative error per observed column\n"
    "and the residuals; -o writes a TOML fragment a case file can include ([asperity.constants.<model>]).";

// The command the arguments name: the first that is not an option (the tool's own options, -h and
// --help, take no value).
std::string_view command_named(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') return argv[i];
  return {};
}

// The module sits beside the tool in the build tree and in <prefix>/lib/geartrib when installed.
void add_fit_command_from_module(CLI::App& app) {
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
  for (const char* name : {GEARTRIB_FIT_MODULE, GEARTRIB_FIT_MODULE_INSTALLED}) {
    const std::filesystem::path path = dir / name;
    if (!std::filesystem::exists(path, ec)) continue;
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) throw std::runtime_error(std::string("cannot load the fit command: ") + dlerror());
    // geartrib::app::add_fit_command(CLI::App&), the one symbol it exports (cmake/fit-module.map).
    void* entry = dlsym(module, "_ZN8geartrib3app15add_fit_commandERN3CLI3AppE");
    if (entry == nullptr) throw std::runtime_error(path.string() + " has no geartrib::app::add_fit_command");
    reinterpret_cast<decltype(&geartrib::app::add_fit_command)>(entry)(app);
    return;
  }
  throw std::runtime_error("the fit command's module " GEARTRIB_FIT_MODULE " is neither in " + dir.string() +
                           " nor in " + (dir / GEARTRIB_FIT_MODULE_INSTALLED).parent_path().string());
}

// Every command, in the order `geartrib --help` lists them.
using AddCommand = void (*)(CLI::App&);
constexpr std::pair<std::string_view, AddCommand> kCommands[] = {
    {"asperity", geartrib::app::add_asperity_command},
    {"run", geartrib::app::add_run_command},
    {"case", geartrib::app::add_case_command},
    {"kinematics", geartrib::app::add_kinematics_command},
    {"rate", geartrib::app::add_rate_command},
    {"report", geartrib::app::add_report_command},
    {"multi-asperity", geartrib::app::add_multi_asperity_command},
    {"ehl", geartrib::app::add_ehl_command},
    {"dynamics", geartrib::app::add_dynamics_command},
    {"fit", add_fit_command_from_module},
    {"surface", geartrib::app::add_surface_command},
    {"contact", geartrib::app::add_contact_command},
    {"fem", geartrib::app::add_fem_command},
    {"sweep", geartrib::app::add_sweep_command},
    {"tradeoff", geartrib::app::add_tradeoff_command},
    {"version", geartrib::app::add_version_command},
};

}  // namespace

int main(int argc, char** argv) try {
  CLI::App app{
      "geartrib - rough-surface asperity contact of spur gears along the line of action.\n"
      "Implements the thesis \"Spur Gear Rough Surface Asperity Elastic-Plastic Contact Model\" (its pair:\n"
      "m = 6 mm, z = 30/30, 45 steel) with the CEB, Kogut-Etsion, Jackson-Green and Zhao-Maietta-Chang models\n"
      "beside it.\n"
      "All quantities are SI inside; data files give units (\"206 GPa\", \"6 mm\").\n"
      "Exit status: 0 success, 2 bad input (the message names file, line, key, value and rule), 1 other failure.",
      "geartrib"};
  app.require_subcommand(1);
  app.fallthrough();
  // A command line that starts with a command builds that command alone: the others' options cost
  // about half a millisecond of each run (docs/reference/performance.md). Any other (--help first,
  // no command, a misspelt one) builds them all, for the list and the messages.
  const std::string_view command = command_named(argc, argv);
  const bool alone =
      argc > 1 && command == argv[1] &&
      std::any_of(std::begin(kCommands), std::end(kCommands), [&](const auto& c) { return c.first == command; });
  for (const auto& [name, add] : kCommands) {
    if (alone && name != command) continue;
    if (name == "fit" && command != "fit") {
      app.add_subcommand("fit", kFitDescription);  // listed, not loaded
    } else {
      add(app);
    }
  }
  try {
    app.parse(argc, argv);
    // What the command wrote to standard output, all of it: a full disk or a closed pipe is a
    // failure (exit 1), not a table silently cut short.
    geartrib::io::flush_stdout();
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (code != 0) return 2;
    geartrib::io::flush_stdout();  // --help: its text, all of it (a failure: exit 1, the outer handler)
    return 0;
  } catch (const geartrib::io::InputError& e) {
    std::cerr << "geartrib: error: " << e.what() << '\n';
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "geartrib: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "geartrib: failure: " << e.what() << '\n';
    return 1;
  }
  return 0;
} catch (const std::exception& e) {  // building the command line (outside the parse's handlers)
  std::cerr << "geartrib: failure: " << e.what() << '\n';
  return 1;
}
