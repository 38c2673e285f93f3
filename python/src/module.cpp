// geartrib's Python module, the compiled half (_geartrib): cases, the mesh cycle, the kinematics,
// the asperity laws over arrays of delta*, surface statistics of a height array, the boundary
// elements on a profile, and one sweep point at a time with the sweep's table. The package
// (python/geartrib/__init__.py) builds the user's API on it: xarray/pandas results, Dask sweeps.
//
// Everything here converts Python values to the C++ types, releases the GIL and calls the same
// functions the command line calls (src/runs/), so the numbers are the command's to the last
// digit. io::InputError becomes geartrib.InputError (a ValueError) with the command line's
// located message and its parts as attributes; std::invalid_argument a ValueError; other
// failures a RuntimeError.
#include "case/asperity_setup.hpp"
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_parameters.hpp"
#include "config/case_prepare.hpp"
#include "config/case_records.hpp"
#include "config/input_error.hpp"
#include "config/text_lines.hpp"
#include "contact/fidelity_registry.hpp"
#include "contact/half_plane_bem.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/run_summary.hpp"
#include "material/material.hpp"
#include "output/column_table.hpp"
#include "runs/asperity_columns.hpp"
#include "runs/kinematics_table.hpp"
#include "runs/mesh_cycle.hpp"
#include "runs/surface_statistics_table.hpp"
#include "runs/sweep_plan.hpp"
#include "runs/sweep_points.hpp"
#include "surface/height_grid.hpp"
#include "surface/surface_statistics.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace geartrib;

