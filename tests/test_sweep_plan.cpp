// Sweep plans and case changes: axis parsing (lists, ranges with units), the factorial's order,
// zipping, shards that partition the points, SI values of swept text, and changes to a case
// (aliases, roughness forms replaced, errors naming the --set).
#include "config/case_prepare.hpp"
#include "config/input_error.hpp"
#include "contact/mesh_contact.hpp"
#include "output/column_table.hpp"
#include "runs/sweep_merge.hpp"
#include "runs/sweep_plan.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

using namespace geartrib;

TEST(SweepPlan, AxesFromListsAndRanges) {
  EXPECT_EQ(io::parse_sweep_axis("module=4mm,6mm, 8mm").values, (std::vector<std::string>{"4mm", "6mm", "8mm"}));
  EXPECT_EQ(io::parse_sweep_axis("face_width=40mm:80mm:5").values,
            (std::vector<std::string>{"40mm", "50mm", "60mm", "70mm", "80mm"}));
  EXPECT_EQ(io::parse_sweep_axis("teeth=20:40:3").values,
            (std::vector<std::string>{"20", "30", "40"}));  // integers stay integers
  EXPECT_EQ(io::parse_sweep_axis("x1=0:1:3").values, (std::vector<std::string>{"0", "0.5", "1"}));
  EXPECT_EQ(io::parse_sweep_axis("model=kogut-etsion,jackson-green").key, "model");
  EXPECT_THROW(io::parse_sweep_axis("module"), std::invalid_argument);
  EXPECT_THROW(io::parse_sweep_axis("face_width=40mm:0.08m:3"), std::invalid_argument);  // units differ
  EXPECT_THROW(io::parse_sweep_axis("face_width=40mm:80mm:1"), std::invalid_argument);   // n < 2
  EXPECT_THROW(io::parse_sweep_axis("module=4mm,,6mm"), std::invalid_argument);
}

TEST(SweepPlan, FactorialFirstAxisSlowestAndZip) {
  io::SweepPlan p;
  p.axes = {io::parse_sweep_axis("a=1,2"), io::parse_sweep_axis("b=x,y,z")};
  p.validate();
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p.point(0)[0].value, "1");
  EXPECT_EQ(p.point(0)[1].value, "x");
  EXPECT_EQ(p.point(2)[1].value, "z");
  EXPECT_EQ(p.point(3)[0].value, "2");
  EXPECT_EQ(p.point(3)[1].value, "x");
  std::set<std::pair<std::string, std::string>> all;
  for (std::size_t i = 0; i < p.size(); ++i) all.insert({p.point(i)[0].value, p.point(i)[1].value});
  EXPECT_EQ(all.size(), 6u);  // every combination once
  p.zip = true;
  EXPECT_THROW(p.validate(), std::invalid_argument);  // 2 and 3 values
  p.axes = {io::parse_sweep_axis("a=1,2,3"), io::parse_sweep_axis("b=x,y,z"), io::parse_sweep_axis("c=fixed")};
  p.validate();
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p.point(2)[0].value, "3");
  EXPECT_EQ(p.point(2)[1].value, "z");
  EXPECT_EQ(p.point(2)[2].value, "fixed");  // a one-value axis at every point
  p.axes.push_back(io::parse_sweep_axis("a=4,5,6"));
  EXPECT_THROW(p.validate(), std::invalid_argument);  // a key twice
}

TEST(SweepPlan, ShardsPartitionThePoints) {
  for (std::size_t n : {1u, 2u, 3u, 7u}) {
    std::vector<int> owners(20, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const io::Shard s = io::parse_shard(std::to_string(i) + "/" + std::to_string(n));
      for (std::size_t k = 0; k < owners.size(); ++k) owners[k] += s.owns(k);
    }
    for (int o : owners) EXPECT_EQ(o, 1) << n;
  }
  for (const char* bad : {"2/2", "1", "a/3", "0/0", "-1/2", "1/2x", "+1/2", " 1/2", "1/ 2", "4000000000000/3",
                          "0/99999999999999999999999", "0/100001"})  // n past kMaxSweepPoints: --merge would refuse it
    EXPECT_THROW(io::parse_shard(bad), std::invalid_argument) << bad;
  EXPECT_EQ(io::parse_shard("99999/100000").count, 100000u);  // the largest sweep's last point alone
  EXPECT_EQ(io::whole_number("100000"), 100000u);
  for (const char* bad : {"", "+4", "-0", "4 ", "1e3", "0x10", "99999999999999999999999"})
    EXPECT_FALSE(io::whole_number(bad)) << bad;
}

