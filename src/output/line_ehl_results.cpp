#include "output/line_ehl_results.hpp"

#include "output/hdf5_handles.hpp"
#include "output/hdf5_results.hpp"

#include <hdf5.h>

#include <stdexcept>

namespace geartrib::io {

void write_line_ehl_hdf5(const std::filesystem::path& path, const LineEhlFile& f) {
  start_hdf5();
  hdf5::NewFile file(path);
  hdf5::columns_group(file, "/profile", f.profile);
  if (!f.series.columns.empty()) hdf5::columns_group(file, "/series", f.series);
  {
    hdf5::Handle summary(H5Gcreate2(file, "/summary", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                         "group /summary");
    if (f.summary.labels.size() != f.summary.rows.size())
      throw std::logic_error("write_line_ehl_hdf5: the summary's rows need their labels");
    for (std::size_t i = 0; i < f.summary.rows.size(); ++i)
      hdf5::number_attribute(summary, f.summary.labels[i], f.summary.rows[i].at(0));
    for (const auto& [name, value] : f.texts) hdf5::string_attribute(summary, name, value);
  }
  {
    hdf5::Handle meta(H5Gcreate2(file, "/meta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group /meta");
    hdf5::string_attribute(meta, "version", GEARTRIB_VERSION);
  }
  file.close();
}

}  // namespace geartrib::io
