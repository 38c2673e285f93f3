#include "topography/topography_files.hpp"

#include "config/input_error.hpp"
#include "config/text_lines.hpp"
#include "config/units.hpp"
#include "output/hdf5_handles.hpp"
#include "output/hdf5_results.hpp"
#include "output/table_writer.hpp"
#include "topography/x3p_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

namespace geartrib::io {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using surface::kMaxCoordinate;
using surface::kMaxGridPoints;
using surface::kMaxHeight;
using surface::kMaxSpacing;
using surface::kMinSpacing;

// What a reader gives: the grid and the unit its lengths were read in (for the plausibility
// warnings): stated by the file ('# units:', HDF5's metres) or assumed from the options.
struct ReadSurface {
  surface::HeightGrid grid;
  double unit = 1.0;
  bool unit_in_file = false;
};

// The blank-, comma- or semicolon-separated tokens of a line, at most `max` of them (a `max + 1`th
// is reported by returning max + 1 tokens): a line of a billion values never becomes a billion
// strings.
std::vector<std::string_view> tokens(const std::string& line, std::size_t max) {
  std::vector<std::string_view> out;
  std::size_t k = 0;
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r'; };
  while (k < line.size() && out.size() <= max) {
    while (k < line.size() && blank(line[k])) ++k;
    const std::size_t b = k;
    while (k < line.size() && !blank(line[k])) ++k;
    if (k > b) out.emplace_back(line.data() + b, k - b);
  }
  return out;
}

bool is_missing(std::string_view t) {
  std::string l(t);
  std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return l == "bad" || l == "nan" || l == "-" || l == "na" || l == "missing";
}

bool parse(std::string_view t, double& v) {
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

// The symbol of a length unit of `unit` metres among those a topography file states (m, mm, um,
// nm); none for another factor.
std::optional<std::string> length_symbol(double unit) {
  for (const char* u : {"m", "mm", "um", "nm"})
    if (std::abs(unit_factor(u, Dimension::length) / unit - 1.0) < 1e-12) return u;
  return std::nullopt;
}

std::string unit_name(double unit) { return length_symbol(unit).value_or(fmt::format("{:g} m", unit)); }

// A length for a message in the unit that reads best: 1e-09 -> "1 nm", 0.0001 -> "100 um".
std::string readable(double metres) {
  for (const char* u : {"m", "mm", "um", "nm"}) {
    const double f = unit_factor(u, Dimension::length);
    if (std::abs(metres) >= f) return fmt::format("{:.3g} {}", metres / f, u);
  }
  return fmt::format("{:.3g} m", metres);
}

// Where the unit of an ASCII file's lengths came from and how to change it: for the messages on
// implausible or out-of-range lengths, which a wrong unit explains more often than not.
std::string unit_hint(double unit, bool unit_in_file) {
  if (unit_in_file) return fmt::format("lengths were read in {} as the file's '# units:' line says", unit_name(unit));
  return fmt::format(
      "lengths were read in {} (no '# units:' line): if the file is in another unit, state it with "
      "a '# units: <unit>' line or --unit",
      unit_name(unit));
}

// The rules on lengths read from a file, after the unit (surface/height_grid.hpp's limits).
std::string spacing_rule(double h) {
  if (h == 0.0) return fmt::format("spacing must be positive: 0 m after the unit (at least {:g} m)", kMinSpacing);
  if (!(h > 0.0)) return "spacing must be positive";
  if (!(h >= kMinSpacing && h <= kMaxSpacing))
    return fmt::format("spacing {:g} m outside {:g} m to {:g} m", h, kMinSpacing, kMaxSpacing);
  return "";
}

}  // namespace

void check_grid_spacing(const std::string& file, int line, const std::string& key, const std::string& value, double h,
                        const std::string& hint) {
  if (const std::string rule = spacing_rule(h); !rule.empty())
    throw InputError(file, line, key, value, h > 0.0 && !hint.empty() ? rule + "; " + hint : rule);
}
void check_grid_height(const std::string& file, int line, const std::string& key, std::string_view value, double z,
                       const std::string& hint) {
  if (!(std::abs(z) <= kMaxHeight))
    throw InputError(file, line, key, std::string(value),
                     fmt::format("height {:g} m beyond +-{:g} m{}{}", z, kMaxHeight, hint.empty() ? "" : "; ", hint));
}
void check_valid_points(const surface::HeightGrid& g, const std::string& file, int line) {
  if (g.size() - g.missing() < surface::kMinValidPoints)
    throw InputError(file, line, "", "",
                     fmt::format("too few valid points ({} of {}; at least {} are needed)", g.size() - g.missing(),
                                 g.size(), surface::kMinValidPoints));
}

namespace {

void check_coordinate(const std::string& file, int line, const std::string& key, std::string_view value, double x,
                      const std::string& hint) {
  if (!(std::abs(x) <= kMaxCoordinate))
    throw InputError(file, line, key, std::string(value),
                     fmt::format("coordinate {:g} m beyond +-{:g} m; {}", x, kMaxCoordinate, hint));
}
InputError too_many_points(const std::string& file, int line) {
  return InputError(file, line, "", "", fmt::format("more than {} points (the limit of a grid)", kMaxGridPoints));
}

// A length on a header line: a bare number is in the file's unit, "0.5 um" carries its own. The
// number is read first, exponent included: "5e-1" is a bare number, never 5 with a unit "e-1".
double header_length(const std::string& value, double unit) {
  const std::string t = trim(value);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::result_out_of_range) throw std::invalid_argument("number beyond the range of a double");
  if (ec == std::errc{} && end == t.data() + t.size()) {
    if (!std::isfinite(v)) throw std::invalid_argument("value must be finite");
    return v * unit;
  }
  return parse_quantity(t, Dimension::length);
}

// surface::grid_from_points and surface::resample refuse a spacing that gives too many points.
surface::HeightGrid regrid(const std::string& file, double spacing, const std::function<surface::HeightGrid()>& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, "resample", fmt::format("{:g} m", spacing), e.what());
  }
}

