#include "app/cli_options.hpp"

#include <iostream>

namespace geartrib::app {

void add_case_argument(CLI::App* cmd, CaseOptions& o) {
  cmd->add_option("case", o.file, "Case file (default: gears/m6z30.toml)");
  cmd->add_option("--set", o.changes,
                  "KEY=VALUE: change a case key for this run, repeatable (a dotted key such as\n"
                  "gear_pair.module=5mm or an alias: module, rq, torque, ...; `geartrib case --schema`)");
}

void add_case_option(CLI::App* cmd, CaseOptions& o) {
  cmd->add_option("--case", o.file, "Case file (default: gears/m6z30.toml)");
  cmd->add_option("--set", o.changes,
                  "KEY=VALUE: change a case key for this run, repeatable (a dotted key such as\n"
                  "gear_pair.module=5mm or an alias: module, rq, torque, ...; `geartrib case --schema`)");
}

void add_table_options(CLI::App* cmd, TableOptions& o) {
  add_output_option(cmd, o.output, "the table, written atomically (default: standard output)");
  add_csv_option(cmd, o.csv,
                 "the table as CSV (header, full precision): to FILE, or without one in place\n"
                 "of the aligned table");
}

void add_output_option(CLI::App* cmd, std::string& file, const std::string& what) {
  cmd->add_option("-o,--output", file, "FILE: " + what);
}

void add_csv_option(CLI::App* cmd, CsvOption& csv, const std::string& what) {
  csv.option = cmd->add_option("--csv", csv.file, "[FILE]: " + what)->expected(0, 1);
}

void add_quiet_flag(CLI::App* cmd, bool& quiet) {
  cmd->add_flag("-q,--quiet", quiet, "No progress bar and no summary");
}

void add_threads_option(CLI::App* cmd, int& threads) {
  cmd->add_option("--threads", threads, "N: worker threads (default: all cores)")->check(CLI::Range(1, 1024));
}

void emit_table(const io::Table& t, const TableOptions& o) {
  if (o.csv.to_file()) io::write_file_atomically(o.csv.file, io::format_csv(t));
  io::output_table(t, o.csv.in_place(), o.output);
}

double quantity_option(const std::string& option, const std::string& text, io::Dimension d) {
  try {
    return io::parse_quantity(text, d);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(option + " '" + text + "': " + e.what());
  }
}

}  // namespace geartrib::app
