#include "output/areal_contact_results.hpp"

#include "output/hdf5_handles.hpp"
#include "output/hdf5_results.hpp"

#include <hdf5.h>

#include <stdexcept>

namespace geartrib::io {

void write_areal_contact_hdf5(const std::filesystem::path& path, const ArealContactFile& f) {
  const std::size_t n = static_cast<std::size_t>(f.nx) * static_cast<std::size_t>(f.ny);
  for (const auto* field : {&f.heights, &f.pressure, &f.gap, &f.spot})
    if (field->size() != n) throw std::logic_error("write_areal_contact_hdf5: a field does not match the grid");
  start_hdf5();
  hdf5::NewFile file(path);
  hdf5::columns_group(file, "/curve", f.curve);
  {
    hdf5::Handle fields(H5Gcreate2(file, "/fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /fields");
    const auto rows = static_cast<std::size_t>(f.ny), cols = static_cast<std::size_t>(f.nx);
    for (const auto& [name, values, units] : {std::tuple{"heights_m", &f.heights, "m"},
                                              {"pressure_Pa", &f.pressure, "Pa"},
                                              {"gap_m", &f.gap, "m"},
                                              {"spot", &f.spot, "1"}})
      H5Dclose(hdf5::matrix_dataset(fields, name, rows, cols, *values, units));
    hdf5::number_attribute(fields, "dx_m", f.dx);
    hdf5::number_attribute(fields, "dy_m", f.dy);
    hdf5::string_attribute(fields, "periodic_x", f.periodic_x ? "yes" : "no");
    hdf5::string_attribute(fields, "periodic_y", f.periodic_y ? "yes" : "no");
  }
  hdf5::columns_group(file, "/spots", f.spots);
  hdf5::columns_group(file, "/stress", f.stress);
  {
    hdf5::Handle summary(H5Gcreate2(file, "/summary", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                         "group /summary");
    for (const auto& [name, value] : f.numbers) hdf5::number_attribute(summary, name, value);
    for (const auto& [name, value] : f.texts) hdf5::string_attribute(summary, name, value);
  }
  hdf5::string_dataset(file, "scene", f.scene);
  {
    hdf5::Handle meta(H5Gcreate2(file, "/meta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /meta");
    hdf5::string_attribute(meta, "version", GEARTRIB_VERSION);
  }
  file.close();
}

}  // namespace geartrib::io
