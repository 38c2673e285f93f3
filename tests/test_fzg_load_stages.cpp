// The FZG load stages: the compiled table against its data file (gears/fzg/load-stages.csv), the
// two lever arms against each other, the torques a case resolves from a stage, and the refusals.
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/fzg_load_stages.hpp"
#include "config/input_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace geartrib;

namespace {

// One data row of the CSV as written: the torques' text keeps its printed precision.
struct CsvRow {
  int stage = 0;
  std::string long_arm, long_status, short_arm, short_status, source;
};

std::vector<std::string> split(const std::string& line, char sep, std::size_t fields) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (out.size() + 1 < fields) {
    const auto end = line.find(sep, start);
    if (end == std::string::npos) break;
    out.push_back(line.substr(start, end - start));
    start = end + 1;
  }
  out.push_back(line.substr(start));
  return out;
}

const std::vector<CsvRow>& csv_rows() {
  static const std::vector<CsvRow> rows = [] {
    std::ifstream in(test::source_dir() / "gears/fzg/load-stages.csv");
    EXPECT_TRUE(in) << "gears/fzg/load-stages.csv";
    std::vector<CsvRow> out;
    std::string line;
    bool header = false;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      if (!header) {  // the columns and their units, as the README and the generator read them
        EXPECT_EQ(line,
                  "load_stage,pinion_torque_arm_0.5m[N m],status_arm_0.5m,pinion_torque_arm_0.35m[N m],"
                  "status_arm_0.35m,source");
        header = true;
        continue;
      }
      const auto f = split(line, ',', 6);
      EXPECT_EQ(f.size(), 6u) << line;
      if (f.size() != 6) continue;
      out.push_back({std::stoi(f[0]), f[1], f[2], f[3], f[4], f[5]});
    }
    return out;
  }();
  return rows;
}

double number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  EXPECT_EQ(*end, '\0') << text;
  return v;
}

// Half a unit of the last printed digit: "265" +-0.5, "372.6" +-0.05, "215.513" +-0.0005.
double half_last_digit(const std::string& text) {
  const auto dot = text.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1);
  return 0.5 * std::pow(10.0, -decimals);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const ResolvedParameter* recorded(const Case& c, const std::string& key) {
  for (const auto& p : c.parameters)
    if (p.key == key) return &p;
  return nullptr;
}

}  // namespace

// The table geartrib runs on is the data file's, row for row and digit for digit (the build copies
// the numbers' text into the code, so the doubles are equal, not close).
TEST(FzgLoadStages, CompiledTableEqualsTheDataFile) {
  const auto& rows = csv_rows();
  const auto& table = io::fzg_load_stages();
  ASSERT_EQ(rows.size(), table.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE("load stage " + std::to_string(rows[i].stage));
    EXPECT_EQ(rows[i].stage, static_cast<int>(i) + 1);
    EXPECT_EQ(table[i].stage, rows[i].stage);
    EXPECT_EQ(table[i].torque_long_arm, number(rows[i].long_arm));
    EXPECT_EQ(table[i].torque_short_arm, number(rows[i].short_arm));
    for (const std::string* status : {&rows[i].long_status, &rows[i].short_status})
      EXPECT_TRUE(*status == "sourced" || *status == "unconfirmed") << *status;
    EXPECT_EQ(table[i].long_arm_sourced, rows[i].long_status == "sourced");
    EXPECT_EQ(table[i].short_arm_sourced, rows[i].short_status == "sourced");
    EXPECT_FALSE(rows[i].source.empty());
  }
}

