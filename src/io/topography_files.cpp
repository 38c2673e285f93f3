#include "io/topography_files.hpp"

#include "io/hdf5_handles.hpp"
#include "io/hdf5_results.hpp"
#include "io/input_error.hpp"
#include "io/table_writer.hpp"
#include "io/text_lines.hpp"
#include "io/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace geartrib::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r') {
      if (!cur.empty()) out.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool is_missing(const std::string& t) {
  std::string l = t;
  std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return l == "bad" || l == "nan" || l == "-" || l == "na" || l == "missing";
}

bool parse(const std::string& t, double& v) {
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc{} && end == t.data() + t.size() && std::isfinite(v);
}

// The value of a '# key: value' comment line with this key.
bool comment_value(const std::string& line, const std::string& key, std::string& value) {
  const auto entry = comment_entry(line);
  if (!entry || entry->first != key) return false;
  value = entry->second;
  return true;
}

// A '# units: <length unit>' line: the unit of the lengths that follow it (heights, coordinates,
// bare spacings); it must come before them. Returns false for any other line.
bool units_line(const std::string& line, const std::string& file, int n, bool lengths_seen, double& unit) {
  std::string value;
  if (!comment_value(line, "units", value)) return false;
  if (lengths_seen)
    throw InputError(file, n, "units", value, "the units line must come before the spacing and the data");
  try {
    unit = unit_factor(value, Dimension::length);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, n, "units", value, e.what());
  }
  return true;
}

void check_enough(const surface::HeightGrid& g, const std::string& file, int line) {
  if (g.size() - g.missing() < 9)
    throw InputError(
        file, line, "", "",
        fmt::format("too few valid points ({} of {}; at least 9 are needed)", g.size() - g.missing(), g.size()));
}

surface::HeightGrid read_xyz(const std::filesystem::path& path, const TopographyReadOptions& o) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(file, 0, "", "", "cannot open topography file");
  double unit = o.unit;
  std::vector<double> xs, ys, zs;
  std::string line;
  int n = 0, first_data = 0;
  while (std::getline(in, line)) {
    ++n;
    std::string value;
    if (units_line(line, file, n, first_data != 0, unit)) continue;
    if (!line.empty() && line[0] == '#') continue;
    const auto t = tokens(line);
    if (t.empty()) continue;
    double x = 0, y = 0, z = 0;
    const bool numeric_xy = t.size() == 3 && parse(t[0], x) && parse(t[1], y);
    const bool z_ok = numeric_xy && (parse(t[2], z) || is_missing(t[2]));
    if (!first_data) {
      if (!z_ok) continue;  // a header line of the profiler's export
      first_data = n;
    } else if (!z_ok) {
      throw InputError(file, n, "", line, "malformed point: expected 'x y z' numbers (z may be Bad or NaN)");
    }
    xs.push_back(x * unit);
    ys.push_back(y * unit);
    zs.push_back(parse(t[2], z) ? z * unit : kNaN);
  }
  if (xs.empty()) throw InputError(file, n, "", "", "no data points");
  if (o.resample > 0.0) {
    surface::HeightGrid g = surface::grid_from_points(xs, ys, zs, o.resample);
    check_enough(g, file, n);
    return g;
  }
  // The points must lie on a regular lattice: distinct x and y, uniformly spaced.
  auto axis = [&](std::vector<double> v, const char* name) {
    std::sort(v.begin(), v.end());
    const double span = v.back() - v.front();
    std::vector<double> u;
    for (double a : v)
      if (u.empty() || a - u.back() > 1e-6 * std::max(span, 1e-300)) u.push_back(a);
    if (u.size() >= 2) {
      const double h = (u.back() - u.front()) / (u.size() - 1);
      for (std::size_t k = 1; k < u.size(); ++k)
        if (std::abs((u[k] - u[k - 1]) / h - 1.0) > 0.01)
          throw InputError(
              file, first_data, name, "",
              "points are not on a regular grid (spacing varies by more than 1%); resample them (--resample SPACING)");
    }
    return u;
  };
  const auto ux = axis(xs, "x"), uy = axis(ys, "y");
  if (ux.size() < 2) throw InputError(file, first_data, "x", "", "the points need at least two distinct x");
  const double dx = (ux.back() - ux.front()) / (ux.size() - 1);
  const double dy = uy.size() > 1 ? (uy.back() - uy.front()) / (uy.size() - 1) : dx;
  surface::HeightGrid g = surface::make_grid(static_cast<int>(ux.size()), static_cast<int>(uy.size()), dx, dy);
  std::fill(g.valid.begin(), g.valid.end(), 0);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const int i = static_cast<int>(std::lround((xs[k] - ux.front()) / dx));
    const int j = uy.size() > 1 ? static_cast<int>(std::lround((ys[k] - uy.front()) / dy)) : 0;
    if (std::isnan(zs[k])) continue;
    g.at(i, j) = zs[k];
    g.valid[static_cast<std::size_t>(j) * g.nx + i] = 1;
  }
  check_enough(g, file, n);
  return g;
}

