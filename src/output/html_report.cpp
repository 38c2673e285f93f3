#include "output/html_report.hpp"

#include "output/hdf5_handles.hpp"
#include "output/table_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

namespace geartrib::io {

namespace {

using hdf5::Handle;
constexpr std::size_t kMaxValues = 100'000'000;  // a path's series: far beyond any run's positions
constexpr double kCelsius = 273.15;

// The result file, read by path ("/mesh/s_m"); absent groups and attributes are optional.
class ResultFile {
 public:
  explicit ResultFile(const std::filesystem::path& path)
      : path_(path), file_(open(path), H5Fclose, "file " + path.string()) {}
  bool has(const std::string& path) const {
    // Each level in turn (H5Lexists needs its parents).
    std::size_t at = 0;
    while ((at = path.find('/', at + 1)) != std::string::npos)
      if (H5Lexists(file_, path.substr(0, at).c_str(), H5P_DEFAULT) <= 0) return false;
    return H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0;
  }
  std::vector<double> numbers(const std::string& path) const {
    return has(path) ? hdf5::read_numbers(file_, path, kMaxValues) : std::vector<double>{};
  }
  std::vector<std::string> strings(const std::string& path) const {
    return has(path) ? hdf5::read_strings(file_, path) : std::vector<std::string>{};
  }
  std::string text(const std::string& path) const { return has(path) ? hdf5::read_string(file_, path) : ""; }
  std::optional<double> attribute(const std::string& group, const std::string& name) const {
    if (!has(group)) return std::nullopt;
    Handle g(H5Oopen(file_, group.c_str(), H5P_DEFAULT), H5Oclose, "object " + group);
    double v = 0.0;
    if (!hdf5::read_number_attribute(g, name, v)) return std::nullopt;
    return v;
  }
  std::string text_attribute(const std::string& group, const std::string& name) const {
    if (!has(group)) return "";
    Handle g(H5Oopen(file_, group.c_str(), H5P_DEFAULT), H5Oclose, "object " + group);
    std::string v;
    hdf5::read_string_attribute(g, name, v);
    return v;
  }

