#include "app/cli_options.hpp"

#include <fmt/format.h>

#include <charconv>
#include <iostream>
#include <stdexcept>

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

void reserve_table(const TableOptions& o, io::OutputSet& outputs) {
  if (!o.output.empty()) outputs.reserve(o.output);
  if (o.csv.to_file()) outputs.reserve(o.csv.file);
}

void emit_table(const io::Table& t, const TableOptions& o, io::OutputSet& outputs) {
  const std::string text = o.csv.in_place() ? io::format_csv(t) : io::format_text(t);
  if (o.csv.to_file()) outputs.add_text(o.csv.file, io::format_csv(t));
  if (o.output.empty()) outputs.add_stdout(text);
  else outputs.add_text(o.output, text);
  outputs.commit();
}

double quantity_option(const std::string& option, const std::string& text, io::Dimension d) {
  try {
    return io::parse_quantity(text, d);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(option + " '" + text + "': " + e.what());
  }
}

RangeOption range_option(const std::string& option, const std::string& text, io::Dimension d, int min_count,
                         int max_count) {
  const auto fail = [&](const std::string& rule) {
    throw std::invalid_argument(fmt::format("{} '{}': {} (expected MIN:MAX:COUNT)", option, text, rule));
  };
  const auto a = text.find(':'), b = text.rfind(':');
  if (a == std::string::npos || a == b) fail("needs three fields");
  RangeOption r;
  r.min = quantity_option(option, text.substr(0, a), d);
  r.max = quantity_option(option, text.substr(a + 1, b - a - 1), d);
  const std::string count = text.substr(b + 1);
  long long n = 0;
  const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
  if (ec != std::errc{} || end != count.data() + count.size() || n < min_count || n > max_count)
    fail(fmt::format("COUNT must be a whole number from {} to {}", min_count, max_count));
  r.count = static_cast<int>(n);
  return r;
}

}  // namespace geartrib::app
