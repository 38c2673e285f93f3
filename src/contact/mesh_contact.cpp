#include "contact/mesh_contact.hpp"

#include "contact/fidelities.hpp"
#include "contact/fidelity.hpp"
#include "contact/mesh_lubrication.hpp"
#include "contact/series_columns.hpp"
#include "contact/stage_clock.hpp"

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

namespace {

// The /mesh series, from the path stage's state.
void add_path_series(const PathState& p, std::vector<Series>& g) {
  g.push_back({"s_m", "m", p.s});
  g.push_back({"roll_angle_rad", "rad", p.roll_angle});
  g.push_back({"gamma", "1", p.gamma});
  g.push_back({"rho1_m", "m", p.rho1});
  g.push_back({"rho2_m", "m", p.rho2});
  g.push_back({"r_eq_m", "m", p.radius});
  g.push_back({"load_share", "1", p.share});
  g.push_back({"line_load_N_per_m", "N/m", p.line_load});
  g.push_back({"hertz_p0_Pa", "Pa", p.hertz_p0});
  g.push_back({"hertz_halfwidth_m", "m", p.half_width});
  g.push_back({"v1_m_per_s", "m/s", p.v1});
  g.push_back({"v2_m_per_s", "m/s", p.v2});
  g.push_back({"entrainment_m_per_s", "m/s", p.entrainment});
  g.push_back({"sliding_m_per_s", "m/s", p.sliding});
  g.push_back({"srr", "1", p.slide_to_roll});
  if (!p.stiffness.empty()) g.push_back({"mesh_stiffness_N_per_m", "N/m", p.stiffness});
  if (!p.transmission_error.empty()) g.push_back({"transmission_error_m", "m", p.transmission_error});
  if (!p.dynamic_factor.empty()) g.push_back({"dynamic_load_factor", "1", p.dynamic_factor});
}

// Stage 1: kinematics and loading of one pair from A to E (and its dynamic load when asked for).
PathState path_stage(const MeshCycleInputs& in, StageClock& clock) {
  PathOptions o;
  o.positions = in.contact.positions;
  o.stiffness = in.contact.mesh_stiffness;
  o.named_points = in.lubrication != nullptr;
  PathState p = path_state(in.mesh, o);
  clock.lap("kinematics");
  if (in.dynamics) {
    apply_dynamics(p, in.mesh, in.dynamics_settings, *in.dynamics);
    clock.lap("dynamics_" + in.dynamics->name());
  }
  return p;
}

// The lubrication's series, summary, verdict and warnings; a fidelity with a statistical model
// beside it takes the film's share from that model, whose notes they then are.
void add_lubrication_outputs(LubricationResult& l, const FidelityTraits& traits, MeshContactResult& r) {
  add_lubrication_series(l, r.lubrication);
  r.lubrication_summary = std::move(l.summary);
  if (!traits.statistical_beside) r.verdict += l.verdict;
  for (auto& w : l.warnings) r.warnings.push_back(traits.statistical_beside ? "statistical model: " + w : std::move(w));
}

// Stages 2 to 5 with fidelity F: its preparation, the film and the shares, its solve, friction,
// temperatures and wear, and the outputs of each.
template <class F>
void run_stages(const MeshCycleInputs& in, const PathState& path, StageClock& clock, MeshContactResult& r) {
  FidelityInputs fi{
      in.mesh,         path,       in.contact, in.running_in, in.flanks, in.lubrication != nullptr, in.solver,
      in.flank_source, in.progress};
  fi.flank_specs = in.flank_specs;
  typename F::State state = F::prepare(fi, clock);
  std::optional<MeshLubrication> lubricated;
  std::vector<double> share(path.size(), 1.0);
  if (in.lubrication && state.surface()) {
    lubricated.emplace(LubricationInputs{*in.lubrication, in.operating, in.flank_specs}, in.mesh, path,
                       *state.surface());
    share = lubricated->asperity_shares();
    clock.lap("film_and_load_sharing");
    fi.film = &*lubricated;
  }
  typename F::Solution solution = F::solve(fi, state, share, clock);
  std::optional<LubricationResult> lubrication;
  if (lubricated) {
    lubrication = lubricated->finish();
    clock.lap("friction_temperature_wear");
  }
  F::write(fi, state, solution, r);
  if (lubrication) add_lubrication_outputs(*lubrication, F::traits, r);
}

}  // namespace

MeshContactResult run_mesh_contact(const MeshCycleInputs& in) {
  MeshContactResult r;
  StageClock clock{r.stages, {}};
  r.path = in.mesh.pair().path();
  r.gears = {in.mesh.pair().pinion(), in.mesh.pair().wheel()};
  r.fidelity = std::string(in.contact.fidelity.name());
  const PathState path = path_stage(in, clock);
  add_path_series(path, r.mesh);
  if (in.mesh.tooth_contact()) {
    r.tooth_contact = in.mesh.analysis().transmission_error_stats(in.mesh.cycle_positions());
    clock.lap("tooth_contact");
  }
  visit_fidelity(in.contact.fidelity.name(), [&]<class F>(FidelityTag<F>) { run_stages<F>(in, path, clock, r); });
  return r;
}

}  // namespace geartrib::contact