// The same weights hang at 0.5 m or 0.35 m; stages 1 and 2 (no weight yet) are the same on both
// arms. So above stage 2 the torques the weights add stand in the arms' ratio:
//   T_0.35 - T_2 = (0.35/0.5) (T_0.5 - T_2),
// to the rounding of the printed values (half a unit of each one's last digit, carried through
// the relation: 1 x T_0.35's, 0.7 x T_0.5's, 0.3 x T_2's). Every row marked sourced keeps it and
// every row marked unconfirmed breaks it: the status says exactly which rows the identity rejects.
TEST(FzgLoadStages, ArmsStandInTheirRatio) {
  const auto& rows = csv_rows();
  ASSERT_EQ(rows.size(), 14u);
  for (int s : {0, 1}) EXPECT_EQ(number(rows[s].long_arm), number(rows[s].short_arm)) << "stage " << s + 1;
  const double t2 = number(rows[1].long_arm), ratio = 0.35 / 0.5;
  int unconfirmed = 0;
  for (std::size_t i = 2; i < rows.size(); ++i) {
    const CsvRow& r = rows[i];
    SCOPED_TRACE("load stage " + std::to_string(r.stage));
    EXPECT_EQ(r.long_status, "sourced");
    const double predicted = t2 + ratio * (number(r.long_arm) - t2);
    const double tolerance =
        half_last_digit(r.short_arm) + ratio * half_last_digit(r.long_arm) + (1.0 - ratio) * half_last_digit("13.7");
    const double off = std::abs(number(r.short_arm) - predicted);
    if (r.short_status == "sourced") {
      EXPECT_LE(off, tolerance) << r.short_arm << " against " << predicted;
    } else {
      EXPECT_GT(off, tolerance) << r.short_arm << " is marked unconfirmed but keeps the ratio";
      ++unconfirmed;
    }
  }
  // The research found stages 13 and 14 of the short arm 4.1 N m below the ratio, all others on it.
  EXPECT_EQ(unconfirmed, 2);
  EXPECT_EQ(rows[12].short_status, "unconfirmed");
  EXPECT_EQ(rows[13].short_status, "unconfirmed");
}

// The figures of issue 29: stage 10 is 372.6 N m on the 0.5 m arm (scuffing and pitting tests) and
// 265.0 N m on the 0.35 m arm of the micropitting test, whose stage 8 is 171.6 N m; 302 N m is stage 9.
TEST(FzgLoadStages, TestsTakeTheirArmsTorque) {
  EXPECT_EQ(io::fzg_pinion_torque("A/8.3/90", 10).torque, 372.6);
  EXPECT_EQ(io::fzg_pinion_torque("PT-C", 10).torque, 372.6);
  EXPECT_EQ(io::fzg_pinion_torque("PT-C", 9).torque, 302.0);
  EXPECT_EQ(io::fzg_pinion_torque("GF-C/8.3/90", 10).torque, 265.0);
  EXPECT_NEAR(io::fzg_pinion_torque("GF-C/8.3/90", 8).torque, 171.6, 0.05);  // 171.585, printed 171.6
  EXPECT_EQ(io::fzg_pinion_torque("GF-C/8.3/90", 10).origin,
            "FZG load stage 10 of GF-C/8.3/90, 0.35 m arm (gears/fzg/load-stages.csv)");
  for (const io::FzgTest& t : io::fzg_tests()) EXPECT_TRUE(t.lever_arm == 0.5 || t.lever_arm == 0.35) << t.name;
}

