#include "contact/mesh_deterministic.hpp"

#include "case/contact_setup.hpp"
#include "contact/series_columns.hpp"
#include "core/keyed_error.hpp"
#include "core/stopwatch.hpp"
#include "surface/rough_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace geartrib::contact {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Fewer elements than this across a contact spot on average: the spots are not resolved
// (a Hertzian spot's peak pressure is within ~5% from four elements across; tests/test_deterministic_contact.cpp).
constexpr double kMinElementsPerSpot = 4.0;

const std::vector<double>& series(const MeshContactResult& r, const char* name) {
  const Series* s = r.find(name);
  if (!s) throw std::logic_error(std::string("mesh cycle: no series ") + name);
  return s->values;
}

// The statistical model (uncoupled) on the same flanks: each flank's spectral moments from its
// profile over the active part (McCool's summits), the rest of the case as it is.
MeshContactResult statistical_on_profiles(const Case& c, const gear::GearMesh& mesh, const RollingFlanks& f,
                                          const FlankSpan& span, int positions, const OdeIntegrator* dynamics) {
  Case sc = c;
  sc.contact.fidelity = ContactFidelity::uncoupled;
  const FlankTrack* tracks[2] = {&f.pinion.front(), &f.wheel.front()};
  GearSpec* gears[2] = {&sc.pinion, &sc.wheel};
  for (int g = 0; g < 2; ++g) {
    gears[g]->flank.roughness =
        surface::spectral_roughness(active_statistics(*tracks[g], span.active_first[g], span.active_last[g]));
  }
  const auto [r1, r2] = surface::flank_summit_radii(sc.pinion.flank.roughness, sc.wheel.flank.roughness);
  sc.pinion.flank.roughness.summit_radius = r1;
  sc.wheel.flank.roughness.summit_radius = r2;
  return run_mesh_contact(sc, mesh, nullptr, {}, positions, dynamics);
}

bool rough(const FlankTrack& t) {
  return std::any_of(t.profile.z.begin(), t.profile.z.end(), [](double z) { return z != 0.0; });
}

