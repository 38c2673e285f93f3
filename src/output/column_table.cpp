#include "output/column_table.hpp"

#include "config/input_error.hpp"
#include "config/text_lines.hpp"
#include "output/hdf5_handles.hpp"
#include "output/hdf5_results.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace geartrib::io {

const Column* ColumnTable::find(const std::string& name) const {
  for (const auto& c : columns)
    if (c.name == name) return &c;
  return nullptr;
}

void ColumnTable::validate() const {
  std::set<std::string> names;
  for (const auto& c : columns) {
    if (!names.insert(c.name).second) throw std::logic_error("ColumnTable: column " + c.name + " twice");
    // The HDF5 layout lists names and units separated by commas, beside the block "values".
    if (c.name.empty() || c.name == "values" || c.name.find(',') != std::string::npos ||
        c.unit.find(',') != std::string::npos)
      throw std::logic_error("ColumnTable: column name '" + c.name + "' or its unit not storable");
    if (c.size() != rows()) throw std::logic_error("ColumnTable: column " + c.name + " has another length");
  }
}

namespace {
std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}
}  // namespace

std::string format_csv(const ColumnTable& t) {
  t.validate();
  std::string out = "# units:";
  for (std::size_t i = 0; i < t.columns.size(); ++i) {
    out += i ? "," : " ";
    out += t.columns[i].unit;
  }
  out += '\n';
  for (std::size_t i = 0; i < t.columns.size(); ++i) {
    out += i ? "," : "";
    out += csv_cell(t.columns[i].name);
  }
  out += '\n';
  for (std::size_t r = 0; r < t.rows(); ++r) {
    for (std::size_t i = 0; i < t.columns.size(); ++i) {
      const Column& c = t.columns[i];
      out += i ? "," : "";
      out += c.text ? csv_cell(c.texts[r]) : fmt::format("{:.10g}", c.numbers[r]);
    }
    out += '\n';
  }
  return out;
}

