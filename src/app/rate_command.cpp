// `geartrib rate`: the ISO ratings of a case (ISO 6336-2/-3 method B, ISO/TS 6336-20/-21/-22) on its
// mesh cycle: every factor with its symbol, value, unit and the clause it comes from, the assumed
// inputs marked, and the safety factors. --csv: the factor table as CSV with SI values.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "contact/run_summary.hpp"
#include "output/table_writer.hpp"
#include "runs/case_rating.hpp"
#include "runs/mesh_cycle.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace geartrib::app {

namespace {

struct Options {
  CaseOptions case_options;
  TableOptions table;
};

void run(const Options& o) {
  Case c = load_case_reporting(o.case_options);
  io::OutputSet outputs;
  reserve_table(o.table, outputs);
  c.rating = runs::default_rating_request(c);
  const contact::MeshContactResult r = runs::run_mesh_cycle(c);
  const rating::RatingResult& rt = *r.rating;
  const char* gear_name[] = {"pair", "pinion", "wheel"};
  std::string text = fmt::format("ISO ratings of {} ({})\n", c.title.empty() ? o.case_options.file : c.title,
                                 fmt::join(rt.methods, ", "));
  text += fmt::format("{:<14} {:<7} {:>12} {:<10} {}\n", "symbol", "gear", "value", "unit", "clause  [* assumed]");
  std::string csv = "symbol,gear,value,unit,clause,assumed,note\n";
  for (const auto& f : rt.factors) {
    const auto [v, unit] = io::engineering_value(f.symbol, f.value, f.unit);
    text += fmt::format("{:<14} {:<7} {:>12.5g} {:<10} {}{}{}\n", f.symbol, gear_name[f.gear + 1], v, unit,
                        f.assumed ? "* " : "", f.clause, f.note.empty() ? "" : " (" + f.note + ")");
    csv += fmt::format("{},{},{:.10g},{},{},{},{}\n", io::csv_field(f.symbol), gear_name[f.gear + 1], f.value,
                       io::csv_field(f.unit), io::csv_field(f.clause), f.assumed ? 1 : 0, io::csv_field(f.note));
  }
  text += "\nSafety factors\n";
  for (const auto& v : contact::rating_summary(rt).values)
    if (v.name != "findings_count" && v.name != "assumed_inputs")
      text += std::isfinite(v.value) ? fmt::format("  {:<14} {:.4g}\n", v.name, v.value)
                                     : fmt::format("  {:<14} not rated\n", v.name);
  for (const auto& f : rt.findings) text += "note: " + f + "\n";
  if (rt.assumed_any()) text += "* an input behind this value is assumed (see the note and the data file's source)\n";
  if (o.table.csv.to_file()) outputs.add_text(o.table.csv.file, csv);
  const std::string& table = o.table.csv.in_place() ? csv : text;
  if (o.table.output.empty()) outputs.add_stdout(table);
  else outputs.add_text(o.table.output, table);
  outputs.commit();
}

}  // namespace

void add_rate_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "rate",
      "ISO ratings of the case's gear pair at its operating point: pitting (ISO 6336-2 method B), tooth-root\n"
      "bending (ISO 6336-3 method B, Y_F and Y_S on the generated root fillet), scuffing by the flash and the\n"
      "integral temperature (ISO/TS 6336-20/-21) and the micropitting film lambda_GF (ISO/TS 6336-22), the\n"
      "lubricated ones from the same path as `geartrib run`. Prints every factor with its value, unit and\n"
      "clause, the assumed inputs marked, and the safety factors. The case's rating.methods, or all that\n"
      "its data allow; the keys under [rating] set K_A, K_Hbeta, the accuracy grade and the life.");
  add_case_argument(cmd, o->case_options);
  add_table_options(cmd, o->table);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
