#include "contact/deterministic/mesh_deterministic.hpp"

#include "contact/persson_contact.hpp"
#include "contact/position_threads.hpp"
#include "contact/series_columns.hpp"
#include "contact/stage_clock.hpp"
#include "core/keyed_error.hpp"
#include "core/stopwatch.hpp"
#include "surface/rough_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geartrib::contact {

namespace {

using deterministic::HistoryRow;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Fewer elements than this across a contact spot on average: the spots are not resolved
// (a Hertzian spot's peak pressure is within ~5% from four elements across; tests/test_deterministic_contact.cpp).
constexpr double kMinElementsPerSpot = 4.0;

bool rough(const FlankTrack& t) {
  return std::any_of(t.profile.z.begin(), t.profile.z.end(), [](double z) { return z != 0.0; });
}

// The statistical model's flanks: each flank's spectral moments from its profile over the active
// part (McCool's summits), the rest as the case gives them.
StatisticalFlanks profile_statistics(const FidelityInputs& in, const FlankSpan& span, const RollingFlanks& flanks) {
  StatisticalFlanks f = in.flanks;
  const FlankTrack* tracks[2] = {&flanks.pinion.front(), &flanks.wheel.front()};
  for (std::size_t g = 0; g < 2; ++g)
    f.roughness[g] =
        surface::spectral_roughness(active_statistics(*tracks[g], span.active_first[g], span.active_last[g]));
  const auto [r1, r2] = surface::flank_summit_radii(f.roughness[0], f.roughness[1]);
  f.roughness[0].summit_radius = r1;
  f.roughness[1].summit_radius = r2;
  return f;
}

// The per-position outputs of one mesh, as the case asks for them.
void add_contact_series(const ContactSettings& cs, const std::vector<DeterministicStrip>& strips,
                        MeshContactResult& r) {
  using S = DeterministicStrip;
  using C = Column<S>;
  if (cs.real_area)
    add_columns<S>(r.contact, strips,
                   {C{"real_area_ratio", "1", [](const S& s) { return s.real_area_ratio; }},
                    C{"real_area_per_width_m", "m", [](const S& s) { return s.real_area_per_width; }},
                    C{"mean_real_pressure_Pa", "Pa", [](const S& s) { return s.mean_real_pressure; }},
                    C{"contact_spots", "1", [](const S& s) { return static_cast<double>(s.contact_spots); }},
                    C{"max_pressure_Pa", "Pa", [](const S& s) { return s.peak_pressure; }},
                    C{"contact_halfwidth_m", "m", [](const S& s) { return s.contact_half_width; }}});
  if (cs.plastic_fraction)
    add_columns<S>(r.contact, strips,
                   {C{"plastic_area_fraction", "1", [](const S& s) { return s.plastic_area_fraction; }},
                    C{"plastic_area_per_width_m", "m", [](const S& s) { return s.plastic_area_per_width; }},
                    C{"max_plastic_deformation_m", "m", [](const S& s) { return s.max_plastic_deformation; }}});
  if (cs.asperity_stress)
    add_columns<S>(r.contact, strips,
                   {C{"max_von_mises_Pa", "Pa", [](const S& s) { return s.max_von_mises; }},
                    C{"max_von_mises_depth_m", "m", [](const S& s) { return s.max_von_mises_depth; }},
                    C{"max_von_mises_x_m", "m", [](const S& s) { return s.max_von_mises_x; }}});
  add_columns<S>(r.contact, strips,
                 {C{"bem_iterations", "1", [](const S& s) { return static_cast<double>(s.iterations); }}});

  // Where the answer holds: the strip long enough, the spots resolved.
  const double e = cs.boundary_elements.element_size;
  auto per_spot = [e](const S& s) {
    return s.contact_spots > 0 ? s.real_area_per_width / (s.contact_spots * e) : kNaN;
  };
  Series eps{"elements_per_spot", "1", {}}, edge{"flag_strip_edge_loaded", "1", {}},
      coarse{"flag_spots_unresolved", "1", {}};
  int n_edge = 0, n_coarse = 0;
  RollingRegime regime;
  for (const S& s : strips) {
    const double k = per_spot(s);
    eps.values.push_back(std::isnan(k) ? 0.0 : k);
    edge.values.push_back(s.edge_loaded ? 1.0 : 0.0);
    const bool unresolved = !std::isnan(k) && k < kMinElementsPerSpot;
    coarse.values.push_back(unresolved ? 1.0 : 0.0);
    n_edge += s.edge_loaded, n_coarse += unresolved;
    regime.add(s.real_area_per_width, s.plastic_area_fraction);
  }
  r.validity.push_back(std::move(eps));
  r.validity.push_back(std::move(edge));
  r.validity.push_back(std::move(coarse));
  r.regime = regime.name();
  r.verdict = fmt::format(
      "Deterministic rough contact of the flanks' profiles (boundary elements of {:.3g} um over +-{:.3g} Hertz "
      "half-widths): {}; of {} loaded positions {} elastic (<1% of the real area yielded), {} fully plastic (>99%).",
      e * 1e6, cs.boundary_elements.strip_halfwidths, r.regime, regime.loaded, regime.elastic, regime.plastic);
  if (n_edge > 0)
    r.verdict += fmt::format(
        " At {} positions the pressure reaches the strip's ends: the contact is cut short there; raise "
        "contact.strip_halfwidths.",
        n_edge);
  if (n_coarse > 0)
    r.verdict += fmt::format(
        " At {} positions the contact spots span fewer than {:g} elements on average: their peak pressures and "
        "plastic areas are not resolved; lower contact.element_size.",
        n_coarse, kMinElementsPerSpot);
  r.flag_counts = {{"strip_edge_loaded", n_edge}, {"spots_unresolved", n_coarse}};
}

// A flank's statistics over its active part as the elements see it: the profile averaged over
// element-sized cells (the summit curvature of the finer profile would count the kinks a plastic
// flattening leaves between element centres).
surface::ProfileStatistics element_statistics(const FlankTrack& t, const FlankSpan& span, int g) {
  std::vector<double> z;
  for (double a = span.active_first[g]; a + span.element_size <= span.active_last[g]; a += span.element_size)
    z.push_back(track_mean(t, a, a + span.element_size));
  return surface::profile_statistics(z, span.element_size);
}

HistoryRow history_row(int mesh, const std::vector<const MeshPass*>& passes,
                       const std::vector<const FlankTrack*> tracks[2], const FlankSpan& span) {
  HistoryRow row;
  row.mesh = mesh;
  row.add_passes(passes);
  for (int g = 0; g < 2; ++g) {  // the teeth's mean statistics, at the elements' sampling
    surface::ProfileStatistics& m = row.flank[g];
    for (const FlankTrack* t : tracks[g]) {
      const surface::ProfileStatistics e = element_statistics(*t, span, g);
      const double w = 1.0 / static_cast<double>(tracks[g].size());
      m.rq += w * e.rq, m.rsk += w * e.rsk, m.summit_radius += w * e.summit_radius, m.peak_height += w * e.peak_height;
    }
  }
  return row;
}

std::vector<double> active_part(const FlankTrack& t, const FlankSpan& span, int g) {
  const double h = t.profile.spacing;
  const auto last = static_cast<long>(t.profile.z.size()) - 1;
  const long k0 = std::clamp(static_cast<long>(std::ceil((span.active_first[g] - t.start) / h)), 0L, last);
  const long k1 = std::clamp(static_cast<long>(std::floor((span.active_last[g] - t.start) / h)), 0L, last);
  return {t.profile.z.begin() + k0, t.profile.z.begin() + k1 + 1};
}

// The refusal of a strip the line load would yield all across, with the advice that holds: the
// strip (in 0.1 half-widths) whose capacity 2 L H is 1.25 w_max, so that the load stays below 0.9 of
// it, when such a strip is possible: within the key's range, its elements within the grid's bound,
// and its reach (the grid's half-length and two elements either side of the contact) on the flanks
// the run reads (a generated profile ends a module beyond the tip, a measured trace where it ends).
// Otherwise no strip carries the load and the advice is the torque.
core::KeyedError strip_overload(const ContactSettings& cs, const DeterministicOptions& o, const FlankSpan& span,
                                const RollingFlanks& flanks, double w_max, double b_max, double capacity,
                                const HalfPlaneGrid& grid) {
  const std::string what = fmt::format(
      "the line load {:.4g} N/m would yield the whole strip (+-{:.4g} mm at the hardness {:.4g} GPa "
      "carries {:.4g} N/m)",
      w_max, grid.size * grid.spacing * 0.5e3, o.pressure_cap * 1e-9, capacity);
  const double needed = std::ceil(10.0 * 1.25 * w_max / (2.0 * o.pressure_cap * b_max)) / 10.0;
  std::string why_not;
  if (needed > DeterministicOptions::kMaxStripHalfwidths) {
    why_not = fmt::format(
        "no strip within the key's range ({:g}) carries it (the flanks would be plastic across "
        "{:.3g} Hertz half-widths)",
        DeterministicOptions::kMaxStripHalfwidths, needed);
  } else {
    DeterministicOptions wider = o;
    wider.strip_halfwidths = needed;
    try {
      const HalfPlaneGrid g = strip_grid(needed * b_max, wider);
      const double reach = 0.5 * g.size * g.spacing + 2.0 * cs.boundary_elements.element_size;  // as the span's margin
      for (int k = 0; k < 2 && why_not.empty(); ++k)
        for (const FlankTrack& t : k == 0 ? flanks.pinion : flanks.wheel)
          // (Its last interval left out: a generated profile's may pass the module beyond the tip,
          // which is the limit.)
          if (span.active_first[k] - reach < t.start || span.active_last[k] + reach > t.end() - t.profile.spacing) {
            why_not = fmt::format(
                "a strip of {:g} half-widths, which would carry it, reaches {:.4g} mm beyond the {}'s active flank, "
                "past the profile the run reads (a generated one ends a module beyond the tip)",
                needed, reach * 1e3, k == 0 ? "pinion" : "wheel");
            break;
          }
    } catch (const std::invalid_argument& e) {
      why_not = fmt::format("a strip of {:g} half-widths, which would carry it, is refused: {}", needed, e.what());
    }
  }
  return core::KeyedError("contact.strip_halfwidths",
                          why_not.empty()
                              ? fmt::format("{}; raise it to at least {:g}, or lower the torque", what, needed)
                              : fmt::format("{}; {}: lower the torque", what, why_not));
}

}  // namespace

