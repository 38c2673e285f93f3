// `geartrib fit`: a registered asperity model's named constants fitted to reference data with
// Ceres; report, TOML fragment for case files, optionally the C++ defaults header.
#include "app/case_loading.hpp"
#include "app/commands.hpp"

#include "case/asperity_setup.hpp"
#include "config/input_error.hpp"
#include "config/resource_budget.hpp"
#include "core/keyed_error.hpp"
#include "fit/fit_files.hpp"
#include "fit/model_fit.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string_view>
#include <utility>

namespace geartrib::app {

namespace {

struct Options {
  std::string list;
  std::string model;
  std::vector<std::string> data;
  std::vector<std::string> free;
  std::vector<std::string> observe;
  std::vector<double> weights;
  std::vector<std::string> bounds;
  std::string loss = "squared";
  double loss_scale = 0.1;
  CaseOptions case_options;
  std::string output;
  std::string report;
  std::string emit_cpp;
  bool quiet = false;
};

void list_constants(const std::string& name) {
  const auto m = asperity::make_asperity_model(name);
  fmt::print("{}: {}\n", m->name(), m->citation());
  const auto specs = m->constant_specs();
  if (specs.empty()) fmt::print("  (no adjustable constants)\n");
  for (std::size_t i = 0; i < specs.size(); ++i)
    fmt::print("  {:<22} default {:<10.6g} range [{:g}, {:g}]  {}\n", specs[i].name, m->constants()[i], specs[i].lower,
               specs[i].upper, specs[i].meaning);
}

// The fit's options from the command's, checked (FitOptions::validate): a refusal names the
// command-line option that set the field.
fit::FitOptions fit_options(const Options& o) {
  fit::FitOptions opt;
  opt.free = o.free;
  for (const auto& name : o.observe) opt.observe.push_back(fit::parse_observable(name));
  opt.observe_weight = o.weights;
  for (const auto& b : o.bounds) {
    const auto eq = b.find('='), colon = b.find(':', eq == std::string::npos ? 0 : eq);
    if (eq == std::string::npos || colon == std::string::npos)
      throw std::invalid_argument("--bound '" + b + "': expected NAME=LOWER:UPPER");
    try {
      opt.bounds.emplace_back(b.substr(0, eq), std::stod(b.substr(eq + 1, colon - eq - 1)),
                              std::stod(b.substr(colon + 1)));
    } catch (const std::logic_error&) {
      throw std::invalid_argument("--bound '" + b + "': LOWER and UPPER must be numbers");
    }
  }
  opt.loss = fit::parse_loss(o.loss);
  opt.loss_scale = o.loss_scale;
  try {
    opt.validate();
  } catch (const core::KeyedError& e) {
    const std::pair<std::string_view, std::string_view> options[] = {
        {"observe_weight", "--weight"}, {"loss_scale", "--loss-scale"}, {"bounds", "--bound"}};
    for (const auto& [field, option] : options)
      if (e.key() == field) throw std::invalid_argument(std::string(option) + (e.what() + field.size()));
    throw;
  }
  return opt;
}

void run(const Options& o) {
  if (!o.list.empty()) return list_constants(o.list);
  if (o.model.empty() || o.data.empty())
    throw std::invalid_argument("fit needs --model NAME and at least one --data FILE (or --list MODEL)");
  const Case c = load_case_reporting(o.case_options, io::kGeometryPart | io::kRoughnessPart);
  io::OutputSet outputs;  // --report, -o and --emit-cpp: all or none, checked before the fit
  for (const std::string* file : {&o.report, &o.output, &o.emit_cpp})
    if (!file->empty()) outputs.reserve(*file);
  const auto model = asperity::make_case_model(c, o.model);
  const fit::FitOptions opt = fit_options(o);
  // Each file is bounded (io::kMaxTableFileBytes), their number is not: the data's memory against the
  // budget, file by file, before the next is read.
  const io::ResourceBudget budget = io::resource_budget();
  std::vector<fit::FitData> data;
  for (const auto& f : o.data) {
    data.push_back(io::read_fit_data(f));
    const double bytes = fit::fit_memory_bytes(data, opt.observe);
    if (bytes > budget.bytes)
      throw io::InputError(
          f, 0, "--data", "",
          fmt::format("with this file the fit would hold about {} ({} data files so far; {:g} bytes a row and {:g} an "
                      "observation, measured), more than the memory budget of {} ({}): fit fewer or shorter data "
                      "files, or fewer columns (--observe), or raise the budget",
                      io::format_bytes(bytes), data.size(), fit::kFitBytesPerRow, fit::kFitBytesPerObservation,
                      io::format_bytes(budget.bytes), io::kMemoryBudgetVariable));
  }
  const fit::FitResult r = fit::fit_model(*model, asperity::contact_pair(c), data, opt);

  std::string provenance = fmt::format("model {}, data", r.model);
  for (const auto& f : o.data) provenance += " " + f;
  if (!o.free.empty()) {
    provenance += ", free";
    for (const auto& f : o.free) provenance += " " + f;
  }
  const std::string report = io::format_fit_report(r);
  if (!o.report.empty()) outputs.add_text(o.report, report);
  if (!o.output.empty()) outputs.add_text(o.output, io::format_fit_toml(r, provenance));
  if (!o.emit_cpp.empty()) outputs.add_text(o.emit_cpp, io::format_fit_cpp(r, provenance));
  outputs.commit();
  if (!o.quiet) std::cout << (o.report.empty() ? report : report.substr(0, report.find("\nResiduals")) + "\n");
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "fit",
      "Fit a registered asperity model's named constants to reference data (validation/fem-reference/*.csv)\n"
      "with Ceres: automatic differentiation through the model's own law, bounds from each constant's range,\n"
      "relative residuals (or residuals over sd_<quantity> columns), optional robust loss. Prints each\n"
      "constant with its standard error, the correlation matrix, the rms relative error per observed column\n"
      "and the residuals; -o writes a TOML fragment a case file can include ([asperity.constants.<model>]).");
  cmd->add_option("--list", o->list, "Print a model's named constants (default, range, meaning) and exit");
  std::string models;
  for (auto n : asperity::asperity_model_names()) models += (models.empty() ? "" : ", ") + std::string(n);
  cmd->add_option("--model", o->model, "Model to fit (" + models + ")");
  cmd->add_option("--data", o->data, "Reference data CSV (repeat for several data sets)");
  cmd->add_option("--free", o->free, "Comma-separated constants to fit (default: all); the rest stay at their values")
      ->delimiter(',');
  cmd->add_option("--observe", o->observe, "Comma-separated observed columns (default: all in the data)")
      ->delimiter(',');
  cmd->add_option("--weight", o->weights, "Comma-separated relative weights, one per --observe column")->delimiter(',');
  cmd->add_option("--bound", o->bounds, "NAME=LOWER:UPPER, narrower bounds than the constant's range (repeatable)");
  cmd->add_option("--loss", o->loss, "squared, huber or cauchy")->check(CLI::IsMember({"squared", "huber", "cauchy"}));
  cmd->add_option("--loss-scale", o->loss_scale, "Residual scale of the robust losses (default 0.1, a relative 10%)")
      ->check(CLI::PositiveNumber);
  add_case_option(cmd, o->case_options);
  add_output_option(cmd, o->output, "the fitted constants as a TOML fragment (the case's overrides are the start)");
  cmd->add_option("--report", o->report, "Write the full report (with every residual and Ceres' report) to this file");
  cmd->add_option("--emit-cpp", o->emit_cpp,
                  "Write the constants as a C++ defaults header (see src/asperity/continuous_defaults.hpp)");
  add_quiet_flag(cmd, o->quiet);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
