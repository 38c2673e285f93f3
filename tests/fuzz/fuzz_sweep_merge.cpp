// libFuzzer harness, structure-aware: the shard files `geartrib sweep --merge` reads, through
// io::merge_sweep_shards. The input does not become a file's bytes (libhdf5's own parser is not
// ours to fuzz): it chooses, field by field, the HDF5 objects written, starting from the shards
// of one consistent sweep (an input of zeros merges) and changing any of them:
//   the /sweep attributes points_total, shard, shard_count, signature, sets, axes: kept, dropped,
//     a fuzzed or interesting text ("4000000000000/3", "0", "99999999999", "abc", "+4", ...), a
//     number instead of a string, an array of strings, a variable-length string;
//   the /points table: its rows (added, dropped), the point indices (NaN, inf, -1, 1e300, 0.5,
//     another's, repeated), status and message cells, extra numeric or text columns with fuzzed
//     names and units, the block's columns/units attributes against its shape, the column order
//     (a name listed again or missing), a text column of another length or variable-length;
//   /scene: kept, dropped, another text.
// The rule (fuzz_support.hpp): a merge or a located refusal; and a merge is the whole sweep: one
// row per point 0..points_total-1 in order, a table that validates and survives a write and read.
#include "fuzz_support.hpp"
#include "output/column_table.hpp"
#include "output/hdf5_handles.hpp"
#include "runs/sweep_merge.hpp"

#include <fuzzer/FuzzedDataProvider.h>
#include <hdf5.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace geartrib;

namespace {

constexpr std::array<const char*, 16> kTexts = {
    "4000000000000/3",      "100000/3", "0", "99999999999", "abc", "+4", "x/3", "1/0",
    "18446744073709551616", "100001",   "1", "2/2",         "",    "-1", "0/1", " 3"};
constexpr std::array<double, 10> kPoints = {std::numeric_limits<double>::quiet_NaN(),
                                            std::numeric_limits<double>::infinity(),
                                            -1.0,
                                            1e300,
                                            0.5,
                                            1e5,
                                            -0.0,
                                            4294967296.0,
                                            18446744073709551616.0,
                                            9007199254740993.0};

std::string fuzzed_text(FuzzedDataProvider& in, const std::string& canonical) {
  switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 1:
    case 2:
      return in.PickValueInArray(kTexts);
    case 3:
      return in.ConsumeRandomLengthString(40);
    default:
      return canonical;
  }
}

// One attribute on /sweep as the input chooses: a string (the canonical or a fuzzed one), dropped,
// a number, an array of two strings, a variable-length string.
void sweep_attribute(FuzzedDataProvider& in, hid_t group, const std::string& name, const std::string& canonical) {
  using io::hdf5::Handle;
  const int form = in.ConsumeIntegralInRange<int>(0, 15);
  if (form == 11) return;  // dropped
  if (form == 12) {
    io::hdf5::number_attribute(group, name, in.ConsumeFloatingPoint<double>());
    return;
  }
  const std::string value = form < 11 ? fuzzed_text(in, canonical) : in.ConsumeRandomLengthString(40);
  if (form == 13 || form == 14) {  // an array of strings, or a variable-length string
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "type");
    const hsize_t n = form == 13 ? 2 : 1;
    if (form == 13) H5Tset_size(type, value.size() + 1);
    else H5Tset_size(type, H5T_VARIABLE);
    Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "space");
    Handle a(H5Acreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "attribute");
    if (form == 13) {
      std::string cells(2 * (value.size() + 1), '\0');
      cells.replace(0, value.size(), value);
      H5Awrite(a, type, cells.data());
    } else {
      const char* p = value.c_str();
      H5Awrite(a, type, &p);
    }
    return;
  }
  io::hdf5::string_attribute(group, name, value);
}

// A 1-D variable-length string dataset (the form of earlier geartrib files).
void vlen_strings(hid_t group, const std::string& name, const std::vector<std::string>& cells) {
  using io::hdf5::Handle;
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "type");
  H5Tset_size(type, H5T_VARIABLE);
  const hsize_t n = cells.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "space");
  Handle set(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, "set");
  std::vector<const char*> p;
  for (const auto& c : cells) p.push_back(c.c_str());
  if (n > 0) H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data());
}

struct Col {
  std::string name, unit;
  bool text = false;
  std::vector<double> numbers;
  std::vector<std::string> texts;
};