DeterministicOptions deterministic_options(const ContactSettings& cs, const Material& m1, const Material& m2) {
  DeterministicOptions o = cs.boundary_elements;
  o.pressure_cap = std::min(m1.hardness, m2.hardness);
  o.poisson_ratio = m1.hardness <= m2.hardness ? m1.poisson_ratio : m2.poisson_ratio;
  o.pinion_plastic_share = m1.hardness < 0.99 * m2.hardness ? 1.0 : m2.hardness < 0.99 * m1.hardness ? 0.0 : 0.5;
  o.subsurface_stress = cs.asperity_stress;
  return o;
}

double strip_solve_seconds(int elements) {
  // Measured on the shipped case (gears/m6z30-deterministic.toml, 201 positions, one thread):
  // 1.18 s for 1280 elements of 0.5 um (docs/reference/timings.md, cycle_deterministic/element_nm:500),
  // 5.9 ms a position's solve with its subsurface stresses; growing as elements^1.61, the boundary
  // elements' measured scaling (docs/reference/benchmarks.md, hertz_line_contact: the iterations grow
  // with the elements). Within a factor of 3 from 1280 to 228526 elements (2 to 20 half-widths, 0.5 um
  // to 28 nm; over at 5120, where the iterations are fewer: docs/reference/performance.md#budgets).
  constexpr double kSeconds = 5.9e-3, kElements = 1280.0, kExponent = 1.61;
  return kSeconds * std::pow(std::max(elements, 1) / kElements, kExponent);
}