surface::HeightGrid read_grid(const std::filesystem::path& path, const TopographyReadOptions& o) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(file, 0, "", "", "cannot open topography file");
  double unit = o.unit, dx = o.spacing * o.unit, dy = 0.0;
  std::vector<std::vector<double>> rows;
  std::string line;
  int n = 0, spacing_line = 0;
  while (std::getline(in, line)) {
    ++n;
    std::string value;
    auto length = [&](const char* key) {
      try {
        // A bare number is in the file's length unit; "0.5 um" carries its own.
        const bool has_unit = value.find_first_of("abcdefghijklmnopqrstuvwxyzµ") != std::string::npos;
        return has_unit ? parse_quantity(value, Dimension::length) : parse_quantity(value, Dimension::length) * unit;
      } catch (const std::invalid_argument& e) {
        throw InputError(file, n, key, value, e.what());
      }
    };
    if (units_line(line, file, n, !rows.empty() || spacing_line != 0, unit)) continue;
    if (comment_value(line, "spacing", value) || comment_value(line, "dx", value)) {
      dx = length("spacing"), spacing_line = n;
      if (!(dx > 0.0)) throw InputError(file, n, "spacing", value, "spacing must be positive");
      continue;
    }
    if (comment_value(line, "dy", value)) {
      dy = length("dy");
      if (!(dy > 0.0)) throw InputError(file, n, "dy", value, "spacing must be positive");
      continue;
    }
    if (!line.empty() && line[0] == '#') continue;
    const auto t = tokens(line);
    if (t.empty()) continue;
    std::vector<double> row;
    for (const auto& tok : t) {
      double v = 0.0;
      if (parse(tok, v)) row.push_back(v * unit);
      else if (is_missing(tok)) row.push_back(kNaN);
      else throw InputError(file, n, "", tok, "not a number or a missing-point marker");
    }
    if (!rows.empty() && row.size() != rows.front().size())
      throw InputError(file, n, "", "",
                       fmt::format("ragged row: {} values, the first row has {}", row.size(), rows.front().size()));
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(file, n, "", "", "no height rows");
  if (!(dx > 0.0))
    throw InputError(file, spacing_line, "spacing", "",
                     "grid spacing missing: give '# spacing: <length>' or --grid-spacing");
  if (rows.front().size() < 2) throw InputError(file, n, "", "", "a height grid needs at least 2 columns");
  surface::HeightGrid g =
      surface::make_grid(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), dx, dy > 0.0 ? dy : dx);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double v = rows[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
      g.at(i, j) = std::isnan(v) ? 0.0 : v;
      g.valid[static_cast<std::size_t>(j) * g.nx + i] = !std::isnan(v);
    }
  check_enough(g, file, n);
  return g;
}

surface::HeightGrid read_hdf5(const std::filesystem::path& path) {
  const std::string file = path.string();
  start_hdf5();
  std::vector<double> z;
  hsize_t dims[2] = {0, 0};
  double dx = 0.0, dy = 0.0;
  try {
    hdf5::Handle f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "file");
    if (H5Lexists(f, "z", H5P_DEFAULT) <= 0)
      throw InputError(file, 0, "/z", "", "missing dataset /z (heights [m], ny x nx)");
    hdf5::Handle d(H5Dopen2(f, "/z", H5P_DEFAULT), H5Dclose, "dataset /z");
    hdf5::Handle space(H5Dget_space(d), H5Sclose, "dataspace");
    if (H5Sget_simple_extent_ndims(space) != 2)
      throw InputError(file, 0, "/z", "", "/z must be a 2-D dataset (ny x nx)");
    H5Sget_simple_extent_dims(space, dims, nullptr);
    if (dims[1] < 2 || dims[0] < 1) throw InputError(file, 0, "/z", "", "/z needs at least 2 points along x");
    if (!hdf5::read_number_attribute(d, "dx", dx) || !(dx > 0.0) || !std::isfinite(dx))
      throw InputError(file, 0, "/z dx", fmt::format("{}", dx), "attribute dx (spacing [m]) must be a positive number");
    if (!hdf5::read_number_attribute(d, "dy", dy)) dy = dx;
    if (!(dy > 0.0) || !std::isfinite(dy))
      throw InputError(file, 0, "/z dy", fmt::format("{}", dy), "attribute dy (spacing [m]) must be positive");
    z.resize(static_cast<std::size_t>(dims[0] * dims[1]));
    hdf5::check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, z.data()), "read /z");
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    throw InputError(file, 0, "", "", std::string("not a readable HDF5 topography file (") + e.what() + ")");
  }
  surface::HeightGrid g = surface::make_grid(static_cast<int>(dims[1]), static_cast<int>(dims[0]), dx, dy);
  for (std::size_t k = 0; k < z.size(); ++k) {
    g.valid[k] = !std::isnan(z[k]);
    g.z[k] = std::isnan(z[k]) ? 0.0 : z[k];
  }
  check_enough(g, file, 0);
  return g;
}

}  // namespace

