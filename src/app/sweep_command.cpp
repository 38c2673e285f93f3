// `geartrib sweep`: what-if studies. One mesh-cycle run per point of a factorial (or zipped) set
// of case changes, in parallel on threads, each point summarised by every mesh-cycle quantity's
// minimum, mean and maximum along A -> E and, lubricated, by the run's mesh-level values. Points
// that fail (impossible geometry, a solver that does not converge) are reported in their row and
// the sweep goes on. `--shard i/n` runs a share of the points; `--merge` joins the shards' files
// into the file the whole sweep would write.
#include "app/case_loading.hpp"
#include "app/commands.hpp"
#include "app/progress_bar.hpp"
#include "runs/sweep_points.hpp"

#include "contact/fidelity_registry.hpp"

#include "config/input_error.hpp"
#include "output/column_table.hpp"
#include "output/hdf5_results.hpp"
#include "output/table_writer.hpp"
#include "runs/sweep_merge.hpp"
#include "runs/sweep_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <iostream>
#include <thread>

#include <sched.h>
#include <sys/resource.h>

namespace geartrib::app {

namespace {

struct Options {
  std::string case_file;
  std::vector<std::string> sets;
  bool zip = false;
  std::string shard;
  int threads = 0;
  std::string output;
  CsvOption csv;
  std::vector<std::string> merge;
  bool quiet = false;
};

std::string signature(const std::string& scene, const std::string& plan) {
  return fmt::format("{:016x}", std::hash<std::string>{}(scene + '\n' + plan));
}

// The table's columns that are the plan's axes, in --set order, comma-separated (the /sweep
// attribute "axes": what a plot takes as its x, lines and panels).
std::string axis_columns(const io::SweepPlan& plan) {
  std::string s;
  for (const auto& a : plan.axes) s += (s.empty() ? "" : ",") + a.key;
  return s;
}

std::filesystem::path output_path(const Options& o) { return o.output.empty() ? "sweep.h5" : o.output; }

// The outputs' temporaries, created before any point runs: a folder that cannot be written is
// reported at once.
void reserve_outputs(const Options& o, io::OutputSet& outputs) {
  outputs.reserve(output_path(o));
  if (o.csv.to_file()) outputs.reserve(o.csv.file);
}

// The table file and the CSV, both or neither.
void write_outputs(const io::ColumnTableFile& f, const Options& o, io::OutputSet& outputs) {
  outputs.add(output_path(o), [&](const std::filesystem::path& tmp) { io::write_column_table_hdf5(tmp, f); });
  if (o.csv.to_file()) outputs.add_text(o.csv.file, io::format_csv(f.table));
  if (o.csv.in_place()) outputs.add_stdout(io::format_csv(f.table));
  outputs.commit();
}

// The process's peak resident memory so far [MB]: VmHWM of /proc/self/status (this program's
// own address space). getrusage's ru_maxrss is the fallback: on Linux it keeps the peak of the
// process before its exec, so a sweep started from a 100 MB Python reports 100 MB.
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0 / 1e6;  // "VmHWM:   123 kB"
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return std::nan("");
  return static_cast<double>(usage.ru_maxrss) * 1024.0 / 1e6;
}

// The cores this process may run on (its CPU affinity: a container's or taskset's share, not
// the machine's), at least 1.
int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// `how`: the run's wall time and threads (empty for a merge).
void print_summary(const io::ColumnTable& t, const std::string& output, const std::string& how = "") {
  const io::Column* status = t.find("status");
  const auto failed = static_cast<std::size_t>(std::count(status->texts.begin(), status->texts.end(), "error"));
  fmt::print("wrote {} ({} points, {} failed; {}peak memory {:.0f} MB)\n", output, t.rows(), failed, how,
             peak_memory_mb());
  const io::Column* message = t.find("message");
  for (std::size_t i = 0; i < t.rows(); ++i)
    if (status->texts[i] == "error")
      fmt::print("  point {}: {}\n", static_cast<long>(t.find("point")->numbers[i]), message->texts[i]);
}

void merge(const Options& o) {
  io::OutputSet outputs;
  reserve_outputs(o, outputs);
  std::vector<std::filesystem::path> shards(o.merge.begin(), o.merge.end());
  const io::ColumnTableFile out = io::merge_sweep_shards(shards);
  write_outputs(out, o, outputs);
  if (!o.quiet) print_summary(out.table, output_path(o).string());
}

void run(const Options& o) {
  if (!o.merge.empty()) {
    if (!o.sets.empty() || !o.shard.empty())
      throw std::invalid_argument("--merge takes only shard files, -o and --csv");
    merge(o);
    return;
  }
  io::SweepPlan plan;
  plan.zip = o.zip;
  for (const auto& s : o.sets) plan.axes.push_back(io::parse_sweep_axis(s));
  plan.validate();
  const io::Shard shard = o.shard.empty() ? io::Shard{} : io::parse_shard(o.shard);
  const std::filesystem::path case_file = case_path(CaseOptions{o.case_file, {}});
  // The base case must load: an error there is the user's, not a point's.
  const Case base = load_case_reporting(CaseOptions{case_file.string(), {}});
  io::OutputSet outputs;
  reserve_outputs(o, outputs);

  std::vector<std::size_t> mine;
  for (std::size_t i = 0; i < plan.size(); ++i)
    if (shard.owns(i)) mine.push_back(i);
  const int threads =
      std::max(1, std::min<int>(o.threads > 0 ? o.threads : available_cores(), static_cast<int>(mine.size())));
  if (!o.quiet)
    std::cerr << fmt::format("sweep: {} points ({}), {} in this shard {}/{}, {} thread{}\n", plan.size(),
                             plan.describe(), mine.size(), shard.index, shard.count, threads, threads == 1 ? "" : "s");
  const auto start = std::chrono::steady_clock::now();
  std::vector<runs::SweepPoint> results(mine.size());
  // Points already run on every thread: the positions of a point whose fidelity solves them on
  // threads of its own (it reads contact.threads) then take one each (unless the sweep sets it).
  const auto& keys = contact::find_fidelity(base.contact.fidelity).traits.keys;
  const bool threaded = std::find(keys.begin(), keys.end(), "contact.threads") != keys.end();
  const runs::CaseLoader load = [&](const std::vector<io::CaseChange>& changes) {
    if (threads == 1 || !threaded) return io::prepare_case(io::load_case(case_file, changes));
    std::vector<io::CaseChange> one = {{"contact.threads", "1"}};
    one.insert(one.end(), changes.begin(), changes.end());
    return io::prepare_case(io::load_case(case_file, one));
  };
  // Dynamic scheduling: each thread takes the next point when done with its last, so points of
  // unequal cost (fidelity, positions, failing early) balance over the threads.
  std::atomic<std::size_t> next{0}, done{0};
  ProgressBar bar(!o.quiet, "points");
  std::vector<std::jthread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (std::size_t k; (k = next.fetch_add(1)) < mine.size();) {
        results[k] = runs::run_sweep_point(load, plan.point(mine[k]), mine[k]);
        bar(static_cast<int>(done.fetch_add(1) + 1), static_cast<int>(mine.size()));
      }
    });
  io::start_hdf5();  // on this thread while the points run: the table's write starts warm
  pool.clear();      // joins

  io::ColumnTableFile f;
  f.table = runs::sweep_table(plan, results);
  f.scene = base.source_text;
  f.attributes = {{"version", GEARTRIB_VERSION},
                  {"case_file", case_file.string()},
                  {"sets", plan.describe()},
                  {"axes", axis_columns(plan)},
                  {"points_total", std::to_string(plan.size())},
                  {"shard", fmt::format("{}/{}", shard.index, shard.count)},
                  {"shard_count", std::to_string(shard.count)},
                  {"signature", signature(base.source_text, plan.describe())},
                  {"mean", "trapezoidal mean over the evenly spaced positions A -> E"}};
  write_outputs(f, o, outputs);
  if (!o.quiet)
    print_summary(f.table, output_path(o).string(),
                  fmt::format("{:.3g} s on {} thread{}, ",
                              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), threads,
                              threads == 1 ? "" : "s"));
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  std::string aliases;
  for (const auto& a : io::case_aliases()) {
    aliases += fmt::format("  {:<17} ", a.name);
    for (std::size_t i = 0; i < a.keys.size(); ++i) aliases += (i ? ", " : "") + std::string(a.keys[i]);
    aliases += "\n";
  }
  auto* cmd = app.add_subcommand(
      "sweep",
      "What-if sweeps: one mesh-cycle run (as `geartrib run`) per point, in parallel on threads.\n"
      "Each --set is an axis: key=v1,v2,v3 or key=lo:hi:n (n evenly spaced values, same unit at both ends).\n"
      "The points are the full factorial (first --set slowest) or, with --zip, the i-th value of each.\n"
      "Keys are the case file's dotted keys (gear_pair.module, pinion.flank.ra, contact.height_points, ...)\n"
      "or these aliases:\n" +
          aliases +
          "Setting one roughness form of a flank (ra, rq, ...) replaces the flank's other form.\n"
          "Output (HDF5 /points with units, /sweep, /scene; --csv): one row per point with the swept values,\n"
          "status and message (a point whose geometry or solve fails is reported there; the sweep goes on),\n"
          "contact ratio, plasticity index, a lubricated run's mesh-level values (mesh_power_loss_W,\n"
          "tooth_friction_efficiency, gear_loss_factor_path, bulk_temperature_K, min_iso_lambda_gf, ...; one\n"
          "column each, NaN for a dry point), and each quantity of `geartrib run` as _min, _mean, _max along\n"
          "A -> E. scripts/plot_design_sweep.py plots quantities over the axes (/sweep attribute axes).\n"
          "Larger than one machine: run `--shard i/n` (0 <= i < n; points with index % n == i) as n jobs of a\n"
          "scheduler array or MPI launcher, each with its own -o, then `geartrib sweep --merge shard*.h5 -o all.h5`.");
  cmd->add_option("case", o->case_file, "Case file (default: gears/m6z30.toml)");
  cmd->add_option("--set", o->sets,
                  "KEY=VALUE as everywhere, where VALUE may be an axis: v1,v2,... or lo:hi:n (repeatable; values are\n"
                  "checked against the case's parameter table before any point runs)");
  cmd->add_flag("--zip", o->zip, "Points are the i-th values of all axes (equal lengths) instead of the factorial");
  cmd->add_option("--shard", o->shard, "Run only points with index % n == i: i/n with 0 <= i < n");
  add_threads_option(cmd, o->threads);
  add_output_option(cmd, o->output, "the HDF5 table of points (default: sweep.h5)");
  add_csv_option(cmd, o->csv,
                 "the table of points as CSV besides the HDF5: to FILE, or without one to\n"
                 "standard output");
  cmd->add_option("--merge", o->merge, "Join shard files (all shards of one sweep) into -o instead of running")
      ->check(CLI::ExistingFile);
  add_quiet_flag(cmd, o->quiet);
  cmd->callback([o] { run(*o); });
}

}  // namespace geartrib::app