DeterministicCost deterministic_cost(const FlankSpan& span, const DeterministicWork& w) {
  // Bytes, measured with /usr/bin/time's peak RSS on the shipped case (docs/reference/performance.md#budgets):
  // a flank profile 8 a point (its heights); a kept pressure profile 24 an element (its pressure, the
  // strip's x and the HDF5 file's writing: 201 against 1001 profiles of 5120 elements, 45 and 142 MB); a
  // strip solver 240 an element (the boundary elements' work vectors, their coarser grids and transforms:
  // 11.4 MB a thread at 51200 elements); a position's series and statistics 3.3 kB (201 against 20001
  // positions: 15 and 78 MB).
  constexpr double kPointBytes = 8.0, kProfileBytes = 24.0, kSolverBytes = 240.0, kPositionBytes = 3.3e3;
  DeterministicCost c;
  for (int g = 0; g < 2; ++g) c.flank_bytes += kPointBytes * w.flank_points[g] * w.teeth[g];
  c.profile_bytes = kProfileBytes * static_cast<double>(w.kept_profiles) * span.elements;
  c.solver_bytes = kSolverBytes * static_cast<double>(std::max(w.threads, 1)) * span.elements;
  c.position_bytes = kPositionBytes * span.positions;
  // Every planned mesh of every tooth pair the order passes (hunting: z1 pairs a revolution).
  c.solves = static_cast<double>(span.positions) * std::max(w.meshes, 1) * std::max(w.teeth[0], 1);
  c.solve_seconds = strip_solve_seconds(span.elements);
  c.seconds = c.solves * c.solve_seconds / std::clamp(w.cores, 1, std::max(span.positions, 1));
  return c;
}