void write_column_table_hdf5(const std::filesystem::path& path, const ColumnTableFile& f) {
  f.table.validate();
  start_hdf5();
  // The numeric columns as one row-major block: one HDF5 object instead of one per column (a
  // sweep has ~165 columns; each object costs ~40 us to create, the block ~0.1 ms in all).
  std::vector<const Column*> numeric;
  std::string order, names, units;
  for (const auto& c : f.table.columns) {
    order += (order.empty() ? "" : ",") + c.name;
    if (c.text) continue;
    numeric.push_back(&c);
    names += (names.empty() ? "" : ",") + c.name;
    units += (units.empty() ? "" : ",") + c.unit;
  }
  const std::size_t rows = f.table.rows(), cols = numeric.size();
  std::vector<double> values(rows * cols);
  for (std::size_t k = 0; k < cols; ++k)
    for (std::size_t r = 0; r < rows; ++r) values[r * cols + k] = numeric[k]->numbers[r];
  {
    using hdf5::Handle;
    hdf5::NewFile file(path);
    {
      Handle points(H5Gcreate2(file, "/points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /points");
      for (const auto& c : f.table.columns)
        if (c.text) hdf5::strings_dataset(points, c.name, c.texts);
      Handle block(hdf5::matrix_dataset(points, "values", rows, cols, values, units), H5Dclose, "dataset values");
      hdf5::string_attribute(block, "columns", names);
      hdf5::string_attribute(points, "columns", order);
    }
    {
      Handle sweep(H5Gcreate2(file, "/sweep", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /sweep");
      for (const auto& [k, v] : f.attributes) hdf5::string_attribute(sweep, k, v);
    }
    hdf5::string_dataset(file, "/scene", f.scene);
    file.close();
  }
}

ColumnTableFile read_column_table_hdf5(const std::filesystem::path& path) {
  using hdf5::Handle;
  start_hdf5();
  ColumnTableFile f;
  // A regular file (not a folder, device or pipe, which HDF5 would read without end).
  if (const std::string why = data_file_problem(path, kNoSizeLimit); !why.empty())
    throw InputError(path.string(), 0, "", "", why);
  try {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "file");
    Handle points(H5Gopen2(file, "/points", H5P_DEFAULT), H5Gclose, "group /points");
    std::string order, names, units;
    if (!hdf5::read_string_attribute(points, "columns", order))
      throw std::runtime_error("no attribute /points columns");
    // The block is written contiguous and uncompressed: it cannot hold more values than the file
    // has bytes / 8 (checked before allocating).
    std::size_t rows = 0, cols = 0;
    const std::vector<double> values =
        hdf5::read_matrix(points, "values", rows, cols, ec ? 0 : static_cast<std::size_t>(bytes / sizeof(double)));
    Handle block(H5Dopen2(points, "values", H5P_DEFAULT), H5Dclose, "dataset values");
    if (!hdf5::read_string_attribute(block, "columns", names) || !hdf5::read_string_attribute(block, "units", units))
      throw std::runtime_error("/points/values needs the attributes columns and units");
    const std::vector<std::string> numeric = split_csv(names), unit = split_csv(units);
    if (numeric.size() != cols || unit.size() != cols)
      throw std::runtime_error(fmt::format("/points/values has {} columns, its attributes name {} and {} units", cols,
                                           numeric.size(), unit.size()));
    std::set<std::string> listed;
    for (const auto& name : split_csv(order)) {
      // Each column once (a name listed again would copy its values again, without bound).
      if (!listed.insert(name).second) throw std::runtime_error("column " + name + " listed twice in /points columns");
      Column c;
      c.name = name;
      const auto at = std::find(numeric.begin(), numeric.end(), name);
      if (at != numeric.end()) {
        const std::size_t k = static_cast<std::size_t>(at - numeric.begin());
        c.unit = unit[k];
        c.numbers.resize(rows);
        for (std::size_t r = 0; r < rows; ++r) c.numbers[r] = values[r * cols + k];
      } else {
        if (name == "values" || !hdf5::is_string_dataset(points, name))
          throw std::runtime_error("column " + name + " is neither in /points/values nor a text dataset");
        c.text = true;
        // The table's rows (the block's) before reading: each cell of a text column is stored in
        // the file, so a column of more rows than the file has bytes is refused unread.
        Handle set(H5Dopen2(points, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
        Handle space(H5Dget_space(set), H5Sclose, "dataspace of " + name);
        hsize_t n = 0;
        if (H5Sget_simple_extent_ndims(space) != 1 || H5Sget_simple_extent_dims(space, &n, nullptr) != 1)
          throw std::runtime_error("text column " + name + " is not a 1-D dataset");
        if ((cols > 0 && n != rows) || (!ec && n > bytes))
          throw std::runtime_error(
              fmt::format("text column {} declares {} strings, the table has {} rows", name, n, rows));
        c.texts = hdf5::read_strings(points, name);
      }
      f.table.columns.push_back(std::move(c));
    }
    Handle sweep(H5Gopen2(file, "/sweep", H5P_DEFAULT), H5Gclose, "group /sweep");
    const int n = static_cast<int>(H5Aget_num_attrs(sweep));
    for (int i = 0; i < n; ++i) {
      char name[256] = {};
      H5Aget_name_by_idx(sweep, ".", H5_INDEX_NAME, H5_ITER_INC, static_cast<hsize_t>(i), name, sizeof name,
                         H5P_DEFAULT);
      std::string v;
      if (hdf5::read_string_attribute(sweep, name, v)) f.attributes[name] = v;
    }
    f.scene = hdf5::read_string(file, "/scene");
    f.table.validate();
  } catch (const std::exception& e) {
    throw InputError(path.string(), 0, "", "", std::string("not a readable geartrib sweep file (") + e.what() + ")");
  }
  return f;
}

}  // namespace geartrib::io
