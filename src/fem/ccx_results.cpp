#include "fem/ccx_results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace geartrib::fem {

namespace {

std::string run_capture(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), p)) out += buf.data();
  pclose(p);
  return out;
}

// Von Mises stress of ccx's stress components (xx, yy, zz, xy, yz, zx).
double von_mises(const std::vector<double>& s) {
  return std::sqrt(0.5 *
                       ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) + (s[2] - s[0]) * (s[2] - s[0])) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

double field(const std::string& line, std::size_t start, std::size_t width) {
  if (line.size() < start + width) throw std::runtime_error("frd: short line: " + line);
  return std::stod(line.substr(start, width));
}

}  // namespace

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

std::filesystem::path find_ccx() {
  if (const char* env = std::getenv("GEARTRIB_CCX"); env && *env)  // an explicit choice: that file or none
    return std::filesystem::exists(env) ? std::filesystem::path(env) : std::filesystem::path();
  const std::string found = run_capture("command -v ccx 2>/dev/null");
  if (found.empty()) return {};
  return std::filesystem::path(found.substr(0, found.find_first_of("\r\n")));
}

std::string ccx_version(const std::filesystem::path& ccx) {
  const std::string out = run_capture(shell_quoted(ccx.string()) + " -v 2>&1");
  std::smatch m;
  if (std::regex_search(out, m, std::regex(R"(Version\s+([0-9.]+))"))) return "CalculiX " + m[1].str();
  return "CalculiX (unknown version)";
}

void run_ccx(const std::filesystem::path& ccx, const std::filesystem::path& dir, const std::string& job) {
  const std::string log = (dir / (job + ".log")).string();
  const std::string command = "cd " + shell_quoted(dir.string()) +
                              " && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 " + shell_quoted(ccx.string()) +
                              " -i " + job + " > " + shell_quoted(log) + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const bool failed =
      status != 0 || text.find("*ERROR") != std::string::npos || !std::filesystem::exists(dir / (job + ".frd"));
  if (failed) {
    const std::string tail = text.size() > 1500 ? text.substr(text.size() - 1500) : text;
    throw std::runtime_error(fmt::format("ccx failed on {} (exit {}); the end of its output:\n{}",
                                         (dir / (job + ".inp")).string(), status, tail));
  }
}

std::vector<FrdField> read_frd(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::vector<FrdField> out;
  std::string line;
  double time = 0.0;
  FrdField* current = nullptr;
  while (std::getline(in, line)) {
    if (line.size() >= 7 && line.compare(2, 5, "100CL") == 0) {
      std::istringstream t(line.substr(7));
      int set = 0;
      t >> set >> time;
      current = nullptr;
    } else if (line.rfind(" -4", 0) == 0) {
      std::istringstream t(line.substr(3));
      FrdField f;
      f.time = time;
      t >> f.name;
      out.push_back(std::move(f));
      current = &out.back();
    } else if (current && line.rfind(" -1", 0) == 0) {
      const int node = static_cast<int>(field(line, 3, 10));
      std::vector<double> v;
      for (std::size_t c = 13; c + 12 <= line.size(); c += 12) v.push_back(field(line, c, 12));
      current->values.emplace(node, std::move(v));
    } else if (line.rfind(" -3", 0) == 0) {
      current = nullptr;
    }
  }
  return out;
}

std::vector<std::vector<double>> read_dat_totals(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::vector<std::vector<double>> out;
  std::string line;
  const std::regex head(R"(total force.*time\s+([-+0-9.eE]+))");
  std::smatch m;
  while (std::getline(in, line)) {
    if (!std::regex_search(line, m, head)) continue;
    const double t = std::stod(m[1].str());
    std::string values;
    while (std::getline(in, values))
      if (values.find_first_not_of(" \t\r") != std::string::npos) break;
    std::istringstream v(values);
    double fx = 0, fy = 0, fz = 0;
    v >> fx >> fy >> fz;
    out.push_back({t, fx, fy, fz});
  }
  return out;
}

std::vector<DatForces> read_dat_forces(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  std::vector<DatForces> out;
  std::string line;
  const std::regex head(R"(^\s*forces \(fx,fy,fz\) for set (\S+) and time\s+([-+0-9.eE]+))");
  std::smatch m;
  DatForces* current = nullptr;
  while (std::getline(in, line)) {
    if (std::regex_search(line, m, head)) {
      out.push_back({m[1].str(), std::stod(m[2].str()), {}});
      current = &out.back();
      continue;
    }
    if (!current) continue;
    std::istringstream v(line);
    int node = 0;
    std::array<double, 3> f{};
    if (v >> node >> f[0] >> f[1] >> f[2]) current->forces[node] = f;
    else if (line.find_first_not_of(" \t\r") != std::string::npos) current = nullptr;
  }
  return out;
}