std::array<std::vector<double>, 2> contact_arcs(const gear::SpurPair& pair, const PathState& p) {
  const double rb[2] = {pair.pinion().base_radius, pair.wheel().base_radius};
  std::array<std::vector<double>, 2> sigma;
  for (std::size_t k = 0; k < p.size(); ++k) {
    sigma[0].push_back(p.rho1[k] * p.rho1[k] / (2.0 * rb[0]));  // involute arc length from the base circle
    sigma[1].push_back(p.rho2[k] * p.rho2[k] / (2.0 * rb[1]));
  }
  return sigma;
}

void set_span_ranges(FlankSpan& span, const gear::SpurPair& pair, const std::array<std::vector<double>, 2>& sigma,
                     const double before[2], const double after[2]) {
  span.positions = static_cast<int>(sigma[0].size());
  for (int g = 0; g < 2; ++g) {
    const auto& sg = sigma[static_cast<std::size_t>(g)];
    for (std::size_t i = 0; i + 1 < sg.size(); ++i)
      span.max_step[g] = std::max(span.max_step[g], std::abs(sg[i + 1] - sg[i]));
    span.active_first[g] = *std::min_element(sg.begin(), sg.end());
    span.active_last[g] = *std::max_element(sg.begin(), sg.end());
    span.first[g] = span.active_first[g] - before[g];
    span.last[g] = span.active_last[g] + after[g];
    const gear::GearBody& body = pair.gear(g);
    const double tip =
        (body.tip_radius * body.tip_radius - body.base_radius * body.base_radius) / (2.0 * body.base_radius);
    span.generated_first[g] = -pair.spec().module;
    span.generated_last[g] = tip + pair.spec().module;
  }
}

