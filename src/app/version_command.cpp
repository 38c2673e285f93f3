// `geartrib version`: the tool's version and the versions of the libraries it was built with.
#include "app/commands.hpp"

#include <CLI/CLI.hpp>

#include <H5public.h>
#include <ceres/version.h>
#include <fmt/core.h>
#include <sundials/sundials_config.h>
#include <boost/version.hpp>

namespace geartrib::app {

void add_version_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the geartrib version and the library versions it was built with");
  cmd->callback([] {
    unsigned h5maj = 0, h5min = 0, h5rel = 0;
    H5get_libversion(&h5maj, &h5min, &h5rel);
    fmt::print("geartrib {}\n", GEARTRIB_VERSION);
    fmt::print("  Eigen    {}\n", GEARTRIB_EIGEN_VERSION);  // versions of header-only libraries: from CMake
    fmt::print("  SUNDIALS {}\n", SUNDIALS_VERSION);
    fmt::print("  Boost    {}.{}.{}\n", BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000, BOOST_VERSION % 100);
    fmt::print("  Ceres    {}\n", CERES_VERSION_STRING);
    fmt::print("  HDF5     {}.{}.{}\n", h5maj, h5min, h5rel);
    fmt::print("  CLI11    {}\n", CLI11_VERSION);
    fmt::print("  toml++   {}\n", GEARTRIB_TOMLPLUSPLUS_VERSION);
    fmt::print("  fmt      {}\n", FMT_VERSION);
  });
}

}  // namespace geartrib::app