// Two axes reaching one key are refused naming both: an alias and a dotted key it stands for, or
// an axis replacing another's key (another form of the same value); keys apart sweep together.
TEST(SweepPlan, OverlappingKeysRefused) {
  auto message = [](std::vector<std::string> axes) {
    io::SweepPlan p;
    for (const auto& a : axes) p.axes.push_back(io::parse_sweep_axis(a));
    try {
      p.validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({"teeth=30,31", "pinion.teeth=25"}),
            "--set teeth (pinion.teeth, wheel.teeth) and --set pinion.teeth set the same key pinion.teeth: a key given "
            "twice (a point would run with the later value while the table records both); give it once");
  EXPECT_NE(message({"z2=40", "teeth=30,31"}).find("set the same key wheel.teeth"), std::string::npos);
  EXPECT_NE(message({"torque=1000Nm", "fzg_load_stage=4,5", "fzg_test=PT-C"})
                .find("--set fzg_load_stage (operating.fzg_load_stage) replaces operating.pinion_torque"),
            std::string::npos);
  EXPECT_NE(message({"pinion.flank.ra=0.4um", "rq=0.2um,0.4um"}).find("replaces pinion.flank.ra"), std::string::npos);
  EXPECT_NE(message({"pinion.flank.m0=1e-12", "summit_radius=20um"}).find("replaces pinion.flank.summit_radius"),
            std::string::npos);
  EXPECT_NE(message({"lubricant=none,../lubricants/mineral-vg220.toml", "viscosity=0.1Pa s"})
                .find("--set viscosity (lubricant.dynamic_viscosity) replaces lubricant.file"),
            std::string::npos);
  EXPECT_EQ(message({"fzg_load_stage=4,5", "fzg_test=PT-C"}), "accepted");
  EXPECT_EQ(message({"pinion.flank.rq=0.2um,0.4um", "wheel.flank.rq=0.3um", "summit_radius=20um"}), "accepted");
  EXPECT_EQ(message({"pinion.flank.topography.file=a.h5,b.h5", "pinion.flank.topography.outliers=3"}), "accepted");
  EXPECT_EQ(message({"module=4mm,5mm", "gear_pair.module_unused_sibling=1"}), "accepted");  // a prefix, not a table
}

TEST(SweepPlan, SiValuesOfSweptText) {
  EXPECT_DOUBLE_EQ(io::si_quantity("4mm")->value, 0.004);
  EXPECT_EQ(io::si_quantity("4mm")->unit, "m");
  EXPECT_DOUBLE_EQ(io::si_quantity("0.2 um")->value, 2e-7);
  EXPECT_DOUBLE_EQ(io::si_quantity("1000 rpm")->value, 1000 * 2 * 3.14159265358979323846 / 60);
  EXPECT_EQ(io::si_quantity("1000 rpm")->unit, "rad/s");
  EXPECT_EQ(io::si_quantity("30")->unit, "1");
  EXPECT_FALSE(io::si_quantity("kogut-etsion"));
  EXPECT_FALSE(io::si_quantity("4 furlongs"));
}

TEST(CaseChanges, AliasesSetKeysAndReplaceRoughnessForms) {
  const auto file = test::source_dir() / "gears/m6z30.toml";
  const Case c = io::prepare_case(
      io::load_case(file, {{"module", "5mm"}, {"rq", "0.4um"}, {"z1", "25"}, {"model", "kogut-etsion"}}));
  EXPECT_DOUBLE_EQ(c.gear_pair.module, 0.005);
  EXPECT_EQ(c.gear_pair.teeth[0], 25);
  EXPECT_EQ(c.gear_pair.teeth[1], 30);
  EXPECT_EQ(c.asperity.model, "kogut-etsion");
  // The case gives ra; rq replaces it on both flanks (exactly one form per flank).
  EXPECT_EQ(c.pinion.flank.roughness.form, surface::FlankRoughness::Form::rq);
  EXPECT_EQ(c.wheel.flank.roughness.form, surface::FlankRoughness::Form::rq);
  EXPECT_NE(c.source_text.find("# --set rq=0.4um"), std::string::npos);  // provenance kept with the results
  const Case same = io::prepare_case(io::load_case(file, {{"gear_pair.module", "5 mm"}}));
  EXPECT_DOUBLE_EQ(same.gear_pair.module, 0.005);
}

TEST(CaseChanges, ErrorsNameTheSet) {
  const auto file = test::source_dir() / "gears/m6z30.toml";
  auto message = [&](std::vector<io::CaseChange> changes) {
    try {
      io::prepare_case(io::load_case(file, changes));
    } catch (const io::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{"module", "-5mm"}}).find("(--set gear_pair.module=-5mm)"), std::string::npos);
  EXPECT_NE(message({{"gear_pair.modul", "5mm"}}).find("unknown key"), std::string::npos);
  EXPECT_NE(message({{"teeth", "30.5"}}).find("expected an integer"), std::string::npos);
  EXPECT_NE(message({{"gear_pair.module.x", "1"}}).find("is a value, not a table"), std::string::npos);
  EXPECT_NE(message({{"mu", "1.5"}}).find("must lie in [0, 1]"), std::string::npos);
  EXPECT_THROW(io::parse_case_change("module"), std::invalid_argument);
}