void plan_rolling_strip(const FidelityInputs& in, FlankSpan& span, std::array<std::vector<double>, 2>& sigma,
                        DeterministicOptions& options, HalfPlaneGrid& grid) {
  const ContactSettings& cs = in.contact;
  const PathState& p = in.path;
  const gear::SpurPair& pair = in.mesh.pair();
  const double b_max = *std::max_element(p.half_width.begin(), p.half_width.end());
  span.element_size = cs.boundary_elements.element_size;
  span.strip_half_length = cs.boundary_elements.strip_halfwidths * b_max;
  sigma = contact_arcs(pair, p);
  options = deterministic_options(cs, *in.flanks.materials[0], *in.flanks.materials[1]);
  // The flanks are read over the grid's whole reach (at least 8 elements) and two elements more.
  grid = strip_grid(span.strip_half_length, options);
  span.elements = grid.size;
  const double margin = 0.5 * grid.size * grid.spacing + 2.0 * cs.boundary_elements.element_size;
  const double margins[2] = {margin, margin};
  set_span_ranges(span, pair, sigma, margins, margins);
}

std::optional<StatisticalSolution> statistical_beside(const FidelityInputs& in,
                                                      const std::optional<SurfaceModel>& model,
                                                      const std::vector<double>& share, StageClock& clock) {
  if (!model) return std::nullopt;
  std::optional<StatisticalSolution> s = solve_statistical(in, *model, StripFidelity::uncoupled, share, nullptr, {});
  clock.lap("statistical_model");
  return s;
}

void build_rolled_flanks_model(const FidelityInputs& in, const FlankSpan& span, const RollingFlanks& flanks,
                               std::string_view fidelity, StageClock& clock, std::optional<SurfaceModel>& model) {
  const bool statistics = rough(flanks.pinion.front()) && rough(flanks.wheel.front());
  if (in.lubricated && !statistics)
    throw core::KeyedError(
        rough(flanks.pinion.front()) ? "wheel.flank" : "pinion.flank",
        fmt::format("a lubricated {} run takes the film's share of the load from the flanks' statistics, and this "
                    "flank's profile is flat: give both flanks a rough profile (or run the case dry)",
                    fidelity));
  if (!statistics) return;
  double p_max = 0.0;
  for (double p : in.path.hertz_p0) p_max = std::max(p_max, p);
  model.emplace(profile_statistics(in, span, flanks), in.contact, p_max);
  clock.lap("statistical_surface_table");
}

void write_statistical_beside(const FidelityInputs& in, const SurfaceModel& m, const StatisticalSolution& s,
                              MeshContactResult& r) {
  std::vector<Series> contact, validity;
  add_statistical_series(s, m, in.contact, contact, validity);
  for (const auto* group : {&contact, &validity})
    for (const Series& q : *group) r.statistical.push_back({"statistical_" + q.name, q.unit, q.values});
  r.surface = m.surface;
  r.plasticity_index = m.plasticity_index;
  r.asperity_model = std::string(m.table.model().name());
  for (const auto& w : s.warnings) r.warnings.push_back("statistical model: " + w);
}

void write_persson_beside(const FidelityInputs& in, const SurfaceModel& m, const std::vector<double>& share,
                          double gradient_factor, MeshContactResult& r) {
  Stopwatch watch;
  const double g = std::sqrt(gradient_factor * (m.flanks.roughness[0].m2 + m.flanks.roughness[1].m2));
  const double hardness = std::min(in.flanks.materials[0]->hardness, in.flanks.materials[1]->hardness);
  Series area{"statistical_persson_real_area_ratio", "1", {}},
      plastic{"statistical_persson_plastic_area_fraction", "1", {}},
      pressure{"statistical_persson_mean_real_pressure_Pa", "Pa", {}};
  for (std::size_t k = 0; k < in.path.size(); ++k) {
    // The Hertz pressure scaled to the asperities' share (its shape kept).
    const PerssonStrip s =
        persson_hertz_strip(in.path.hertz_p0[k] * share[k], in.mesh.composite_modulus(), g, hardness);
    area.values.push_back(s.real_area_ratio);
    plastic.values.push_back(s.plastic_area_fraction);
    pressure.values.push_back(s.mean_real_pressure);
  }
  r.statistical.push_back(std::move(area));
  r.statistical.push_back(std::move(plastic));
  r.statistical.push_back(std::move(pressure));
  r.stages.push_back({"persson_beside", watch.lap()});
}

