#include "contact/areal/mesh_areal.hpp"

#include "contact/persson_contact.hpp"
#include "contact/series_columns.hpp"
#include "contact/stage_clock.hpp"
#include "core/keyed_error.hpp"
#include "surface/synthetic_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace geartrib::contact::areal {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr NamedChoice<ArealLay> kLays[] = {{ArealLay::isotropic, "isotropic"},
                                           {ArealLay::directional, "directional"},
                                           {ArealLay::extruded, "extruded"},
                                           {ArealLay::patch, "patch"}};
constexpr NamedChoice<ArealPatch> kPatches[] = {{ArealPatch::synthesis, "synthesis"}, {ArealPatch::tiled, "tiled"}};
// A window narrower than this many correlation lengths holds too few independent spots: refused
// below one, and the verdict says so below four.
constexpr double kMinWindowCorrelations = 1.0;
}  // namespace

std::span<const NamedChoice<ArealLay>> areal_lay_choices() { return kLays; }
std::span<const NamedChoice<ArealPatch>> areal_patch_choices() { return kPatches; }

void ArealMeshOptions::validate() const {
  if (!(window > 0.0) || !std::isfinite(window)) throw core::KeyedError("window", "the window must be positive");
  if (points < kMinPoints || points > kMaxPoints)
    throw core::KeyedError("points", fmt::format("from {} to {} points across the face", kMinPoints, kMaxPoints));
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw core::KeyedError("tolerance", "the tolerance must lie in (0, 1)");
  if (!(lay_ratio >= 1.0 && lay_ratio <= kMaxLayRatio))
    throw core::KeyedError("lay_ratio", fmt::format("the lay ratio must lie in [1, {:g}]", kMaxLayRatio));
}

double areal_run_bytes(const FlankSpan& span, const ArealMeshOptions& o, const int teeth[2]) {
  double maps = 0.0;
  if (o.lay != ArealLay::extruded || span.running_in)
    for (int g = 0; g < 2; ++g) {  // each map, and while the first is made its noise and spectrum (about 2.5 x)
      const double points = 8.0 * (std::ceil(span.length(g) / span.element_size) + 3.0) * o.points;
      maps += points * (teeth[g] + (g == 0 ? 2.5 : 0.0));
    }
  if (span.running_in)  // a pass's deformation of each flank's map
    for (int g = 0; g < 2; ++g) maps += 8.0 * (std::ceil(span.length(g) / span.element_size) + 3.0) * o.points;
  ArealGrid w;
  w.nx = span.elements, w.ny = o.points, w.dx = span.element_size, w.dy = o.spacing();
  w.periodic_x = false, w.periodic_y = true;
  return maps + areal_solve_bytes(w);
}