// The sweep's _mean along the path: the trapezoidal rule, exact for a linear series.
TEST(SweepSummary, PathMeanIsTrapezoidal) {
  EXPECT_DOUBLE_EQ(contact::path_mean({2.0, 4.0, 6.0, 8.0}), 5.0);  // linear: the midpoint value
  EXPECT_DOUBLE_EQ(contact::path_mean({1.0, 1.0, 1.0}), 1.0);
  EXPECT_DOUBLE_EQ(contact::path_mean({0.0, 1.0, 0.0}), 0.5);  // a hat: (0/2 + 1 + 0/2)/2
  EXPECT_DOUBLE_EQ(contact::path_mean({3.0}), 3.0);
}

// The sweep file: numeric columns in one block, text columns as datasets; read back exactly
// (doubles bit for bit, text with UTF-8 and empty cells, the column order, the units).
TEST(SweepFile, RoundTripKeepsOrderUnitsAndText) {
  io::ColumnTableFile f;
  auto number = [](std::string name, std::string unit, std::vector<double> v) {
    io::Column c;
    c.name = std::move(name);
    c.unit = std::move(unit);
    c.numbers = std::move(v);
    return c;
  };
  io::Column text;
  text.name = "status";
  text.text = true;
  text.texts = {"ok", "", "error: \xc2\xb5m beyond range"};  // UTF-8 (micro sign) and an empty cell
  f.table.columns = {number("point", "1", {0, 1, 2}), text, number("p0_max", "Pa", {1.0 / 3.0, -0.0, 1e300})};
  f.attributes = {{"sets", "torque=1,2,3"}};
  f.scene = "[gear_pair]\nmodule = 6mm\n";
  const auto path = std::filesystem::temp_directory_path() / "geartrib_sweep_roundtrip.h5";
  io::write_column_table_hdf5(path, f);
  const io::ColumnTableFile back = io::read_column_table_hdf5(path);
  ASSERT_EQ(back.table.columns.size(), 3u);
  EXPECT_EQ(back.table.columns[0].name, "point");
  EXPECT_EQ(back.table.columns[1].texts, text.texts);
  EXPECT_EQ(back.table.columns[2].unit, "Pa");
  EXPECT_EQ(back.table.columns[2].numbers, f.table.columns[2].numbers);
  EXPECT_TRUE(std::signbit(back.table.columns[2].numbers[1]));
  EXPECT_EQ(back.attributes.at("sets"), "torque=1,2,3");
  EXPECT_EQ(back.scene, f.scene);
  EXPECT_EQ(io::format_csv(back.table), io::format_csv(f.table));
  std::filesystem::remove(path);
}