void RollingRegime::add(double real_area, double plastic_area_fraction) {
  if (!(real_area > 0.0)) return;
  ++loaded;
  elastic += plastic_area_fraction < 0.01;
  plastic += plastic_area_fraction > 0.99;
}

std::string RollingRegime::name() const {
  return elastic == loaded ? "elastic" : plastic == loaded ? "fully plastic" : "elastic-plastic";
}

std::vector<std::string> path_point_names(const PathState& p) {
  const auto& path = p.path;
  const std::pair<const char*, double> named[] = {
      {"A", path.a}, {"B", path.b}, {"C", path.c}, {"D", path.d}, {"E", path.e}};
  std::vector<std::string> point_name(p.size());
  for (const auto& [name, s] : named) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < p.s.size(); ++k)
      if (std::abs(p.s[k] - s) < std::abs(p.s[best] - s)) best = k;
    point_name[best] = name;
  }
  return point_name;
}

std::vector<bool> kept_profiles(const ContactSettings& cs, const PathState& p) {
  std::vector<bool> keep(p.size(), cs.pressure_profiles == PressureProfiles::all);
  if (cs.pressure_profiles == PressureProfiles::points) {
    const std::vector<std::string> names = path_point_names(p);
    for (std::size_t k = 0; k < names.size(); ++k)
      if (!names[k].empty()) keep[k] = true;
  }
  return keep;
}

double FlankMap::at(double sigma, int j) const {
  const double u = (sigma - start) / dx;
  const int i = std::clamp(static_cast<int>(std::floor(u)), 0, nx - 2);
  const double t = std::clamp(u - i, 0.0, 1.0);
  const double* row = &z[static_cast<std::size_t>(j) * nx];
  return row[i] + t * (row[i + 1] - row[i]);
}