std::vector<std::pair<double, double>> contact_intervals(const std::vector<double>& x, const std::vector<double>& gap,
                                                         double min_touch) {
  std::vector<std::pair<double, double>> out;
  if (gap.empty()) return out;
  const double touch = std::max(min_touch, 0.1 * std::max(0.0, -*std::min_element(gap.begin(), gap.end())));
  auto edge = [&](std::size_t k, int dir) {  // k touching; open nodes follow in direction dir
    // Open nodes on the rim whose gap is below a tenth of the next one's lie within the
    // discretisation of the edge (penalty contact, element-wise integration): skip them.
    std::size_t k1 = k + dir;
    while (k1 + static_cast<std::size_t>(2 * dir) < x.size() && gap[k1] < 0.1 * gap[k1 + dir]) k1 += dir;
    const std::size_t k2 = k1 + dir;
    double e = x[k];
    if (k2 < x.size() && gap[k2] > gap[k1]) {
      const double q = std::pow(gap[k1] / gap[k2], 2.0 / 3.0);
      e = (x[k1] - q * x[k2]) / (1.0 - q);
      e = std::clamp(e, std::min(x[k], x[k1]), std::max(x[k], x[k1]));
    }
    return e;
  };
  for (std::size_t k = 0; k < gap.size(); ++k) {
    if (gap[k] > touch) continue;
    const std::size_t first = k;
    while (k + 1 < gap.size() && gap[k + 1] <= touch) ++k;
    const double left = first == 0 ? x[0] : edge(first, -1);
    const double right = k + 1 == gap.size() ? x[k] : edge(k, +1);
    out.emplace_back(left, right);
  }
  return out;
}

std::vector<bool> surface_yielded_nodes(const std::vector<double>& peeq, double threshold) {
  std::vector<bool> out(peeq.size());
  for (std::size_t k = 0; k < peeq.size(); ++k) {
    if (k == 0 || k + 1 == peeq.size()) {
      out[k] = peeq[k] > threshold;
      continue;
    }
    std::array<double, 3> v{peeq[k - 1], peeq[k], peeq[k + 1]};
    std::sort(v.begin(), v.end());
    out[k] = v[1] > threshold;
  }
  return out;
}

double surface_yield_share(const std::vector<double>& radius, const std::vector<bool>& yielded, double contact_radius) {
  if (radius.size() != yielded.size())
    throw std::invalid_argument("surface_yield_share: radii and yielded flags differ in number");
  if (!(contact_radius > 0.0)) return 0.0;
  const double a = contact_radius;
  double area = 0.0;  // over pi
  for (std::size_t k = 0; k < radius.size(); ++k) {
    if (!yielded[k]) continue;
    const double lo = k == 0 ? 0.0 : 0.5 * (radius[k - 1] + radius[k]);
    const double hi = k + 1 == radius.size() ? a : 0.5 * (radius[k] + radius[k + 1]);
    const double l = std::clamp(lo, 0.0, a), h = std::clamp(hi, 0.0, a);
    if (h > l) area += h * h - l * l;
  }
  return std::clamp(area / (a * a), 0.0, 1.0);
}

