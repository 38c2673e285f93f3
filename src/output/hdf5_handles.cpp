#include "output/hdf5_handles.hpp"

#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace geartrib::io::hdf5 {

Handle::Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
  if (id < 0) throw std::runtime_error("HDF5: cannot create " + what);
}

NewFile::NewFile(std::filesystem::path path) : path_(std::move(path)) {
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list");
  // Grown 1 MiB at a time (glibc's realloc moves large blocks by remapping pages, not copying).
  check(H5Pset_fapl_core(access, std::size_t{1} << 20, false), "H5Pset_fapl_core");
  id_ = H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
  if (id_ < 0) throw std::runtime_error("HDF5: cannot create " + path_.string());
}

NewFile::~NewFile() {
  if (id_ >= 0) H5Fclose(id_);  // in memory: nothing to write, nothing to fail
}

void NewFile::close() {
  const hid_t id = id_;
  const auto fail = [&](const std::string& why) { throw std::runtime_error("HDF5: " + path_.string() + ": " + why); };
  if (H5Fget_obj_count(id, H5F_OBJ_ALL) != 1) fail("objects still open at its close");  // the file itself only
  if (H5Fflush(id, H5F_SCOPE_LOCAL) < 0) fail("cannot flush the file's image");
  const ssize_t size = H5Fget_file_image(id, nullptr, 0);
  if (size < 0) fail("cannot size the file's image");
  std::string image(static_cast<std::size_t>(size), '\0');
  if (size > 0 && H5Fget_file_image(id, image.data(), image.size()) != size) fail("cannot copy the file's image");
  id_ = -1;
  if (H5Fclose(id) < 0) fail("cannot close the file");
  write_bytes(path_, image);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

void string_attribute(hid_t obj, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type, std::max<std::size_t>(1, value.size())), "H5Tset_size");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attr(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "attribute " + name);
  check(H5Awrite(attr, type, value.c_str()), "write attribute " + name);
}

void number_attribute(hid_t obj, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attr(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              "attribute " + name);
  check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

bool read_number_attribute(hid_t obj, const std::string& name, double& value) {
  const htri_t exists = H5Aexists(obj, name.c_str());
  if (exists == 0) return false;
  if (exists < 0) throw std::runtime_error("attribute " + name + ": cannot be looked up");
  Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  Handle type(H5Aget_type(a), H5Tclose, "type of attribute " + name);
  Handle space(H5Aget_space(a), H5Sclose, "dataspace of attribute " + name);
  if (H5Tget_class(type) != H5T_FLOAT)
    throw std::runtime_error("attribute " + name + " is not a floating-point number");
  const H5S_class_t shape = H5Sget_simple_extent_type(space);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (shape == H5S_NULL || (shape == H5S_SIMPLE && count != 1) || (shape != H5S_SCALAR && shape != H5S_SIMPLE))
    throw std::runtime_error(
        fmt::format("attribute {} holds {} values, not one number", name, std::max<hssize_t>(count, 0)));
  double v = 0.0;  // one double: the dataspace holds exactly one element
  check(H5Aread(a, H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  value = v;
  return true;
}

bool read_string_attribute(hid_t obj, const std::string& name, std::string& value) {
  if (H5Aexists(obj, name.c_str()) <= 0) return false;
  Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  Handle type(H5Aget_type(a), H5Tclose, "attribute type");
  if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0) return false;
  // One string: an array of them would be read past the buffer of one.
  Handle space(H5Aget_space(a), H5Sclose, "dataspace of attribute " + name);
  const H5S_class_t shape = H5Sget_simple_extent_type(space);
  if (!(shape == H5S_SCALAR || (shape == H5S_SIMPLE && H5Sget_simple_extent_npoints(space) == 1)))
    throw std::runtime_error("attribute " + name + " is not one string");
  // Its declared size (up to 4 GB in the type) checked before allocating: the value is stored
  // in the file, so it cannot be larger than the file.
  const std::size_t size = H5Tget_size(type);
  hsize_t file_bytes = 0;
  Handle file(H5Iget_file_id(obj), H5Fclose, "file of attribute " + name);
  if (H5Fget_filesize(file, &file_bytes) < 0 || size > file_bytes)
    throw std::runtime_error("attribute " + name + " declares more bytes than its file holds");
  std::string buffer(size, '\0');
  if (H5Aread(a, type, buffer.data()) < 0) return false;
  value = buffer.substr(0, buffer.find('\0'));
  return true;
}

namespace {
// A new UTF-8 string type of `size` bytes (H5T_VARIABLE: variable length), for a Handle to own.
hid_t utf8_type(std::size_t size) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  if (type >= 0 && (H5Tset_size(type, size) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0)) {
    H5Tclose(type);
    return -1;
  }
  return type;
}
}  // namespace

void columns_group(hid_t file, const std::string& name, const ColumnTable& t) {
  t.validate();
  Handle group(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group " + name);
  for (const Column& c : t.columns) {
    if (c.text) strings_dataset(group, c.name, c.texts);
    else number_dataset(group, c.name, c.numbers, c.unit);
  }
}

void number_dataset(hid_t group, const std::string& name, const std::vector<double>& values, const std::string& units) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "dataspace");
  Handle set(H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "dataset " + name);
  if (n > 0) check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + name);
  string_attribute(set, "units", units);
}

hid_t matrix_dataset(hid_t group, const std::string& name, std::size_t rows, std::size_t cols,
                     const std::vector<double>& values, const std::string& units) {
  if (values.size() != rows * cols) throw std::logic_error("matrix_dataset: " + name + " has another size");
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose, "dataspace");
  const hid_t set = H5Dcreate2(group, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) throw std::runtime_error("HDF5: cannot create dataset " + name);
  try {
    if (!values.empty())
      check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + name);
    string_attribute(set, "units", units);
  } catch (...) {
    H5Dclose(set);
    throw;
  }
  return set;
}

