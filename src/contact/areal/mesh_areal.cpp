#include "contact/areal/mesh_areal.hpp"

#include "contact/persson_contact.hpp"
#include "contact/series_columns.hpp"
#include "contact/stage_clock.hpp"
#include "core/keyed_error.hpp"
#include "surface/synthetic_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geartrib::contact::areal {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr NamedChoice<ArealLay> kLays[] = {{ArealLay::isotropic, "isotropic"}, {ArealLay::extruded, "extruded"}};
// A window narrower than this many correlation lengths holds too few independent spots: refused
// below one, and the verdict says so below four.
constexpr double kMinWindowCorrelations = 1.0;
}  // namespace

std::span<const NamedChoice<ArealLay>> areal_lay_choices() { return kLays; }

void ArealMeshOptions::validate() const {
  if (!(window > 0.0) || !std::isfinite(window)) throw core::KeyedError("window", "the window must be positive");
  if (points < kMinPoints || points > kMaxPoints)
    throw core::KeyedError("points", fmt::format("from {} to {} points across the face", kMinPoints, kMaxPoints));
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw core::KeyedError("tolerance", "the tolerance must lie in (0, 1)");
}

double FlankMap::at(double sigma, int j) const {
  const double u = (sigma - start) / dx;
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, nx - 2);
  const double t = std::clamp(u - i, 0.0, 1.0);
  const double* row = &z[static_cast<std::size_t>(j) * nx];
  return row[i] + t * (row[i + 1] - row[i]);
}

double areal_run_bytes(const FlankSpan& span, const ArealMeshOptions& o) {
  double maps = 0.0;
  if (o.lay == ArealLay::isotropic)
    for (int g = 0; g < 2; ++g)  // each map, and while one is made its noise and spectrum (about 2.5 x)
      maps += 8.0 * std::ceil(span.length(g) / span.element_size) * o.points * (g == 0 ? 3.5 : 1.0);
  ArealGrid w;
  w.nx = span.elements, w.ny = o.points, w.dx = span.element_size, w.dy = o.spacing();
  w.periodic_x = false, w.periodic_y = true;
  return maps + areal_solve_bytes(w);
}

std::array<FlankMap, 2> flank_maps(const FidelityInputs& in, const FlankSpan& span, const RollingFlanks& flanks) {
  const ArealMeshOptions& o = in.contact.areal;
  const double e = span.element_size;
  std::array<FlankMap, 2> maps;
  for (int g = 0; g < 2; ++g) {
    const FlankTrack& t = g == 0 ? flanks.pinion.front() : flanks.wheel.front();
    FlankMap& m = maps[static_cast<std::size_t>(g)];
    // Element centres from half an element inside the track's start to half one inside its end.
    m.start = t.start + 0.5 * e;
    m.nx = std::max(2, static_cast<int>(std::floor((t.end() - t.start) / e)));
    m.ny = o.points;
    m.dx = e;
    m.dy = o.spacing();
    if (static_cast<double>(m.nx) * m.ny > static_cast<double>(surface::kMaxGridPoints))
      throw core::KeyedError("areal.points",
                             fmt::format("the {}'s map would hold {} x {} points, beyond the {} a height map may hold: "
                                         "fewer points across the face, or a coarser contact.element_size",
                                         g == 0 ? "pinion" : "wheel", m.nx, m.ny, surface::kMaxGridPoints));
    // Isotropic: the generated ground profile's Gaussian correlation in every direction.
    const surface::FlankSpec* spec = in.flank_specs[static_cast<std::size_t>(g)];
    const std::string gear = g == 0 ? "pinion" : "wheel";
    if (!spec || !spec->profile || spec->profile->kind != surface::ProfileKind::ground)
      throw core::KeyedError(
          "areal.lay",
          fmt::format("an isotropic map is made from a generated ground profile ([{}.flank.profile] kind = \"ground\": "
                      "its Rq and correlation length), and the {}'s flank is not one: give it one, or take "
                      "areal.lay = \"extruded\" (its profile across the face)",
                      gear, gear));
    const surface::GeneratedProfileSpec& p = *spec->profile;
    if (o.window < kMinWindowCorrelations * p.correlation_length)
      throw core::KeyedError("areal.window",
                             fmt::format("the window across the face ({:.4g} um) is narrower than the {}'s correlation "
                                         "length ({:.4g} um): it holds no independent spot; widen it to at least "
                                         "four correlation lengths",
                                         o.window * 1e6, gear, p.correlation_length * 1e6));
    if (!(p.correlation_length >= 2.0 * std::max(m.dx, m.dy)))
      throw core::KeyedError("areal.points",
                             fmt::format("the {}'s correlation length ({:.4g} um) spans fewer than two points (along "
                                         "{:.4g} um, across {:.4g} um): more points across the face, or a finer "
                                         "contact.element_size",
                                         gear, p.correlation_length * 1e6, m.dx * 1e6, m.dy * 1e6));
    surface::GaussianSurfaceSpec gs;
    gs.nx = m.nx, gs.ny = m.ny, gs.dx = m.dx, gs.dy = m.dy, gs.rq = p.rq;
    gs.correlation_length = p.correlation_length;
    gs.seed = p.seed;
    m.z = surface::gaussian_surface(gs).z;
  }
  return maps;
}