TopographyFormat topography_format(const std::filesystem::path& file) {
  std::string e = file.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (e == ".xyz" || e == ".asc") return TopographyFormat::xyz;
  if (e == ".csv" || e == ".txt" || e == ".grd") return TopographyFormat::grid;
  if (e == ".h5" || e == ".hdf5") return TopographyFormat::hdf5;
  throw InputError(file.string(), 0, "", "",
                   "unknown topography format (extensions: .xyz .asc, .csv .txt .grd, .h5 .hdf5)");
}

surface::HeightGrid read_topography(const std::filesystem::path& file, const TopographyReadOptions& o) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), 0, "", "", "file not found");
  surface::HeightGrid g;
  switch (topography_format(file)) {
    case TopographyFormat::xyz:
      g = read_xyz(file, o);
      break;
    case TopographyFormat::grid:
      g = read_grid(file, o);
      break;
    case TopographyFormat::hdf5:
      g = read_hdf5(file);
      break;
  }
  if (o.resample > 0.0 && topography_format(file) != TopographyFormat::xyz) {
    g = surface::resample(g, o.resample);
    check_enough(g, file.string(), 0);
  }
  return g;
}

LoadedSurface load_surface(const std::filesystem::path& file, const TopographyReadOptions& read,
                           const surface::CleanupOptions& cleanup) {
  LoadedSurface s{read_topography(file, read), {}};
  try {
    s.cleanup = surface::clean_surface(s.grid, cleanup);
  } catch (const std::invalid_argument& e) {
    throw InputError(file.string(), 0, "", "", std::string("clean-up: ") + e.what());
  }
  return s;
}

void write_topography(const std::filesystem::path& file, const surface::HeightGrid& g, double unit) {
  g.validate();
  const TopographyFormat format = topography_format(file);
  if (format == TopographyFormat::hdf5) {
    write_atomically(file, [&](const std::filesystem::path& tmp) {
      start_hdf5();
      hdf5::Handle f(H5Fcreate(tmp.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, tmp.string());
      hdf5::string_attribute(f, "geartrib_version", GEARTRIB_VERSION);
      hdf5::string_attribute(f, "content", "surface heights z[j][i] at x = i dx, y = j dy; NaN: missing point");
      hsize_t dims[2] = {static_cast<hsize_t>(g.ny), static_cast<hsize_t>(g.nx)};
      hdf5::Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose, "dataspace");
      hdf5::Handle d(H5Dcreate2(f, "/z", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
                     "dataset /z");
      std::vector<double> z(g.z);
      for (std::size_t k = 0; k < z.size(); ++k)
        if (!g.valid[k]) z[k] = kNaN;
      hdf5::check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, z.data()), "write /z");
      hdf5::string_attribute(d, "units", "m");  // of z and of the spacings dx, dy
      hdf5::number_attribute(d, "dx", g.dx);
      hdf5::number_attribute(d, "dy", g.dy);
    });
    return;
  }
  std::string unit_name = "m";
  for (const char* u : {"m", "mm", "um", "nm"})
    if (std::abs(unit_factor(u, Dimension::length) / unit - 1.0) < 1e-12) unit_name = u;
  std::string out = "# geartrib surface\n# units: " + unit_name + "\n";
  if (format == TopographyFormat::xyz) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        out += g.ok(i, j)
                   ? fmt::format("{:.10g} {:.10g} {:.10g}\n", i * g.dx / unit, j * g.dy / unit, g.at(i, j) / unit)
                   : fmt::format("{:.10g} {:.10g} Bad\n", i * g.dx / unit, j * g.dy / unit);
  } else {
    out += fmt::format("# spacing: {:.12g} {}\n# dy: {:.12g} {}\n", g.dx / unit, unit_name, g.dy / unit, unit_name);
    const char sep = file.extension() == ".csv" ? ',' : ' ';
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        if (i) out += sep;
        out += g.ok(i, j) ? fmt::format("{:.10g}", g.at(i, j) / unit) : std::string("NaN");
      }
      out += '\n';
    }
  }
  write_file_atomically(file, out);
}

}  // namespace geartrib::io