void string_dataset(hid_t group, const std::string& name, const std::string& value) {
  Handle type(utf8_type(std::max<std::size_t>(1, value.size())), H5Tclose, "string type");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle set(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "dataset " + name);
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.c_str()), "write " + name);
}

void strings_dataset(hid_t group, const std::string& name, const std::vector<std::string>& values) {
  // Fixed length (the longest value, NUL-padded): variable-length strings go through HDF5's global
  // heap and its conversion paths, ~1 ms per dataset; these cost as much as a number column.
  std::size_t width = 1;
  for (const auto& v : values) width = std::max(width, v.size());
  std::string cells(values.size() * width, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) values[i].copy(cells.data() + i * width, values[i].size());
  const hsize_t n = values.size();
  Handle type(utf8_type(width), H5Tclose, "string type");
  check(H5Tset_strpad(type, H5T_STR_NULLPAD), "H5Tset_strpad");
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "dataspace");
  Handle set(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "dataset " + name);
  if (n > 0) check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, cells.data()), "write " + name);
}

bool is_string_dataset(hid_t group, const std::string& name) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle type(H5Dget_type(set), H5Tclose, "type of " + name);
  return H5Tget_class(type) == H5T_STRING;
}

std::vector<double> read_matrix(hid_t group, const std::string& name, std::size_t& rows, std::size_t& cols,
                                std::size_t max_values) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, "dataspace of " + name);
  if (H5Sget_simple_extent_ndims(space) != 2) throw std::runtime_error("HDF5: " + name + " is not a 2-D dataset");
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  if (dims[1] != 0 && dims[0] > max_values / dims[1])
    throw std::runtime_error(
        fmt::format("HDF5: {} declares {} x {} values (at most {})", name, dims[0], dims[1], max_values));
  rows = static_cast<std::size_t>(dims[0]);
  cols = static_cast<std::size_t>(dims[1]);
  std::vector<double> out(rows * cols);
  if (!out.empty()) check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::vector<double> read_numbers(hid_t group, const std::string& name, std::size_t max_values) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, "dataspace of " + name);
  if (H5Sget_simple_extent_ndims(space) != 1) throw std::runtime_error("HDF5: " + name + " is not a 1-D dataset");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  if (n > max_values)
    throw std::runtime_error(fmt::format("HDF5: {} declares {} values (at most {})", name, n, max_values));
  Handle type(H5Dget_type(set), H5Tclose, "type of " + name);
  if (H5Tget_class(type) != H5T_FLOAT) throw std::runtime_error("HDF5: " + name + " is not a floating-point dataset");
  std::vector<double> out(static_cast<std::size_t>(n));
  if (!out.empty()) check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  return out;
}

std::string read_string(hid_t group, const std::string& name) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle type(H5Dget_type(set), H5Tclose, "type of " + name);
  if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0)
    throw std::runtime_error("HDF5: " + name + " is not a fixed-length string");
  // One string, whose declared size the file stores (checked before allocating).
  Handle space(H5Dget_space(set), H5Sclose, "dataspace of " + name);
  const H5S_class_t shape = H5Sget_simple_extent_type(space);
  if (!(shape == H5S_SCALAR || (shape == H5S_SIMPLE && H5Sget_simple_extent_npoints(space) == 1)))
    throw std::runtime_error("HDF5: " + name + " is not one string");
  if (H5Dget_storage_size(set) < H5Tget_size(type))
    throw std::runtime_error("HDF5: " + name + " holds fewer bytes than its type declares");
  std::string buffer(H5Tget_size(type), '\0');
  check(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()), "read " + name);
  return buffer.substr(0, buffer.find('\0'));
}

std::vector<std::string> read_strings(hid_t group, const std::string& name) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  Handle space(H5Dget_space(set), H5Sclose, "dataspace of " + name);
  hsize_t n = 0;
  if (H5Sget_simple_extent_ndims(space) != 1) throw std::runtime_error("HDF5: " + name + " is not a 1-D dataset");
  H5Sget_simple_extent_dims(space, &n, nullptr);
  Handle stored(H5Dget_type(set), H5Tclose, "type of " + name);
  if (H5Tget_class(stored) != H5T_STRING) throw std::runtime_error("HDF5: " + name + " is not a string dataset");
  std::vector<std::string> out;
  if (H5Tis_variable_str(stored) > 0) {  // earlier geartrib files and other writers
    Handle type(utf8_type(H5T_VARIABLE), H5Tclose, "string type");
    std::vector<char*> pointers(n, nullptr);
    if (n > 0) check(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), "read " + name);
    out.reserve(pointers.size());
    for (char* p : pointers) out.emplace_back(p ? p : "");
    if (n > 0) H5Dvlen_reclaim(type, space, H5P_DEFAULT, pointers.data());
    return out;
  }
  const std::size_t width = H5Tget_size(stored);
  // The dataset's own storage bounds the buffer: n x width bytes must be what the file holds.
  if (width == 0 || n > H5Dget_storage_size(set) / width)
    throw std::runtime_error("HDF5: " + name + " holds fewer bytes than its shape declares");
  std::string cells(n * width, '\0');
  if (n > 0) check(H5Dread(set, stored, H5S_ALL, H5S_ALL, H5P_DEFAULT, cells.data()), "read " + name);
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string cell = cells.substr(i * width, width);
    out.push_back(cell.substr(0, cell.find('\0')));
  }
  return out;
}

}  // namespace geartrib::io::hdf5
