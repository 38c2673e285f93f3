#include "runs/sweep_merge.hpp"

#include "config/input_error.hpp"
#include "runs/sweep_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace geartrib::io {

namespace {

// The merged table's cells (columns x points) at most: a sweep at kMaxSweepPoints with ~200
// columns has 2e7; the bound keeps a crafted union of columns (one shard's many columns times
// another's many points) below ~2 GB of cells.
constexpr std::size_t kMaxMergedCells = 50'000'000;

// A value from a file as a message shows it: quoted, at most 60 characters.
std::string shown(const std::string& v) {
  constexpr std::size_t kShown = 60;
  return "\"" + (v.size() > kShown ? v.substr(0, kShown) + "..." : v) + "\"";
}

std::string attribute_key(const std::string& name) { return "/sweep attribute " + name; }

struct ShardFile {
  std::filesystem::path path;
  ColumnTableFile file;
  std::size_t total = 0;  // points_total
  Shard shard;            // index / count
  std::string name() const { return path.string(); }
  [[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& rule) const {
    throw InputError(name(), 0, key, value, rule);
  }
  const std::string& attribute(const std::string& key) const {
    const auto it = file.attributes.find(key);
    if (it == file.attributes.end())
      fail(attribute_key(key), "", "missing: not a geartrib sweep shard (`geartrib sweep --shard i/n` writes it)");
    return it->second;
  }
  // A whole-number attribute in [1, kMaxSweepPoints].
  std::size_t count(const std::string& key, const std::string& what) const {
    const std::string& text = attribute(key);
    const std::optional<std::size_t> n = whole_number(text);
    if (!n || *n < 1 || *n > kMaxSweepPoints)
      fail(attribute_key(key), shown(text),
           fmt::format("must be a whole number of {} from 1 to {} (the largest sweep)", what, kMaxSweepPoints));
    return *n;
  }
  const Column& column(const std::string& name, bool text) const {
    const Column* c = file.table.find(name);
    if (!c || c->text != text)
      fail("/points/" + name, "",
           fmt::format("{}: not a geartrib sweep shard (which has a {} column {})", c ? "of another kind" : "missing",
                       text ? "text" : "numeric", name));
    return *c;
  }
};

// The points shard `s` owns of a sweep of `total` points: those with index % count == index.
std::size_t owned(const Shard& s, std::size_t total) {
  return s.index < total ? (total - 1 - s.index) / s.count + 1 : 0;
}

// The file's own statements, each checked before it is used.
ShardFile read_shard(const std::filesystem::path& path) {
  ShardFile f;
  f.path = path;
  f.file = read_column_table_hdf5(path);
  f.attribute("signature");
  f.total = f.count("points_total", "points");
  const std::size_t count = f.count("shard_count", "shards");
  const std::string& text = f.attribute("shard");
  const std::optional<Shard> shard = shard_from_text(text);
  if (!shard || shard->count != count)
    f.fail(attribute_key("shard"), shown(text),
           fmt::format("must be i/n with 0 <= i < n and n the shard_count ({})", count));
  f.shard = *shard;

  const Column& point = f.column("point", false);
  const Column& status = f.column("status", true);
  f.column("message", true);
  const std::size_t rows = point.numbers.size(), expected = owned(f.shard, f.total);
  if (rows != expected)
    f.fail("/points/point", fmt::format("{} rows", rows),
           fmt::format("shard {}/{} of a {}-point sweep owns {} point{} (index % {} == {})", f.shard.index,
                       f.shard.count, f.total, expected, expected == 1 ? "" : "s", f.shard.count, f.shard.index));
  std::vector<bool> seen(f.total, false);
  for (std::size_t r = 0; r < rows; ++r) {
    const double v = point.numbers[r];
    if (!(std::isfinite(v) && v >= 0.0 && v < static_cast<double>(f.total) && v == std::floor(v)) ||
        !f.shard.owns(static_cast<std::size_t>(v)))
      f.fail("/points/point", fmt::format("{} (row {})", v, r),
             fmt::format("must be a point of shard {}/{}: a whole number below points_total ({}) with index % {} "
                         "== {}",
                         f.shard.index, f.shard.count, f.total, f.shard.count, f.shard.index));
    if (seen[static_cast<std::size_t>(v)])
      f.fail("/points/point", fmt::format("{} (row {})", v, r), "a point given twice in the shard");
    seen[static_cast<std::size_t>(v)] = true;
    if (status.texts[r] != "ok" && status.texts[r] != "error")
      f.fail("/points/status", fmt::format("{} (row {})", shown(status.texts[r]), r), "must be ok or error");
  }
  return f;
}

// `f` against the first file: one sweep.
void check_same_sweep(const ShardFile& f, const ShardFile& first) {
  auto differs = [&](const std::string& key, const std::string& here, const std::string& there) {
    f.fail(attribute_key(key), shown(here),
           fmt::format("from another sweep (case, --set or --zip differ) than {}, whose {} is {}", first.name(), key,
                       shown(there)));
  };
  for (const char* key : {"signature", "points_total", "shard_count", "sets", "axes"}) {
    const auto a = f.file.attributes.find(key), b = first.file.attributes.find(key);
    const bool in_a = a != f.file.attributes.end(), in_b = b != first.file.attributes.end();
    if (in_a != in_b || (in_a && a->second != b->second))
      differs(key, in_a ? a->second : "(none)", in_b ? b->second : "(none)");
  }
  if (f.file.scene != first.file.scene)
    f.fail("/scene", "",
           fmt::format("from another sweep than {}: the base case's text differs (same signature, edited file?)",
                       first.name()));
}

}  // namespace

ColumnTableFile merge_sweep_shards(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) throw std::invalid_argument("--merge: no shard files given");
  std::vector<ShardFile> files;
  files.reserve(paths.size());
  for (const auto& p : paths) {
    files.push_back(read_shard(p));
    check_same_sweep(files.back(), files.front());
  }
  const ShardFile& first = files.front();
  const std::size_t total = first.total, count = first.shard.count;