TEST(FzgLoadStages, RefusesWhatTheTableDoesNotHold) {
  auto rule = [](std::string_view test, int stage) {
    try {
      io::fzg_pinion_torque(test, stage);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(rule("A/8.3/90", 0), "FZG load stage 0 must lie in [1, 14]");
  EXPECT_EQ(rule("A/8.3/90", 15), "FZG load stage 15 must lie in [1, 14]");
  EXPECT_NE(rule("A/16.6/140", 5).find("unknown FZG test 'A/16.6/140'"), std::string::npos);
  EXPECT_NE(rule("GF-C/8.3/90", 13).find("0.35 m arm's torque at load stage 13 (438.8533 N m) is unconfirmed"),
            std::string::npos);
  EXPECT_EQ(rule("A/8.3/90", 14), "accepted");  // 714.2 N m, sourced on the long arm
}

// A case naming a stage runs the table's torque, recorded where the torque's row stands with the
// table as its origin; a --set torque replaces the stage, a --set stage the torque.
TEST(FzgLoadStages, CaseResolvesTheStagesTorque) {
  const auto file = test::source_dir() / "gears/fzg-c.toml";
  const Case c = io::prepare_case(io::load_case(file));
  EXPECT_EQ(c.operating.pinion_torque, 265.0);
  ASSERT_NE(recorded(c, "operating.pinion_torque"), nullptr);
  EXPECT_EQ(recorded(c, "operating.pinion_torque")->value, "265 N m");
  EXPECT_EQ(recorded(c, "operating.pinion_torque")->origin.text(),
            "FZG load stage 10 of GF-C/8.3/90, 0.35 m arm (gears/fzg/load-stages.csv)");
  for (std::size_t i = 0; i + 1 < c.parameters.size(); ++i) {  // the torque's place in the table's order
    if (c.parameters[i].key == "operating.pinion_torque") {
      EXPECT_EQ(c.parameters[i + 1].key, "operating.fzg_load_stage");
    }
  }
  EXPECT_EQ(io::prepare_case(io::load_case(file, {{"fzg_load_stage", "8"}})).operating.pinion_torque, 171.585);
  EXPECT_EQ(io::prepare_case(io::load_case(file, {{"fzg_test", "PT-C"}})).operating.pinion_torque, 372.6);
  const Case given = io::prepare_case(io::load_case(file, {{"torque", "300Nm"}}));
  EXPECT_EQ(given.operating.pinion_torque, 300.0);
  EXPECT_EQ(recorded(given, "operating.fzg_load_stage"), nullptr);
  EXPECT_EQ(recorded(given, "operating.pinion_torque")->origin.text(), "--set");
  EXPECT_EQ(io::prepare_case(io::load_case(test::source_dir() / "gears/fzg-a.toml")).operating.pinion_torque, 534.5);
  // The relabelled validation case runs the torque it always ran.
  EXPECT_EQ(io::prepare_case(io::load_case(test::source_dir() / "validation/fzg-c-lubricated/fzg-c-lubricated.toml"))
                .operating.pinion_torque,
            372.6);
  EXPECT_EQ(
      io::prepare_case(io::load_case(test::source_dir() / "validation/fzg-type-c/fzg-c.toml")).operating.pinion_torque,
      302.0);
}

// Each refusal names the file, line, key, value and rule.
TEST(FzgLoadStages, CaseRefusals) {
  const auto file = test::source_dir() / "gears/fzg-c.toml";
  const std::string text = read(file);
  auto error = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto pos = t.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) t.replace(pos, from.size(), to);
    try {
      io::prepare_case(io::load_case_text(t, file, {}, io::kMeshCycleParts));  // what a run asks of a case
    } catch (const io::InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for " << to;
    return io::InputError("", 0, "", "", "");
  };
  auto line_of = [&](const std::string& what) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(text.find(what)), '\n'));
  };
  const int stage_line = line_of("fzg_load_stage = 10");
  {
    const auto e = error("fzg_load_stage = 10", "fzg_load_stage = 15");
    EXPECT_EQ(e.file(), file.string());
    EXPECT_EQ(e.line(), stage_line);
    EXPECT_EQ(e.key(), "operating.fzg_load_stage");
    EXPECT_EQ(e.value(), "15");
    EXPECT_EQ(e.rule(), "must lie in [1, 14]");
  }
  {
    const auto e = error("fzg_load_stage = 10", "fzg_load_stage = 13");
    EXPECT_EQ(e.key(), "operating.fzg_load_stage");
    EXPECT_NE(e.rule().find("is unconfirmed in gears/fzg/load-stages.csv"), std::string::npos) << e.rule();
  }
  {
    const auto e = error("fzg_load_stage = 10", "fzg_load_stage = 10\npinion_torque = \"265 N m\"");
    EXPECT_EQ(e.key(), "operating.pinion_torque");
    EXPECT_EQ(e.line(), stage_line + 1);
    EXPECT_EQ(e.rule(), "give the torque or the FZG load stage, not both (operating.fzg_load_stage = 10 at " +
                            file.string() + ":" + std::to_string(stage_line) + ")");
  }
  EXPECT_EQ(error("fzg_test = \"GF-C/8.3/90\"", "").key(), "operating.fzg_load_stage");
  EXPECT_EQ(error("fzg_load_stage = 10", "pinion_torque = \"265 N m\"").key(), "operating.fzg_test");
  {  // neither a torque nor a stage: the torque is missing, and the rule says how to give it
    const auto e = error("fzg_load_stage = 10", "");
    EXPECT_EQ(e.key(), "operating.pinion_torque");
    EXPECT_NE(e.rule().find("or give operating.fzg_load_stage with operating.fzg_test"), std::string::npos);
  }
  EXPECT_NE(error("\"GF-C/8.3/90\"", "\"GF-C\"").rule().find("unknown FZG test 'GF-C'"), std::string::npos);
  EXPECT_EQ(error("fzg_load_stage = 10", "fzg_load_stage = 9.5").rule(), "expected an integer");
}