ReadSurface read_xyz(const std::filesystem::path& path, const TopographyReadOptions& o) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(file, 0, "", "", "cannot open topography file");
  ReadSurface r;
  r.unit = o.unit;
  std::vector<double> xs, ys, zs;
  std::string line;
  int n = 0, first_data = 0;
  while (std::getline(in, line)) {
    ++n;
    if (units_line(line, file, n, first_data != 0, r.unit)) {
      r.unit_in_file = true;
      continue;
    }
    if (!line.empty() && line[0] == '#') continue;
    const auto t = tokens(line, 3);
    if (t.empty()) continue;
    double x = 0, y = 0, z = 0;
    const bool numeric_xy = t.size() == 3 && parse(t[0], x) && parse(t[1], y);
    const bool z_ok = numeric_xy && (parse(t[2], z) || is_missing(t[2]));
    if (!first_data) {
      if (!z_ok) continue;  // a header line of the profiler's export
      first_data = n;
    } else if (!z_ok) {
      throw InputError(file, n, "", line.substr(0, 80),
                       "malformed point: expected 'x y z' numbers (z may be Bad or NaN)");
    }
    if (xs.size() >= kMaxGridPoints) throw too_many_points(file, n);
    const bool measured = parse(t[2], z);
    if (!(std::abs(x * r.unit) <= kMaxCoordinate && std::abs(y * r.unit) <= kMaxCoordinate) ||
        (measured && !(std::abs(z * r.unit) <= kMaxHeight))) {  // the message's hint only when needed
      const std::string hint = unit_hint(r.unit, r.unit_in_file);
      check_coordinate(file, n, "x", t[0], x * r.unit, hint);
      check_coordinate(file, n, "y", t[1], y * r.unit, hint);
      check_grid_height(file, n, "z", t[2], z * r.unit, hint);
    }
    xs.push_back(x * r.unit);
    ys.push_back(y * r.unit);
    zs.push_back(measured ? z * r.unit : kNaN);
  }
  if (xs.empty()) throw InputError(file, n, "", "", "no data points");
  if (o.resample > 0.0) {
    r.grid = regrid(file, o.resample, [&] { return surface::grid_from_points(xs, ys, zs, o.resample); });
    check_valid_points(r.grid, file, n);
    return r;
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
  // The lattice the points span, against the points given, before it is allocated: an export
  // lists every pixel (missing ones as Bad), so a lattice of more than 4 cells a point is not one.
  const double cells = static_cast<double>(ux.size()) * static_cast<double>(uy.size());
  const std::string lattice = fmt::format("{} x {} from {} points", ux.size(), uy.size(), xs.size());
  if (cells > static_cast<double>(kMaxGridPoints))
    throw InputError(file, first_data, "lattice", lattice, fmt::format("more than {} grid points", kMaxGridPoints));
  if (cells > 4.0 * static_cast<double>(xs.size()))
    throw InputError(file, first_data, "lattice", lattice,
                     "fewer than one point per 4 lattice cells: not a grid export; bin a scattered cloud with "
                     "--resample SPACING");
  const double dx = (ux.back() - ux.front()) / (ux.size() - 1);
  const double dy = uy.size() > 1 ? (uy.back() - uy.front()) / (uy.size() - 1) : dx;
  check_grid_spacing(file, first_data, "x", fmt::format("{:g} m", dx), dx, unit_hint(r.unit, r.unit_in_file));
  check_grid_spacing(file, first_data, "y", fmt::format("{:g} m", dy), dy, unit_hint(r.unit, r.unit_in_file));
  r.grid = surface::make_grid(static_cast<int>(ux.size()), static_cast<int>(uy.size()), dx, dy);
  surface::HeightGrid& g = r.grid;
  std::fill(g.valid.begin(), g.valid.end(), 0);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const int i = static_cast<int>(std::lround((xs[k] - ux.front()) / dx));
    const int j = uy.size() > 1 ? static_cast<int>(std::lround((ys[k] - uy.front()) / dy)) : 0;
    if (std::isnan(zs[k])) continue;
    g.at(i, j) = zs[k];
    g.valid[static_cast<std::size_t>(j) * g.nx + i] = 1;
  }
  check_valid_points(g, file, n);
  return r;
}