  // Every shard once (each file's rows already checked against its shard: together every point once).
  std::vector<const ShardFile*> by_shard(count, nullptr);
  for (const auto& f : files) {
    const ShardFile*& seen = by_shard[f.shard.index];
    if (seen)
      f.fail(attribute_key("shard"), shown(f.attribute("shard")),
             fmt::format("shard {}/{} given twice (also {})", f.shard.index, count, seen->name()));
    seen = &f;
  }
  for (std::size_t s = 0; s < count; ++s)
    if (!by_shard[s])
      throw std::invalid_argument(
          fmt::format("--merge: shard {}/{} is missing (the {} file{} given hold {} of the {} "
                      "shards of {}'s sweep)",
                      s, count, files.size(), files.size() == 1 ? "" : "s", files.size(), count, first.name()));

  // Columns: the union, a column missing so far placed after the one before it in its file: a shard
  // lacks what all its points lacked (a dry shard of a mixed sweep the mesh-level values, a static
  // one the dynamic quantities), and the merged table keeps the unsharded table's order.
  ColumnTableFile out;
  out.scene = first.file.scene;
  out.attributes = first.file.attributes;
  out.attributes.insert_or_assign("shard", std::string("0/1"));
  out.attributes.insert_or_assign("shard_count", std::string("1"));
  auto& columns = out.table.columns;
  for (const auto& f : files) {
    auto at = columns.begin();
    for (const auto& c : f.file.table.columns) {
      auto same = std::find_if(columns.begin(), columns.end(), [&](const Column& x) { return x.name == c.name; });
      if (same == columns.end()) {
        same = columns.insert(at, {c.name, c.unit, c.text, {}, {}});
      } else if (same->text != c.text || same->unit != c.unit) {
        f.fail("/points/" + c.name, "",
               fmt::format("column {} is {} here and {} in another shard", c.name,
                           c.text ? "text" : "numeric [" + c.unit + "]",
                           same->text ? "text" : "numeric [" + same->unit + "]"));
      }
      at = same + 1;
    }
    if (columns.size() > kMaxMergedCells / total)
      f.fail("/points", fmt::format("{} columns", columns.size()),
             fmt::format("the shards' columns together ({}) times the sweep's {} points exceed {} cells",
                         columns.size(), total, kMaxMergedCells));
  }

  // The rows in point order: point -> (file, row); each file's column of each merged column.
  std::vector<std::pair<std::size_t, std::size_t>> order(total, {files.size(), 0});
  std::vector<std::vector<const Column*>> sources(files.size());
  for (std::size_t k = 0; k < files.size(); ++k) {
    const ColumnTable& t = files[k].file.table;
    const auto& points = t.find("point")->numbers;
    for (std::size_t r = 0; r < points.size(); ++r) order[static_cast<std::size_t>(points[r])] = {k, r};
    for (const auto& c : columns) sources[k].push_back(t.find(c.name));
  }
  for (std::size_t j = 0; j < columns.size(); ++j) {
    Column& c = columns[j];
    if (c.text) c.texts.reserve(total);
    else c.numbers.reserve(total);
    for (std::size_t i = 0; i < total; ++i) {
      const auto [k, row] = order[i];
      if (k == files.size()) throw std::logic_error(fmt::format("merge_sweep_shards: point {} in no shard", i));
      const Column* s = sources[k][j];
      if (c.text) c.texts.push_back(s ? s->texts[row] : "");
      else c.numbers.push_back(s ? s->numbers[row] : std::nan(""));
    }
  }
  out.table.validate();
  return out;
}

}  // namespace geartrib::io