namespace deterministic {

namespace {

// The strip, its boundary elements and the span of each flank it reads (plan_rolling_strip).
void plan_strip(const FidelityInputs& in, BoundaryElements::State& st) {
  plan_rolling_strip(in, st.span, st.sigma, st.options, st.grid);
  st.span.running_in = in.running_in.meshes > 0;
}

// The positions' strips, at the load the asperities carry, and which pressure profiles are kept.
std::vector<StripPosition> strip_positions(const PathState& p, const BoundaryElements::State& st,
                                           const std::vector<double>& share) {
  std::vector<StripPosition> positions;
  for (std::size_t k = 0; k < p.size(); ++k)
    positions.push_back(
        {p.line_load[k] * share[k], p.radius[k], p.half_width[k], st.sigma[0][k], st.sigma[1][k], p.s[k]});
  return positions;
}

// The running-in record before the first mesh: the flanks as made.
std::optional<RunningInResult> running_in_start(const FidelityInputs& in, const BoundaryElements::State& st) {
  if (in.running_in.meshes <= 0) return std::nullopt;
  RunningInResult ri;
  ri.teeth = tooth_order_name(st.hunting ? ToothOrder::hunting : ToothOrder::pair);
  ri.tolerance = in.contact.boundary_elements.plastic_overlap;
  for (int g = 0; g < 2; ++g) {
    const FlankTrack& t = g == 0 ? st.flanks.pinion.front() : st.flanks.wheel.front();
    ri.spacing[static_cast<std::size_t>(g)] = t.profile.spacing;
    ri.initial[static_cast<std::size_t>(g)] = active_part(t, st.span, g);
  }
  return ri;
}

// The meshes: one (no running-in), or until shakedown, each flank lowered by its plastic deformation.
void run_meshes(const FidelityInputs& in, BoundaryElements::State& st, const std::vector<StripPosition>& positions,
                const std::vector<bool>& keep, BoundaryElements::Solution& out) {
  const int n = static_cast<int>(positions.size());
  const int planned = std::max(1, in.running_in.meshes);
  const int per_round = st.hunting ? st.teeth[0] : 1;
  const long long all_solves = static_cast<long long>(planned) * per_round * n;
  if (all_solves > std::numeric_limits<int>::max())  // meshes x teeth x positions, a combination: unkeyed
    throw std::invalid_argument(
        fmt::format("running-in of {} meshes x {} tooth pairs x {} positions: more strip solves "
                    "than a run can count ({})",
                    planned, per_round, n, std::numeric_limits<int>::max()));
  const int total_solves = static_cast<int>(all_solves);
  const int threads = position_threads(in.contact, n);
  int solved = 0;
  auto pass = [&](const FlankTrack& p, const FlankTrack& w, bool first) {
    MeshPass m = mesh_pass(p, w, positions, in.mesh.composite_modulus(), st.span.strip_half_length, st.options,
                           first ? keep : std::vector<bool>{}, threads, [&](int done, int) {
                             if (in.progress) in.progress(solved + done, total_solves);
                           });
    solved += n;
    return m;
  };
  auto lower = [](FlankTrack& t, const std::vector<double>& d) {
    for (std::size_t k = 0; k < d.size(); ++k) t.profile.z[k] -= d[k];
  };
  std::vector<const FlankTrack*> all[2];
  for (const auto& t : st.flanks.pinion) all[0].push_back(&t);
  for (const auto& t : st.flanks.wheel) all[1].push_back(&t);
  std::optional<RunningInResult>& ri = out.running_in;
  if (ri) out.history.push_back(history_row(0, {}, all, st.span));
  for (int round = 1; round <= planned; ++round) {
    std::vector<MeshPass> passes;
    for (int k = 0; k < per_round; ++k) {
      // Hunting order: pinion tooth k meets wheel tooth (mesh number) mod z2.
      const long mesh_number = static_cast<long>(round - 1) * per_round + k;
      FlankTrack& p = st.flanks.pinion[static_cast<std::size_t>(k)];
      FlankTrack& w = st.flanks.wheel[static_cast<std::size_t>(mesh_number % st.teeth[1])];
      passes.push_back(pass(p, w, round == 1 && k == 0));
      if (ri) lower(p, passes.back().plastic_pinion), lower(w, passes.back().plastic_wheel);
    }
    if (ri) {
      std::vector<const MeshPass*> views;
      views.reserve(passes.size());
      for (const auto& q : passes) views.push_back(&q);
      out.history.push_back(history_row(round, views, all, st.span));
    }
    double new_plastic = 0.0;
    for (const auto& q : passes) new_plastic = std::max(new_plastic, q.max_new_plastic);
    if (round == 1) out.first = std::move(passes.front());  // its pressure profiles moved, not copied
    if (!ri) break;
    ri->meshes = round;
    if (new_plastic <= in.contact.boundary_elements.plastic_overlap) {
      ri->shakedown_mesh = round;
      break;
    }
  }
  if (in.progress) in.progress(total_solves, total_solves);
}

}  // namespace

BoundaryElements::State BoundaryElements::prepare(const FidelityInputs& in, StageClock& clock) {
  // The caller's inputs, no option field: unkeyed.
  if (!in.flank_source) throw std::invalid_argument("the deterministic fidelity needs the flanks' profiles");
  State st;
  plan_strip(in, st);
  st.hunting = in.running_in.hunting();
  const int* z = in.mesh.pair().spec().teeth;
  st.teeth[0] = st.hunting ? z[0] : 1;
  st.teeth[1] = st.hunting ? z[1] : 1;
  st.flanks = in.flank_source(st.span, st.teeth);
  if (static_cast<int>(st.flanks.pinion.size()) != st.teeth[0] ||
      static_cast<int>(st.flanks.wheel.size()) != st.teeth[1])
    throw std::logic_error("deterministic run: the flank source gave the wrong number of teeth");
  clock.lap("flank_profiles");
  // The statistical model on the same flanks (both rough), and in lubricated runs the film's share.
  build_rolled_flanks_model(in, st.span, st.flanks, name, clock, st.model);
  return st;
}

BoundaryElements::Solution BoundaryElements::solve(const FidelityInputs& in, State& st,
                                                   const std::vector<double>& share, StageClock& clock) {
  Solution out;
  out.share = share;
  out.statistical = statistical_beside(in, st.model, share, clock);
  const ContactSettings& cs = in.contact;
  const PathState& p = in.path;
  const std::vector<StripPosition> positions = strip_positions(p, st, share);
  const std::vector<bool> keep = kept_profiles(cs, p);
  // The strip carries at most 2 L H (every element at the cap): beyond it the contact is plastic
  // across the whole strip and would spread beyond it.
  const double capacity = st.grid.size * st.grid.spacing * st.options.pressure_cap;
  const double w_max = *std::max_element(p.line_load.begin(), p.line_load.end());
  const double b_max = *std::max_element(p.half_width.begin(), p.half_width.end());
  if (w_max > 0.9 * capacity) throw strip_overload(cs, st.options, st.span, st.flanks, w_max, b_max, capacity, st.grid);
  out.running_in = running_in_start(in, st);
  run_meshes(in, st, positions, keep, out);
  clock.lap("deterministic_contact");
  if (out.running_in)
    for (int g = 0; g < 2; ++g)
      out.running_in->final[static_cast<std::size_t>(g)] =
          active_part(g == 0 ? st.flanks.pinion.front() : st.flanks.wheel.front(), st.span, g);
  return out;
}

void BoundaryElements::write(const FidelityInputs& in, State& st, Solution& s, MeshContactResult& r) {
  if (s.statistical) {
    write_statistical_beside(in, *st.model, *s.statistical, r);
    write_persson_beside(in, *st.model, s.share, 1.0, r);  // the profiles extruded across the face
  }
  add_contact_series(in.contact, s.first.strips, r);
  // The pressure profiles kept (first mesh), on the strip's grid (the one every solver has).
  std::vector<double> x(static_cast<std::size_t>(st.grid.size));
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = st.grid.x(static_cast<int>(j));
  const std::vector<std::string> names = path_point_names(in.path);
  for (std::size_t k = 0; k < s.first.strips.size(); ++k) {
    if (s.first.strips[k].pressure.empty()) continue;
    r.pressure_profiles.push_back(
        {static_cast<int>(k), names[k], in.path.s[k], x, std::move(s.first.strips[k].pressure)});
  }
  if (!s.running_in) return;
  write_running_in_history(s.history, *s.running_in);
  r.running_in = std::move(s.running_in);
}

}  // namespace deterministic