ReadSurface read_grid(const std::filesystem::path& path, const TopographyReadOptions& o) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(file, 0, "", "", "cannot open topography file");
  ReadSurface r;
  r.unit = o.unit;
  double dx = o.spacing * o.unit, dy = 0.0;
  std::vector<double> values;  // row-major, `width` a row
  std::size_t width = 0, rows = 0;
  std::string line;
  int n = 0, spacing_line = 0;
  while (std::getline(in, line)) {
    ++n;
    std::string value;
    auto length = [&](const char* key) {
      try {
        return header_length(value, r.unit);
      } catch (const std::invalid_argument& e) {
        throw InputError(file, n, key, value, e.what());
      }
    };
    if (units_line(line, file, n, rows != 0 || spacing_line != 0, r.unit)) {
      r.unit_in_file = true;
      continue;
    }
    if (comment_value(line, "spacing", value) || comment_value(line, "dx", value)) {
      dx = length("spacing"), spacing_line = n;
      check_grid_spacing(file, n, "spacing", value, dx, unit_hint(r.unit, r.unit_in_file));
      continue;
    }
    if (comment_value(line, "dy", value)) {
      dy = length("dy");
      check_grid_spacing(file, n, "dy", value, dy, unit_hint(r.unit, r.unit_in_file));
      continue;
    }
    if (!line.empty() && line[0] == '#') continue;
    const auto t = tokens(line, kMaxGridPoints - values.size());
    if (t.empty()) continue;
    if (values.size() + t.size() > kMaxGridPoints) throw too_many_points(file, n);
    if (rows > 0 && t.size() != width)
      throw InputError(file, n, "", "", fmt::format("ragged row: {} values, the first row has {}", t.size(), width));
    for (const auto& tok : t) {
      double v = 0.0;
      if (parse(tok, v)) {
        if (!(std::abs(v * r.unit) <= kMaxHeight))
          check_grid_height(file, n, "", tok, v * r.unit, unit_hint(r.unit, r.unit_in_file));
        values.push_back(v * r.unit);
      } else if (is_missing(tok)) {
        values.push_back(kNaN);
      } else {
        throw InputError(file, n, "", std::string(tok.substr(0, 80)), "not a number or a missing-point marker");
      }
    }
    width = t.size();
    ++rows;
  }
  if (rows == 0) throw InputError(file, n, "", "", "no height rows");
  if (!(dx > 0.0))
    throw InputError(file, spacing_line, "spacing", "",
                     "grid spacing missing: give '# spacing: <length>' or --grid-spacing");
  check_grid_spacing(file, spacing_line, "spacing", fmt::format("{:g} m", dx), dx, unit_hint(r.unit, r.unit_in_file));
  if (width < 2) throw InputError(file, n, "", "", "a height grid needs at least 2 columns");
  r.grid = surface::make_grid(static_cast<int>(width), static_cast<int>(rows), dx, dy > 0.0 ? dy : dx);
  surface::set_heights(r.grid, values);
  check_valid_points(r.grid, file, n);
  return r;
}

