// The mesh cycle's hot kernels on the seed's case, so that regressions show: the summit-height
// quadrature at one separation, the pressure-separation table, the separation inversion, one
// strip (uncoupled, coupled), the coupled strip along the path (cold, warm), the highest
// asperity's stresses, the whole cycle as `geartrib run` does it, dry and lubricated, and the
// deterministic cycle, the mixed-EHL window and cycle, the load sharings. Run:
// ./build/tests/geartrib_bench --benchmark_filter='gw_|strip_|cycle|ehl_'
#include "case/asperity_setup.hpp"
#include "case/contact_setup.hpp"
#include "case/gear_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/mesh_path.hpp"
#include "contact/mixed_ehl/mesh_mixed_ehl.hpp"
#include "contact/rough_line_contact.hpp"
#include "lubrication/lubricant.hpp"
#include "runs/case_rating.hpp"
#include "runs/mesh_cycle.hpp"
#include "solvers/kinsol_solver.hpp"
#include "surface/flank_profile.hpp"

#include <benchmark/benchmark.h>

#include <memory>

using namespace geartrib;

namespace {
struct Setup {
  Case c = io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30.toml"));
  gear::GearMesh mesh = gear::case_mesh(c);
  surface::EquivalentSurface surface = contact::case_equivalent_surface(c);
  asperity::ContactPair pair = asperity::contact_pair(c);
  std::unique_ptr<asperity::AsperityModel> model = asperity::make_case_model(c, c.asperity.model);
  double line_load = mesh.normal_force() / c.gear_pair.face_width;  // the whole load on one pair
  double radius = mesh.pair().flank(mesh.pair().path().c).radius_equivalent;
  std::unique_ptr<contact::GreenwoodWilliamson> gw = table(contact::GreenwoodWilliamsonOptions{});
  std::unique_ptr<contact::GreenwoodWilliamson> table(const contact::GreenwoodWilliamsonOptions& o) const {
    return std::make_unique<contact::GreenwoodWilliamson>(surface, *model, pair, 3e9, o);
  }
};
const Setup& setup() {
  static const Setup s;
  return s;
}

void gw_quadrature(benchmark::State& state) {
  contact::GreenwoodWilliamsonOptions o;
  o.height_points = static_cast<int>(state.range(0));
  const auto gw = setup().table(o);
  const double d = gw->separation_for_pressure(1e8);
  for (auto _ : state) benchmark::DoNotOptimize(gw->at_separation(d));
}

void gw_table(benchmark::State& state) {
  contact::GreenwoodWilliamsonOptions o;
  o.table_points_per_sigma = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(setup().table(o));
}

void gw_separation_inversion(benchmark::State& state) {
  const auto& gw = *setup().gw;
  double p = 1e6;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gw.separation_for_pressure(p));
    p = p < 2e9 ? p * 1.3 : 1e6;
  }
}

void strip_uncoupled(benchmark::State& state) {
  const Setup& s = setup();
  contact::StripOptions o;
  o.strip_points = static_cast<int>(state.range(0));
  const contact::RoughLineContact strip(*s.gw, s.mesh.composite_modulus(), s.c.gear_pair.face_width, o, nullptr);
  for (auto _ : state) benchmark::DoNotOptimize(strip.solve(s.line_load, s.radius));
}

void strip_coupled(benchmark::State& state) {
  const Setup& s = setup();
  contact::StripOptions o;
  o.fidelity = contact::StripFidelity::coupled;
  o.coupled_nodes = static_cast<int>(state.range(0));
  const solvers::KinsolSolver kinsol;
  const contact::RoughLineContact strip(*s.gw, s.mesh.composite_modulus(), s.c.gear_pair.face_width, o, &kinsol);
  for (auto _ : state) benchmark::DoNotOptimize(strip.solve(s.line_load, s.radius));
}

// The coupled strip at the 201 positions of the dry cycle, in order along the path: each from
// the Hertz pressure (cold: warm:0) or from the previous position's solution and factorised
// Jacobian (warm:1, as run_mesh_contact does). Issue 17: at most 0.1 s for the 201.
void strip_coupled_path(benchmark::State& state) {
  const Setup& s = setup();
  static const contact::MeshContactResult path = [&] {
    Case c = s.c;
    c.lubrication.lubricated = false;
    return runs::run_mesh_contact(c, s.mesh, nullptr, {}, 201);
  }();
  const auto& line_load = path.find("line_load_N_per_m")->values;
  const auto& radius = path.find("r_eq_m")->values;
  contact::StripOptions o;
  o.fidelity = contact::StripFidelity::coupled;
  const solvers::KinsolSolver kinsol;
  const contact::RoughLineContact strip(*s.gw, s.mesh.composite_modulus(), s.c.gear_pair.face_width, o, &kinsol);
  const bool warm = state.range(0) == 1;
  for (auto _ : state) {
    contact::CoupledStripState carried;
    int iterations = 0;
    for (std::size_t k = 0; k < line_load.size(); ++k)
      iterations += strip.solve(line_load[k], radius[k], 1.0, warm ? &carried : nullptr).solver_iterations;
    state.counters["iterations"] = iterations;
    if (warm) {
      state.counters["jacobians"] = carried.jacobians();
      state.counters["cold_starts"] = carried.cold_solves();
    }
  }
}

