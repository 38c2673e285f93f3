#include "contact/statistical/strip_fidelities.hpp"

#include "asperity/side_contact.hpp"
#include "asperity/von_mises_table.hpp"
#include "contact/series_columns.hpp"
#include "contact/stage_clock.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace geartrib::contact {

namespace {

// The strip at every position, each from the last (coupled: they follow the path).
std::vector<StripResult> solve_strips(const FidelityInputs& in, const RoughLineContact& strip,
                                      const std::vector<double>& share, const std::function<void(int, int)>& progress) {
  const PathState& p = in.path;
  const int n = static_cast<int>(p.size());
  std::vector<StripResult> strips;
  strips.reserve(p.size());
  CoupledStripState warm;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    try {
      strips.push_back(strip.solve(p.line_load[k], p.radius[k], share[k], &warm));
    } catch (const std::runtime_error& e) {  // a solve that did not converge: say where on the path
      throw std::runtime_error(fmt::format("position {} of {} (s = {:.6g} mm from A, line load {:.6g} N/m): {}", i + 1,
                                           n, p.s[k] * 1e3, p.line_load[k], e.what()));
    }
    if (progress) progress(i + 1, n);
  }
  return strips;
}

// Greenwood-Williamson sums independent summits; a real area beyond the nominal one means the
// summation (or the asperity model's area law, extrapolated) has left its validity.
void warn_real_area(const std::vector<StripResult>& strips, const PathState& p, const std::string& model,
                    std::vector<std::string>& warnings) {
  if (strips.empty()) return;
  const auto worst = std::max_element(strips.begin(), strips.end(), [](const StripResult& a, const StripResult& b) {
    return a.real_area_ratio < b.real_area_ratio;
  });
  if (!(worst->real_area_ratio > 1.0)) return;
  const auto over =
      std::count_if(strips.begin(), strips.end(), [](const StripResult& s) { return s.real_area_ratio > 1.0; });
  warnings.push_back("real-area ratio " + std::to_string(worst->real_area_ratio) +
                     " > 1 at s = " + std::to_string(p.s[static_cast<std::size_t>(worst - strips.begin())] * 1e3) +
                     " mm (" + std::to_string(over) + " positions): the summits' areas overlap; the " + model +
                     " model's area law is outside its fitted range here");
}

// Where the answer holds: per position, and one verdict for the run.
void judge(const FidelityInputs& in, const SurfaceModel& m, StatisticalSolution& s) {
  const ContactSettings& cs = in.contact;
  const double face = in.mesh.pair().spec().face_width;
  s.validity.reserve(s.strips.size());
  for (const auto& st : s.strips) s.validity.push_back(position_validity(m.table, st, face));
  PathContact path;
  for (const auto& st : s.strips) {
    if (cs.plastic_fraction) path.plastic_area_fraction.push_back(st.plastic_area_fraction);
    if (cs.plastic_fraction) path.plastic_contact_fraction.push_back(st.plastic_contact_fraction);
    if (cs.real_area) path.mean_real_pressure.push_back(st.mean_real_pressure);
  }
  s.verdict = validity_verdict(s.validity, m.plasticity_index, m.table, path);
}

// The highest asperity's stresses, in side contact when mu > 0.
std::vector<HighestAsperity> highest_asperities(const FidelityInputs& in, const SurfaceModel& m,
                                                const std::vector<StripResult>& strips, bool& side) {
  const StatisticalFlanks& f = m.flanks;
  side = f.friction > 0.0;
  asperity::SideContactGeometry geometry;
  if (side)
    geometry = asperity::side_contact_geometry(f.roughness[0].summit_radius, f.roughness[1].summit_radius, f.friction);
  // The normalised von Mises table (nodes computed as the path needs them), or none: the exact
  // maximisation at every position.
  std::optional<asperity::VonMisesTable> table;
  if (in.contact.stress_table > 0) table.emplace(m.table.pair().poisson_ratio, in.contact.stress_table);
  std::vector<HighestAsperity> highest;
  highest.reserve(strips.size());
  for (const auto& st : strips)
    highest.push_back(highest_asperity(m.table, st, in.mesh.pair().spec().face_width, side ? &geometry : nullptr,
                                       table ? &*table : nullptr));
  return highest;
}

}  // namespace

