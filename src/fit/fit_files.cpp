#include "fit/fit_files.hpp"

#include "config/input_error.hpp"
#include "config/text_lines.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace geartrib::io {

namespace {
std::string identifier(std::string s) {
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}
}  // namespace

fit::FitData read_fit_data(const std::filesystem::path& file) {
  fit::FitData d;
  d.name = file.string();
  std::istringstream in(read_data_file(file, kMaxTableFileBytes));  // a regular file of at most 64 MiB
  enum class Kind { observed, std_dev, weight };
  struct Col {
    Kind kind;
    std::size_t index;  // into d.columns
  };
  std::vector<Col> cols;
  std::string line;
  int n = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++n;
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s.front() == '#') {
      if (auto entry = comment_entry(s)) d.provenance.push_back(std::move(*entry));
      continue;
    }
    const auto cells = split_csv(s);
    if (!header) {
      header = true;
      if (cells.empty() || cells[0] != "delta_star")
        throw InputError(d.name, n, cells.empty() ? "" : cells[0], "", "the first column must be delta_star");
      for (std::size_t i = 1; i < cells.size(); ++i) {
        const std::string& h = cells[i];
        try {
          if (h == "weight") {
            cols.push_back({Kind::weight, 0});
          } else if (h.rfind("sd_", 0) == 0) {
            const fit::Observable o = fit::parse_observable(h.substr(3));
            std::size_t k = 0;
            while (k < d.columns.size() && d.columns[k].what != o) ++k;
            if (k == d.columns.size())
              throw std::invalid_argument("a standard deviation column must follow its quantity's column");
            cols.push_back({Kind::std_dev, k});
          } else {
            d.columns.push_back({fit::parse_observable(h), {}, {}});
            cols.push_back({Kind::observed, d.columns.size() - 1});
          }
        } catch (const std::invalid_argument& e) {
          throw InputError(d.name, n, h, "", e.what());
        }
      }
      continue;
    }
    if (cells.size() != cols.size() + 1)
      throw InputError(d.name, n, "", s, fmt::format("row has {} cells, the header {}", cells.size(), cols.size() + 1));
    // A cell's value; `column` counts from 1 (delta_star), for the message.
    auto number = [&](const std::string& cell, const std::string& key, std::size_t column, bool allow_empty) {
      if (cell.empty()) {
        if (allow_empty) return std::numeric_limits<double>::quiet_NaN();
        throw InputError(d.name, n, key, "", fmt::format("missing value (column {})", column));
      }
      double v = 0.0;
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
      if (ec != std::errc{} || end != cell.data() + cell.size() || !std::isfinite(v))
        throw InputError(d.name, n, key, cell, fmt::format("not a finite number (column {})", column));
      return v;
    };
    auto check = [&](const std::string& why, const std::string& key, const std::string& cell, std::size_t column) {
      if (!why.empty()) throw InputError(d.name, n, key, cell, fmt::format("{} (column {})", why, column));
    };
    d.delta_star.push_back(number(cells[0], "delta_star", 1, false));
    check(fit::delta_star_problem(d.delta_star.back()), "delta_star", cells[0], 1);
    d.line.push_back(n);
    d.weight.push_back(1.0);
    for (auto& c : d.columns) {
      c.values.push_back(std::numeric_limits<double>::quiet_NaN());
      c.std_dev.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const std::string& cell = cells[i + 1];
      const std::size_t column = i + 2;
      switch (cols[i].kind) {
        case Kind::weight: {
          const double w = number(cell, "weight", column, false);
          if (!(w >= 0.0 && w <= fit::kMaxRowWeight))
            check(fmt::format("a row weight must lie in [0, {:g}]", fit::kMaxRowWeight), "weight", cell, column);
          d.weight.back() = w;
          break;
        }
        case Kind::observed: {
          const fit::Observable what = d.columns[cols[i].index].what;
          const std::string key(fit::to_string(what));
          const double v = number(cell, key, column, true);
          if (!std::isnan(v)) check(fit::observation_problem(what, v), key, cell, column);
          d.columns[cols[i].index].values.back() = v;
          break;
        }
        case Kind::std_dev: {
          const std::string key = "sd_" + std::string(fit::to_string(d.columns[cols[i].index].what));
          const double sd = number(cell, key, column, true);
          if (!std::isnan(sd)) check(fit::std_dev_problem(sd), key, cell, column);
          d.columns[cols[i].index].std_dev.back() = sd;
          break;
        }
      }
    }
  }
  if (d.delta_star.empty()) throw InputError(d.name, n, "", "", "reference data has no rows");
  // Columns without any standard deviation keep an empty list (relative residuals).
  for (auto& c : d.columns) {
    bool any = false;
    for (double v : c.std_dev) any = any || !std::isnan(v);
    if (!any) c.std_dev.clear();
  }
  return d;
}