ReadSurface read_hdf5(const std::filesystem::path& path) {
  const std::string file = path.string();
  start_hdf5();
  ReadSurface r;
  r.unit_in_file = true;  // metres by the format
  std::vector<double> z;
  hsize_t dims[2] = {0, 0};
  double dx = 0.0, dy = 0.0;
  try {
    const hid_t fid = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (fid < 0)
      throw InputError(file, 0, "", "", "not a readable HDF5 topography file (not HDF5, corrupt or truncated)");
    hdf5::Handle f(fid, H5Fclose, "file");
    if (H5Lexists(f, "z", H5P_DEFAULT) <= 0)
      throw InputError(file, 0, "/z", "", "missing dataset /z (heights [m], ny x nx)");
    const hid_t did = H5Dopen2(f, "/z", H5P_DEFAULT);
    if (did < 0) throw InputError(file, 0, "/z", "", "cannot open /z as a dataset (corrupt, or not a dataset)");
    hdf5::Handle d(did, H5Dclose, "dataset /z");
    hdf5::Handle type(H5Dget_type(d), H5Tclose, "type of /z");
    if (H5Tget_class(type) != H5T_FLOAT) throw InputError(file, 0, "/z", "", "/z must hold floating-point heights [m]");
    hdf5::Handle space(H5Dget_space(d), H5Sclose, "dataspace");
    if (H5Sget_simple_extent_ndims(space) != 2)
      throw InputError(file, 0, "/z", "", "/z must be a 2-D dataset (ny x nx)");
    hdf5::check(H5Sget_simple_extent_dims(space, dims, nullptr), "dimensions of /z");
    const std::string shape = fmt::format("{} x {}", dims[0], dims[1]);
    if (dims[1] < 2 || dims[0] < 1) throw InputError(file, 0, "/z", shape, "/z needs at least 2 points along x");
    // The declared size against the limit and against what the file holds, before allocating.
    if (dims[0] > kMaxGridPoints / dims[1])
      throw InputError(file, 0, "/z", shape, fmt::format("more than {} points (the limit of a grid)", kMaxGridPoints));
    const hsize_t points = dims[0] * dims[1];
    H5D_space_status_t status{};
    hdf5::check(H5Dget_space_status(d, &status), "storage status of /z");
    if (status != H5D_SPACE_STATUS_ALLOCATED)
      throw InputError(file, 0, "/z", shape, "the file does not store all of /z's values (never written)");
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
    const hsize_t stored = H5Dget_storage_size(d);
    hdf5::Handle plist(H5Dget_create_plist(d), H5Pclose, "creation properties of /z");
    const bool filtered = H5Pget_nfilters(plist) != 0;
    if (!ec && stored > file_bytes)
      throw InputError(file, 0, "/z", shape,
                       fmt::format("claims {} bytes of storage in a file of {} bytes (corrupt)", stored, file_bytes));
    if (!filtered && stored < points * H5Tget_size(type))
      throw InputError(file, 0, "/z", shape,
                       fmt::format("stores {} bytes, fewer than its {} values need (corrupt)", stored, points));
    auto attribute = [&](const char* name, double& value) {
      try {
        return hdf5::read_number_attribute(d, name, value);
      } catch (const std::runtime_error& e) {
        throw InputError(file, 0, std::string("/z ") + name, "", e.what());
      }
    };
    if (!attribute("dx", dx))
      throw InputError(file, 0, "/z dx", "", "attribute dx (spacing [m]) missing: one positive number");
    check_grid_spacing(file, 0, "/z dx", fmt::format("{}", dx), dx);
    if (!attribute("dy", dy)) dy = dx;
    check_grid_spacing(file, 0, "/z dy", fmt::format("{}", dy), dy);
    z.resize(static_cast<std::size_t>(points));
    hdf5::check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, z.data()), "read /z");
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(file, 0, "", "", std::string("not a readable HDF5 topography file (") + e.what() + ")");
  }
  r.grid = surface::make_grid(static_cast<int>(dims[1]), static_cast<int>(dims[0]), dx, dy);
  for (std::size_t k = 0; k < z.size(); ++k)  // NaN marks a missing point; infinities, absurd heights refused
    if (!std::isnan(z[k]) && !(std::abs(z[k]) <= kMaxHeight))
      check_grid_height(file, 0, fmt::format("/z[{}][{}]", k / dims[1], k % dims[1]), fmt::format("{}", z[k]), z[k],
                        "NaN alone marks a missing point");
  surface::set_heights(r.grid, z);
  check_valid_points(r.grid, file, 0);
  return r;
}

