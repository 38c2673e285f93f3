// The points of a what-if sweep and their table: what `geartrib sweep` runs on threads and the
// Python module's geartrib.sweep runs on a Dask cluster, so that both give the same table.
#pragma once

#include "case/case.hpp"
#include "config/case_file.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/run_summary.hpp"
#include "output/column_table.hpp"
#include "runs/sweep_plan.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace geartrib::runs {

// One quantity of one point: its extremes and its (trapezoidal) mean along the path A -> E.
struct QuantitySummary {
  std::string name, unit;
  double min = 0.0, mean = 0.0, max = 0.0;
};

// One point's run: its status and message, the run's verdict, its mesh-level values and every
// quantity's summary.
struct SweepPoint {
  std::size_t index = 0;
  bool ok = false;
  std::string message;  // the error, or the loader's and the run's warnings
  double seconds = 0.0;
  double contact_ratio = 0.0;
  double plasticity_index = 0.0;
  std::string regime;                              // the run's validity verdict, in one word
  std::string verdict;                             // and in full
  std::vector<contact::SummaryValue> flag_counts;  // positions_<flag>: the validity summary's values
  std::vector<contact::SummaryValue> summary;      // a lubricated run's mesh-level values; dry: none
  std::vector<QuantitySummary> quantities;
};

// Loads the base case with a point's changes (from its file, or from text in memory).
using CaseLoader = std::function<Case(const std::vector<io::CaseChange>&)>;

// Runs point `index` with its changes; never throws: a failure is the point's status and message.
SweepPoint run_sweep_point(const CaseLoader& load, const std::vector<io::CaseChange>& changes, std::size_t index);

// The table: point index, the swept values (numeric with their SI unit when every value of the
// axis is a quantity of one unit, else text), status, message, seconds, contact ratio, plasticity
// index, regime and verdict, positions per validity flag, the lubricated runs' mesh-level values
// (one column each, named as contact::validity_summary and lubrication_summary name them), then each quantity's _min,
// _mean, _max. A point without a flag, value or quantity that others have (a failed or dry one) has NaN there.
io::ColumnTable sweep_table(const io::SweepPlan& plan, const std::vector<SweepPoint>& points);

}  // namespace geartrib::runs