 private:
  static hid_t open(const std::filesystem::path& path) {
    if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path.string() + ": no such file");
    if (H5Fis_hdf5(path.c_str()) <= 0) throw std::runtime_error(path.string() + ": not an HDF5 file");
    return H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  }
  std::filesystem::path path_;
  Handle file_;
};

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

std::string num(double v, int digits = 4) {
  if (!std::isfinite(v)) return "&ndash;";
  return fmt::format("{:.{}g}", v, digits);
}

// A plain-text unit (io::engineering_value's) as HTML; the number's "1" shows nothing.
std::string html_unit(const std::string& unit) {
  if (unit == "1") return "";
  if (unit == "um") return "&micro;m";
  if (unit == "degC") return "&deg;C";
  if (unit == "N/(mm um)") return "N/(mm &micro;m)";
  if (unit == "N^0.5/mm") return "N<sup>0.5</sup>/mm";
  return escape(unit);
}

// --- inline SVG line plots ---

// A "nice" tick step (1, 2 or 5 x 10^k) giving about `n` intervals over `span`.
double tick_step(double span, int n) {
  const double raw = span / n, mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / mag;
  return (r < 1.5 ? 1.0 : r < 3.5 ? 2.0 : r < 7.5 ? 5.0 : 10.0) * mag;
}

struct Curve {
  std::string name;
  std::vector<double> y;
};

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"};

std::string svg_plot(const std::string& title, const std::string& x_label, const std::vector<double>& x,
                     const std::vector<Curve>& curves, const std::string& y_label,
                     const std::vector<std::pair<std::string, double>>& marks) {
  const double w = 640, h = 300, left = 70, right = 20, top = 30, bottom = 45;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
  for (double v : x) x0 = std::min(x0, v), x1 = std::max(x1, v);
  for (const auto& c : curves)
    for (double v : c.y)
      if (std::isfinite(v)) y0 = std::min(y0, v), y1 = std::max(y1, v);
  if (!(x1 > x0) || !(y1 >= y0)) return "";
  if (y1 - y0 < 1e-12 * std::max(1.0, std::abs(y1)))
    y0 -= 0.5 * std::max(1.0, std::abs(y0)), y1 += 0.5 * std::max(1.0, std::abs(y1));
  const double step = tick_step(y1 - y0, 5);
  y0 = std::floor(y0 / step) * step;
  y1 = std::ceil(y1 / step) * step;
  auto px = [&](double v) { return left + (v - x0) / (x1 - x0) * (w - left - right); };
  auto py = [&](double v) { return h - bottom - (v - y0) / (y1 - y0) * (h - top - bottom); };
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" role=\"img\" "
      "aria-label=\"{2}\">\n<text x=\"{3}\" y=\"18\" font-size=\"14\" font-weight=\"bold\">{2}</text>\n",
      w, h, escape(title), left);
  s += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", left, top,
                   w - left - right, h - top - bottom);
  for (double t = y0; t <= y1 + 0.5 * step; t += step)
    s += fmt::format(
        "<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/><text x=\"{3}\" y=\"{4:.1f}\" "
        "font-size=\"11\" text-anchor=\"end\">{5}</text>\n",
        left, w - right, py(t), left - 5, py(t) + 4, num(std::abs(t) < 1e-9 * step ? 0.0 : t, 4));
  const double xs = tick_step(x1 - x0, 6);
  for (double t = std::ceil(x0 / xs) * xs; t <= x1 + 1e-9 * xs; t += xs)
    s += fmt::format("<text x=\"{:.1f}\" y=\"{}\" font-size=\"11\" text-anchor=\"middle\">{}</text>\n", px(t),
                     h - bottom + 15, num(t, 4));
  for (const auto& [name, at] : marks)
    if (at >= x0 && at <= x1)
      s += fmt::format(
          "<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#999\" stroke-dasharray=\"3,3\"/><text "
          "x=\"{0:.1f}\" y=\"{3}\" font-size=\"11\" text-anchor=\"middle\">{4}</text>\n",
          px(at), top, h - bottom, top - 3, escape(name));
  for (std::size_t k = 0; k < curves.size(); ++k) {
    std::string points;
    for (std::size_t i = 0; i < x.size() && i < curves[k].y.size(); ++i)
      if (std::isfinite(curves[k].y[i])) points += fmt::format("{:.1f},{:.1f} ", px(x[i]), py(curves[k].y[i]));
    s += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\" points=\"{}\"/>\n", kColours[k % 5],
                     points);
    if (curves.size() > 1)
      s += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"{}\">{}</text>\n", w - right - 150,
                       top + 14 + 13 * static_cast<double>(k), kColours[k % 5], escape(curves[k].name));
  }
  s += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
                   0.5 * (left + w - right), h - 8, x_label);
  s += fmt::format(
      "<text x=\"14\" y=\"{0}\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 14 {0})\">{1}</text>\n",
      0.5 * (top + h - bottom), y_label);
  return s + "</svg>\n";
}

std::vector<double> scaled(std::vector<double> v, double scale, double offset = 0.0) {
  for (double& x : v) x = x * scale + offset;
  return v;
}

// The number at the start of a parameter's stored value ("0.006 m" -> 0.006); NaN when none.
double leading_number(const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  return end == value.c_str() ? NAN : v;
}

}  // namespace