std::vector<double> stress_depths(double element_size, double hertz_half_width) {
  std::vector<double> d;
  for (double k : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0}) d.push_back(k * element_size);
  if (hertz_half_width > 0.0) d.push_back(0.786 * hertz_half_width);
  return d;
}

Areal::State Areal::prepare(const FidelityInputs& in, StageClock& clock) {
  if (!in.flank_source) throw std::invalid_argument("the areal fidelity needs the flanks' profiles");
  const ContactSettings& cs = in.contact;
  State st;
  FlankSpan& span = st.span;
  plan_rolling_strip(in, span, st.sigma, st.options, st.grid);
  span.reader = FlankSpan::Reader::areal;
  const int teeth[2] = {1, 1};
  st.flanks = in.flank_source(span, teeth);
  clock.lap("flank_profiles");
  if (cs.areal.lay == ArealLay::isotropic) {
    st.maps = flank_maps(in, span, st.flanks);
    clock.lap("flank_maps");
  }
  build_rolled_flanks_model(in, span, st.flanks, name, clock, st.model);
  return st;
}

Areal::Solution Areal::solve(const FidelityInputs& in, State& st, const std::vector<double>& share, StageClock& clock) {
  Solution out;
  out.share = share;
  out.statistical = statistical_beside(in, st.model, share, clock);
  const ContactSettings& cs = in.contact;
  const PathState& p = in.path;
  const int nx = st.grid.size, ny = cs.areal.points;
  const double e = st.grid.spacing;
  ArealGrid g;
  g.nx = nx, g.ny = ny, g.dx = e, g.dy = cs.areal.spacing(), g.periodic_x = false, g.periodic_y = true;
  const ElasticKernel kernel(g, in.mesh.composite_modulus());
  ArealOptions o;
  o.composite_modulus = in.mesh.composite_modulus();
  o.hardness = st.options.pressure_cap;
  o.poisson_ratio = st.options.poisson_ratio;
  o.tolerance = cs.areal.tolerance;
  const double length = nx * e;  // the window along the involute [m]
  const std::vector<bool> keep = kept_profiles(cs, p);
  std::vector<double> h(g.size()), start;
  const int n = static_cast<int>(p.size());
  for (int k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    ArealStrip s;
    const double w = p.line_load[kk] * share[kk], b = p.half_width[kk];
    if (w > 0.0) {
      if (w >= 0.9 * length * o.hardness)
        throw core::KeyedError(
            "contact.strip_halfwidths",
            fmt::format("the line load {:.4g} N/m would yield the window along the involute (+-{:.4g} mm at the "
                        "hardness {:.4g} GPa carries {:.4g} N/m): raise contact.strip_halfwidths or lower the torque",
                        w, 0.5e3 * length, o.hardness * 1e-9, length * o.hardness));
      const bool extruded = cs.areal.lay == ArealLay::extruded;
      const FlankTrack &pinion = st.flanks.pinion.front(), &wheel = st.flanks.wheel.front();
      for (int i = 0; i < nx; ++i) {
        // Extruded: each profile's mean over the element, as the deterministic fidelity's strip takes it.
        const double x = st.grid.x(i), sp = st.sigma[0][kk] - x, sw = st.sigma[1][kk] + x;
        const double parabola = -x * x / (2.0 * p.radius[kk]);
        const double profiles =
            extruded ? track_mean(pinion, sp - 0.5 * e, sp + 0.5 * e) + track_mean(wheel, sw - 0.5 * e, sw + 0.5 * e)
                     : 0.0;
        for (int j = 0; j < ny; ++j)
          h[static_cast<std::size_t>(j) * nx + i] =
              parabola + (extruded ? profiles : st.maps[0].at(sp, j) + st.maps[1].at(sw, j));
      }
      const ArealSolution sol = solve_contact(kernel, h, Control::mean_pressure, w / length, o, start);
      start = sol.pressure;
      const ContactSpots spots = contact_spots(g, sol.pressure);
      const double area = sol.contact_fraction * g.area();  // [m^2] in the window
      s.real_area_per_width = area / (ny * g.dy);
      s.real_area_ratio = s.real_area_per_width / (2.0 * b);
      s.contact_spots = static_cast<int>(spots.area.size());
      s.peak_pressure = sol.peak_pressure;
      s.mean_real_pressure = s.real_area_per_width > 0.0 ? w / s.real_area_per_width : 0.0;
      s.plastic_area_fraction = sol.contact_fraction > 0.0 ? sol.plastic_fraction / sol.contact_fraction : 0.0;
      s.plastic_area_per_width = sol.plastic_fraction * length;
      s.iterations = sol.iterations;
      s.converged = sol.converged;
      double gap = 0.0;
      int band = 0;
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const std::size_t e_ij = static_cast<std::size_t>(j) * nx + i;
          if (std::abs(st.grid.x(i)) <= std::max(b, 0.5 * e)) gap += std::max(sol.gap[e_ij], 0.0), ++band;
          if ((i == 0 || i == nx - 1) && sol.pressure[e_ij] > 0.0) s.edge_loaded = true;
        }
      s.mean_gap = band > 0 ? gap / band : kNaN;
      if (cs.asperity_stress) {
        const std::vector<double> depths = stress_depths(e, b);
        for (const SubsurfacePlane& pl : subsurface_von_mises(kernel, sol.pressure, o.poisson_ratio, depths))
          if (pl.max_von_mises > s.max_von_mises) s.max_von_mises = pl.max_von_mises, s.max_von_mises_depth = pl.depth;
      }
      if (keep[kk]) {
        s.pressure.assign(static_cast<std::size_t>(nx), 0.0);
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i)
            s.pressure[static_cast<std::size_t>(i)] += sol.pressure[static_cast<std::size_t>(j) * nx + i] / ny;
      }
    } else if (keep[kk]) {
      s.pressure.assign(static_cast<std::size_t>(nx), 0.0);
    }
    out.strips.push_back(std::move(s));
    if (in.progress) in.progress(k + 1, n);
  }
  clock.lap("areal_contact");
  return out;
}