void write_running_in_history(const std::vector<deterministic::HistoryRow>& history, RunningInResult& ri) {
  using H = deterministic::HistoryRow;
  using C = Column<H>;
  add_columns<H>(ri.history, history,
                 {C{"mesh", "1", [](const H& h) { return h.mesh; }},
                  C{"new_plastic_deformation_m", "m", [](const H& h) { return h.new_plastic; }},
                  C{"real_area_ratio_mean", "1", [](const H& h) { return h.real_area; }},
                  C{"plastic_area_fraction_mean", "1", [](const H& h) { return h.plastic_fraction; }},
                  C{"max_pressure_Pa", "Pa", [](const H& h) { return h.peak_pressure; }},
                  C{"pinion_rq_m", "m", [](const H& h) { return h.flank[0].rq; }},
                  C{"pinion_peak_height_m", "m", [](const H& h) { return h.flank[0].peak_height; }},
                  C{"pinion_rsk", "1", [](const H& h) { return h.flank[0].rsk; }},
                  C{"pinion_summit_radius_m", "m", [](const H& h) { return h.flank[0].summit_radius; }},
                  C{"wheel_rq_m", "m", [](const H& h) { return h.flank[1].rq; }},
                  C{"wheel_peak_height_m", "m", [](const H& h) { return h.flank[1].peak_height; }},
                  C{"wheel_rsk", "1", [](const H& h) { return h.flank[1].rsk; }},
                  C{"wheel_summit_radius_m", "m", [](const H& h) { return h.flank[1].summit_radius; }}});
}

}  // namespace geartrib::contact
