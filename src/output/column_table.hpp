// A table of named columns with units, each numeric or text, for results with text cells (sweep
// points: swept model names, status, messages). io::Table stays the numeric table of the other
// commands. CSV quotes text cells that need it (RFC 4180); HDF5 stores the numeric columns as
// one float64 block "values" (rows x columns, attributes "columns" and "units": comma-separated
// lists), each text column as a dataset of UTF-8 strings, all in one group whose attribute
// "columns" gives the column order.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace geartrib::io {

struct Column {
  std::string name;
  std::string unit;  // "" for text
  bool text = false;
  std::vector<double> numbers;
  std::vector<std::string> texts;
  std::size_t size() const { return text ? texts.size() : numbers.size(); }
};

struct ColumnTable {
  std::vector<Column> columns;
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  const Column* find(const std::string& name) const;
  void validate() const;  // equal lengths, unique names
};

// A comment line "# units: u1,u2,..." ("" for text columns), the header of names, the rows.
std::string format_csv(const ColumnTable& t);

// A results file: the table in group /points, string attributes on group /sweep, the scene text
// as /scene. write_column_table_hdf5 writes `path` as it is: a command writes it through an
// io::OutputSet (all outputs or none).
struct ColumnTableFile {
  ColumnTable table;
  std::map<std::string, std::string> attributes;
  std::string scene;
};
void write_column_table_hdf5(const std::filesystem::path& path, const ColumnTableFile& f);
// Throws InputError naming the file when it is not such a file.
ColumnTableFile read_column_table_hdf5(const std::filesystem::path& path);

}  // namespace geartrib::io
