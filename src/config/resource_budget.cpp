#include "config/resource_budget.hpp"

#include "config/input_error.hpp"
#include "config/text_lines.hpp"
#include "config/units.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <utility>

namespace geartrib::io {

namespace {

using Unit = std::pair<std::string_view, double>;
constexpr double kKi = 1024.0;
constexpr std::array<Unit, 9> kByteUnits{{{"B", 1.0},
                                          {"kB", 1e3},
                                          {"MB", 1e6},
                                          {"GB", 1e9},
                                          {"TB", 1e12},
                                          {"KiB", kKi},
                                          {"MiB", kKi* kKi},
                                          {"GiB", kKi* kKi* kKi},
                                          {"TiB", kKi* kKi* kKi* kKi}}};
constexpr std::array<Unit, 4> kTimeUnits{{{"s", 1.0}, {"min", 60.0}, {"h", 3600.0}, {"d", 86400.0}}};

// "<number> <unit>" (space optional) in [lo, hi] after the unit's factor.
template <std::size_t N>
double parse(const std::string& text, const char* variable, const std::array<Unit, N>& units, double lo, double hi,
             const std::string& range) {
  std::string names;
  for (const auto& [name, factor] : units) names += (names.empty() ? "" : ", ") + std::string(name);
  const std::string t = trim(text);
  const NumberAndUnit n = split_number(t);  // the case files' number grammar
  auto refuse = [&](const std::string& rule) { throw InputError("environment", 0, variable, text, rule); };
  if (n.status != NumberAndUnit::ok) refuse(fmt::format("expected a number and a unit ({})", names));
  const std::string_view unit = n.unit;
  for (const auto& [name, factor] : units) {
    if (unit != name) continue;
    const double value = n.value * factor;
    if (!(std::isfinite(value) && value >= lo && value <= hi)) refuse("must lie in " + range);
    return value;
  }
  refuse(unit.empty() ? fmt::format("give a unit ({})", names)
                      : fmt::format("unknown unit '{}' (known: {})", unit, names));
  return 0.0;  // not reached
}

}  // namespace

double parse_budget_bytes(const std::string& text) {
  return parse(text, kMemoryBudgetVariable, kByteUnits, kKi * kKi, std::pow(kKi, 6), "[1 MiB, 1 EiB]");
}

double parse_budget_seconds(const std::string& text) {
  return parse(text, kTimeBudgetVariable, kTimeUnits, 1.0, 365.0 * 86400.0, "[1 s, 365 d]");
}

ResourceBudget resource_budget() {
  ResourceBudget b;
  if (const char* m = std::getenv(kMemoryBudgetVariable); m && *m) b.bytes = parse_budget_bytes(m);
  if (const char* t = std::getenv(kTimeBudgetVariable); t && *t) b.seconds = parse_budget_seconds(t);
  return b;
}

std::string format_bytes(double bytes) {
  if (bytes >= kKi * kKi * kKi * kKi) return fmt::format("{:.3g} TiB", bytes / (kKi * kKi * kKi * kKi));
  if (bytes >= kKi * kKi * kKi) return fmt::format("{:.3g} GiB", bytes / (kKi * kKi * kKi));
  if (bytes >= kKi * kKi) return fmt::format("{:.3g} MiB", bytes / (kKi * kKi));
  return fmt::format("{:.3g} KiB", bytes / kKi);
}

std::string format_duration(double seconds) {
  if (seconds >= 2.0 * 86400.0) return fmt::format("{:.3g} d", seconds / 86400.0);
  if (seconds >= 3600.0) return fmt::format("{:.3g} h", seconds / 3600.0);
  if (seconds >= 120.0) return fmt::format("{:.3g} min", seconds / 60.0);
  if (seconds >= 1.0) return fmt::format("{:.3g} s", seconds);
  return fmt::format("{:.3g} ms", seconds * 1e3);
}

}  // namespace geartrib::io