std::array<std::vector<FlankMap>, 2> flank_maps(const FidelityInputs& in, const FlankSpan& span,
                                                const RollingFlanks& flanks) {
  const ArealMeshOptions& o = in.contact.areal;
  const double e = span.element_size;
  std::array<std::vector<FlankMap>, 2> maps;
  for (int g = 0; g < 2; ++g) {
    const std::vector<FlankTrack>& tracks = g == 0 ? flanks.pinion : flanks.wheel;
    const std::string gear = g == 0 ? "pinion" : "wheel";
    for (std::size_t tooth = 0; tooth < tracks.size(); ++tooth) {
      const FlankTrack& t = tracks[tooth];
      FlankMap m;
      // Element centres from half an element inside the track's start to half one inside its end.
      m.start = t.start + 0.5 * e;
      m.nx = std::max(2, static_cast<int>(std::floor((t.end() - t.start) / e)));
      m.ny = o.points;
      m.dx = e;
      m.dy = o.spacing();
      if (static_cast<double>(m.nx) * m.ny > static_cast<double>(surface::kMaxGridPoints))
        throw core::KeyedError("areal.points",
                               fmt::format("the {}'s map would hold {} x {} points, beyond the {} a height map may "
                                           "hold: fewer points across the face, or a coarser contact.element_size",
                                           gear, m.nx, m.ny, surface::kMaxGridPoints));
      if (o.lay == ArealLay::extruded) {  // the profile's element means, every row
        m.z.resize(static_cast<std::size_t>(m.nx) * m.ny);
        for (int i = 0; i < m.nx; ++i) {
          const double sigma = m.start + i * e, z = track_mean(t, sigma - 0.5 * e, sigma + 0.5 * e);
          for (int j = 0; j < m.ny; ++j) m.z[static_cast<std::size_t>(j) * m.nx + i] = z;
        }
        maps[static_cast<std::size_t>(g)].push_back(std::move(m));
        continue;
      }
      // Isotropic or directional: the generated ground profile's Gaussian correlation.
      const surface::FlankSpec* spec = in.flank_specs[static_cast<std::size_t>(g)];
      if (!spec || !spec->profile || spec->profile->kind != surface::ProfileKind::ground)
        throw core::KeyedError(
            "areal.lay",
            fmt::format("an {} map is made from a generated ground profile ([{}.flank.profile] kind = \"ground\": "
                        "its Rq and correlation length), and the {}'s flank is not one: give it one, take "
                        "areal.lay = \"patch\" (a measured topography) or \"extruded\" (its profile across the face)",
                        choice_name(areal_lay_choices(), o.lay), gear, gear));
      const surface::GeneratedProfileSpec& p = *spec->profile;
      if (o.window < kMinWindowCorrelations * p.correlation_length)
        throw core::KeyedError("areal.window",
                               fmt::format("the window across the face ({:.4g} um) is narrower than the {}'s "
                                           "correlation length ({:.4g} um): it holds no independent spot; widen it to "
                                           "at least four correlation lengths",
                                           o.window * 1e6, gear, p.correlation_length * 1e6));
      if (!(p.correlation_length >= 2.0 * std::max(m.dx, m.dy)))
        throw core::KeyedError("areal.points",
                               fmt::format("the {}'s correlation length ({:.4g} um) spans fewer than two points "
                                           "(along {:.4g} um, across {:.4g} um): more points across the face, or a "
                                           "finer contact.element_size",
                                           gear, p.correlation_length * 1e6, m.dx * 1e6, m.dy * 1e6));
      surface::GaussianSurfaceSpec gs;
      gs.nx = m.nx, gs.ny = m.ny, gs.dx = m.dx, gs.dy = m.dy, gs.rq = p.rq;
      gs.correlation_length = p.correlation_length;
      if (o.lay == ArealLay::directional) gs.correlation_length_y = o.lay_ratio * p.correlation_length;
      gs.seed = p.seed + tooth;  // tooth t of the hunting order, as the generated profiles
      m.z = surface::gaussian_surface(gs).z;
      maps[static_cast<std::size_t>(g)].push_back(std::move(m));
    }
  }
  return maps;
}

std::vector<double> stress_depths(double element_size, double hertz_half_width) {
  std::vector<double> d;
  for (double k : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0}) d.push_back(k * element_size);
  if (hertz_half_width > 0.0) d.push_back(0.786 * hertz_half_width);
  return d;
}

