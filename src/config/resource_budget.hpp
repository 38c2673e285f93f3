// The memory and time one job may be estimated to take before it starts. A job whose size alone
// says it would need more (a deterministic run's flanks, pressure profiles and solves; a fit's data)
// is refused before it computes, with its estimate and the key to change
// (docs/reference/performance.md#budgets). The budget comes from the environment, so that the
// command line, the Python module and Dask workers share it:
//   GEARTRIB_MEMORY_BUDGET  default 4 GiB: a number and B, kB, MB, GB, TB, KiB, MiB, GiB or TiB;
//   GEARTRIB_TIME_BUDGET    default 1 h: a number and s, min, h or d.
#pragma once

#include <string>

namespace geartrib::io {

inline constexpr const char* kMemoryBudgetVariable = "GEARTRIB_MEMORY_BUDGET";
inline constexpr const char* kTimeBudgetVariable = "GEARTRIB_TIME_BUDGET";

struct ResourceBudget {
  double bytes = 4.0 * 1024.0 * 1024.0 * 1024.0;  // 4 GiB
  double seconds = 3600.0;                        // 1 h
};

// The budget from the environment (a variable unset or empty: its default). A value that is not a
// size (1 MiB to 1 EiB) or a duration (1 s to 1 year) is an InputError naming the variable.
ResourceBudget resource_budget();
double parse_budget_bytes(const std::string& text);    // throws InputError naming GEARTRIB_MEMORY_BUDGET
double parse_budget_seconds(const std::string& text);  // throws InputError naming GEARTRIB_TIME_BUDGET

// For the messages: "24.5 GiB", "512 MiB"; "14 h", "25 min", "40 s", "5.9 ms".
std::string format_bytes(double bytes);
std::string format_duration(double seconds);

}  // namespace geartrib::io
