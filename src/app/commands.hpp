// Subcommands of the geartrib command line. Each adds itself to the CLI11 app; its callback
// runs the command and throws on bad input (main maps the exception to the exit status).
// This header names them only: each command includes what it uses.
#pragma once

namespace CLI {
class App;
}

namespace geartrib::app {

void add_asperity_command(CLI::App& app);
void add_case_command(CLI::App& app);
void add_contact_command(CLI::App& app);
void add_kinematics_command(CLI::App& app);
void add_rate_command(CLI::App& app);
void add_report_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_multi_asperity_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_dynamics_command(CLI::App& app);
void add_ehl_command(CLI::App& app);
void add_surface_command(CLI::App& app);
void add_fem_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_tradeoff_command(CLI::App& app);
void add_version_command(CLI::App& app);

}  // namespace geartrib::app