namespace {

// Persson's full gradient over the slope variance along the involute, on both flanks' maps (tooth 0):
// finite differences at their spacings, across the face periodic.
double map_gradient_factor(const std::array<std::vector<FlankMap>, 2>& maps) {
  double along = 0.0, across = 0.0;
  for (const auto& teeth : maps) {
    const FlankMap& m = teeth.front();
    double sx = 0.0, sy = 0.0;
    for (int j = 0; j < m.ny; ++j)
      for (int i = 0; i < m.nx; ++i) {
        const double z = m.z[static_cast<std::size_t>(j) * m.nx + i];
        if (i + 1 < m.nx) sx += std::pow((m.z[static_cast<std::size_t>(j) * m.nx + i + 1] - z) / m.dx, 2);
        sy += std::pow((m.z[static_cast<std::size_t>((j + 1) % m.ny) * m.nx + i] - z) / m.dy, 2);
      }
    along += sx / (static_cast<double>(m.nx - 1) * m.ny);
    across += sy / (static_cast<double>(m.nx) * m.ny);
  }
  return along > 0.0 ? (along + across) / along : 1.0;
}

// A flank's plastic deformation from a strip's (d per element, nx x ny [m]): at each of the map's points
// inside the strip (sigma = sigma_c + direction x), share times d linear between the element centres;
// the deepest of a mesh's positions kept (into: the map's size).
void lay_plastic(const HalfPlaneGrid& g, const FlankMap& m, double sigma_c, int direction, const std::vector<double>& d,
                 double share, std::vector<double>& into) {
  const double x_lo = g.x(0), x_hi = g.x(g.size - 1);
  const double s_lo = direction > 0 ? sigma_c + x_lo : sigma_c - x_hi;
  const double s_hi = direction > 0 ? sigma_c + x_hi : sigma_c - x_lo;
  const int k0 = std::max(0, static_cast<int>(std::ceil((s_lo - m.start) / m.dx)));
  const int k1 = std::min(m.nx - 1, static_cast<int>(std::floor((s_hi - m.start) / m.dx)));
  for (int k = k0; k <= k1; ++k) {
    const double f = (direction * (m.start + k * m.dx - sigma_c) - x_lo) / g.spacing;
    const int i = std::clamp(static_cast<int>(std::floor(f)), 0, g.size - 2);
    const double w = std::clamp(f - i, 0.0, 1.0);
    for (int j = 0; j < m.ny; ++j) {
      const std::size_t row = static_cast<std::size_t>(j) * g.size;
      const double dk = share * ((1.0 - w) * d[row + i] + w * d[row + i + 1]);
      double& slot = into[static_cast<std::size_t>(j) * m.nx + k];
      slot = std::max(slot, dk);
    }
  }
}

// The maps' profile statistics along the involute over the active part, the mean over rows and teeth.
surface::ProfileStatistics map_statistics(const std::vector<FlankMap>& maps, const FlankSpan& span, int g) {
  surface::ProfileStatistics mean;
  double n = 0.0;
  for (const FlankMap& m : maps) {
    const int k0 = std::max(0, static_cast<int>(std::ceil((span.active_first[g] - m.start) / m.dx)));
    const int k1 = std::min(m.nx - 1, static_cast<int>(std::floor((span.active_last[g] - m.start) / m.dx)));
    if (k1 - k0 < 8) continue;
    for (int j = 0; j < m.ny; ++j) {
      const double* row = &m.z[static_cast<std::size_t>(j) * m.nx];
      const surface::ProfileStatistics p =
          surface::profile_statistics(std::span<const double>(row + k0, row + k1 + 1), m.dx);
      mean.rq += p.rq, mean.rsk += p.rsk, mean.summit_radius += p.summit_radius, mean.peak_height += p.peak_height;
      n += 1.0;
    }
  }
  if (n > 0.0) mean.rq /= n, mean.rsk /= n, mean.summit_radius /= n, mean.peak_height /= n;
  return mean;
}

// The middle row of a map over the flank's active part, for the running-in record.
std::vector<double> active_row(const FlankMap& m, const FlankSpan& span, int g) {
  const int k0 = std::max(0, static_cast<int>(std::ceil((span.active_first[g] - m.start) / m.dx)));
  const int k1 = std::min(m.nx - 1, static_cast<int>(std::floor((span.active_last[g] - m.start) / m.dx)));
  const double* row = &m.z[static_cast<std::size_t>(m.ny / 2) * m.nx];
  return {row + k0, row + std::max(k0, k1 + 1)};
}

}  // namespace

Areal::State Areal::prepare(const FidelityInputs& in, StageClock& clock) {
  if (!in.flank_source) throw std::invalid_argument("the areal fidelity needs the flanks' profiles");
  const ContactSettings& cs = in.contact;
  State st;
  FlankSpan& span = st.span;
  plan_rolling_strip(in, span, st.sigma, st.options, st.grid);
  span.reader = FlankSpan::Reader::areal;
  span.running_in = in.running_in.meshes > 0;
  st.hunting = in.running_in.hunting();
  const int* z = in.mesh.pair().spec().teeth;
  st.teeth[0] = st.hunting ? z[0] : 1;
  st.teeth[1] = st.hunting ? z[1] : 1;
  st.flanks = in.flank_source(span, st.teeth);
  if (static_cast<int>(st.flanks.pinion.size()) != st.teeth[0] ||
      static_cast<int>(st.flanks.wheel.size()) != st.teeth[1])
    throw std::logic_error("areal run: the flank source gave the wrong number of teeth");
  clock.lap("flank_profiles");
  const ArealLay lay = cs.areal.lay;
  if (lay == ArealLay::patch) {
    if (static_cast<int>(st.flanks.pinion_maps.size()) != st.teeth[0] ||
        static_cast<int>(st.flanks.wheel_maps.size()) != st.teeth[1])
      throw std::logic_error("areal run: the flank source gave no patch maps");
    st.maps = {std::move(st.flanks.pinion_maps), std::move(st.flanks.wheel_maps)};
  } else if (lay != ArealLay::extruded || span.running_in) {
    st.maps = flank_maps(in, span, st.flanks);
    clock.lap("flank_maps");
  }
  switch (lay) {
    case ArealLay::extruded:
      st.gradient_factor = 1.0;
      break;
    case ArealLay::isotropic:
      st.gradient_factor = 2.0;
      break;
    case ArealLay::directional:
      st.gradient_factor = 1.0 + 1.0 / (cs.areal.lay_ratio * cs.areal.lay_ratio);
      break;
    case ArealLay::patch:
      st.gradient_factor = map_gradient_factor(st.maps);
      break;
  }
  build_rolled_flanks_model(in, span, st.flanks, name, clock, st.model);
  return st;
}

