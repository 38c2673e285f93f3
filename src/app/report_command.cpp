// `geartrib report`: the calculation report of a run's result file, one self-contained HTML page
// (output/html_report.hpp).
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "output/html_report.hpp"
#include "output/table_writer.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace geartrib::app {

namespace {

struct Options {
  std::string result;
  std::string output;
};

void run(const Options& o) {
  const std::filesystem::path out = o.output.empty()
                                        ? std::filesystem::path(o.result).filename().replace_extension(".html")
                                        : std::filesystem::path(o.output);
  io::OutputSet outputs;
  outputs.reserve(out);
  outputs.add_text(out, io::html_report(o.result, std::filesystem::path(o.result).filename().string()));
  outputs.commit();
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report",
      "The calculation report of a `geartrib run` result: one self-contained HTML page (no scripts, no\n"
      "external files; plots inline) with the case, the gear data and the diameters of A..E and the active\n"
      "profile, the operating point, the safety factors and every rating factor with its clause (assumed\n"
      "inputs shaded), the path quantities at the named points in MPa, um, degC and 1/min, plots along the\n"
      "path, the validity verdict and the warnings. `geartrib run CASE --report` writes it beside the run.");
  cmd->add_option("result", o->result, "RESULT.h5: a `geartrib run` result file")->required()->check(CLI::ExistingFile);
  add_output_option(cmd, o->output, "the report (default: <result name>.html in the working directory)");
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