void strip_highest_asperity(benchmark::State& state) {
  const Setup& s = setup();
  const contact::RoughLineContact strip(*s.gw, s.mesh.composite_modulus(), s.c.gear_pair.face_width, {}, nullptr);
  const contact::StripResult r = strip.solve(s.line_load, s.radius);
  const auto side = asperity::side_contact_geometry(s.c.pinion.flank.roughness.summit_radius,
                                                    s.c.wheel.flank.roughness.summit_radius, s.c.friction_coefficient);
  for (auto _ : state) benchmark::DoNotOptimize(contact::highest_asperity(*s.gw, r, s.c.gear_pair.face_width, &side));
}

void cycle(benchmark::State& state) {
  Case c = setup().c;
  c.lubrication.lubricated = false;  // the dry cycle (the seed's scene)
  c.contact.fidelity = state.range(0) == 1 ? ContactFidelity::coupled : ContactFidelity::uncoupled;
  const solvers::KinsolSolver kinsol;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        runs::run_mesh_contact(c, setup().mesh, c.contact.fidelity == ContactFidelity::coupled ? &kinsol : nullptr));
}
// The lubricated cycle against the dry one at the same positions (issue 16: at most twice the
// dry cycle's time): the default case with and without its [lubricant].
void cycle_lubricated(benchmark::State& state) {
  Case c = setup().c;
  c.lubrication.lubricated = state.range(0) == 1;
  const int positions = static_cast<int>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(runs::run_mesh_contact(c, setup().mesh, nullptr, {}, positions));
}
// The loaded tooth contact (issue 33: compatibility adds at most 20 % to the default cycle): the
// default lubricated case with the load shared by ISO (0), by the pairs' stiffness (1), by
// compatibility with gears/m6z30-relief.toml's tip reliefs (2) or without them (3: the same loads
// as 1 but for the Hertzian approach).
Case with_load_sharing(int sharing) {
  Case c = setup().c;
  if (sharing == 1) c.mesh.load_sharing = gear::LoadSharing::stiffness;
  if (sharing == 3) c.mesh.load_sharing = gear::LoadSharing::compatibility;
  if (sharing == 2)
    c.mesh =
        io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30-relief.toml")).mesh;
  return c;
}
// The whole cycle, its mesh built in the loop.
void cycle_load_sharing(benchmark::State& state) {
  const Case c = with_load_sharing(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const gear::GearMesh mesh = gear::case_mesh(c);
    benchmark::DoNotOptimize(runs::run_mesh_contact(c, mesh, nullptr, {}));
  }
}
// The path stage alone (its kinematics and loads over 201 positions, and under compatibility the
// transmission error over one base pitch): the solve's own cost.
void path_load_sharing(benchmark::State& state) {
  const Case c = with_load_sharing(static_cast<int>(state.range(0)));
  const gear::GearMesh mesh = gear::case_mesh(c);
  for (auto _ : state) {
    benchmark::DoNotOptimize(contact::path_state(mesh, contact::PathOptions{}));
    if (mesh.tooth_contact())
      benchmark::DoNotOptimize(mesh.analysis().transmission_error_stats(mesh.cycle_positions()));
  }
}
// The ratings of the default case on its cycle's result (issue 34: under 1 ms): arg 0 pitting and
// bending, 1 all four methods (the micropitting's permissible film runs the C-GF test gear's
// lubricated cycle at 21 positions), 2 all four with lambda_GFP given (no test-gear cycle).
void case_rating(benchmark::State& state) {
  Case c = io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30.toml"));
  const int which = static_cast<int>(state.range(0));
  if (which == 0) c.rating.scuffing = c.rating.micropitting = false;
  if (which == 2) c.lubrication.lubricant.permissible_lambda = 0.2;
  const gear::GearMesh mesh = gear::case_mesh(c);
  const contact::MeshContactResult cycle = runs::run_mesh_contact(c, mesh, nullptr, {});
  for (auto _ : state) benchmark::DoNotOptimize(runs::rate_case(c, mesh, cycle));
}
// The deterministic cycle (issue 20: the default 201 positions in at most 5 s on one core):
// gears/m6z30-deterministic.toml on one thread at element sizes 2, 1, 0.5 (its default) and
// 0.25 um [nm in the argument].
void cycle_deterministic(benchmark::State& state) {
  Case c =
      io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30-deterministic.toml"));
  c.contact.threads = 1;
  c.contact.boundary_elements.element_size = static_cast<double>(state.range(0)) * 1e-9;
  for (auto _ : state) benchmark::DoNotOptimize(runs::run_mesh_cycle(c));
}
// The mixed-EHL fidelity (issue 32: a position's window of 2048 nodes in under 5 s on one core).
// One window at the single pair's B-side position (4 of 11) of gears/m6z30-mixed-ehl.toml, the oil
// at its 70 degC inlet, flanks ground at Rq 10 nm (the thick film) on 0.25 um profiles, two
// contact widths at Courant 1, with its flash temperature and subsurface stress: the nodes over
// [-4 b, 1.5 b] in the first argument, the lead-in (mixed_ehl.lead_in, b/u) in the second.
void ehl_window(benchmark::State& state) {
  const Setup& s = setup();
  contact::PathOptions po;
  po.positions = 11;
  const contact::PathState p = contact::path_state(s.mesh, po);
  const std::array<std::vector<double>, 2> sigma = contact::contact_arcs(s.mesh.pair(), p);
  const std::size_t k = 4;
  const lubrication::OilState oil = lubrication::oil_state(s.c.lubrication.lubricant, s.c.operating.oil_temperature);
  contact::mixed_ehl::WindowSetup w;
  w.fluid.viscosity = oil.dynamic_viscosity;
  w.fluid.pressure_viscosity = oil.pressure_viscosity;
  w.fluid.eyring_stress = oil.eyring_stress;
  w.fluid.limiting_shear_coefficient = oil.limiting_shear_coefficient;
  w.composite_modulus = s.mesh.composite_modulus();
  w.solver.nodes = static_cast<int>(state.range(0));
  w.lead_in = static_cast<double>(state.range(1));
  w.solver.hardness = std::min(s.c.pinion.material.hardness, s.c.wheel.material.hardness);
  w.instant = {p.line_load[k], p.radius[k], p.v1[k], p.v2[k]};
  w.sigma_pinion = sigma[0][k], w.sigma_wheel = sigma[1][k];
  w.thermal_coefficient[0] = w.thermal_coefficient[1] = 1.2e4;
  surface::GeneratedProfileSpec g;
  g.rq = 10e-9;
  g.spacing = 0.25e-6;
  auto flank = [&](double centre, std::uint64_t seed) {
    g.seed = seed;
    return contact::FlankTrack{surface::generate_profile(g, 4e-3), centre - 2e-3};
  };
  const contact::FlankTrack pinion = flank(sigma[0][k], 1), wheel = flank(sigma[1][k], 2);
  for (auto _ : state) benchmark::DoNotOptimize(contact::mixed_ehl::solve_window(pinion, wheel, w));
}
// The mixed-EHL cycle (issue 32: the default case's A..E in under 30 s): gears/m6z30-mixed-ehl.toml
// with its flanks at Rq 10 nm (the thick film) at 5 positions on one thread.
void cycle_mixed_ehl(benchmark::State& state) {
  Case c = io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30-mixed-ehl.toml",
                                          {{"pinion.flank.profile.rq", "10 nm"},
                                           {"wheel.flank.profile.rq", "10 nm"},
                                           {"contact.positions", "5"},
                                           {"contact.threads", "1"}}));
  for (auto _ : state) benchmark::DoNotOptimize(runs::run_mesh_cycle(c));
}
}  // namespace