namespace {

// One mesh of a pinion tooth and a wheel tooth along the path: each position's strip, and (running-in)
// the deepest plastic deformation each flank's map takes from them.
struct ArealMeshPass {
  std::vector<ArealStrip> strips;
  std::array<std::vector<double>, 2> plastic;  // per map point [m] (running-in only)
  double max_new_plastic = 0.0;                // [m]
};

struct ArealMeshSetup {
  const FidelityInputs& in;
  const Areal::State& st;
  const ElasticKernel& kernel;
  const ArealOptions& options;
  const std::vector<double>& share;
  std::vector<bool> keep;  // the positions whose pressure profiles are kept (the first mesh's only)
};

ArealMeshPass areal_mesh_pass(const ArealMeshSetup& m, int pinion_tooth, int wheel_tooth, bool running_in, bool first,
                              const std::function<void(int)>& solved) {
  const FidelityInputs& in = m.in;
  const Areal::State& st = m.st;
  const ContactSettings& cs = in.contact;
  const PathState& p = in.path;
  const ArealGrid& g = m.kernel.grid();
  const int nx = g.nx, ny = g.ny;
  const double e = g.dx, length = nx * e;  // the window along the involute [m]
  const ArealOptions& o = m.options;
  const FlankTrack& pinion = st.flanks.pinion[static_cast<std::size_t>(pinion_tooth)];
  const FlankTrack& wheel = st.flanks.wheel[static_cast<std::size_t>(wheel_tooth)];
  const bool mapped = !st.maps[0].empty();
  const FlankMap* pm = mapped ? &st.maps[0][static_cast<std::size_t>(pinion_tooth)] : nullptr;
  const FlankMap* wm = mapped ? &st.maps[1][static_cast<std::size_t>(wheel_tooth)] : nullptr;
  const double share1 = st.options.pinion_plastic_share, share2 = 1.0 - share1;
  ArealMeshPass out;
  if (running_in && !mapped) throw std::logic_error("areal running-in without the flanks' maps");
  if (running_in) out.plastic = {std::vector<double>(pm->z.size(), 0.0), std::vector<double>(wm->z.size(), 0.0)};
  std::vector<double> h(g.size()), start, plastic(running_in ? g.size() : 0);
  const int n = static_cast<int>(p.size());
  for (int k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const bool keep = first && kk < m.keep.size() && m.keep[kk];
    ArealStrip s;
    const double w = p.line_load[kk] * m.share[kk], b = p.half_width[kk];
    if (w > 0.0) {
      if (w >= 0.9 * length * o.hardness)
        throw core::KeyedError(
            "contact.strip_halfwidths",
            fmt::format("the line load {:.4g} N/m would yield the window along the involute (+-{:.4g} mm at the "
                        "hardness {:.4g} GPa carries {:.4g} N/m): raise contact.strip_halfwidths or lower the torque",
                        w, 0.5e3 * length, o.hardness * 1e-9, length * o.hardness));
      for (int i = 0; i < nx; ++i) {
        // Without maps (extruded, no running-in): each profile's mean over the element, as the
        // deterministic fidelity's strip takes it.
        const double x = st.grid.x(i), sp = st.sigma[0][kk] - x, sw = st.sigma[1][kk] + x;
        const double parabola = -x * x / (2.0 * p.radius[kk]);
        const double profiles =
            mapped ? 0.0
                   : track_mean(pinion, sp - 0.5 * e, sp + 0.5 * e) + track_mean(wheel, sw - 0.5 * e, sw + 0.5 * e);
        for (int j = 0; j < ny; ++j)
          h[static_cast<std::size_t>(j) * nx + i] = parabola + (mapped ? pm->at(sp, j) + wm->at(sw, j) : profiles);
      }
      const ArealSolution sol = solve_contact(m.kernel, h, Control::mean_pressure, w / length, o, start);
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
        for (const SubsurfacePlane& pl : subsurface_von_mises(m.kernel, sol.pressure, o.poisson_ratio, depths))
          if (pl.max_von_mises > s.max_von_mises) s.max_von_mises = pl.max_von_mises, s.max_von_mises_depth = pl.depth;
      }
      if (keep) {
        s.pressure.assign(static_cast<std::size_t>(nx), 0.0);
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i)
            s.pressure[static_cast<std::size_t>(i)] += sol.pressure[static_cast<std::size_t>(j) * nx + i] / ny;
      }
      if (running_in && sol.plastic_fraction > 0.0) {
        // The plastic interpenetration where the pressure is capped: the flanks lowered by it.
        for (std::size_t q = 0; q < plastic.size(); ++q) plastic[q] = std::max(-sol.gap[q], 0.0);
        if (share1 > 0.0) lay_plastic(st.grid, *pm, st.sigma[0][kk], -1, plastic, share1, out.plastic[0]);
        if (share2 > 0.0) lay_plastic(st.grid, *wm, st.sigma[1][kk], +1, plastic, share2, out.plastic[1]);
      }
    } else if (keep) {
      s.pressure.assign(static_cast<std::size_t>(nx), 0.0);
    }
    out.strips.push_back(std::move(s));
    solved(k + 1);
  }
  for (const auto& d : out.plastic)
    for (double v : d) out.max_new_plastic = std::max(out.max_new_plastic, v);
  return out;
}