namespace {

using Changes = std::vector<std::pair<std::string, std::string>>;

std::vector<io::CaseChange> to_changes(const Changes& changes) {
  std::vector<io::CaseChange> out;
  for (const auto& [key, value] : changes) out.push_back({key, value});
  return out;
}

// Where a case comes from: its file, or its text with the name standing for the file in messages
// and the folder its relative file names are taken from.
struct CaseSource {
  std::string file;
  std::optional<std::string> text;
  std::string name;
  std::string directory;
  Case load(const std::vector<io::CaseChange>& changes, unsigned parts = io::kMeshCycleParts) const {
    return io::prepare_case(text ? io::load_case_text(*text, name, changes, parts, directory)
                                 : io::load_case(file, changes, parts));
  }
};

CaseSource source_of(const std::string& file, const std::optional<std::string>& text, const std::string& name,
                     const std::string& directory) {
  return CaseSource{file, text, name.empty() ? file : name, directory};
}

py::array_t<double> to_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::list series_list(const std::vector<contact::Series>& group) {
  py::list out;
  for (const auto& s : group) out.append(py::make_tuple(s.name, s.unit, to_array(s.values)));
  return out;
}

// A summary's texts and values into `d` by the names of the HDF5 attributes, each after `prefix`.
void add_summary(py::dict& d, const contact::Summary& s, const std::string& prefix = "") {
  for (const auto& t : s.texts) d[py::str(prefix + t.name)] = t.value;
  for (const auto& v : s.values) d[py::str(prefix + v.name)] = v.value;
}

// The mesh cycle's result: its series by group and its summaries (contact/run_summary.hpp: the
// HDF5 file's attributes by the same names; /meta's and /contact/validity's at the top).
py::dict result_dict(const contact::MeshContactResult& r) {
  py::dict d;
  d["mesh"] = series_list(r.mesh);
  d["contact"] = series_list(r.contact);
  d["validity"] = series_list(r.validity);
  d["lubrication"] = series_list(r.lubrication);
  // Deterministic runs: the statistical model on the same flanks (empty otherwise), the pressure
  // across the strip at the positions kept (empty: none kept) and the running-in (when run).
  d["statistical"] = series_list(r.statistical);
  // A kept profile's place on the path and its abscissae.
  auto located = [](const auto& p) {
    py::dict q;
    q["position"] = p.position;
    q["point"] = p.point;
    q["s_m"] = p.s;
    q["x_m"] = to_array(p.x);
    return q;
  };
  py::list profiles;
  for (const auto& p : r.pressure_profiles) {
    py::dict q = located(p);
    q["pressure_Pa"] = to_array(p.pressure);
    profiles.append(q);
  }
  d["pressure_profiles"] = profiles;
  // Mixed-EHL runs: the windows' series, the profiles through the contact kept, the summary.
  d["mixed_ehl"] = series_list(r.mixed_ehl);
  py::list ehl_profiles;
  for (const auto& p : r.ehl_profiles) {
    py::dict q = located(p);
    for (const auto& [name, at] : {std::pair{"peak", &p.peak}, std::pair{"middle", &p.middle}}) {
      const std::string k = name;
      q[py::str(k + "_time_s")] = at->time;
      q[py::str(k + "_pressure_Pa")] = to_array(at->pressure);
      q[py::str(k + "_film_m")] = to_array(at->film);
      q[py::str(k + "_shear_Pa")] = to_array(at->shear);
      q[py::str(k + "_state")] = to_array(at->state);
    }
    ehl_profiles.append(q);
  }
  d["mixed_ehl_profiles"] = ehl_profiles;
  if (r.mixed_ehl_summary) {
    py::dict q;
    add_summary(q, contact::mixed_ehl_summary(*r.mixed_ehl_summary));
    d["mixed_ehl_summary"] = q;
  }
  if (r.running_in) {
    const auto& ri = *r.running_in;
    py::dict q;
    add_summary(q, contact::running_in_summary(ri));
    q["history"] = series_list(ri.history);
    const char* gear[2] = {"pinion", "wheel"};
    for (int g = 0; g < 2; ++g) {
      const std::string name = gear[g];
      q[py::str(name + "_profile_initial_m")] = to_array(ri.initial[g]);
      q[py::str(name + "_profile_final_m")] = to_array(ri.final[g]);
    }
    d["running_in"] = q;
  }
  if (!r.synthesis.empty()) {
    // Flanks synthesised from a measured patch: the file's /synthesis/<gear> attributes as "<gear>.<name>".
    py::dict q;
    for (const auto& f : r.synthesis) add_summary(q, contact::synthesis_summary(f), f.gear + ".");
    d["synthesis"] = q;
  }
  add_summary(d, contact::validity_summary(r));
  d["warnings"] = r.warnings;
  add_summary(d, contact::surface_summary(r));
  py::dict path;
  add_summary(path, contact::path_summary(r.path));
  add_summary(path, contact::gear_summary(r));
  if (r.tooth_contact) add_summary(path, contact::tooth_contact_summary(*r.tooth_contact));
  d["path"] = path;
  py::dict stages;
  for (const auto& st : r.stages) stages[py::str(st.name)] = st.seconds;
  d["stages_s"] = stages;
  if (r.lubrication_summary) {
    const auto& l = *r.lubrication_summary;
    py::dict s;
    add_summary(s, contact::lubrication_summary(l));
    py::dict points;
    std::vector<std::string> names;
    for (const auto& p : l.points) names.push_back(p.name);
    points["point"] = names;
    for (const auto& q : contact::named_point_series(l)) points[py::str(q.name)] = q.values;
    s["points"] = points;
    d["lubrication_summary"] = s;
  }
  if (r.rating) {
    // The ratings as /rating holds them: the verdict's values (NaN where not rated), the factor table
    // as parallel lists, the findings.
    py::dict q;
    add_summary(q, contact::rating_summary(*r.rating));
    py::list factors;
    for (const auto& f : r.rating->factors) {
      py::dict row;
      row["symbol"] = f.symbol;
      row["gear"] = f.gear == 0 ? "pinion" : f.gear == 1 ? "wheel" : "pair";
      row["value"] = f.value;
      row["unit"] = f.unit;
      row["clause"] = f.clause;
      row["assumed"] = f.assumed;
      row["note"] = f.note;
      factors.append(row);
    }
    q["factors"] = factors;
    q["findings"] = r.rating->findings;
    d["rating"] = q;
  }
  return d;
}

// A sweep point as plain Python values (a Dask task's result travels pickled).
py::dict point_dict(const runs::SweepPoint& p) {
  py::dict d;
  d["index"] = p.index;
  d["ok"] = p.ok;
  d["message"] = p.message;
  d["seconds"] = p.seconds;
  d["contact_ratio"] = p.contact_ratio;
  d["plasticity_index"] = p.plasticity_index;
  d["regime"] = p.regime;
  d["verdict"] = p.verdict;
  py::list flags, summary, quantities;
  for (const auto& f : p.flag_counts) flags.append(py::make_tuple(f.name, f.unit, f.value));
  for (const auto& v : p.summary) summary.append(py::make_tuple(v.name, v.unit, v.value));
  for (const auto& q : p.quantities) quantities.append(py::make_tuple(q.name, q.unit, q.min, q.mean, q.max));
  d["flag_counts"] = flags;
  d["summary"] = summary;
  d["quantities"] = quantities;
  return d;
}

runs::SweepPoint point_from(const py::dict& d) {
  runs::SweepPoint p;
  p.index = d["index"].cast<std::size_t>();
  p.ok = d["ok"].cast<bool>();
  p.message = d["message"].cast<std::string>();
  p.seconds = d["seconds"].cast<double>();
  p.contact_ratio = d["contact_ratio"].cast<double>();
  p.plasticity_index = d["plasticity_index"].cast<double>();
  p.regime = d["regime"].cast<std::string>();
  p.verdict = d["verdict"].cast<std::string>();
  const auto summary_values = [&](const char* key, std::vector<contact::SummaryValue>& into) {
    for (const auto& v : d[key].cast<py::list>()) {
      const auto t = v.cast<py::tuple>();
      into.push_back({t[0].cast<std::string>(), t[1].cast<std::string>(), t[2].cast<double>()});
    }
  };
  summary_values("flag_counts", p.flag_counts);
  summary_values("summary", p.summary);
  for (const auto& q : d["quantities"].cast<py::list>()) {
    const auto t = q.cast<py::tuple>();
    p.quantities.push_back({t[0].cast<std::string>(), t[1].cast<std::string>(), t[2].cast<double>(),
                            t[3].cast<double>(), t[4].cast<double>()});
  }
  return p;
}

io::SweepPlan make_plan(const std::vector<std::string>& axes, bool zip) {
  io::SweepPlan plan;
  plan.zip = zip;
  for (const auto& a : axes) plan.axes.push_back(io::parse_sweep_axis(a));
  plan.validate();
  return plan;
}

// A column table as a list of (name, unit, is_text, values): float64 arrays or lists of str.
py::list column_list(const io::ColumnTable& t) {
  py::list out;
  for (const auto& c : t.columns) {
    if (c.text) out.append(py::make_tuple(c.name, c.unit, true, py::cast(c.texts)));
    else out.append(py::make_tuple(c.name, c.unit, false, to_array(c.numbers)));
  }
  return out;
}

std::vector<double> to_vector(const py::array_t<double, py::array::c_style | py::array::forcecast>& a) {
  return std::vector<double>(a.data(), a.data() + a.size());
}

using HeightArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Arguments within the ranges of the file readers and the case schema: a finite value no file or
// case could hold is refused (ValueError naming the argument, the value and the rule), never
// carried into a NaN or inf.
void require_in(const std::string& argument, double v, double lo, double hi, const char* unit,
                const std::string& whose) {
  if (!(v >= lo && v <= hi))
    throw std::invalid_argument(
        fmt::format("{} = {:g}{}: must lie in [{:g}, {:g}]{} ({})", argument, v, unit, lo, hi, unit, whose));
}
// Plane-strain moduli, composite E* = 1/((1 - nu1^2)/E1 + (1 - nu2^2)/E2) or single-body
// E/(1 - nu^2), of materials within the material files' Young's moduli and 0 < nu < 0.5.
constexpr double kMinPlaneStrainModulus = kMinYoungsModulus / 2.0;   // [Pa]
constexpr double kMaxPlaneStrainModulus = kMaxYoungsModulus / 0.75;  // [Pa]
const std::string kModulusRule =
    fmt::format("a plane-strain modulus of materials within the material files' Young's modulus range [{:g}, {:g}] Pa",
                kMinYoungsModulus, kMaxYoungsModulus);
// A returned number that is not finite is a model that left its range unnoticed: RuntimeError
// naming the output and the element (the command line's check, runs::check_finite_outputs).
void require_finite(const std::string& output, const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw std::runtime_error(fmt::format("{}[{}] is {}: a model left its range unnoticed", output, i, values[i]));
}

// A height array z[y, x] [m] (NaN: missing) as a grid of spacing dx, dy [m] (dy = 0: dx), within
// the grid limits (surface::make_grid checks the size before allocating).
surface::HeightGrid grid_from(const HeightArray& z, double dx, double dy) {
  if (dy < 0.0) throw std::invalid_argument("dy must be positive (or absent: dx)");
  if (z.ndim() != 2) throw std::invalid_argument("heights must be a 2-D array (ny, nx)");
  if (z.shape(0) > std::numeric_limits<int>::max() || z.shape(1) > std::numeric_limits<int>::max())
    throw std::invalid_argument("height array too large");
  surface::HeightGrid g =
      surface::make_grid(static_cast<int>(z.shape(1)), static_cast<int>(z.shape(0)), dx, dy > 0 ? dy : dx);
  const std::span<const double> heights(z.data(), g.size());
  for (double h : heights)
    if (std::isinf(h)) throw std::invalid_argument("heights must be finite (NaN marks a missing point)");
  surface::set_heights(g, heights);
  if (const std::string rule = surface::height_rule(g); !rule.empty()) throw std::invalid_argument(rule);
  return g;
}

// The pair's six values by name (SI), each a number; ContactPair::validate checks their ranges.
asperity::ContactPair pair_from(const py::dict& d) {
  asperity::ContactPair p;
  const std::pair<const char*, double*> fields[] = {{"radius", &p.radius},
                                                    {"modulus", &p.modulus},
                                                    {"youngs_modulus", &p.youngs_modulus},
                                                    {"poisson_ratio", &p.poisson_ratio},
                                                    {"yield_strength", &p.yield_strength},
                                                    {"hardness", &p.hardness}};
  for (const auto& [name, value] : fields) {
    if (!d.contains(name))
      throw std::invalid_argument(std::string("pair: no '") + name +
                                  "' (give radius, modulus, youngs_modulus, poisson_ratio, yield_strength, hardness)");
    try {
      *value = py::float_(d[name]).cast<double>();
    } catch (const py::error_already_set&) {
      throw std::invalid_argument(std::string("pair: '") + name + "' must be a number");
    }
  }
  for (const auto& item : d)
    if (std::none_of(std::begin(fields), std::end(fields),
                     [&](const auto& f) { return py::str(item.first).cast<std::string>() == f.first; }))
      throw std::invalid_argument("pair: unknown key '" + py::str(item.first).cast<std::string>() + "'");
  p.validate();
  // The ranges of the case schema's summit radius and of a material file's values.
  const io::Parameter& summit = *io::find_parameter("pinion.flank.summit_radius").parameter;
  require_in("pair['radius']", p.radius, summit.min, summit.max, " m", "the case's summit-radius range");
  require_in("pair['youngs_modulus']", p.youngs_modulus, kMinYoungsModulus, kMaxYoungsModulus, " Pa",
             "a material file's range");
  require_in("pair['modulus']", p.modulus, kMinPlaneStrainModulus, kMaxPlaneStrainModulus, " Pa", kModulusRule);
  require_in("pair['yield_strength']", p.yield_strength, 0.0, p.youngs_modulus, " Pa",
             "a material file's rule: positive and below Young's modulus");
  require_in("pair['hardness']", p.hardness, p.yield_strength, kMaxYoungsModulus, " Pa",
             "a material file's rule: from the yield strength to 1e13 Pa");
  return p;
}

py::dict pair_dict(const asperity::ContactPair& p) {
  py::dict d;
  d["radius"] = p.radius;
  d["modulus"] = p.modulus;
  d["youngs_modulus"] = p.youngs_modulus;
  d["poisson_ratio"] = p.poisson_ratio;
  d["yield_strength"] = p.yield_strength;
  d["hardness"] = p.hardness;
  return d;
}

}  // namespace

