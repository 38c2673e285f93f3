// The command line's one grammar: options that several commands take are added here, so that a
// flag means the same thing everywhere (tests/cli_grammar.sh walks every command's --help):
//   -o, --output FILE   the command's result to FILE instead of standard output
//   --csv [FILE]        the table as CSV: to FILE, else where the table goes (-o or stdout)
//   --set KEY=VALUE     a case key changed for this run (repeatable)
//   -q, --quiet         no progress bar and no summary
//   --threads N         worker threads
#pragma once

#include "config/units.hpp"
#include "output/table_writer.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace geartrib::app {

// The case a command reads: the positional CASE (default gears/m6z30.toml) or, for commands whose
// positionals are other files, --case; and its --set changes.
struct CaseOptions {
  std::string file;
  std::vector<std::string> changes;
};
void add_case_argument(CLI::App* cmd, CaseOptions& o);  // positional CASE and --set
void add_case_option(CLI::App* cmd, CaseOptions& o);    // --case FILE and --set

// --csv [FILE]: whether it was given, and where the CSV goes.
struct CsvOption {
  std::string file;                     // --csv FILE; empty or "-": CSV where the table goes
  const CLI::Option* option = nullptr;  // set by add_csv_option
  bool given() const { return option && option->count() > 0; }
  bool to_file() const { return !file.empty() && file != "-"; }  // a CSV file besides the table
  bool in_place() const { return given() && !to_file(); }        // CSV instead of the aligned table
};

// Where a command's table goes: -o FILE (or stdout), and --csv [FILE].
struct TableOptions {
  std::string output;
  CsvOption csv;
};
void add_table_options(CLI::App* cmd, TableOptions& o);
// -o FILE for a command whose result is a file of its own (HDF5, a surface); `what` says which
// (the help reads "FILE: <what>").
void add_output_option(CLI::App* cmd, std::string& file, const std::string& what);
// --csv [FILE] for commands whose table is beside another result (run, sweep): "[FILE]: <what>".
void add_csv_option(CLI::App* cmd, CsvOption& csv, const std::string& what);
void add_quiet_flag(CLI::App* cmd, bool& quiet);
void add_threads_option(CLI::App* cmd, int& threads);

// The table's files (-o FILE, --csv FILE) reserved before any work: a target that cannot be
// written is refused (exit 2) before anything is computed.
void reserve_table(const TableOptions& o, io::OutputSet& outputs);
// Writes the table as the options ask, all or none through `outputs` (committed here): aligned
// text to -o or stdout, CSV instead when --csv is given without a file, and CSV to the file --csv
// names besides.
void emit_table(const io::Table& t, const TableOptions& o, io::OutputSet& outputs);

// A command-line quantity with a unit ("0.5 um", "1000 rpm"), SI; the error names the option.
double quantity_option(const std::string& option, const std::string& text, io::Dimension d);

// MIN:MAX:COUNT of a sweep option: MIN and MAX as quantities of dimension `d` (SI), COUNT a whole
// number from `min_count` to `max_count` read without wrapping. The errors name the option and
// its text.
struct RangeOption {
  double min = 0.0, max = 0.0;
  int count = 0;
};
RangeOption range_option(const std::string& option, const std::string& text, io::Dimension d, int min_count,
                         int max_count);

}  // namespace geartrib::app