deterministic::HistoryRow areal_history_row(int mesh, const std::vector<const ArealMeshPass*>& passes,
                                            const Areal::State& st) {
  deterministic::HistoryRow row;
  row.mesh = mesh;
  row.add_passes(passes);
  for (int g = 0; g < 2; ++g) row.flank[g] = map_statistics(st.maps[static_cast<std::size_t>(g)], st.span, g);
  return row;
}

}  // namespace

Areal::Solution Areal::solve(const FidelityInputs& in, State& st, const std::vector<double>& share, StageClock& clock) {
  Solution out;
  out.share = share;
  out.statistical = statistical_beside(in, st.model, share, clock);
  const ContactSettings& cs = in.contact;
  ArealGrid g;
  g.nx = st.grid.size, g.ny = cs.areal.points, g.dx = st.grid.spacing, g.dy = cs.areal.spacing();
  g.periodic_x = false, g.periodic_y = true;
  const ElasticKernel kernel(g, in.mesh.composite_modulus());
  ArealOptions o;
  o.composite_modulus = in.mesh.composite_modulus();
  o.hardness = st.options.pressure_cap;
  o.poisson_ratio = st.options.poisson_ratio;
  o.tolerance = cs.areal.tolerance;
  const ArealMeshSetup setup{in, st, kernel, o, share, kept_profiles(cs, in.path)};
  // The meshes: one (no running-in), or until shakedown, each flank's map lowered by its plastic
  // deformation; the hunting order's pinion tooth k meets wheel tooth (mesh number) mod z2.
  const bool running_in = in.running_in.meshes > 0;
  const int planned = std::max(1, in.running_in.meshes), per_round = st.hunting ? st.teeth[0] : 1;
  const int n = static_cast<int>(in.path.size());
  const long long all_solves = static_cast<long long>(planned) * per_round * n;
  if (all_solves > std::numeric_limits<int>::max())
    throw std::invalid_argument(
        fmt::format("running-in of {} meshes x {} tooth pairs x {} positions: more window "
                    "solves than a run can count",
                    planned, per_round, n));
  const int total = static_cast<int>(all_solves);
  int solved = 0;
  if (running_in) {
    RunningInResult ri;
    ri.teeth = tooth_order_name(st.hunting ? ToothOrder::hunting : ToothOrder::pair);
    ri.tolerance = cs.boundary_elements.plastic_overlap;
    for (int gg = 0; gg < 2; ++gg) {
      const FlankMap& m = st.maps[static_cast<std::size_t>(gg)].front();
      ri.spacing[static_cast<std::size_t>(gg)] = m.dx;
      ri.initial[static_cast<std::size_t>(gg)] = active_row(m, st.span, gg);
    }
    out.running_in = std::move(ri);
    out.history.push_back(areal_history_row(0, {}, st));
  }
  for (int round = 1; round <= planned; ++round) {
    std::vector<ArealMeshPass> passes;
    for (int k = 0; k < per_round; ++k) {
      const long mesh_number = static_cast<long>(round - 1) * per_round + k;
      const int wheel_tooth = static_cast<int>(mesh_number % st.teeth[1]);
      passes.push_back(areal_mesh_pass(setup, k, wheel_tooth, running_in, round == 1 && k == 0, [&](int done) {
        if (in.progress) in.progress(solved + done, total);
      }));
      solved += n;
      if (running_in) {
        const ArealMeshPass& q = passes.back();
        auto lower = [](FlankMap& m, const std::vector<double>& d) {
          for (std::size_t i = 0; i < d.size(); ++i) m.z[i] -= d[i];
        };
        lower(st.maps[0][static_cast<std::size_t>(k)], q.plastic[0]);
        lower(st.maps[1][static_cast<std::size_t>(wheel_tooth)], q.plastic[1]);
      }
    }
    double new_plastic = 0.0;
    for (const auto& q : passes) new_plastic = std::max(new_plastic, q.max_new_plastic);
    if (running_in) {
      std::vector<const ArealMeshPass*> views;
      views.reserve(passes.size());
      for (const auto& q : passes) views.push_back(&q);
      out.history.push_back(areal_history_row(round, views, st));
    }
    if (round == 1) out.strips = std::move(passes.front().strips);
    if (!running_in) break;
    out.running_in->meshes = round;
    if (new_plastic <= cs.boundary_elements.plastic_overlap) {
      out.running_in->shakedown_mesh = round;
      break;
    }
  }
  if (in.progress) in.progress(total, total);
  clock.lap("areal_contact");
  if (out.running_in)
    for (int gg = 0; gg < 2; ++gg)
      out.running_in->final[static_cast<std::size_t>(gg)] =
          active_row(st.maps[static_cast<std::size_t>(gg)].front(), st.span, gg);
  return out;
}