ReadSurface read_any(const std::filesystem::path& file, const TopographyReadOptions& o) {
  const TopographyFormat format = topography_format(file);
  const bool binary = format == TopographyFormat::hdf5 || format == TopographyFormat::x3p;
  if (const std::string why = data_file_problem(file, binary ? kNoSizeLimit : kMaxTopographyTextBytes); !why.empty())
    throw InputError(file.string(), 0, "", "", why);
  if (o.resample > 0.0 && !(o.resample >= kMinSpacing && o.resample <= kMaxSpacing))
    throw InputError(file.string(), 0, "resample", fmt::format("{:g} m", o.resample),
                     fmt::format("spacing outside {:g} m to {:g} m", kMinSpacing, kMaxSpacing));
  ReadSurface r;
  switch (format) {
    case TopographyFormat::xyz:
      r = read_xyz(file, o);
      break;
    case TopographyFormat::grid:
      r = read_grid(file, o);
      break;
    case TopographyFormat::hdf5:
      r = read_hdf5(file);
      break;
    case TopographyFormat::x3p:
      r.grid = read_x3p(file);
      r.unit_in_file = true;  // metres by ISO 25178-72
      break;
  }
  if (o.resample > 0.0 && format != TopographyFormat::xyz) {
    r.grid = regrid(file.string(), o.resample, [&] { return surface::resample(r.grid, o.resample); });
    check_valid_points(r.grid, file.string(), 0);
  }
  return r;
}

}  // namespace

TopographyFormat topography_format(const std::filesystem::path& file) {
  std::string e = file.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (e == ".xyz" || e == ".asc") return TopographyFormat::xyz;
  if (e == ".csv" || e == ".txt" || e == ".grd") return TopographyFormat::grid;
  if (e == ".h5" || e == ".hdf5") return TopographyFormat::hdf5;
  if (e == ".x3p") return TopographyFormat::x3p;
  throw InputError(file.string(), 0, "", "",
                   "unknown topography format (extensions: .xyz .asc, .csv .txt .grd, .h5 .hdf5, .x3p)");
}

surface::HeightGrid read_topography(const std::filesystem::path& file, const TopographyReadOptions& o) {
  return read_any(file, o).grid;
}

std::vector<std::string> unit_warnings(const std::string& file, const surface::HeightGrid& g, double unit,
                                       bool unit_in_file, bool check_spacing) {
  const TopographyFormat format = topography_format(file);
  const std::string hint =
      format == TopographyFormat::hdf5  ? "an HDF5 topography holds metres (/z, dx, dy); check how it was written"
      : format == TopographyFormat::x3p ? "an X3P holds metres (ISO 25178-72: Increment, Offset, heights); check "
                                          "how it was written"
                                        : unit_hint(unit, unit_in_file);
  std::vector<std::string> out;
  if (check_spacing && (std::min(g.dx, g.dy) < kPlausibleSpacing[0] || std::max(g.dx, g.dy) > kPlausibleSpacing[1]))
    out.push_back(fmt::format(
        "{}: warning: spacing {} x {} is implausible for a measured surface ({} to {} expected): {}", file,
        readable(g.dx), readable(g.dy), readable(kPlausibleSpacing[0]), readable(kPlausibleSpacing[1]), hint));
  double mean = 0.0, var = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.valid[k]) mean += g.z[k], ++n;
  mean /= static_cast<double>(std::max<std::size_t>(n, 1));
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.valid[k]) var += (g.z[k] - mean) * (g.z[k] - mean);
  const double rq = std::sqrt(var / static_cast<double>(std::max<std::size_t>(n, 1)));
  if (n > 0 && !(rq >= kPlausibleRq[0] && rq <= kPlausibleRq[1]))
    out.push_back(fmt::format("{}: warning: Rq {} is implausible for a measured flank ({} to {} expected): {}", file,
                              readable(rq), readable(kPlausibleRq[0]), readable(kPlausibleRq[1]), hint));
  return out;
}