// Shard `index` of `count` of a `total`-point sweep, as the input changes it, written to `path`.
void write_shard(FuzzedDataProvider& in, const fs::path& path, std::size_t index, std::size_t count,
                 std::size_t total) {
  using io::hdf5::Handle;
  // The canonical table: the points the shard owns; then the input's changes.
  std::vector<double> points;
  for (std::size_t i = index; i < total; i += count) points.push_back(static_cast<double>(i));
  const int row_change = in.ConsumeIntegralInRange<int>(0, 7);
  if (row_change == 1 && !points.empty()) points.pop_back();
  if (row_change == 2) points.push_back(points.empty() ? 0.0 : points.back() + static_cast<double>(count));
  if (row_change == 3 && !points.empty()) points.push_back(points.front());
  for (int k = in.ConsumeIntegralInRange<int>(0, 2); k > 0 && !points.empty(); --k) {
    const std::size_t r = in.ConsumeIntegralInRange<std::size_t>(0, points.size() - 1);
    points[r] = in.ConsumeBool() ? in.PickValueInArray(kPoints) : static_cast<double>(in.ConsumeIntegral<int>());
  }
  const std::size_t rows = points.size();
  std::vector<Col> cols;
  cols.push_back({"point", in.ConsumeBool() ? in.ConsumeRandomLengthString(4) : "1", false, points, {}});
  Col status{"status", "", true, {}, {}}, message{"message", "", true, {}, {}};
  Col torque{"torque", "N m", false, {}, {}}, loss{"mesh_power_loss_W", "W", false, {}, {}};
  for (std::size_t r = 0; r < rows; ++r) {
    status.texts.push_back(in.ConsumeIntegralInRange<int>(0, 9) == 9 ? in.ConsumeRandomLengthString(8)
                           : in.ConsumeBool()                        ? "error"
                                                                     : "ok");
    message.texts.push_back(in.ConsumeRandomLengthString(16));
    torque.numbers.push_back(100.0 * (points[r] + 1.0));
    loss.numbers.push_back(in.ConsumeFloatingPoint<double>());
  }
  cols.push_back(torque);
  cols.push_back(status);
  cols.push_back(message);
  if (in.ConsumeBool()) cols.push_back(loss);  // a column some shards have
  for (int k = in.ConsumeIntegralInRange<int>(0, 2); k > 0; --k) {
    Col extra;
    extra.name = in.ConsumeBool() ? in.PickValueInArray(std::array<const char*, 6>{
                                        "point", "status", "torque", "values", "mesh_power_loss_W", "regime"})
                                  : in.ConsumeRandomLengthString(12);
    extra.text = in.ConsumeBool();
    extra.unit = extra.text ? "" : in.ConsumeRandomLengthString(4);
    for (std::size_t r = 0; r < rows; ++r) {
      if (extra.text) extra.texts.push_back(in.ConsumeRandomLengthString(8));
      else extra.numbers.push_back(in.ConsumeFloatingPoint<double>());
    }
    cols.push_back(extra);
  }
  if (in.ConsumeIntegralInRange<int>(0, 7) == 7 && cols.size() > 1)  // a column dropped
    cols.erase(cols.begin() + static_cast<std::ptrdiff_t>(in.ConsumeIntegralInRange<std::size_t>(0, cols.size() - 1)));

  // The HDF5 objects, as io::write_column_table_hdf5 writes them unless the input says otherwise
  // (written here without its checks, so that what it would refuse to write can be read).
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "file");
  {
    Handle group(H5Gcreate2(file, "/points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "/points");
    std::string order, names, units;
    std::vector<const Col*> numeric;
    for (const auto& c : cols) {
      order += (order.empty() ? "" : ",") + c.name;
      if (c.text) {
        if (c.name == "values") continue;                                 // the block's own name
        if (H5Lexists(group, c.name.c_str(), H5P_DEFAULT) > 0) continue;  // a text column named twice
        std::vector<std::string> cells = c.texts;
        const int shape = in.ConsumeIntegralInRange<int>(0, 9);
        if (shape == 8) cells.push_back("extra");
        if (shape == 9 && !cells.empty()) cells.pop_back();
        if (shape == 7) vlen_strings(group, c.name, cells);
        else io::hdf5::strings_dataset(group, c.name, cells);
        continue;
      }
      numeric.push_back(&c);
      names += (names.empty() ? "" : ",") + c.name;
      units += (units.empty() ? "" : ",") + c.unit;
    }
    std::vector<double> block(rows * numeric.size());
    for (std::size_t k = 0; k < numeric.size(); ++k)
      for (std::size_t r = 0; r < rows; ++r) block[r * numeric.size() + k] = numeric[k]->numbers[r];
    const int layout = in.ConsumeIntegralInRange<int>(0, 15);
    if (layout == 1) names += ",ghost";                                        // more names than columns
    if (layout == 2) units = units.substr(0, units.rfind(','));                // fewer units
    if (layout == 3) order += ",point";                                        // a column listed twice
    if (layout == 4) order = order.substr(0, order.rfind(','));                // one left out
    if (layout == 5) order += "," + in.ConsumeRandomLengthString(12);          // one that is nowhere
    if (layout == 6) io::hdf5::number_dataset(group, "values", block, units);  // 1-D
    else {
      Handle set(io::hdf5::matrix_dataset(group, "values", rows, numeric.size(), block, units), H5Dclose, "values");
      if (layout != 7) io::hdf5::string_attribute(set, "columns", names);
    }
    if (layout == 8) io::hdf5::number_attribute(group, "columns", 1.0);
    else io::hdf5::string_attribute(group, "columns", order);
  }
  {
    Handle group(H5Gcreate2(file, "/sweep", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "/sweep");
    sweep_attribute(in, group, "points_total", std::to_string(total));
    sweep_attribute(in, group, "shard", std::to_string(index) + "/" + std::to_string(count));
    sweep_attribute(in, group, "shard_count", std::to_string(count));
    sweep_attribute(in, group, "signature", "0123456789abcdef");
    sweep_attribute(in, group, "sets", "torque=100Nm:" + std::to_string(100 * total) + "Nm:" + std::to_string(total));
    sweep_attribute(in, group, "axes", "torque");
    io::hdf5::string_attribute(group, "version", "fuzz");
  }
  const int scene = in.ConsumeIntegralInRange<int>(0, 7);
  if (scene == 6) return;  // no /scene
  io::hdf5::string_dataset(file, "/scene", scene == 7 ? in.ConsumeRandomLengthString(32) : "[gear_pair]\n");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // libhdf5's own error stack printing: off
    return true;
  }();
  (void)quiet;
  FuzzedDataProvider in(data, size);
  // The sweep: 1 to 9 points in 1 to 4 shards; the files: its shards in a fuzzed order, each given
  // once unless the input repeats or leaves one out.
  const std::size_t total = in.ConsumeIntegralInRange<std::size_t>(1, 9);
  const std::size_t count = in.ConsumeIntegralInRange<std::size_t>(1, 4);
  std::vector<std::size_t> shards;
  for (std::size_t i = 0; i < count; ++i) shards.push_back(i);
  const int set_change = in.ConsumeIntegralInRange<int>(0, 7);
  if (set_change == 1) shards.pop_back();
  if (set_change == 2) shards.push_back(in.ConsumeIntegralInRange<std::size_t>(0, count - 1));
  if (set_change == 3 && shards.size() > 1) std::swap(shards.front(), shards.back());
  std::vector<fs::path> paths;
  for (std::size_t k = 0; k < shards.size(); ++k) {
    paths.push_back(fuzz::scratch() / ("shard-" + std::to_string(k) + ".h5"));
    try {
      write_shard(in, paths.back(), shards[k], count, total);
    } catch (const std::exception&) {
      return 0;  // an object HDF5 itself would not write (a name it refuses): no input
    }
  }
  if (paths.empty()) return 0;
  // With GEARTRIB_FUZZ_STATS set, the inputs merged and refused (by the key or the rule refused) are
  // counted and printed at exit: how deep a corpus reaches (fuzz_sweep_merge -runs=0 CORPUS).
  static std::map<std::string, long> outcomes;
  static const bool stats = [] {
    if (!std::getenv("GEARTRIB_FUZZ_STATS")) return false;
    std::atexit([] {
      for (const auto& [what, n] : outcomes) std::fprintf(stderr, "%8ld  %s\n", n, what.c_str());
    });
    return true;
  }();
  fuzz::expect_accepted_or_refused([&] {
    io::ColumnTableFile merged;
    try {
      merged = io::merge_sweep_shards(paths);
      if (stats) ++outcomes["merged"];
    } catch (const io::InputError& e) {
      if (stats) ++outcomes["refused: " + (e.key().empty() ? e.rule().substr(0, 40) : e.key())];
      throw;
    } catch (const std::invalid_argument& e) {
      if (stats) ++outcomes["refused: " + std::string(e.what()).substr(0, 40)];
      throw;
    }
    // A merge is the whole sweep, its points in order, and a table that round-trips.
    const io::Column* point = merged.table.find("point");
    const std::size_t stated = std::stoul(merged.attributes.at("points_total"));
    if (!point || merged.table.rows() != stated) {
      std::fprintf(stderr, "finding: merged %zu rows of a %zu-point sweep\n", merged.table.rows(), stated);
      std::abort();
    }
    for (std::size_t i = 0; i < stated; ++i)
      if (point->numbers[i] != static_cast<double>(i)) {
        std::fprintf(stderr, "finding: merged row %zu holds point %g\n", i, point->numbers[i]);
        std::abort();
      }
    merged.table.validate();
    const fs::path out = fuzz::scratch() / "merged.h5";
    io::write_column_table_hdf5(out, merged);
    if (io::format_csv(io::read_column_table_hdf5(out).table) != io::format_csv(merged.table)) {
      std::fprintf(stderr, "finding: the merged table does not round-trip\n");
      std::abort();
    }
  });
  return 0;
}
