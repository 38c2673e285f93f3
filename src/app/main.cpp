// geartrib: spur-gear mesh tribology along the line of action. Thin command line over the
// geartrib_physics and geartrib_io libraries.
#include "app/commands.hpp"

#include <CLI/CLI.hpp>

#include "io/input_error.hpp"

#include <iostream>
#include <stdexcept>

int main(int argc, char** argv) try {
  CLI::App app{
      "geartrib - rough-surface asperity contact of spur gears along the line of action.\n"
      "Implements the elastic-plastic asperity contact thesis of the seed (m = 6 mm, z = 30/30, 45 steel)\n"
      "with the CEB, Kogut-Etsion, Jackson-Green and Zhao-Maietta-Chang models beside it.\n"
      "All quantities are SI inside; data files give units (\"206 GPa\", \"6 mm\").\n"
      "Exit status: 0 success, 2 bad input (the message names file, line, key, value and rule), 1 other failure.",
      "geartrib"};
  app.require_subcommand(1);
  app.fallthrough();
  geartrib::app::add_asperity_command(app);
  geartrib::app::add_run_command(app);
  geartrib::app::add_case_command(app);
  geartrib::app::add_kinematics_command(app);
  geartrib::app::add_multi_asperity_command(app);
  geartrib::app::add_dynamics_command(app);
  geartrib::app::add_fit_command(app);
  geartrib::app::add_surface_command(app);
  geartrib::app::add_fem_command(app);
  geartrib::app::add_sweep_command(app);
  geartrib::app::add_tradeoff_command(app);
  geartrib::app::add_version_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
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
