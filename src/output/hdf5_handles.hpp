// Small RAII layer over the HDF5 C API shared by the HDF5 writers and readers (src/output, src/topography, src/runs).
#pragma once

#include "output/column_table.hpp"

#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

namespace geartrib::io::hdf5 {

// Owns an HDF5 identifier and closes it with the matching function; throws std::runtime_error
// naming `what` when the identifier is invalid. The close's status is not checked: a file written
// through NewFile does no I/O on closing its objects (reading, a close has nothing to lose).
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what);
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { close_(id_); }
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// A new HDF5 file built in memory (HDF5's core driver without a backing store) and written to
// `path` by close() alone, each write checked (io::write_bytes). HDF5 itself never writes it: HDF5
// 1.10 cannot close a file whose flush failed (a full disk, a file-size limit) and keeps it open,
// and its shutdown at exit then crashes (SIGSEGV). Without close() (an exception), nothing is
// written. Costs a copy of the file in memory while close() writes it.
class NewFile {
 public:
  explicit NewFile(std::filesystem::path path);  // throws std::runtime_error
  NewFile(const NewFile&) = delete;
  NewFile& operator=(const NewFile&) = delete;
  ~NewFile();
  operator hid_t() const { return id_; }
  // Every object of the file closed first; throws std::runtime_error naming the file and the
  // reason (HDF5's, or the system's: EFBIG, ENOSPC, EIO).
  void close();

 private:
  hid_t id_ = -1;
  std::filesystem::path path_;
};

void check(herr_t status, const std::string& what);  // throws std::runtime_error when status < 0
void string_attribute(hid_t obj, const std::string& name, const std::string& value);
void number_attribute(hid_t obj, const std::string& name, double value);
// Reads one floating-point number from an attribute (a scalar, or a simple dataspace of exactly one
// element); false when the attribute is absent. Throws std::runtime_error naming the attribute when
// it is present but anything else (an array, a string, an integer, unreadable): it is never read
// into `value` unless it holds exactly one number.
bool read_number_attribute(hid_t obj, const std::string& name, double& value);
// Reads a string attribute; false when it is absent or not a string.
bool read_string_attribute(hid_t obj, const std::string& name, std::string& value);

// Datasets: 1-D float64 with attribute "units"; one UTF-8 string (scalar); 1-D UTF-8 strings.
void number_dataset(hid_t group, const std::string& name, const std::vector<double>& values, const std::string& units);
// 2-D float64 `rows` x `cols`, row-major `values`, attribute "units"; returns the open dataset
// for further attributes.
hid_t matrix_dataset(hid_t group, const std::string& name, std::size_t rows, std::size_t cols,
                     const std::vector<double>& values, const std::string& units);
void string_dataset(hid_t group, const std::string& name, const std::string& value);
// A group `name` of a table's columns: numeric ones as number_dataset, text ones as strings_dataset.
void columns_group(hid_t file, const std::string& name, const ColumnTable& t);
void strings_dataset(hid_t group, const std::string& name, const std::vector<std::string>& values);
// Readers of the same; throw std::runtime_error naming the dataset when it is missing or of
// another kind.
// A 2-D float64 dataset, row-major, with its shape; throws when it is not 2-D or has more than
// `max_values` values (checked before allocating).
std::vector<double> read_matrix(hid_t group, const std::string& name, std::size_t& rows, std::size_t& cols,
                                std::size_t max_values);
// A 1-D float64 dataset; throws when it is not 1-D or has more than `max_values` values (checked
// before allocating).
std::vector<double> read_numbers(hid_t group, const std::string& name, std::size_t max_values);
std::string read_string(hid_t group, const std::string& name);
std::vector<std::string> read_strings(hid_t group, const std::string& name);
bool is_string_dataset(hid_t group, const std::string& name);

}  // namespace geartrib::io::hdf5
