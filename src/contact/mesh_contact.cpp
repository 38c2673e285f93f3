#include "contact/mesh_contact.hpp"

#include "asperity/side_contact.hpp"
#include "case/asperity_setup.hpp"
#include "case/contact_setup.hpp"
#include "case/gear_setup.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_deterministic.hpp"
#include "contact/mesh_lubrication.hpp"
#include "contact/rough_line_contact.hpp"
#include "contact/series_columns.hpp"
#include "contact/validity.hpp"
#include "core/stopwatch.hpp"
#include "gear/mesh_dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace geartrib::contact {

const Series* MeshContactResult::find(const std::string& name) const {
  for (const auto* group : groups())
    for (const auto& s : *group)
      if (s.name == name) return &s;
  return nullptr;
}

double path_mean(const std::vector<double>& v) {
  if (v.size() < 2) return v.empty() ? 0.0 : v.front();
  double sum = 0.5 * (v.front() + v.back());
  for (std::size_t i = 1; i + 1 < v.size(); ++i) sum += v[i];
  return sum / static_cast<double>(v.size() - 1);
}

MeshContactResult run_mesh_contact(const Case& c, const gear::GearMesh& mesh, const NonlinearSolver* solver,
                                   const std::function<void(int, int)>& progress, int positions,
                                   const OdeIntegrator* dynamics,
                                   const std::function<RollingFlanks(const FlankSpan&, const int[2])>& flanks) {
  const ContactSettings& cs = c.contact;
  const int n = positions > 0 ? positions : cs.positions;
  MeshContactResult r;
  r.path = mesh.pair().path();
  r.fidelity = cs.deterministic() ? "deterministic" : cs.coupled() ? "coupled" : "uncoupled";
  Stopwatch clock;

  // Stage 1: kinematics and loading of one pair from A to E.
  const auto add = add_series;
  std::vector<double> s_m, share, line_load, r_eq, p0, b_h;
  std::vector<std::pair<std::string, PathPoint>> named;
  {
    auto& s_v = add(r.mesh, "s_m", "m");
    auto& roll = add(r.mesh, "roll_angle_rad", "rad");
    auto& gamma = add(r.mesh, "gamma", "1");
    auto& rho1 = add(r.mesh, "rho1_m", "m");
    auto& rho2 = add(r.mesh, "rho2_m", "m");
    auto& req = add(r.mesh, "r_eq_m", "m");
    auto& sh = add(r.mesh, "load_share", "1");
    auto& w = add(r.mesh, "line_load_N_per_m", "N/m");
    auto& hp = add(r.mesh, "hertz_p0_Pa", "Pa");
    auto& hb = add(r.mesh, "hertz_halfwidth_m", "m");
    auto& v1 = add(r.mesh, "v1_m_per_s", "m/s");
    auto& v2 = add(r.mesh, "v2_m_per_s", "m/s");
    auto& ue = add(r.mesh, "entrainment_m_per_s", "m/s");
    auto& vs = add(r.mesh, "sliding_m_per_s", "m/s");
    auto& srr = add(r.mesh, "srr", "1");
    // The tooth-pair stiffness (potential energy, the costliest part of this stage) only when
    // asked for or when the load sharing uses it.
    const bool stiffness = cs.mesh_stiffness || mesh.analysis().method() == gear::LoadSharing::stiffness;
    std::vector<double>* ks = stiffness ? &add(r.mesh, "mesh_stiffness_N_per_m", "N/m") : nullptr;
    const auto& path = r.path;
    const auto pair_stiffness =
        stiffness ? gear::MeshAnalysis::PairStiffness::computed : gear::MeshAnalysis::PairStiffness::omitted;
    for (int i = 0; i < n; ++i) {
      const double s = path.a + path.length * i / (n - 1);
      const gear::MeshInstant m = mesh.analysis().at(s, false, pair_stiffness);
      const gear::PairLoad* own = &m.pair_at(s);
      const gear::FlankGeometry f = mesh.pair().flank(s);
      const gear::FlankKinematics k = mesh.pair().kinematics(s, mesh.pinion_speed());
      s_v.push_back(s);
      roll.push_back(mesh.pair().roll_angle(0, s));
      gamma.push_back(f.roll_parameter);
      rho1.push_back(f.radius_pinion);
      rho2.push_back(f.radius_wheel);
      req.push_back(f.radius_equivalent);
      sh.push_back(own->share);
      w.push_back(own->line_load);
      hp.push_back(own->hertz_peak);
      hb.push_back(own->hertz_half_width);
      v1.push_back(k.rolling_pinion);
      v2.push_back(k.rolling_wheel);
      ue.push_back(k.entrainment);
      vs.push_back(k.sliding);
      srr.push_back(k.slide_to_roll);
      if (ks) ks->push_back(m.mesh_stiffness);
    }
    s_m = s_v;
    r_eq = req;
    share = sh;
    r.stages.push_back({"kinematics", clock.lap()});
    // ISO/TS 6336-22's named points where they stand, B and D with the single pair's load: the
    // lubricated summary evaluates its models there.
    if (c.lubrication.lubricated) {
      const std::pair<const char*, double> points[] = {
          {"A", path.a}, {"AB", 0.5 * (path.a + path.b)}, {"B", path.b}, {"C", path.c},
          {"D", path.d}, {"DE", 0.5 * (path.d + path.e)}, {"E", path.e}};
      for (const auto& [name, s] : points) {
        const gear::PairLoad own = mesh.analysis().at(s, true, pair_stiffness).pair_at(s);
        const gear::FlankGeometry f = mesh.pair().flank(s);
        const gear::FlankKinematics k = mesh.pair().kinematics(s, mesh.pinion_speed());
        named.emplace_back(name, PathPoint{s, own.line_load, own.hertz_half_width, own.hertz_peak, f.radius_equivalent,
                                           k.rolling_pinion, k.rolling_wheel, own.share});
      }
    }
    if (c.dynamics.engine != gear::DynamicsEngine::none) {
      // The steady mesh cycle at the operating speed; each pair's dynamic load replaces its share.
      if (!dynamics) throw std::invalid_argument("the case asks for dynamics but no integrator was given");
      const gear::MeshDynamics dyn(mesh, gear::dynamics_settings(c));
      const gear::SteadyCycle cycle = dyn.steady_cycle(*dynamics, mesh.pinion_speed());
      auto& factor = add(r.mesh, "dynamic_load_factor", "1");
      const double width = mesh.pair().spec().face_width;
      for (std::size_t i = 0; i < s_v.size(); ++i) {
        const double dynamic = dyn.pair_force(cycle, s_v[i]) / width;
        factor.push_back(w[i] > 0.0 ? dynamic / w[i] : 1.0);
        w[i] = dynamic;
        const gear::PairLoad l = mesh.analysis().pair_load(s_v[i], dynamic);
        hp[i] = l.hertz_peak;
        hb[i] = l.hertz_half_width;
      }
      for (auto& [name, point] : named) {
        // B and D on the single pair's side: a hair inside [B, D], where the pair at E has left (at B)
        // or the pair at A not yet arrived (at D); the force is continuous there.
        const double inside = 1e-9 * path.length;
        const double at = name == std::string("B")   ? point.s + inside
                          : name == std::string("D") ? point.s - inside
                                                     : point.s;
        point.line_load = dyn.pair_force(cycle, at) / width;
        const gear::PairLoad l = mesh.analysis().pair_load(point.s, point.line_load);
        point.hertz_p0 = l.hertz_peak;
        point.half_width = l.hertz_half_width;
      }
      r.stages.push_back({"dynamics_" + dynamics->name(), clock.lap()});
    }
    line_load = w;
    p0 = hp;
  }

  if (cs.deterministic()) {  // the flanks' profiles through boundary elements (mesh_deterministic.cpp)
    if (!flanks) throw std::invalid_argument("the deterministic fidelity needs the flanks' profiles");
    run_deterministic(c, mesh, r, flanks, progress, dynamics);
    return r;
  }

  // Stage 2: the equivalent surface and its pressure-separation table (built once).
  r.surface = case_equivalent_surface(c);
  const asperity::ContactPair pair = asperity::contact_pair(c);
  r.plasticity_index = surface::plasticity_index(r.surface, pair.modulus, pair.hardness);
  const auto model = asperity::make_case_model(c, c.asperity.model);
  r.asperity_model = std::string(model->name());
  const GreenwoodWilliamsonOptions gwo = greenwood_williamson_options(c);
  double p_max = 0.0;
  for (double p : p0) p_max = std::max(p_max, p);
  const GreenwoodWilliamson gw(r.surface, *model, pair, 1.5 * p_max + 1.0, gwo);
  r.stages.push_back({"surface_table", clock.lap()});

  // Lubricated: the film and the load it leaves to the asperities at every position.
  std::optional<PathState> path_state;
  std::optional<MeshLubrication> lubricated;
  if (c.lubrication.lubricated) {
    auto series = [&](const char* name) { return r.find(name)->values; };
    path_state =
        PathState{s_m,   line_load, series("hertz_halfwidth_m"), p0, r_eq, series("v1_m_per_s"), series("v2_m_per_s"),
                  share, named};
    lubricated.emplace(c, mesh, *path_state, gw);
    r.stages.push_back({"film_and_load_sharing", clock.lap()});
  }

  // Stage 3: the rough line contact across the strip at every position.
  const StripOptions so = strip_options(c);
  const RoughLineContact strip(gw, mesh.composite_modulus(), mesh.pair().spec().face_width, so, solver);
  std::vector<StripResult> strips;
  strips.reserve(static_cast<std::size_t>(n));
  CoupledStripState warm;  // coupled: each position starts from the last (they follow the path)
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    try {
      strips.push_back(strip.solve(line_load[k], r_eq[k], lubricated ? lubricated->asperity_share(k) : 1.0, &warm));
    } catch (const std::runtime_error& e) {  // a solve that did not converge: say where on the path
      throw std::runtime_error(fmt::format("position {} of {} (s = {:.6g} mm from A, line load {:.6g} N/m): {}", i + 1,
                                           n, s_m[k] * 1e3, line_load[k], e.what()));
    }
    if (progress) progress(i + 1, n);
  }
  r.stages.push_back({cs.coupled() ? "strip_contact_coupled" : "strip_contact_uncoupled", clock.lap()});
  using StripColumn = Column<StripResult>;
  if (cs.real_area)
    add_columns<StripResult>(
        r.contact, strips,
        {StripColumn{"real_area_ratio", "1", [](const StripResult& st) { return st.real_area_ratio; }},
         StripColumn{"real_area_per_width_m", "m", [](const StripResult& st) { return st.real_area_per_width; }},
         StripColumn{"mean_real_pressure_Pa", "Pa", [](const StripResult& st) { return st.mean_real_pressure; }},
         StripColumn{"contacts_per_width_per_m", "1/m", [](const StripResult& st) { return st.contacts_per_width; }},
         StripColumn{"max_nominal_pressure_Pa", "Pa", [](const StripResult& st) { return st.max_nominal_pressure; }},
         StripColumn{"contact_halfwidth_m", "m", [](const StripResult& st) { return st.contact_half_width; }},
         StripColumn{"min_separation_m", "m", [](const StripResult& st) { return st.min_separation; }}});
  if (cs.real_area) {
    // Greenwood-Williamson sums independent summits; a real area beyond the nominal one means the
    // summation (or the asperity model's area law, extrapolated) has left its validity.
    const auto& a = r.find("real_area_ratio")->values;
    const auto worst = std::max_element(a.begin(), a.end());
    if (*worst > 1.0)
      r.warnings.push_back("real-area ratio " + std::to_string(*worst) + " > 1 at s = " +
                           std::to_string(s_m[static_cast<std::size_t>(worst - a.begin())] * 1e3) + " mm (" +
                           std::to_string(std::count_if(a.begin(), a.end(), [](double x) { return x > 1.0; })) +
                           " positions): the summits' areas overlap; the " + r.asperity_model +
                           " model's area law is outside its fitted range here");
  }
  if (cs.plastic_fraction)
    add_columns<StripResult>(
        r.contact, strips,
        {StripColumn{"plastic_area_fraction", "1", [](const StripResult& st) { return st.plastic_area_fraction; }},
         StripColumn{"plastic_contact_fraction", "1",
                     [](const StripResult& st) { return st.plastic_contact_fraction; }}});

  // Where the answer holds: per position, and one verdict for the run (cheap: one law
  // evaluation per position).
  {
    std::vector<PositionValidity> pv;
    pv.reserve(strips.size());
    for (const auto& st : strips) pv.push_back(position_validity(gw, st, mesh.pair().spec().face_width));
    add_series(r.validity, "plasticity_index", "1").assign(pv.size(), r.plasticity_index);
    using V = PositionValidity;
    add_columns<V>(
        r.validity, pv,
        {Column<V>{"separation_over_summit_sigma", "1", [](const V& v) { return v.separation_over_sigma; }},
         Column<V>{"max_delta_star", "1", [](const V& v) { return v.max_delta_star; }},
         Column<V>{"max_interference_over_summit_radius", "1",
                   [](const V& v) { return v.max_interference_over_radius; }},
         Column<V>{"max_contact_radius_over_summit_radius", "1",
                   [](const V& v) { return v.max_contact_radius_over_radius; }},
         Column<V>{"max_contact_radius_over_half_summit_spacing", "1",
                   [](const V& v) { return v.max_contact_radius_over_half_spacing; }},
         Column<V>{"flag_beyond_fitted_range", "1",
                   [](const V& v) { return static_cast<double>(v.beyond_fitted_range); }},
         Column<V>{"flag_beyond_paraboloid", "1", [](const V& v) { return static_cast<double>(v.beyond_paraboloid); }},
         Column<V>{"flag_fully_plastic_limit", "1",
                   [](const V& v) { return static_cast<double>(v.fully_plastic_limit); }},
         Column<V>{"flag_summits_interact", "1", [](const V& v) { return static_cast<double>(v.summits_interact); }},
         Column<V>{"flag_deep_separation", "1", [](const V& v) { return static_cast<double>(v.deep_separation); }}});
    auto values = [&](const char* name) {
      const Series* s = r.find(name);
      return s ? s->values : std::vector<double>{};
    };
    const ValidityVerdict verdict = validity_verdict(
        pv, r.plasticity_index, gw,
        {values("plastic_area_fraction"), values("plastic_contact_fraction"), values("mean_real_pressure_Pa")});
    r.regime = verdict.regime;
    r.verdict = verdict.text;
    r.flag_counts = {{"beyond_fitted_range", verdict.beyond_fitted_range},
                     {"beyond_paraboloid", verdict.beyond_paraboloid},
                     {"fully_plastic_limit", verdict.fully_plastic_limit},
                     {"summits_interact", verdict.summits_interact},
                     {"deep_separation", verdict.deep_separation}};
  }

  // Stage 4 (if asked): the highest asperity's stresses, in side contact when mu > 0.
  if (cs.asperity_stress) {
    const bool side = c.friction_coefficient > 0.0;
    asperity::SideContactGeometry geometry;
    if (side)
      geometry = asperity::side_contact_geometry(c.pinion.flank.roughness.summit_radius,
                                                 c.wheel.flank.roughness.summit_radius, c.friction_coefficient);
    // The normalised von Mises table (nodes computed as the path needs them), or none: the exact
    // maximisation at every position.
    std::optional<asperity::VonMisesTable> table;
    if (cs.stress_table > 0) table.emplace(gw.pair().poisson_ratio, cs.stress_table);
    std::vector<HighestAsperity> highest;
    highest.reserve(strips.size());
    for (const auto& st : strips)
      highest.push_back(highest_asperity(gw, st, mesh.pair().spec().face_width, side ? &geometry : nullptr,
                                         table ? &*table : nullptr));
    using H = HighestAsperity;
    add_columns<H>(r.contact, highest,
                   {Column<H>{"max_asperity_interference_m", "m", [](const H& h) { return h.interference; }},
                    Column<H>{"max_asperity_pressure_Pa", "Pa", [](const H& h) { return h.peak_pressure; }},
                    Column<H>{"max_asperity_von_mises_Pa", "Pa", [](const H& h) { return h.von_mises; }}});
    r.stages.push_back({side ? "asperity_stress_side_contact" : "asperity_stress_normal_contact", clock.lap()});
  }
  if (lubricated) {
    lubricated->finish(r);
    r.stages.push_back({"friction_temperature_wear", clock.lap()});
  }
  return r;
}

}  // namespace geartrib::contact