// Names the block's comma lists could not hold are a programming error, caught before writing.
TEST(SweepFile, UnstorableNamesRefused) {
  io::ColumnTable t;
  io::Column c;
  c.name = "a,b";
  c.numbers = {1.0};
  t.columns = {c};
  EXPECT_THROW(t.validate(), std::logic_error);
  t.columns[0].name = "values";  // the block's own name
  EXPECT_THROW(t.validate(), std::logic_error);
}

// Merging shards: the table the unsharded sweep writes; every number a shard states checked
// against the rule, the error naming the file, the attribute or column and the value.
TEST(SweepFile, MergeJoinsShardsAndChecksTheirStatements) {
  const auto dir = std::filesystem::temp_directory_path() / "geartrib_sweep_merge_test";
  std::filesystem::create_directories(dir);
  auto shard = [&](std::size_t index, std::map<std::string, std::string> attributes, bool lubricated) {
    io::ColumnTableFile f;
    io::Column point{"point", "1", false, {}, {}}, status{"status", "", true, {}, {}},
        message{"message", "", true, {}, {}}, loss{"mesh_power_loss_W", "W", false, {}, {}};
    for (std::size_t i = index; i < 5; i += 2) {
      point.numbers.push_back(static_cast<double>(i));
      status.texts.emplace_back("ok");
      message.texts.emplace_back("");
      loss.numbers.push_back(10.0 * static_cast<double>(i));
    }
    f.table.columns = {point, status, message};
    if (lubricated) f.table.columns.push_back(loss);
    f.attributes = {
        {"points_total", "5"}, {"shard", std::to_string(index) + "/2"}, {"shard_count", "2"}, {"signature", "abc"}};
    for (const auto& [k, v] : attributes) f.attributes[k] = v;
    f.scene = "scene";
    const auto path = dir / ("s" + std::to_string(index) + "-" + std::to_string(attributes.size()) + ".h5");
    io::write_column_table_hdf5(path, f);
    return path;
  };
  const auto s0 = shard(0, {}, true), s1 = shard(1, {}, false);
  const io::ColumnTableFile merged = io::merge_sweep_shards({s1, s0});
  ASSERT_EQ(merged.table.rows(), 5u);
  EXPECT_EQ(merged.table.find("point")->numbers, (std::vector<double>{0, 1, 2, 3, 4}));
  // The lubricated shard's column in its place, NaN at the dry shard's points.
  const auto& loss = merged.table.find("mesh_power_loss_W")->numbers;
  EXPECT_EQ(loss[0], 0.0);
  EXPECT_TRUE(std::isnan(loss[1]));
  EXPECT_EQ(loss[4], 40.0);
  EXPECT_EQ(merged.attributes.at("shard"), "0/1");

  auto refusal = [&](const std::filesystem::path& bad, const std::filesystem::path& other) {
    try {
      io::merge_sweep_shards({other, bad});
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.file(), bad.string());
      return e.key() + " = " + e.value() + ": " + e.rule();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(shard(1, {{"shard", "4000000000000/2"}}, false), s0),
            "/sweep attribute shard = \"4000000000000/2\": must be i/n with 0 <= i < n and n the shard_count (2)");
  EXPECT_EQ(refusal(shard(0, {{"shard_count", "0"}}, false), s1),
            "/sweep attribute shard_count = \"0\": must be a whole number of shards from 1 to 100000 (the largest "
            "sweep)");
  EXPECT_EQ(refusal(shard(0, {{"points_total", "99999999999"}}, false), s1),
            "/sweep attribute points_total = \"99999999999\": must be a whole number of points from 1 to 100000 (the "
            "largest sweep)");
  // Shard 1 of a 4-point sweep owns the same points (1, 3) as of 5: the totals compared.
  EXPECT_EQ(refusal(shard(1, {{"points_total", "4"}}, false), s0).substr(0, 60),
            "/sweep attribute points_total = \"4\": from another sweep (cas");
  std::filesystem::remove_all(dir);
}