StatisticalSolution solve_statistical(const FidelityInputs& in, const SurfaceModel& m, StripFidelity fidelity,
                                      const std::vector<double>& share, StageClock* clock,
                                      const std::function<void(int, int)>& progress) {
  const ContactSettings& cs = in.contact;
  StripOptions options = cs.strip;  // the case's strip, solved at this fidelity
  options.fidelity = fidelity;
  const RoughLineContact strip(m.table, in.mesh.composite_modulus(), in.mesh.pair().spec().face_width, options,
                               in.solver);
  StatisticalSolution s;
  s.strips = solve_strips(in, strip, share, progress);
  if (clock) clock->lap(fidelity == StripFidelity::coupled ? "strip_contact_coupled" : "strip_contact_uncoupled");
  if (cs.real_area) warn_real_area(s.strips, in.path, std::string(m.table.model().name()), s.warnings);
  judge(in, m, s);
  if (cs.asperity_stress) {
    bool side = false;
    s.highest = highest_asperities(in, m, s.strips, side);
    if (clock) clock->lap(side ? "asperity_stress_side_contact" : "asperity_stress_normal_contact");
  }
  return s;
}

void add_statistical_series(const StatisticalSolution& s, const SurfaceModel& m, const ContactSettings& cs,
                            std::vector<Series>& contact, std::vector<Series>& validity) {
  using S = StripResult;
  using C = Column<S>;
  if (cs.real_area)
    add_columns<S>(contact, s.strips,
                   {C{"real_area_ratio", "1", [](const S& st) { return st.real_area_ratio; }},
                    C{"real_area_per_width_m", "m", [](const S& st) { return st.real_area_per_width; }},
                    C{"mean_real_pressure_Pa", "Pa", [](const S& st) { return st.mean_real_pressure; }},
                    C{"contacts_per_width_per_m", "1/m", [](const S& st) { return st.contacts_per_width; }},
                    C{"max_nominal_pressure_Pa", "Pa", [](const S& st) { return st.max_nominal_pressure; }},
                    C{"contact_halfwidth_m", "m", [](const S& st) { return st.contact_half_width; }},
                    C{"min_separation_m", "m", [](const S& st) { return st.min_separation; }}});
  if (cs.plastic_fraction)
    add_columns<S>(contact, s.strips,
                   {C{"plastic_area_fraction", "1", [](const S& st) { return st.plastic_area_fraction; }},
                    C{"plastic_contact_fraction", "1", [](const S& st) { return st.plastic_contact_fraction; }}});
  using H = HighestAsperity;
  if (!s.highest.empty())
    add_columns<H>(contact, s.highest,
                   {Column<H>{"max_asperity_interference_m", "m", [](const H& h) { return h.interference; }},
                    Column<H>{"max_asperity_pressure_Pa", "Pa", [](const H& h) { return h.peak_pressure; }},
                    Column<H>{"max_asperity_von_mises_Pa", "Pa", [](const H& h) { return h.von_mises; }}});
  validity.push_back({"plasticity_index", "1", std::vector<double>(s.validity.size(), m.plasticity_index)});
  using V = PositionValidity;
  add_columns<V>(
      validity, s.validity,
      {Column<V>{"separation_over_summit_sigma", "1", [](const V& v) { return v.separation_over_sigma; }},
       Column<V>{"max_delta_star", "1", [](const V& v) { return v.max_delta_star; }},
       Column<V>{"max_interference_over_summit_radius", "1", [](const V& v) { return v.max_interference_over_radius; }},
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
}

namespace statistical {

template <StripFidelity kStrip>
typename StripFidelityBase<kStrip>::State StripFidelityBase<kStrip>::prepare(const FidelityInputs& in,
                                                                             StageClock& clock) {
  State s;
  double p_max = 0.0;
  for (double p : in.path.hertz_p0) p_max = std::max(p_max, p);
  s.model.emplace(in.flanks, in.contact, p_max);
  clock.lap("surface_table");
  return s;
}

template <StripFidelity kStrip>
void StripFidelityBase<kStrip>::write(const FidelityInputs& in, State& state, StatisticalSolution& s,
                                      MeshContactResult& r) {
  const SurfaceModel& m = *state.model;
  r.surface = m.surface;
  r.plasticity_index = m.plasticity_index;
  r.asperity_model = std::string(m.table.model().name());
  add_statistical_series(s, m, in.contact, r.contact, r.validity);
  r.regime = s.verdict.regime;
  r.verdict = s.verdict.text;
  r.flag_counts = {{"beyond_fitted_range", s.verdict.beyond_fitted_range},
                   {"beyond_paraboloid", s.verdict.beyond_paraboloid},
                   {"fully_plastic_limit", s.verdict.fully_plastic_limit},
                   {"summits_interact", s.verdict.summits_interact},
                   {"deep_separation", s.verdict.deep_separation}};
  r.warnings.insert(r.warnings.end(), s.warnings.begin(), s.warnings.end());
}

template struct StripFidelityBase<StripFidelity::uncoupled>;
template struct StripFidelityBase<StripFidelity::coupled>;

}  // namespace statistical
}  // namespace geartrib::contact