void Areal::write(const FidelityInputs& in, State& st, Solution& s, MeshContactResult& r) {
  const ContactSettings& cs = in.contact;
  if (s.statistical) {
    write_statistical_beside(in, *st.model, *s.statistical, r);
    // Persson on the maps' full gradient (State::gradient_factor).
    write_persson_beside(in, *st.model, s.share, st.gradient_factor, r);
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
  const bool generated = cs.areal.lay == ArealLay::isotropic || cs.areal.lay == ArealLay::directional;
  const double across = cs.areal.lay == ArealLay::directional ? cs.areal.lay_ratio : 1.0;
  for (const surface::FlankSpec* spec : in.flank_specs)
    if (generated && spec && spec->profile && cs.areal.window < 4.0 * across * spec->profile->correlation_length) {
      r.verdict += cs.areal.lay == ArealLay::isotropic
                       ? " The window across the face holds fewer than four correlation lengths: its spots are few; "
                         "widen areal.window."
                       : " The window across the face holds fewer than four of the lay's correlation lengths across "
                         "it: the maps are nearly extruded there and their spots few; widen areal.window.";
      break;
    }
  if (s.running_in) {
    const RunningInResult& ri = *s.running_in;
    r.verdict += ri.shakedown_mesh > 0
                     ? fmt::format(" Running-in: shakedown at mesh {} (no new plastic deformation beyond {:.3g} um).",
                                   ri.shakedown_mesh, ri.tolerance * 1e6)
                     : fmt::format(
                           " Running-in: {} meshes without shakedown (new plastic deformation still beyond "
                           "{:.3g} um).",
                           ri.meshes, ri.tolerance * 1e6);
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
  if (!s.running_in) return;
  write_running_in_history(s.history, *s.running_in);
  r.running_in = std::move(s.running_in);
}

}  // namespace geartrib::contact::areal