std::string html_report(const std::filesystem::path& result, const std::string& name) {
  const ResultFile f(result);
  if (!f.has("/mesh/s_m") || !f.has("/parameters/key"))
    throw std::runtime_error(result.string() + ": not a `geartrib run` result (no /mesh/s_m or /parameters)");
  std::map<std::string, std::string> p;
  {
    const auto keys = f.strings("/parameters/key"), values = f.strings("/parameters/value");
    for (std::size_t i = 0; i < keys.size() && i < values.size(); ++i) p[keys[i]] = values[i];
  }
  auto param = [&](const std::string& key) { return p.count(key) ? leading_number(p[key]) : NAN; };
  auto mesh_attr = [&](const std::string& name) { return f.attribute("/mesh", name).value_or(NAN); };
  const std::string title = p.count("title") ? p["title"] : name;

  std::string h = R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
)";
  h += "<title>geartrib report: " + escape(title) + "</title>\n";
  h += R"(<style>
body{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1em}td,th{border:1px solid #bbb;padding:2px 6px;font-size:13px}
th{background:#eee}td.n{text-align:right;font-variant-numeric:tabular-nums}tr.assumed td{background:#fff6d6}
.low{color:#b00;font-weight:bold}pre{background:#f6f6f6;padding:.5em;overflow-x:auto;font-size:12px}
.note{font-size:13px;color:#444}h2{border-bottom:1px solid #ccc;margin-top:1.5em}
</style></head><body>
)";
  h += "<h1>Calculation report</h1>\n<p><b>" + escape(title) + "</b></p>\n";
  h += fmt::format(
      "<p class=\"note\">geartrib {} &middot; result file {} &middot; case {} &middot; contact fidelity {}, "
      "asperity model {}</p>\n",
      escape(f.text_attribute("/meta", "version")), escape(name), escape(f.text_attribute("/scene", "file")),
      escape(f.text_attribute("/meta", "fidelity")), escape(f.text_attribute("/meta", "asperity_model")));

  // --- safety factors ---
  const bool rated = f.has("/rating/symbol");
  h += "<h2 id=\"safety\">Safety factors</h2>\n";
  if (rated) {
    h += "<p>Rated: " + escape(f.text_attribute("/rating", "methods")) +
         ".</p>\n<table><tr><th>safety</th><th>pinion</th><th>wheel</th><th>method</th></tr>\n";
    // A safety below 1 is marked (lambda_GF,min is a film ratio, not a safety: never marked).
    auto cell = [&](const char* name) {
      const auto v = f.attribute("/rating", name);
      if (!v) return std::string("<td>not rated</td>");
      const bool low = *v < 1.0 && std::string(name) != "lambda_GF_min";
      return fmt::format("<td class=\"n{}\">{}</td>", low ? " low" : "", num(*v, 4));
    };
    h += "<tr><td>S<sub>H</sub> pitting</td>" + cell("S_H_pinion") + cell("S_H_wheel") +
         "<td>ISO 6336-2 method B</td></tr>\n";
    h += "<tr><td>S<sub>F</sub> tooth root</td>" + cell("S_F_pinion") + cell("S_F_wheel") +
         "<td>ISO 6336-3 method B</td></tr>\n";
    h += "<tr><td>S<sub>B</sub> scuffing, flash temperature</td>" + cell("S_B") +
         "<td></td><td>ISO/TS 6336-20</td></tr>\n";
    h += "<tr><td>S<sub>intS</sub> scuffing, integral temperature</td>" + cell("S_intS") +
         "<td></td><td>ISO/TS 6336-21</td></tr>\n";
    h += "<tr><td>S<sub>&lambda;</sub> micropitting</td>" + cell("S_lambda") +
         "<td></td><td>ISO/TS 6336-22 method B</td></tr>\n";
    h += "<tr><td>&lambda;<sub>GF,min</sub></td>" + cell("lambda_GF_min") +
         "<td></td><td>ISO/TS 6336-22</td></tr>\n</table>\n";
    if (f.attribute("/rating", "assumed_inputs").value_or(0.0) > 0.0)
      h += "<p class=\"note\">Rows shaded in the factor table rest on an assumed input (its note and the data file's "
           "source say which).</p>\n";
    const auto findings = f.strings("/rating/findings");
    if (!findings.empty()) {
      h += "<ul>\n";
      for (const auto& s : findings) h += "<li>" + escape(s) + "</li>\n";
      h += "</ul>\n";
    }
  } else {
    h += "<p>Not rated: the case names no [rating] methods (geartrib rate computes them).</p>\n";
  }

  // --- gear data ---
  h += "<h2 id=\"gears\">Gear data</h2>\n<table><tr><th></th><th>pinion</th><th>wheel</th><th>unit</th></tr>\n";
  auto row2 = [&](const std::string& label, double a, double b, const std::string& unit) {
    h += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td>{}</td></tr>\n", label,
                     num(a, 6), num(b, 6), unit);
  };
  row2("teeth z", param("pinion.teeth"), param("wheel.teeth"), "");
  row2("profile shift x", param("pinion.profile_shift"), param("wheel.profile_shift"), "");
  for (const char* d : {"reference", "base", "tip", "root", "sap", "eap"}) {
    const std::string label = std::string(d) == "sap"   ? "start of active profile d<sub>Nf</sub>"
                              : std::string(d) == "eap" ? "end of active profile d<sub>Na</sub>"
                                                        : std::string(d) + " diameter";
    row2(label, 1e3 * mesh_attr(fmt::format("pinion_{}_diameter_m", d)),
         1e3 * mesh_attr(fmt::format("wheel_{}_diameter_m", d)), "mm");
  }
  for (const char* pt : {"A", "B", "C", "D", "E"})
    row2(fmt::format("diameter at {}", pt), 1e3 * mesh_attr(fmt::format("pinion_diameter_at_{}_m", pt)),
         1e3 * mesh_attr(fmt::format("wheel_diameter_at_{}_m", pt)), "mm");
  h += "</table>\n<table><tr><th>pair</th><th>value</th><th>unit</th></tr>\n";
  auto row1 = [&](const std::string& label, double v, const std::string& unit) {
    h += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td>{}</td></tr>\n", label, num(v, 6), unit);
  };
  row1("module m", 1e3 * param("gear_pair.module"), "mm");
  row1("pressure angle &alpha;", param("gear_pair.pressure_angle") * 180.0 / std::numbers::pi, "deg");
  row1("face width b", 1e3 * param("gear_pair.face_width"), "mm");
  row1("transverse contact ratio &epsilon;<sub>&alpha;</sub>", mesh_attr("contact_ratio"), "");
  row1("base pitch p<sub>b</sub>", 1e3 * mesh_attr("base_pitch_m"), "mm");
  h += "</table>\n";

  // --- operating point ---
  h += "<h2 id=\"operating\">Operating point</h2>\n<table><tr><th></th><th>value</th><th>unit</th></tr>\n";
  row1("pinion torque T<sub>1</sub>", param("operating.pinion_torque"), "N m");
  row1("pinion speed n<sub>1</sub>", param("operating.pinion_speed") * 60.0 / (2.0 * std::numbers::pi), "1/min");
  if (f.has("/lubrication")) {
    row1("oil temperature &theta;<sub>oil</sub>",
         f.attribute("/lubrication", "oil_temperature_K").value_or(NAN) - kCelsius, "&deg;C");
    row1("bulk temperature &theta;<sub>M</sub>",
         f.attribute("/lubrication", "bulk_temperature_K").value_or(NAN) - kCelsius, "&deg;C");
    h += "<tr><td>lubricant</td><td colspan=\"2\">" + escape(f.text_attribute("/lubrication", "lubricant")) +
         "</td></tr>\n";
  }
  h += "</table>\n";

  // --- the rating factors ---
  if (rated) {
    const auto symbol = f.strings("/rating/symbol"), gear = f.strings("/rating/gear"), unit = f.strings("/rating/unit"),
               clause = f.strings("/rating/clause"), note = f.strings("/rating/note");
    const auto value = f.numbers("/rating/value"), assumed = f.numbers("/rating/assumed");
    h +=
        "<h2 id=\"factors\">Rating factors</h2>\n<table><tr><th>symbol</th><th>gear</th><th>value</th><th>unit</th><th>clause</th><th>assumed</th></tr>\n";
    for (std::size_t i = 0; i < symbol.size() && i < value.size(); ++i) {
      const bool a = i < assumed.size() && assumed[i] > 0.0;
      const EngineeringValue e = engineering_value(symbol[i], value[i], i < unit.size() ? unit[i] : "");
      const double v = e.value;
      const std::string u = html_unit(e.unit);
      h += fmt::format("<tr{}><td>{}</td><td>{}</td><td class=\"n\">{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                       a ? " class=\"assumed\"" : "", escape(symbol[i]), escape(i < gear.size() ? gear[i] : ""),
                       num(v, 5), u, escape(i < clause.size() ? clause[i] : ""),
                       a ? "yes" + (i < note.size() && !note[i].empty() ? ": " + escape(note[i]) : std::string()) : "");
    }
    h += "</table>\n";
  }

  // --- along the path ---
  const std::vector<double> s = f.numbers("/mesh/s_m");
  std::vector<double> diameter(s.size());
  const double r_b1 = 0.5 * mesh_attr("pinion_base_diameter_m");
  for (std::size_t i = 0; i < s.size(); ++i) diameter[i] = 2e3 * std::hypot(r_b1, s[i]);
  std::vector<std::pair<std::string, double>> marks;
  for (const char* pt : {"A", "B", "C", "D", "E"}) marks.emplace_back(pt, 1e3 * mesh_attr(fmt::format("s_{}_m", pt)));
  const std::vector<double> s_mm = scaled(s, 1e3);
  const std::string x_label = "roll length from T1 [mm] (pinion diameter " +
                              num(diameter.empty() ? NAN : diameter.front(), 5) + " to " +
                              num(diameter.empty() ? NAN : diameter.back(), 5) + " mm)";
  h += "<h2 id=\"path\">Along the path of contact</h2>\n";
  if (f.has("/lubrication/points/s_m")) {
    const auto names = f.strings("/lubrication/points/point");
    const auto ps = f.numbers("/lubrication/points/s_m");
    struct Column {
      const char* title;
      std::string path;
      double scale, offset;
    };
    const Column cols[] = {
        {"line load [N/mm]", "/lubrication/points/line_load_N_per_m", 1e-3, 0.0},
        {"film h [&micro;m]", "/lubrication/points/film_m", 1e6, 0.0},
        {"&lambda; (mean gap)", "/lubrication/points/lambda_mean_gap", 1.0, 0.0},
        {"&lambda;<sub>GF</sub> ISO", "/lubrication/points/iso_lambda_gf", 1.0, 0.0},
        {"asperity share", "/lubrication/points/asperity_load_share", 1.0, 0.0},
        {"friction &mu;", "/lubrication/points/friction_coefficient", 1.0, 0.0},
        {"flash &theta;<sub>fl</sub> [K]", "/lubrication/points/flash_temperature_K", 1.0, 0.0},
        {"contact &theta;<sub>B</sub> [&deg;C]", "/lubrication/points/contact_temperature_K", 1.0, -kCelsius},
        {"ISO &theta;<sub>B</sub> [&deg;C]", "/lubrication/points/iso_contact_temperature_K", 1.0, -kCelsius}};
    h += "<table><tr><th>point</th><th>pinion d [mm]</th><th>wheel d [mm]</th>";
    for (const auto& c : cols) h += std::string("<th>") + c.title + "</th>";
    h += "</tr>\n";
    std::vector<std::vector<double>> data;
    for (const auto& c : cols) data.push_back(f.numbers(c.path));
    const double r_b2 = 0.5 * mesh_attr("wheel_base_diameter_m"), t1t2 = mesh_attr("line_of_action_m");
    for (std::size_t i = 0; i < names.size() && i < ps.size(); ++i) {
      h += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>", escape(names[i]),
                       num(2e3 * std::hypot(r_b1, ps[i]), 6), num(2e3 * std::hypot(r_b2, t1t2 - ps[i]), 6));
      for (std::size_t k = 0; k < data.size(); ++k)
        h += "<td class=\"n\">" + num(i < data[k].size() ? data[k][i] * cols[k].scale + cols[k].offset : NAN) + "</td>";
      h += "</tr>\n";
    }
    h += "</table>\n";
  }
  h += svg_plot("Load share", x_label, s_mm, {{"load share [-]", f.numbers("/mesh/load_share")}}, "load share [-]",
                marks);
  h += svg_plot("Hertz pressure", x_label, s_mm, {{"p_H", scaled(f.numbers("/mesh/hertz_p0_Pa"), 1e-6)}}, "p0 [MPa]",
                marks);
  if (f.has("/lubrication/film_m")) {
    h += svg_plot("Film thickness", x_label, s_mm,
                  {{"film h", scaled(f.numbers("/lubrication/film_m"), 1e6)},
                   {"ISO h_Y", scaled(f.numbers("/lubrication/iso_film_hy_m"), 1e6)}},
                  "film [um]", marks);
    h += svg_plot("Specific film thickness", x_label, s_mm,
                  {{"lambda (mean gap)", f.numbers("/lubrication/lambda_mean_gap")},
                   {"lambda_GF (ISO)", f.numbers("/lubrication/iso_lambda_gf")}},
                  "lambda [-]", marks);
    h += svg_plot(
        "Temperatures", x_label, s_mm,
        {{"contact (model)", scaled(f.numbers("/lubrication/contact_temperature_K"), 1.0, -kCelsius)},
         {"contact (ISO/TS 6336-20)", scaled(f.numbers("/lubrication/iso_contact_temperature_K"), 1.0, -kCelsius)}},
        "temperature [degC]", marks);
    h += svg_plot("Friction coefficient", x_label, s_mm, {{"mu", f.numbers("/lubrication/friction_coefficient")}},
                  "mu [-]", marks);
  }
  if (f.has("/contact/real_area_ratio"))
    h += svg_plot("Real contact area", x_label, s_mm, {{"A_r/A", f.numbers("/contact/real_area_ratio")}}, "A_r/A [-]",
                  marks);

  // --- validity ---
  h += "<h2 id=\"validity\">Where the models hold</h2>\n";
  h += "<p><b>Regime:</b> " + escape(f.text_attribute("/contact/validity", "regime")) + "</p>\n";
  h += "<p>" + escape(f.text_attribute("/contact/validity", "verdict")) + "</p>\n";
  const auto warnings = f.strings("/meta/warnings");
  if (!warnings.empty()) {
    h += "<h3>Warnings</h3>\n<ul>\n";
    for (const auto& w : warnings) h += "<li>" + escape(w) + "</li>\n";
    h += "</ul>\n";
  }

  // --- the scene ---
  h += "<h2 id=\"scene\">The case as run</h2>\n<details><summary>case file (with the --set changes)</summary><pre>" +
       escape(f.text("/scene")) + "</pre></details>\n";
  h +=
      "<details><summary>every parameter, its value and where it came from</summary><table><tr><th>key</th><th>value</th><th>origin</th></tr>\n";
  {
    const auto keys = f.strings("/parameters/key"), values = f.strings("/parameters/value"),
               origins = f.strings("/parameters/origin");
    for (std::size_t i = 0; i < keys.size(); ++i)
      h += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", escape(keys[i]),
                       escape(i < values.size() ? values[i] : ""), escape(i < origins.size() ? origins[i] : ""));
  }
  h += "</table></details>\n</body></html>\n";
  return h;
}

}  // namespace geartrib::io