void Areal::write(const FidelityInputs& in, State& st, Solution& s, MeshContactResult& r) {
  const ContactSettings& cs = in.contact;
  if (s.statistical) {
    write_statistical_beside(in, *st.model, *s.statistical, r);
    // Persson on the maps' gradient: isotropic, twice the profiles' slope variance; extruded, theirs.
    write_persson_beside(in, *st.model, s.share, cs.areal.lay == ArealLay::isotropic ? 2.0 : 1.0, r);
  }
  using S = ArealStrip;
  using C = Column<S>;
  if (cs.real_area)
    add_columns<S>(r.contact, s.strips,
                   {C{"real_area_ratio", "1", [](const S& a) { return a.real_area_ratio; }},
                    C{"real_area_per_width_m", "m", [](const S& a) { return a.real_area_per_width; }},
                    C{"mean_real_pressure_Pa", "Pa", [](const S& a) { return a.mean_real_pressure; }},
                    C{"contact_spots", "1", [](const S& a) { return static_cast<double>(a.contact_spots); }},
                    C{"max_pressure_Pa", "Pa", [](const S& a) { return a.peak_pressure; }},
                    C{"mean_gap_m", "m", [](const S& a) { return a.mean_gap; }}});
  if (cs.plastic_fraction)
    add_columns<S>(r.contact, s.strips,
                   {C{"plastic_area_fraction", "1", [](const S& a) { return a.plastic_area_fraction; }},
                    C{"plastic_area_per_width_m", "m", [](const S& a) { return a.plastic_area_per_width; }}});
  if (cs.asperity_stress)
    add_columns<S>(r.contact, s.strips,
                   {C{"max_von_mises_Pa", "Pa", [](const S& a) { return a.max_von_mises; }},
                    C{"max_von_mises_depth_m", "m", [](const S& a) { return a.max_von_mises_depth; }}});
  add_columns<S>(r.contact, s.strips,
                 {C{"areal_iterations", "1", [](const S& a) { return static_cast<double>(a.iterations); }}});
  Series edge{"flag_strip_edge_loaded", "1", {}}, stopped{"flag_not_converged", "1", {}};
  int n_edge = 0, n_stopped = 0;
  RollingRegime regime;
  for (const S& a : s.strips) {
    edge.values.push_back(a.edge_loaded ? 1.0 : 0.0);
    stopped.values.push_back(a.converged ? 0.0 : 1.0);
    n_edge += a.edge_loaded, n_stopped += !a.converged;
    regime.add(a.real_area_per_width, a.plastic_area_fraction);
  }
  r.validity.push_back(std::move(edge));
  r.validity.push_back(std::move(stopped));
  r.regime = regime.name();
  r.verdict = fmt::format(
      "Areal rough contact of both flanks' height maps ({} lay; elements of {:.3g} um along the involute over +-{:.3g} "
      "Hertz half-widths, {} points over {:.4g} um across the face, periodic): {}; of {} loaded positions {} elastic "
      "(<1% of the real area yielded), {} fully plastic (>99%).",
      choice_name(areal_lay_choices(), cs.areal.lay), st.grid.spacing * 1e6, cs.boundary_elements.strip_halfwidths,
      cs.areal.points, cs.areal.window * 1e6, r.regime, regime.loaded, regime.elastic, regime.plastic);
  for (const surface::FlankSpec* spec : in.flank_specs)
    if (cs.areal.lay == ArealLay::isotropic && spec && spec->profile &&
        cs.areal.window < 4.0 * spec->profile->correlation_length) {
      r.verdict +=
          " The window across the face holds fewer than four correlation lengths: its spots are few; widen "
          "areal.window.";
      break;
    }
  if (n_edge > 0)
    r.verdict += fmt::format(
        " At {} positions the pressure reaches the window's ends along the involute: raise contact.strip_halfwidths.",
        n_edge);
  if (n_stopped > 0) r.verdict += fmt::format(" At {} positions the solver stopped before areal.tolerance.", n_stopped);
  r.flag_counts = {{"strip_edge_loaded", n_edge}, {"not_converged", n_stopped}};
  std::vector<double> x(static_cast<std::size_t>(st.grid.size));
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = st.grid.x(static_cast<int>(j));
  const std::vector<std::string> names = path_point_names(in.path);
  for (std::size_t k = 0; k < s.strips.size(); ++k) {
    if (s.strips[k].pressure.empty()) continue;
    r.pressure_profiles.push_back({static_cast<int>(k), names[k], in.path.s[k], x, std::move(s.strips[k].pressure)});
  }
}

}  // namespace geartrib::contact::areal