// The per-position outputs of one mesh, as the case asks for them.
void add_contact_series(const Case& c, const std::vector<DeterministicStrip>& strips, MeshContactResult& r) {
  using S = DeterministicStrip;
  using C = Column<S>;
  const ContactSettings& cs = c.contact;
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
  const double e = cs.element_size;
  auto per_spot = [e](const S& s) {
    return s.contact_spots > 0 ? s.real_area_per_width / (s.contact_spots * e) : kNaN;
  };
  std::vector<double>& eps = add_series(r.validity, "elements_per_spot", "1");
  std::vector<double>& edge = add_series(r.validity, "flag_strip_edge_loaded", "1");
  std::vector<double>& coarse = add_series(r.validity, "flag_spots_unresolved", "1");
  int n_edge = 0, n_coarse = 0, loaded = 0, elastic = 0, plastic = 0;
  for (const S& s : strips) {
    const double k = per_spot(s);
    eps.push_back(std::isnan(k) ? 0.0 : k);
    edge.push_back(s.edge_loaded ? 1.0 : 0.0);
    const bool unresolved = !std::isnan(k) && k < kMinElementsPerSpot;
    coarse.push_back(unresolved ? 1.0 : 0.0);
    n_edge += s.edge_loaded, n_coarse += unresolved;
    if (s.real_area_per_width > 0.0) {
      ++loaded;
      elastic += s.plastic_area_fraction < 0.01;
      plastic += s.plastic_area_fraction > 0.99;
    }
  }
  r.regime = elastic == loaded ? "elastic" : plastic == loaded ? "fully plastic" : "elastic-plastic";
  r.verdict = fmt::format(
      "Deterministic rough contact of the flanks' profiles (boundary elements of {:.3g} um over +-{:.3g} Hertz "
      "half-widths): {}; of {} loaded positions {} elastic (<1% of the real area yielded), {} fully plastic (>99%).",
      e * 1e6, cs.strip_halfwidths, r.regime, loaded, elastic, plastic);
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

// Rows of the running-in history.
struct HistoryRow {
  double mesh = 0.0, new_plastic = kNaN, real_area = kNaN, plastic_fraction = kNaN, peak_pressure = kNaN;
  surface::ProfileStatistics flank[2];
};

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
  if (!passes.empty()) {
    row.new_plastic = row.real_area = row.plastic_fraction = row.peak_pressure = 0.0;
    for (const MeshPass* p : passes) {
      std::vector<double> area, fraction;
      for (const auto& s : p->strips) {
        area.push_back(s.real_area_ratio);
        fraction.push_back(s.plastic_area_fraction);
        row.peak_pressure = std::max(row.peak_pressure, s.peak_pressure);
      }
      row.new_plastic = std::max(row.new_plastic, p->max_new_plastic);
      row.real_area += path_mean(area) / static_cast<double>(passes.size());
      row.plastic_fraction += path_mean(fraction) / static_cast<double>(passes.size());
    }
  }
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
      const double reach = 0.5 * g.size * g.spacing + 2.0 * cs.element_size;  // as the span's margin
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

int strip_threads(const ContactSettings& cs, int positions) {
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::clamp(cs.threads > 0 ? cs.threads : hardware, 1, std::max(1, positions));
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

void run_deterministic(const Case& c, const gear::GearMesh& mesh, MeshContactResult& r, const FlankSource& source,
                       const std::function<void(int, int)>& progress, const OdeIntegrator* dynamics) {
  const ContactSettings& cs = c.contact;
  const auto& s_m = series(r, "s_m");
  const auto& load = series(r, "line_load_N_per_m");
  const auto& r_eq = series(r, "r_eq_m");
  const auto& b_h = series(r, "hertz_halfwidth_m");
  const auto& rho1 = series(r, "rho1_m");
  const auto& rho2 = series(r, "rho2_m");
  const int n = static_cast<int>(s_m.size());
  Stopwatch clock;

  // The strip, the span of each flank it reads, and the flanks.
  const double rb[2] = {mesh.pair().pinion().base_radius, mesh.pair().wheel().base_radius};
  const double b_max = *std::max_element(b_h.begin(), b_h.end());
  FlankSpan span;
  span.element_size = cs.element_size;
  span.strip_half_length = cs.strip_halfwidths * b_max;
  std::vector<double> sigma[2];
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sigma[0].push_back(rho1[k] * rho1[k] / (2.0 * rb[0]));  // involute arc length from the base circle
    sigma[1].push_back(rho2[k] * rho2[k] / (2.0 * rb[1]));
  }
  // The boundary elements: the softer flank's hardness caps the pressure and takes the plastic
  // deformation (equal hardness: half each).
  const DeterministicOptions o = deterministic_options(c);
  // The flanks are read over the grid's whole reach (at least 8 elements) and two elements more.
  const HalfPlaneGrid grid = strip_grid(span.strip_half_length, o);
  span.elements = grid.size;
  const double margin = 0.5 * grid.size * grid.spacing + 2.0 * cs.element_size;
  span.positions = n;
  span.running_in = c.running_in.meshes > 0;
  for (int g = 0; g < 2; ++g) {
    for (int i = 0; i + 1 < n; ++i)
      span.max_step[g] = std::max(span.max_step[g], std::abs(sigma[g][static_cast<std::size_t>(i + 1)] -
                                                             sigma[g][static_cast<std::size_t>(i)]));
    span.active_first[g] = *std::min_element(sigma[g].begin(), sigma[g].end());
    span.active_last[g] = *std::max_element(sigma[g].begin(), sigma[g].end());
    span.first[g] = span.active_first[g] - margin;
    span.last[g] = span.active_last[g] + margin;
    const gear::GearBody& body = mesh.pair().gear(g);
    const double tip =
        (body.tip_radius * body.tip_radius - body.base_radius * body.base_radius) / (2.0 * body.base_radius);
    span.generated_first[g] = -c.gear_pair.module;
    span.generated_last[g] = tip + c.gear_pair.module;
  }
  const bool hunting = c.running_in.teeth == "hunting" && c.running_in.meshes > 0;
  const int teeth[2] = {hunting ? c.gear_pair.teeth[0] : 1, hunting ? c.gear_pair.teeth[1] : 1};
  RollingFlanks flanks = source(span, teeth);
  if (static_cast<int>(flanks.pinion.size()) != teeth[0] || static_cast<int>(flanks.wheel.size()) != teeth[1])
    throw std::logic_error("deterministic run: the flank source gave the wrong number of teeth");
  r.stages.push_back({"flank_profiles", clock.lap()});

  // The statistical model on the same flanks (both rough), and in lubricated runs the film's share.
  const bool statistics = rough(flanks.pinion.front()) && rough(flanks.wheel.front());
  std::vector<double> share(static_cast<std::size_t>(n), 1.0);
  if (c.lubrication.lubricated && !statistics)
    throw core::KeyedError(
        rough(flanks.pinion.front()) ? "wheel.flank" : "pinion.flank",
        "a lubricated deterministic run takes the film's share of the load from the flanks' statistics, and this "
        "flank's profile is flat: give both flanks a rough profile (or run the case dry)");
  if (statistics) {
    MeshContactResult st = statistical_on_profiles(c, mesh, flanks, span, n, dynamics);
    for (const auto* group : {&st.contact, &st.validity})
      for (const Series& q : *group) r.statistical.push_back({"statistical_" + q.name, q.unit, q.values});
    r.lubrication = std::move(st.lubrication);
    r.lubrication_summary = std::move(st.lubrication_summary);
    r.surface = st.surface;
    r.plasticity_index = st.plasticity_index;
    r.asperity_model = st.asperity_model;
    for (const auto& w : st.warnings) r.warnings.push_back("statistical model: " + w);
    if (const Series* a = r.find("asperity_load_share")) share = a->values;
    r.stages.push_back({"statistical_model", clock.lap()});
  }

  std::vector<StripPosition> positions;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    positions.push_back({load[k] * share[k], r_eq[k], b_h[k], sigma[0][k], sigma[1][k], s_m[k]});
  }
  std::vector<bool> keep(static_cast<std::size_t>(n), cs.pressure_profiles == PressureProfiles::all);
  const auto& path = r.path;
  const std::pair<const char*, double> named[] = {
      {"A", path.a}, {"B", path.b}, {"C", path.c}, {"D", path.d}, {"E", path.e}};
  std::vector<std::string> point_name(static_cast<std::size_t>(n));
  for (const auto& [name, s] : named) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < s_m.size(); ++k)
      if (std::abs(s_m[k] - s) < std::abs(s_m[best] - s)) best = k;
    point_name[best] = name;
    if (cs.pressure_profiles == PressureProfiles::points) keep[best] = true;
  }
  // The strip carries at most 2 L H (every element at the cap): beyond it the contact is plastic
  // across the whole strip and would spread beyond it.
  const double capacity = grid.size * grid.spacing * o.pressure_cap;
  const double w_max = *std::max_element(load.begin(), load.end());
  if (w_max > 0.9 * capacity) throw strip_overload(cs, o, span, flanks, w_max, b_max, capacity, grid);
  const int threads = strip_threads(cs, n);
  const double modulus = mesh.composite_modulus();

  // The meshes: one (no running-in), or until shakedown.
  const int planned = std::max(1, c.running_in.meshes);
  const int per_round = hunting ? teeth[0] : 1;
  const long long all_solves = static_cast<long long>(planned) * per_round * n;
  if (all_solves > std::numeric_limits<int>::max())
    throw std::invalid_argument(
        fmt::format("running-in of {} meshes x {} tooth pairs x {} positions: more strip solves "
                    "than a run can count ({})",
                    planned, per_round, n, std::numeric_limits<int>::max()));
  const int total_solves = static_cast<int>(all_solves);
  int solved = 0;
  auto pass = [&](const FlankTrack& p, const FlankTrack& w, bool first) {
    MeshPass out = mesh_pass(p, w, positions, modulus, span.strip_half_length, o, first ? keep : std::vector<bool>{},
                             threads, [&](int done, int) {
                               if (progress) progress(solved + done, total_solves);
                             });
    solved += n;
    return out;
  };
  auto lower = [](FlankTrack& t, const std::vector<double>& d) {
    for (std::size_t k = 0; k < d.size(); ++k) t.profile.z[k] -= d[k];
  };
  std::vector<const FlankTrack*> all[2];
  for (const auto& t : flanks.pinion) all[0].push_back(&t);
  for (const auto& t : flanks.wheel) all[1].push_back(&t);
  std::optional<RunningInResult> ri;
  std::vector<HistoryRow> rows;
  if (c.running_in.meshes > 0) {
    ri.emplace();
    ri->teeth = hunting ? "hunting" : "pair";
    ri->tolerance = c.running_in.tolerance;
    for (int g = 0; g < 2; ++g) {
      const FlankTrack& t = g == 0 ? flanks.pinion.front() : flanks.wheel.front();
      ri->spacing[g] = t.profile.spacing;
      ri->initial[g] = active_part(t, span, g);
    }
    rows.push_back(history_row(0, {}, all, span));
  }
  MeshPass first;
  for (int round = 1; round <= planned; ++round) {
    std::vector<MeshPass> passes;
    for (int k = 0; k < per_round; ++k) {
      // Hunting order: pinion tooth k meets wheel tooth (mesh number) mod z2.
      const long mesh_number = static_cast<long>(round - 1) * per_round + k;
      FlankTrack& p = flanks.pinion[static_cast<std::size_t>(k)];
      FlankTrack& w = flanks.wheel[static_cast<std::size_t>(mesh_number % teeth[1])];
      passes.push_back(pass(p, w, round == 1 && k == 0));
      if (ri) {
        lower(p, passes.back().plastic_pinion);
        lower(w, passes.back().plastic_wheel);
      }
    }
    if (ri) {
      std::vector<const MeshPass*> views;
      for (const auto& q : passes) views.push_back(&q);
      rows.push_back(history_row(round, views, all, span));
    }
    double new_plastic = 0.0;
    for (const auto& q : passes) new_plastic = std::max(new_plastic, q.max_new_plastic);
    if (round == 1) first = std::move(passes.front());  // its pressure profiles moved, not copied
    if (!ri) break;
    ri->meshes = round;
    if (new_plastic <= c.running_in.tolerance) {
      ri->shakedown_mesh = round;
      break;
    }
  }
  if (progress) progress(total_solves, total_solves);
  r.stages.push_back({"deterministic_contact", clock.lap()});

  add_contact_series(c, first.strips, r);
  {  // the pressure profiles kept (first mesh), on the strip's grid (the one every solver has)
    std::vector<double> x(static_cast<std::size_t>(grid.size));
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = grid.x(static_cast<int>(j));
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (first.strips[k].pressure.empty()) continue;
      r.pressure_profiles.push_back({i, point_name[k], s_m[k], x, std::move(first.strips[k].pressure)});
    }
  }
  if (ri) {
    for (int g = 0; g < 2; ++g)
      ri->final[g] = active_part(g == 0 ? flanks.pinion.front() : flanks.wheel.front(), span, g);
    using H = HistoryRow;
    using C = Column<H>;
    add_columns<H>(ri->history, rows,
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
    r.running_in = std::move(ri);
  }
}

}  // namespace geartrib::contact