PYBIND11_MODULE(_geartrib, m) {
  m.doc() = "geartrib's compiled core; use the geartrib package";
  m.attr("__version__") = GEARTRIB_VERSION;
  m.attr("source_dir") = GEARTRIB_SOURCE_DIR;  // the build tree's data (gears/, materials/)

  // geartrib.InputError: the command line's located message, its parts as attributes.
  static py::exception<io::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("key") = e.key();
      error.attr("value") = e.value();
      error.attr("rule") = e.rule();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    }
  });

  m.def(
      "load_case",
      [](const std::string& file, const std::optional<std::string>& text, const std::string& name,
         const std::string& directory, const Changes& changes) {
        const CaseSource src = source_of(file, text, name, directory);
        py::gil_scoped_release release;
        return src.load(to_changes(changes));
      },
      py::arg("file"), py::arg("text"), py::arg("name"), py::arg("directory"), py::arg("changes"),
      "Loads and checks a case (its file, or its TOML text standing for `name`, relative files from\n"
      "`directory`) with (key, value) changes.");

  m.def(
      "read_case_text",
      [](const std::filesystem::path& file) { return io::read_data_file(file, io::kMaxTomlFileBytes); },
      py::arg("file"), "A case file's text (a regular file of at most 1 MiB, as the loader reads it).");

  py::class_<Case>(m, "LoadedCase", "A case as it runs (SI); see geartrib.Case")
      .def_readonly("title", &Case::title)
      .def_readonly("source_text", &Case::source_text)
      .def_readonly("warnings", &Case::warnings)
      .def_property_readonly("parameters", [](const Case& c) {
        py::list out;
        for (const auto& p : io::current_parameters(c)) out.append(py::make_tuple(p.key, p.value, p.origin.text()));
        return out;
      });

  m.def(
      "run",
      [](const Case& c) {
        contact::MeshContactResult r;
        {
          py::gil_scoped_release release;
          r = runs::run_mesh_cycle(c);
        }
        return result_dict(r);
      },
      py::arg("case"), "The mesh cycle as `geartrib run` runs it: series by group and the run's findings.");

  m.def(
      "kinematics",
      [](const Case& c, const std::vector<std::string>& points, std::optional<int> positions) {
        io::Table t;
        {
          py::gil_scoped_release release;
          const gear::GearMesh mesh = gear::case_mesh(c);
          t = positions ? runs::kinematics_table(mesh, *positions) : runs::kinematics_table(mesh, points);
        }
        py::array_t<double> rows(
            {static_cast<py::ssize_t>(t.rows.size()), static_cast<py::ssize_t>(t.header.size() - 1)});
        auto r = rows.mutable_unchecked<2>();
        for (std::size_t i = 0; i < t.rows.size(); ++i)
          for (std::size_t j = 0; j < t.rows[i].size(); ++j)
            r(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = t.rows[i][j];
        return py::make_tuple(std::vector<std::string>(t.header.begin() + 1, t.header.end()), t.labels, rows);
      },
      py::arg("case"), py::arg("points"), py::arg("positions"),
      "The `geartrib kinematics` table: (column names with units, row labels, rows).");

  m.def(
      "fidelities",
      [] {
        std::vector<py::dict> out;
        for (const contact::FidelityEntry& f : contact::fidelities()) {
          py::dict d;
          d["name"] = std::string(f.name);
          d["description"] = std::string(f.description);
          std::vector<std::string> keys(f.traits.keys.begin(), f.traits.keys.end());
          d["keys"] = keys;
          d["needs_nonlinear_solver"] = f.traits.needs.nonlinear_solver;
          d["needs_flank_profiles"] = f.traits.needs.flank_profiles;
          std::vector<std::string> groups;
          for (const auto& g : f.traits.groups) groups.emplace_back(g.path);
          d["groups"] = groups;
          out.push_back(d);
        }
        return out;
      },
      "The registered contact fidelities (contact.fidelity's choices): name, description, the case keys a run "
      "of it reads, what it needs and the result groups it writes.");

  m.def("asperity_models", [] {
    std::vector<std::string> names;
    for (auto n : asperity::asperity_model_names()) names.emplace_back(n);
    return names;
  });

  m.def(
      "contact_pair", [](const Case& c) { return pair_dict(asperity::contact_pair(c)); }, py::arg("case"),
      "The case's equivalent asperity pair (radius, moduli, Poisson's ratio, yield strength, hardness; SI).");

  m.def(
      "asperity",
      [](const std::optional<Case>& c, const std::optional<py::dict>& pair_values, const std::string& model_name,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& delta_star, bool stresses) {
        const std::vector<double> d = to_vector(delta_star);
        for (double v : d)
          if (!(v >= 0.0 && v <= 1e6))
            throw std::invalid_argument("delta_star must lie in [0, 1e6] (got " + std::to_string(v) + ")");
        if (!c && !pair_values) throw std::invalid_argument("give a case or a pair");
        const asperity::ContactPair pair = pair_values ? pair_from(*pair_values) : asperity::contact_pair(*c);
        const std::unique_ptr<asperity::AsperityModel> model =
            c ? asperity::make_case_model(*c, model_name) : asperity::make_asperity_model(model_name);
        constexpr std::size_t kColumns = std::size(runs::kAsperityColumns);
        std::vector<std::vector<double>> columns(kColumns, std::vector<double>(d.size()));
        std::vector<std::vector<bool>> flags(3, std::vector<bool>(d.size()));
        asperity::Critical crit;
        {
          py::gil_scoped_release release;
          crit = model->critical(pair);
          for (std::size_t i = 0; i < d.size(); ++i) {
            const asperity::AsperityState s = model->evaluate(
                pair, d[i] * crit.interference, stresses ? asperity::Detail::full : asperity::Detail::profile);
            for (std::size_t k = 0; k < kColumns; ++k) columns[k][i] = runs::kAsperityColumns[k].get(s);
            flags[0][i] = s.beyond_fitted_range;
            flags[1][i] = s.beyond_paraboloid;
            flags[2][i] = s.fully_plastic_limit;
          }
        }
        py::list out;
        for (std::size_t k = 0; k < kColumns; ++k) {
          const auto& col = runs::kAsperityColumns[k];
          if (!stresses && (col.quantity == "max_von_mises" || col.quantity == "von_mises_depth")) continue;
          require_finite(std::string(col.quantity), columns[k]);
          const std::string unit = col.suffix.empty() ? "1" : std::string(col.suffix.substr(1));
          out.append(py::make_tuple(std::string(col.quantity), unit, to_array(columns[k])));
        }
        const char* flag_names[] = {"beyond_fitted_range", "beyond_paraboloid", "fully_plastic_limit"};
        for (int k = 0; k < 3; ++k) {
          py::array_t<bool> a(static_cast<py::ssize_t>(d.size()));
          for (std::size_t i = 0; i < d.size(); ++i) a.mutable_data()[i] = flags[static_cast<std::size_t>(k)][i];
          out.append(py::make_tuple(flag_names[k], "1", a));
        }
        py::dict critical;
        critical["interference_m"] = crit.interference;
        critical["load_N"] = crit.load;
        critical["area_m2"] = crit.area;
        critical["peak_pressure_Pa"] = crit.peak_pressure;
        return py::make_tuple(out, critical, pair_dict(pair), std::string(model->name()),
                              std::string(model->citation()));
      },
      py::arg("case"), py::arg("pair"), py::arg("model"), py::arg("delta_star"), py::arg("stresses"),
      "One asperity model over an array of delta* = delta/delta_c (the model's own delta_c).");

  m.def(
      "surface_statistics",
      [](const HeightArray& z, double dx, double dy, int form_degree, double cutoff, double outliers) {
        surface::HeightGrid g = grid_from(z, dx, dy);
        surface::CleanupOptions clean;
        clean.form_degree = form_degree;
        clean.waviness_cutoff = cutoff;
        clean.outlier_limit = outliers;
        clean.validate();
        io::Table t;
        {
          py::gil_scoped_release release;
          g.validate();
          const surface::CleanupReport report = surface::clean_surface(g, clean);
          t = runs::surface_statistics_table(surface::surface_statistics(g), &report);
        }
        py::dict d;
        for (std::size_t i = 0; i < t.rows.size(); ++i) {
          require_finite(t.labels[i], {t.rows[i].front()});
          d[py::str(t.labels[i])] = t.rows[i].front();
        }
        return d;
      },
      py::arg("z"), py::arg("dx"), py::arg("dy"), py::arg("form_degree"), py::arg("cutoff"), py::arg("outliers"),
      "Statistics of a height grid z[y, x] [m] (NaN missing) after the clean-up of `geartrib surface stats`,\n"
      "named as that command names them.");

  m.def(
      "read_surface",
      [](const std::filesystem::path& path, double unit, double spacing) {
        io::TopographyReadOptions o;
        o.unit = unit;
        o.spacing = spacing;
        surface::HeightGrid g;
        {
          py::gil_scoped_release release;
          g = io::read_topography(path, o);
        }
        py::array_t<double> z({static_cast<py::ssize_t>(g.ny), static_cast<py::ssize_t>(g.nx)});
        const std::vector<double> heights = surface::heights_or_nan(g);
        std::copy(heights.begin(), heights.end(), z.mutable_data());
        return py::make_tuple(z, g.dx, g.dy);
      },
      py::arg("path"), py::arg("unit"), py::arg("spacing"),
      "A topography file as `geartrib surface` reads it: (z[y, x] in m with NaN missing, dx, dy).");

  m.def(
      "write_surface",
      [](const std::filesystem::path& path, const HeightArray& z, double dx, double dy, double unit) {
        surface::HeightGrid g = grid_from(z, dx, dy);
        g.validate();
        py::gil_scoped_release release;
        io::write_topography(path, g, unit);
      },
      py::arg("path"), py::arg("z"), py::arg("dx"), py::arg("dy"), py::arg("unit"),
      "Writes a height grid in the format of the extension (.x3p, .h5, .csv, ...), atomically.");

  m.def(
      "boundary_elements",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& gap, double dx, double modulus,
         std::optional<double> line_load, std::optional<double> approach, double pressure_cap, bool periodic,
         double reference_length, double tolerance) {
        if (gap.ndim() != 1) throw std::invalid_argument("the profile must be a 1-D array");
        if (line_load.has_value() == approach.has_value())
          throw std::invalid_argument("give the line load or the approach, one of them");
        if (gap.size() < 2 || gap.size() > (1 << 24))
          throw std::invalid_argument("the profile must have 2 to 2^24 elements");
        for (py::ssize_t i = 0; i < gap.size(); ++i)
          if (!std::isfinite(gap.data()[i]))
            throw std::invalid_argument("the profile (gap) must be finite: element " + std::to_string(i));
        if ((line_load && !(std::isfinite(*line_load) && *line_load >= 0.0)) || (approach && !std::isfinite(*approach)))
          throw std::invalid_argument("the line load must be finite and >= 0, the approach finite");
        contact::HalfPlaneGrid grid{0.0, dx, static_cast<int>(gap.size())};
        if (!(dx > 0.0 && std::isfinite(dx))) throw std::invalid_argument("dx must be positive and finite");
        // The ranges of the files and cases the command line reads: heights within the topography
        // readers' +-1 m (a gap between two such surfaces within 2 m), their spacing, a material's
        // modulus; and the load or approach of a linear-elastic solve (strains far below one: a mean
        // pressure up to the modulus, an approach up to the profile's length).
        require_in("dx", dx, surface::kMinSpacing, surface::kMaxSpacing, " m", "the topography readers' spacing");
        require_in("modulus", modulus, kMinPlaneStrainModulus, kMaxPlaneStrainModulus, " Pa", kModulusRule);
        for (py::ssize_t i = 0; i < gap.size(); ++i)
          if (!(std::abs(gap.data()[i]) <= 2.0 * surface::kMaxHeight))  // the name formatted only to refuse
            require_in(fmt::format("gap[{}] (from the profile)", i), gap.data()[i], -2.0 * surface::kMaxHeight,
                       2.0 * surface::kMaxHeight, " m", "heights within the topography readers' +-1 m");
        const double length = dx * static_cast<double>(gap.size());
        if (line_load)
          require_in("line_load", *line_load, 0.0, modulus * length, " N/m",
                     "a mean pressure over the profile up to the modulus: linear elasticity");
        if (approach)
          require_in("approach", *approach, -length, length, " m", "up to the profile's length: linear elasticity");
        contact::BemOptions o;
        o.pressure_cap = pressure_cap;
        o.periodic = periodic;
        o.reference_length = reference_length;
        o.tolerance = tolerance;
        o.validate();
        const std::vector<double> g0 = to_vector(gap);
        contact::BemSolution s;
        {
          py::gil_scoped_release release;
          const contact::HalfPlaneBem bem(grid, modulus, o);
          s = line_load ? bem.solve_load(g0, *line_load) : bem.solve_approach(g0, *approach);
        }
        require_finite("pressure_Pa", s.pressure);
        require_finite("displacement_m", s.displacement);
        require_finite("gap_m", s.gap);
        require_finite("approach_m, line_load_N_per_m", {s.approach, s.line_load});
        py::dict d;
        std::vector<double> x(g0.size());
        for (int i = 0; i < grid.size; ++i) x[static_cast<std::size_t>(i)] = grid.x(i);
        d["x_m"] = to_array(x);
        d["pressure_Pa"] = to_array(s.pressure);
        d["displacement_m"] = to_array(s.displacement);
        d["gap_m"] = to_array(s.gap);
        d["approach_m"] = s.approach;
        d["line_load_N_per_m"] = s.line_load;
        d["iterations"] = s.iterations;
        d["coarse_iterations"] = s.coarse_iterations;
        d["complementarity_error"] = s.complementarity_error;
        d["contact_elements"] = s.contact_elements;
        d["capped_elements"] = s.capped_elements;
        d["seconds"] = s.seconds;
        return d;
      },
      py::arg("gap"), py::arg("dx"), py::arg("modulus"), py::arg("line_load"), py::arg("approach"),
      py::arg("pressure_cap"), py::arg("periodic"), py::arg("reference_length"), py::arg("tolerance"),
      "Plane-strain boundary elements of a rigid flat on an elastic half-plane with the undeformed gap given.");

  m.def(
      "sweep_plan",
      [](const std::vector<std::string>& axes, bool zip) {
        const io::SweepPlan plan = make_plan(axes, zip);
        py::list points;
        for (std::size_t i = 0; i < plan.size(); ++i) {
          Changes ch;
          for (const auto& c : plan.point(i)) ch.emplace_back(c.key, c.value);
          points.append(py::cast(ch));
        }
        return py::make_tuple(points, plan.describe());
      },
      py::arg("axes"), py::arg("zip"),
      "Parses and checks the axes (\"key=v1,v2\" or \"key=lo:hi:n\", as --set of `geartrib sweep`): each "
      "point's changes and the plan's description.");

  m.def(
      "sweep_point",
      [](const std::string& file, const std::optional<std::string>& text, const std::string& name,
         const std::string& directory, const Changes& base_changes, const Changes& changes, std::size_t index) {
        const CaseSource src = source_of(file, text, name, directory);
        std::vector<io::CaseChange> all = to_changes(base_changes);
        for (const auto& c : to_changes(changes)) all.push_back(c);
        runs::SweepPoint p;
        {
          py::gil_scoped_release release;
          p = runs::run_sweep_point([&](const std::vector<io::CaseChange>& ch) { return src.load(ch); }, all, index);
        }
        return point_dict(p);
      },
      py::arg("file"), py::arg("text"), py::arg("name"), py::arg("directory"), py::arg("base_changes"),
      py::arg("changes"), py::arg("index"),
      "One sweep point as `geartrib sweep` runs it, as plain Python values (never raises).");

  m.def(
      "sweep_table",
      [](const std::vector<std::string>& axes, bool zip, const py::list& points) {
        const io::SweepPlan plan = make_plan(axes, zip);
        std::vector<runs::SweepPoint> p;
        for (const auto& d : points) p.push_back(point_from(d.cast<py::dict>()));
        return column_list(runs::sweep_table(plan, p));
      },
      py::arg("axes"), py::arg("zip"), py::arg("points"),
      "The sweep's table of points, as `geartrib sweep` writes it.");

  m.def(
      "read_sweep",
      [](const std::filesystem::path& path) {
        const io::ColumnTableFile f = io::read_column_table_hdf5(path);
        return py::make_tuple(column_list(f.table), f.attributes, f.scene);
      },
      py::arg("path"), "A `geartrib sweep` HDF5 file: (columns, /sweep attributes, scene).");
}