LoadedSurface load_surface(const std::filesystem::path& file, const TopographyReadOptions& read,
                           const surface::CleanupOptions& cleanup) {
  ReadSurface r = read_any(file, read);
  LoadedSurface s{std::move(r.grid), {}, {}};
  try {
    s.cleanup = surface::clean_surface(s.grid, cleanup);
  } catch (const std::invalid_argument& e) {
    throw InputError(file.string(), 0, "", "", std::string("clean-up: ") + e.what());
  }
  s.warnings = unit_warnings(file.string(), s.grid, r.unit, r.unit_in_file, !(read.resample > 0.0));
  return s;
}

void write_topography(const std::filesystem::path& file, const surface::HeightGrid& g, double unit) {
  OutputSet set;
  add_topography(set, file, g, unit);
  set.commit();
}

void add_topography(OutputSet& outputs, const std::filesystem::path& file, const surface::HeightGrid& g, double unit) {
  g.validate();
  // Nothing the readers would refuse.
  if (const std::string rule = surface::height_rule(g); !rule.empty())
    throw std::invalid_argument(fmt::format("{}: {}: no reader would take the file back", file.string(), rule));
  const TopographyFormat format = topography_format(file);
  if (format == TopographyFormat::x3p) {
    outputs.add(file, [&](const std::filesystem::path& tmp) { write_x3p_archive(tmp, g); });  // in metres
    return;
  }
  if (format == TopographyFormat::hdf5) {
    outputs.add(file, [&](const std::filesystem::path& tmp) {
      start_hdf5();
      hdf5::NewFile f(tmp);
      hdf5::string_attribute(f, "geartrib_version", GEARTRIB_VERSION);
      hdf5::string_attribute(f, "content", "surface heights z[j][i] at x = i dx, y = j dy; NaN: missing point");
      {
        hsize_t dims[2] = {static_cast<hsize_t>(g.ny), static_cast<hsize_t>(g.nx)};
        hdf5::Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose, "dataspace");
        hdf5::Handle d(H5Dcreate2(f, "/z", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
                       "dataset /z");
        {
          const std::vector<double> z = surface::heights_or_nan(g);  // freed before the file's image is copied
          hdf5::check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, z.data()), "write /z");
        }
        hdf5::string_attribute(d, "units", "m");  // of z and of the spacings dx, dy
        hdf5::number_attribute(d, "dx", g.dx);
        hdf5::number_attribute(d, "dy", g.dy);
      }
      f.close();
    });
    return;
  }
  // The file states its unit by symbol: one it cannot state would be read back at the wrong scale.
  const std::optional<std::string> stated = length_symbol(unit);
  if (!stated)
    throw std::invalid_argument(fmt::format(
        "{}: the length unit of a text topography file must be m, mm, um or nm (got {:g} m)", file.string(), unit));
  const std::string& symbol = *stated;
  std::string out = "# geartrib surface\n# units: " + symbol + "\n";
  if (format == TopographyFormat::xyz) {
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        out += g.ok(i, j)
                   ? fmt::format("{:.10g} {:.10g} {:.10g}\n", i * g.dx / unit, j * g.dy / unit, g.at(i, j) / unit)
                   : fmt::format("{:.10g} {:.10g} Bad\n", i * g.dx / unit, j * g.dy / unit);
  } else {
    out += fmt::format("# spacing: {:.12g} {}\n# dy: {:.12g} {}\n", g.dx / unit, symbol, g.dy / unit, symbol);
    const char sep = file.extension() == ".csv" ? ',' : ' ';
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        if (i) out += sep;
        out += g.ok(i, j) ? fmt::format("{:.10g}", g.at(i, j) / unit) : std::string("NaN");
      }
      out += '\n';
    }
  }
  outputs.add_text(file, out);
}

}  // namespace geartrib::io
