// Joining the shards of a sweep (`geartrib sweep --shard i/n -o part-i.h5`, each its own HDF5
// file) into the table the unsharded sweep would have written (`geartrib sweep --merge`).
#pragma once

#include "output/column_table.hpp"

#include <filesystem>
#include <vector>

namespace geartrib::io {

// Reads every shard file and joins them, points in index order; the columns are the union, a
// column only some shards have (the mesh-level values of a mixed dry and lubricated sweep) in the
// unsharded table's place, NaN or empty where a shard lacks it.
//
// Nothing a file states is used before it is checked: each /sweep attribute (points_total a whole
// number in [1, kMaxSweepPoints], shard_count in [1, kMaxSweepPoints], shard "i/n" with n =
// shard_count), the columns point (numeric), status ("ok" or "error") and message (text), each
// shard's rows against the points its shard owns (index % n == i, each once, below points_total),
// and across the files: one sweep (signature, points_total, shard_count, sets, axes, scene), every
// shard once, each column of one kind and unit. Throws InputError naming the file, the attribute
// or column, its value and the rule broken.
ColumnTableFile merge_sweep_shards(const std::vector<std::filesystem::path>& shards);

}  // namespace geartrib::io
