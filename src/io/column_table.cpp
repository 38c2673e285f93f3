#include "io/column_table.hpp"

#include "io/hdf5_handles.hpp"
#include "io/input_error.hpp"
#include "io/table_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

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
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    using hdf5::Handle;
    Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "file " + tmp.string());
    {
      Handle points(H5Gcreate2(file, "/points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /points");
      std::string order;
      for (const auto& c : f.table.columns) {
        order += (order.empty() ? "" : ",") + c.name;
        if (c.text) hdf5::strings_dataset(points, c.name, c.texts);
        else hdf5::number_dataset(points, c.name, c.numbers, c.unit);
      }
      hdf5::string_attribute(points, "columns", order);
    }
    {
      Handle sweep(H5Gcreate2(file, "/sweep", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /sweep");
      for (const auto& [k, v] : f.attributes) hdf5::string_attribute(sweep, k, v);
    }
    hdf5::string_dataset(file, "/scene", f.scene);
  });
}

ColumnTableFile read_column_table_hdf5(const std::filesystem::path& path) {
  using hdf5::Handle;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  ColumnTableFile f;
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "file");
    Handle points(H5Gopen2(file, "/points", H5P_DEFAULT), H5Gclose, "group /points");
    std::string order;
    if (!hdf5::read_string_attribute(points, "columns", order))
      throw std::runtime_error("no attribute /points columns");
    std::size_t start = 0;
    while (start <= order.size()) {
      const std::size_t comma = std::min(order.find(',', start), order.size());
      Column c;
      c.name = order.substr(start, comma - start);
      c.text = hdf5::is_string_dataset(points, c.name);
      if (c.text) {
        c.texts = hdf5::read_strings(points, c.name);
      } else {
        c.numbers = hdf5::read_numbers(points, c.name);
        Handle set(H5Dopen2(points, c.name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + c.name);
        hdf5::read_string_attribute(set, "units", c.unit);
      }
      f.table.columns.push_back(std::move(c));
      start = comma + 1;
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