namespace {
// A standard error or correlation, or "n/a" where the covariance leaves it undefined (never "nan"
// in an output).
std::string stat(double v, const char* spec) {
  return std::isfinite(v) ? fmt::format(fmt::runtime(spec), v) : std::string("n/a");
}
}  // namespace

std::string format_fit_report(const fit::FitResult& r) {
  std::string out =
      fmt::format("Fit of model '{}' ({} iterations, final cost {:.6g})\n\n", r.model, r.iterations, r.final_cost);
  out += fmt::format("{:<22} {:>16} {:>14}  {}\n", "constant", "value", "std error", "");
  for (const auto& c : r.constants)
    out += fmt::format("{:<22} {:>16.10g} {:>14}  {}\n", c.name, c.value, stat(c.std_error, "{:.4g}"),
                       c.free ? "free" : "fixed");
  std::vector<std::string> free;
  for (const auto& c : r.constants)
    if (c.free) free.push_back(c.name);
  out += "\nCorrelation of the free constants\n";
  out += fmt::format("{:<22}", "");
  for (std::size_t j = 0; j < free.size(); ++j) out += fmt::format(" {:>8}", j + 1);
  out += "\n";
  for (std::size_t i = 0; i < free.size(); ++i) {
    out += fmt::format("{:<18} ({:>1})", free[i], i + 1);
    for (double v : r.correlation[i]) out += fmt::format(" {:>8}", stat(v, "{:.4f}"));
    out += "\n";
  }
  out += "\nRoot-mean-square relative error per observed column\n";
  for (const auto& [o, v] : r.rms_relative) out += fmt::format("  {:<26} {:.4g}\n", fit::to_string(o), v);
  out += "... per data set\n";
  for (const auto& x : r.rms_by_data)
    out += fmt::format("  {:<48} {:<26} {:.4g}\n", x.data, fit::to_string(x.what), x.rms);
  out += "\nResiduals (model/observed - 1)\n";
  out += fmt::format("{:<48} {:>5} {:>12} {:<26} {:>14} {:>14} {:>10}\n", "data", "line", "delta_star", "quantity",
                     "observed", "model", "relative");
  for (const auto& x : r.residuals)
    out += fmt::format("{:<48} {:>5} {:>12.6g} {:<26} {:>14.8g} {:>14.8g} {:>10}\n", x.data, x.line, x.delta_star,
                       fit::to_string(x.what), x.observed, x.model, stat(x.relative, "{:.3e}"));
  out += "\n" + r.ceres_report;
  return out;
}

std::string format_fit_toml(const fit::FitResult& r, const std::string& provenance) {
  std::string out = "# Fitted by geartrib fit: " + provenance + "\n";
  for (const auto& [o, v] : r.rms_relative)
    out += fmt::format("# rms relative error of {}: {:.4g}\n", fit::to_string(o), v);
  out += fmt::format("[asperity.constants.{}]\n", r.model);
  for (const auto& c : r.constants)
    if (c.free)
      out += fmt::format("{} = {:.12g}  # std error {}\n", c.name, c.value,
                         std::isfinite(c.std_error) ? fmt::format("{:.4g}", c.std_error) : "not identifiable");
  return out;
}

std::string format_fit_cpp(const fit::FitResult& r, const std::string& provenance) {
  std::string out =
      "// Generated by `geartrib fit --emit-cpp` (" + provenance + "): the default constants of the '" + r.model +
      "' model.\n// Do not edit by hand; rerun the fit.\n#pragma once\n\nnamespace geartrib::asperity::fitted {\n\n";
  for (const auto& c : r.constants)
    out += fmt::format("inline constexpr double {}_{} = {:.17g};\n", identifier(r.model), c.name, c.value);
  out += "\n}  // namespace geartrib::asperity::fitted\n";
  return out;
}

}  // namespace geartrib::io
