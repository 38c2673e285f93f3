// `geartrib case`: a case as it would run (every declared key, its value and where it came
// from) and the parameter table itself (--schema), which docs/reference/case-file.md is.
#include "app/case_loading.hpp"
#include "app/commands.hpp"

#include "config/case_parameters.hpp"
#include "config/case_records.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>

namespace geartrib::app {

namespace {

struct Options {
  CaseOptions case_options;
  bool schema = false;
  bool markdown = false;
  std::string output;
};

// The listing or the schema to -o FILE (reserved first) or standard output.
void write(const std::string& text, const std::string& output, io::OutputSet& outputs) {
  if (output.empty()) outputs.add_stdout(text);
  else outputs.add_text(output, text);
  outputs.commit();
}

void run(const Options& o) {
  io::OutputSet outputs;
  if (!o.output.empty()) outputs.reserve(o.output);
  if (o.schema) return write(o.markdown ? io::case_schema_markdown() : io::case_schema_csv(), o.output, outputs);
  // Only the geometry is required here: the listing says what the other parts would need.
  const Case c = load_case_reporting(o.case_options, io::kGeometryPart);
  std::size_t width = 0;
  const std::vector<ResolvedParameter> parameters = io::current_parameters(c);
  for (const auto& p : parameters) width = std::max(width, p.key.size());
  std::string text = fmt::format("# {}\n", c.title);
  for (const auto& p : parameters) text += fmt::format("{:<{}}  {:<24}  {}\n", p.key, width, p.value, p.origin.text());
  for (const io::Parameter& p : io::case_parameters()) {
    if (p.required_by == 0 || (p.required_by & io::kGeometryPart)) continue;
    const std::string key = p.key_for(0);
    if (std::none_of(c.parameters.begin(), c.parameters.end(),
                     [&](const ResolvedParameter& r) { return r.key == key; }))
      text += fmt::format("{:<{}}  {:<24}  {}\n", key, width, "(not given)", "needed by the commands that use it");
  }
  write(text, o.output, outputs);
}

}  // namespace

void add_case_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "case",
      "A case as it would run: every key of the parameter table with its value (SI) and where it came from\n"
      "(file:line, --set, or default), after the --set changes. With --schema: the table itself, one row per\n"
      "key with its kind, SI unit, default, range or choices, the parts that require it, its aliases and\n"
      "meaning (CSV, or --markdown: docs/reference/case-file.md is this output).");
  add_case_argument(cmd, o->case_options);
  cmd->add_flag("--schema", o->schema, "Print the parameter table instead of a case");
  cmd->add_flag("--markdown", o->markdown, "The schema as a Markdown table")->needs("--schema");
  add_output_option(cmd, o->output, "the listing or the schema, written atomically (default: standard output)");
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