std::vector<SingleAsperityResult> read_single_asperity(const SingleAsperitySpec& spec, const SingleAsperityDeck& deck,
                                                       const std::filesystem::path& dir, const std::string& job) {
  const double radius = 1.0, dc = deck.critical_interference;                     // [mm]
  const double e_prime = spec.modulus * 1e-6, sy = spec.yield_strength * 1e-6;    // [MPa]
  const double fc = 4.0 / 3.0 * e_prime * std::sqrt(radius) * std::pow(dc, 1.5);  // [N]
  const double ac = std::sqrt(radius * dc), area_c = std::numbers::pi * radius * dc;
  const auto totals = read_dat_totals(dir / (job + ".dat"));
  const auto forces = read_dat_forces(dir / (job + ".dat"));
  const auto fields = read_frd(dir / (job + ".frd"));
  std::map<int, double> depth(deck.node_depth.begin(), deck.node_depth.end()),
      rpos(deck.node_r.begin(), deck.node_r.end());
  std::vector<SingleAsperityResult> out;
  for (double level : spec.delta_star) {
    SingleAsperityResult r;
    r.delta_star = level;
    auto at_time = [&](const std::string& name) -> const FrdField* {
      for (const auto& f : fields)
        if (f.name == name && std::abs(f.time - level) <= 1e-6 * level) return &f;
      return nullptr;
    };
    const FrdField* disp = at_time("DISP");
    if (!disp)
      throw std::runtime_error(
          fmt::format("ccx wrote no displacements at delta* = {} (did the run stop early?)", level));
    // Force: ccx expands an axisymmetric model into a 2-degree wedge; its totals are 1/180 of the whole.
    double force = 0.0;
    bool found = false;
    for (const auto& t : totals)
      if (std::abs(t[0] - level) <= 1e-6 * level) force = std::abs(t[2]) * 180.0, found = true;
    if (!found) throw std::runtime_error(fmt::format("ccx printed no reaction at delta* = {}", level));
    r.load_star = force / fc;
    // Contact radius: gap of the deformed surface to the flat at y = -delta.
    const double flat = -level * dc;
    std::vector<double> gap;
    for (std::size_t k = 0; k < deck.top_nodes.size(); ++k) {
      const double r0 = deck.top_node_r[k];
      const auto& u = disp->values.at(deck.top_nodes[k]);
      gap.push_back(flat - (-r0 * r0 / (2.0 * radius) + u[1]));  // > 0 open, <= 0 touching (penalty penetration)
    }
    std::vector<double> xs;
    for (std::size_t k = 0; k < deck.top_nodes.size(); ++k)
      xs.push_back(deck.top_node_r[k] + disp->values.at(deck.top_nodes[k])[0]);
    const auto zones = contact_intervals(xs, gap, 1e-3 * level * dc);
    const double a = zones.empty() ? 0.0 : zones.back().second;  // outermost edge (the zone starts on the axis)
    r.contact_radius = a / ac;
    r.area_star = std::numbers::pi * a * a / area_c;
    r.mean_pressure_over_yield = a > 0.0 ? force / (std::numbers::pi * a * a) / sy : 0.0;
    // Peak pressure: each flat node's reaction (x 180: the wedge) over its ring of the flat,
    // between the midpoints to its neighbours; the axis node's tiny ring is left out.
    const auto& fn = deck.flat_nodes;
    for (const auto& f : forces)
      if (f.set == "NCONTACT" && std::abs(f.time - level) <= 1e-6 * level)
        for (std::size_t k = 2; k + 1 < fn.size(); ++k) {
          const auto it = f.forces.find(fn[k].first);
          if (it == f.forces.end()) continue;
          const double r0 = 0.5 * (fn[k - 1].second + fn[k].second), r1 = 0.5 * (fn[k].second + fn[k + 1].second);
          const double p = std::abs(it->second[1]) * 180.0 / (std::numbers::pi * (r1 * r1 - r0 * r0));
          r.max_pressure_over_yield = std::max(r.max_pressure_over_yield, p / sy);
        }
    if (const FrdField* stress = at_time("STRESS")) {
      for (const auto& [node, s] : stress->values) {
        if (s.size() < 6 || !depth.count(node)) continue;
        const double vm = von_mises(s);
        if (vm / sy > r.max_von_mises_over_yield) {
          r.max_von_mises_over_yield = vm / sy;
          r.max_von_mises_depth = a > 0.0 ? depth[node] / a : 0.0;
        }
      }
    }
    if (const FrdField* pe = at_time("PE")) {
      for (const auto& [node, v] : pe->values) {
        if (v.empty() || !(v[0] > 0.0) || !depth.count(node)) continue;
        r.plastic_depth = std::max(r.plastic_depth, depth[node] / ac);
        if (depth[node] == 0.0) r.plastic_surface_radius = std::max(r.plastic_surface_radius, rpos[node] / ac);
      }
      // The yielded share of the contact disc at the surface, over the deformed surface nodes
      // (the radii the contact radius comes from).
      std::vector<double> peeq;
      for (int node : deck.top_nodes) {
        const auto it = pe->values.find(node);
        peeq.push_back(it != pe->values.end() && !it->second.empty() ? it->second[0] : 0.0);
      }
      // The deck's tiny first cell at the axis (top nodes 0-2, 2e-5 R wide: its face collapses in
      // ccx's wedge) gives no usable nodal PEEQ (5.6e-3 at delta* = 50 beside -5e-4 outside it); its
      // nodes take the value of the first node beyond it (its area is below 1e-7 of the contact).
      for (std::size_t k = 0; k < 3 && peeq.size() > 3; ++k) peeq[k] = peeq[3];
      const std::vector<bool> yielded = surface_yielded_nodes(peeq);
      r.plastic_surface_area_fraction = surface_yield_share(xs, yielded, a);
      const auto first = std::find(yielded.begin(), yielded.end(), true);
      if (first != yielded.end())
        r.plastic_surface_inner_radius = xs[static_cast<std::size_t>(first - yielded.begin())] / ac;
    }
    // Its standard deviation: half the share of the surface element (corner to corner: top nodes
    // 2i..2i+2) that contains the contact edge, at least 0.02 (the yielded/unyielded boundary is
    // placed within about one element: ccx's nodal PEEQ is extrapolated from the integration points).
    r.plastic_surface_area_fraction_sd = 0.02;
    for (std::size_t k = 0; a > 0.0 && k + 2 < xs.size(); k += 2)
      if (xs[k] <= a && a < xs[k + 2]) {
        r.plastic_surface_area_fraction_sd = std::max(0.02, 0.5 * (xs[k + 2] * xs[k + 2] - xs[k] * xs[k]) / (a * a));
        break;
      }
    out.push_back(r);
  }
  return out;
}

}  // namespace geartrib::fem

