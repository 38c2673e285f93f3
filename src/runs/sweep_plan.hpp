// The points of a what-if sweep (`geartrib sweep`): each `--set key=values` is an axis, the
// points are their full factorial (the first axis varying slowest) or, zipped, the i-th value of
// every axis. Values stay text (applied to the case as io::CaseChange, converted there, once).
#pragma once

#include "config/case_file.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

struct SweepAxis {
  std::string key;                  // case key or alias
  std::vector<std::string> values;  // as applied: "4mm", "30", "kogut-etsion"
};

// "key=v1,v2,v3" or "key=lo:hi:n" (n >= 2 evenly spaced values, lo and hi in the same unit:
// "40mm:80mm:5" -> 40mm, 50mm, ..., 80mm; integer ends with integer steps stay integers).
// Throws std::invalid_argument naming the text and the rule broken.
SweepAxis parse_sweep_axis(const std::string& text);

// At most 10^5 points in one sweep (or shard plan): each point keeps ~13 kB of summaries (1.3 GB at
// the bound) and the default case's points take ~1.6 ms each (~80 s on 2 cores). Larger plans
// run as separate sweeps.
inline constexpr std::size_t kMaxSweepPoints = 100000;

struct SweepPlan {
  std::vector<SweepAxis> axes;
  bool zip = false;
  // At least one axis, no key twice, zipped axes of equal length (or one value), at most
  // kMaxSweepPoints points.
  void validate() const;
  std::size_t size() const;
  // The changes of point i (0 <= i < size()).
  std::vector<CaseChange> point(std::size_t i) const;
  // The axes as given, one "key=v1,v2" per axis, ';' separated (stored with the results).
  std::string describe() const;
};

// A share of the points for one process: `--shard i/n` takes points with index % n == i
// (0 <= i < n), round robin so that slow regions of the sweep spread over the shards.
struct Shard {
  std::size_t index = 0;
  std::size_t count = 1;
  bool owns(std::size_t point) const { return point % count == index; }
};
// "i/n" with 0 <= i < n, both whole numbers written in decimal digits alone; nullopt otherwise.
std::optional<Shard> shard_from_text(std::string_view text);
Shard parse_shard(const std::string& text);  // the same; throws std::invalid_argument naming --shard
// A whole number written in decimal digits alone ("12"; not "", "+1", " 1", "1e3", "0x10") that
// fits std::size_t; nullopt otherwise.
std::optional<std::size_t> whole_number(std::string_view text);

// The SI value of a swept value when it is a number or a quantity of the unit table ("4mm" ->
// 0.004), with the SI unit; nullopt for text (model names, file names).
struct SiValue {
  double value = 0.0;
  std::string unit;
};
std::optional<SiValue> si_quantity(const std::string& text);

}  // namespace geartrib::io
