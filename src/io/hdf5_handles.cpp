#include "io/hdf5_handles.hpp"

#include <algorithm>
#include <stdexcept>

namespace geartrib::io::hdf5 {

Handle::Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
  if (id < 0) throw std::runtime_error("HDF5: cannot create " + what);
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
  Handle attr(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "attribute " + name);
  check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

bool read_number_attribute(hid_t obj, const std::string& name, double& value) {
  if (H5Aexists(obj, name.c_str()) <= 0) return false;
  const hid_t a = H5Aopen(obj, name.c_str(), H5P_DEFAULT);
  if (a < 0) return false;
  const hid_t type = H5Aget_type(a);
  const bool numeric = type >= 0 && H5Tget_class(type) == H5T_FLOAT;
  const bool ok = numeric && H5Aread(a, H5T_NATIVE_DOUBLE, &value) >= 0;
  if (type >= 0) H5Tclose(type);
  H5Aclose(a);
  return ok;
}

}  // namespace geartrib::io::hdf5