namespace geartrib::fem {

std::vector<CylinderLevelResult> read_cylinders(const CylindersSpec& spec, const CylindersDeck& deck,
                                                const std::filesystem::path& dir, const std::string& job) {
  const double mm = 1e-3;  // deck millimetres -> metres
  const auto fields = read_frd(dir / (job + ".frd"));
  const auto forces = read_dat_forces(dir / (job + ".dat"));
  const std::size_t n = spec.cylinders.size();
  // Each asperity's share runs to the midpoints between axes [mm].
  std::vector<double> lo(n), hi(n);
  for (std::size_t k = 0; k < n; ++k) {
    lo[k] = k == 0 ? -1e300 : 0.5 * (spec.cylinders[k - 1].centre + spec.cylinders[k].centre) / mm;
    hi[k] = k + 1 == n ? 1e300 : 0.5 * (spec.cylinders[k].centre + spec.cylinders[k + 1].centre) / mm;
  }
  auto share = [&](double x) {
    for (std::size_t k = 0; k < n; ++k)
      if (x >= lo[k] && x < hi[k]) return k;
    return n - 1;
  };
  std::vector<CylinderLevelResult> out;
  for (double level : spec.levels) {
    auto at_time = [&](const std::string& name) -> const FrdField* {
      for (const auto& f : fields)
        if (f.name == name && std::abs(f.time - level) <= 1e-6 * level) return &f;
      return nullptr;
    };
    const FrdField* disp = at_time("DISP");
    if (!disp)
      throw std::runtime_error(fmt::format("ccx wrote no displacements at level {} (did the run stop early?)", level));
    CylinderLevelResult r;
    r.level = level;
    r.asperities.resize(n);
    // Loads: the flat's nodal reactions [N per mm of length] -> N/m.
    for (const auto& f : forces)
      if (f.set == "NCONTACT" && std::abs(f.time - level) <= 1e-6 * level)
        for (const auto& [node, v] : f.forces) {
          const auto it = std::find_if(deck.flat_nodes.begin(), deck.flat_nodes.end(),
                                       [id = node](const auto& p) { return p.first == id; });
          if (it == deck.flat_nodes.end()) continue;
          r.asperities[share(it->second)].load += -v[1] * 1e3;
          r.line_load += -v[1] * 1e3;
        }
    // Contact widths from the deformed surface against the flat at y = -approach.
    const double flat = -level * spec.unit / mm;
    std::vector<double> xs, gap;
    for (std::size_t k = 0; k < deck.top_nodes.size(); ++k) {
      const auto& u = disp->values.at(deck.top_nodes[k]);
      xs.push_back(deck.top_x[k] + u[0]);
      gap.push_back(flat - (deck.top_y[k] + u[1]));
    }
    for (const auto& [a, b] : contact_intervals(xs, gap, -1e-3 * flat))
      r.asperities[share(0.5 * (a + b))].contact_width += (b - a) * mm;
    // Stresses: largest von Mises within one contact width of each asperity's surface.
    if (const FrdField* stress = at_time("STRESS")) {
      for (std::size_t q = 0; q < deck.node_xy.size(); ++q) {
        const auto& [node, xy] = deck.node_xy[q];
        const auto it = stress->values.find(node);
        if (it == stress->values.end() || it->second.size() < 6) continue;
        const std::size_t k = share(xy.first);
        if (deck.node_depth[q] > std::max(r.asperities[k].contact_width / mm, 2.0 * deck.tip_element)) continue;
        const auto& s = it->second;
        const double vm = von_mises(s) * 1e6;
        r.asperities[k].max_von_mises = std::max(r.asperities[k].max_von_mises, vm);
      }
    }
    if (const FrdField* pe = at_time("PE"))
      for (const auto& [node, xy] : deck.node_xy) {
        const auto it = pe->values.find(node);
        if (it != pe->values.end() && !it->second.empty())
          r.asperities[share(xy.first)].max_plastic_strain =
              std::max(r.asperities[share(xy.first)].max_plastic_strain, it->second[0]);
      }
    out.push_back(r);
  }
  return out;
}

}  // namespace geartrib::fem
