// The memory and time budget a job is checked against before it starts (config/resource_budget.hpp):
// its two environment variables, their units and ranges, and every refusal naming the variable.
#include "config/input_error.hpp"
#include "config/resource_budget.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace geartrib;

namespace {
// Sets an environment variable for one scope, restoring what was there.
struct ScopedVariable {
  std::string name, saved;
  bool had = false;
  ScopedVariable(const char* n, const char* value) : name(n) {
    if (const char* v = std::getenv(n)) had = true, saved = v;
    if (value) ::setenv(n, value, 1);
    else ::unsetenv(n);
  }
  ~ScopedVariable() {
    if (had) ::setenv(name.c_str(), saved.c_str(), 1);
    else ::unsetenv(name.c_str());
  }
};
// The message of the InputError `f` throws (empty when it throws none).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ResourceBudget, DefaultsWhenUnsetOrEmpty) {
  const ScopedVariable m(io::kMemoryBudgetVariable, nullptr), t(io::kTimeBudgetVariable, "");
  const io::ResourceBudget b = io::resource_budget();
  EXPECT_EQ(b.bytes, 4.0 * 1024 * 1024 * 1024);
  EXPECT_EQ(b.seconds, 3600.0);
}

TEST(ResourceBudget, SizesAndDurationsWithTheirUnits) {
  EXPECT_EQ(io::parse_budget_bytes("16 GiB"), 16.0 * 1024 * 1024 * 1024);
  EXPECT_EQ(io::parse_budget_bytes("8e9B"), 8e9);
  EXPECT_EQ(io::parse_budget_bytes(" 500 MB "), 5e8);
  EXPECT_EQ(io::parse_budget_bytes("1 MiB"), 1024.0 * 1024);  // the least
  EXPECT_EQ(io::parse_budget_seconds("24 h"), 86400.0);
  EXPECT_EQ(io::parse_budget_seconds("90min"), 5400.0);
  EXPECT_EQ(io::parse_budget_seconds("365 d"), 365.0 * 86400.0);  // the most
  const ScopedVariable m(io::kMemoryBudgetVariable, "32 GiB"), t(io::kTimeBudgetVariable, "2 d");
  const io::ResourceBudget b = io::resource_budget();
  EXPECT_EQ(b.bytes, 32.0 * 1024 * 1024 * 1024);
  EXPECT_EQ(b.seconds, 2.0 * 86400.0);
}

TEST(ResourceBudget, MalformedValuesNameTheVariableAndTheRule) {
  EXPECT_EQ(refusal([] { io::parse_budget_bytes("4 XB"); }),
            "environment: key 'GEARTRIB_MEMORY_BUDGET' = 4 XB: unknown unit 'XB' (known: B, kB, MB, GB, TB, KiB, MiB, "
            "GiB, TiB)");
  EXPECT_EQ(refusal([] { io::parse_budget_bytes("4096"); }),
            "environment: key 'GEARTRIB_MEMORY_BUDGET' = 4096: give a unit (B, kB, MB, GB, TB, KiB, MiB, GiB, TiB)");
  EXPECT_EQ(refusal([] { io::parse_budget_bytes("lots"); }),
            "environment: key 'GEARTRIB_MEMORY_BUDGET' = lots: expected a number and a unit (B, kB, MB, GB, TB, KiB, "
            "MiB, GiB, TiB)");
  for (const char* outside : {"-1 GiB", "0 B", "1023 KiB", "1e7 TiB", "1e300 TB", "nan GiB", "inf B"})
    EXPECT_NE(refusal([&] { io::parse_budget_bytes(outside); }).find("must lie in [1 MiB, 1 EiB]"), std::string::npos)
        << outside;
  EXPECT_EQ(refusal([] { io::parse_budget_seconds("1 week"); }),
            "environment: key 'GEARTRIB_TIME_BUDGET' = 1 week: unknown unit 'week' (known: s, min, h, d)");
  for (const char* outside : {"0.5 s", "366 d", "-1 h"})
    EXPECT_NE(refusal([&] { io::parse_budget_seconds(outside); }).find("must lie in [1 s, 365 d]"), std::string::npos)
        << outside;
  const ScopedVariable t(io::kTimeBudgetVariable, "soon");
  EXPECT_NE(refusal([] { io::resource_budget(); }).find("GEARTRIB_TIME_BUDGET' = soon"), std::string::npos);
}

TEST(ResourceBudget, MessagesInBinaryUnitsAndReadableDurations) {
  EXPECT_EQ(io::format_bytes(26.3e9), "24.5 GiB");
  EXPECT_EQ(io::format_bytes(4.0 * 1024 * 1024 * 1024), "4 GiB");
  EXPECT_EQ(io::format_bytes(600e3), "586 KiB");
  EXPECT_EQ(io::format_duration(50000.0), "13.9 h");
  EXPECT_EQ(io::format_duration(600.0), "10 min");
  EXPECT_EQ(io::format_duration(42.0), "42 s");
  EXPECT_EQ(io::format_duration(3.0 * 86400.0), "3 d");
  EXPECT_EQ(io::format_duration(3600.0), "1 h");
  EXPECT_EQ(io::format_duration(5.9e-3), "5.9 ms");
}