BENCHMARK(ehl_window)
    ->Args({1024, 4})
    ->Args({2048, 4})
    ->Args({2048, 0})
    ->ArgNames({"nodes", "lead_in"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(cycle_mixed_ehl)->Unit(benchmark::kMillisecond);
BENCHMARK(cycle_deterministic)
    ->Arg(2000)
    ->Arg(1000)
    ->Arg(500)
    ->Arg(250)
    ->ArgName("element_nm")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(cycle_load_sharing)->DenseRange(0, 3)->ArgName("sharing")->Unit(benchmark::kMillisecond);
BENCHMARK(path_load_sharing)->DenseRange(0, 3)->ArgName("sharing")->Unit(benchmark::kMillisecond);
BENCHMARK(case_rating)->DenseRange(0, 2)->ArgName("methods")->Unit(benchmark::kMicrosecond);
BENCHMARK(cycle_lubricated)
    ->ArgsProduct({{0, 1}, {201, 1000}})
    ->ArgNames({"lubricated", "positions"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(gw_quadrature)->RangeMultiplier(4)->Range(16, 1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(gw_table)->RangeMultiplier(4)->Range(4, 256)->Unit(benchmark::kMillisecond);
BENCHMARK(gw_separation_inversion);
BENCHMARK(strip_uncoupled)->RangeMultiplier(4)->Range(8, 512)->Unit(benchmark::kMicrosecond);
BENCHMARK(strip_coupled)->RangeMultiplier(2)->Range(32, 256)->Unit(benchmark::kMillisecond);
BENCHMARK(strip_coupled_path)->Arg(0)->Arg(1)->ArgName("warm")->Unit(benchmark::kMillisecond);
BENCHMARK(strip_highest_asperity)->Unit(benchmark::kMicrosecond);
BENCHMARK(cycle)->Arg(0)->Arg(1)->ArgName("coupled")->Unit(benchmark::kMillisecond);
