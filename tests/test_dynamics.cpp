// Mesh dynamics: both integrators against exact solutions and each other, the resonance, the
// low-speed limit, the explicit stiffness steps.
#include "gear/mesh_dynamics.hpp"
#include "solvers/integrators.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace geartrib;
using namespace geartrib::gear;

namespace {
constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;

Case with_damping(double zeta) {
  Case c = test::seed_case();
  c.dynamics.damping_ratio = zeta;
  return c;
}
}  // namespace

class EachIntegrator : public ::testing::TestWithParam<DynamicsEngine> {};

TEST_P(EachIntegrator, UndampedHarmonicSolution) {
  // m x'' + k x = F from rest at 0: x = (F/k)(1 - cos w t).
  const auto integ = solvers::make_integrator(GetParam());
  const double m = 4.5, k = 1.3e9, f = 1.2e4, w = std::sqrt(k / m), xs = f / k;
  OdeSystem sys{2, [&](double, const std::vector<double>& y, std::vector<double>& d) {
                  d.resize(2);
                  d[0] = y[1];
                  d[1] = (f - k * y[0]) / m;
                }};
  std::vector<double> y{0.0, 0.0}, times;
  for (int i = 1; i <= 50; ++i) times.push_back(i * 1e-5);
  std::vector<std::vector<double>> samples;
  integ->integrate(sys, 0.0, 5e-4, y, times, samples, {1e-11, 1e-11 * xs});
  for (std::size_t i = 0; i < times.size(); ++i)
    EXPECT_NEAR(samples[i][0], xs * (1.0 - std::cos(w * times[i])), 1e-7 * xs)
        << times[i];  // 1e4 x rtol: global error growth
}

TEST_P(EachIntegrator, DampedStepSettlesToTheStaticDeflection) {
  const auto integ = solvers::make_integrator(GetParam());
  const double m = 4.5, k = 1.3e9, f = 1.2e4, c = 2.0 * 0.1 * std::sqrt(k * m), xs = f / k;
  OdeSystem sys{2, [&](double, const std::vector<double>& y, std::vector<double>& d) {
                  d.resize(2);
                  d[0] = y[1];
                  d[1] = (f - c * y[1] - k * y[0]) / m;
                }};
  std::vector<double> y{0.0, 0.0};
  std::vector<std::vector<double>> samples;
  integ->integrate(sys, 0.0, 0.05, y, {}, samples, {1e-10, 1e-12 * xs});  // ~ 860 periods: exp(-0.1 w t) ~ 1e-200
  EXPECT_NEAR(y[0] / xs, 1.0, 1e-8);
  EXPECT_NEAR(y[1], 0.0, 1e-8 * xs * std::sqrt(k / m));
}

INSTANTIATE_TEST_SUITE_P(Engines, EachIntegrator, ::testing::Values(DynamicsEngine::cvode, DynamicsEngine::odeint));

TEST(MeshDynamics, EnginesAgreeOnTheSteadyCycle) {
  const GearMesh mesh = case_mesh(test::seed_case());
  DynamicsSettings s = dynamics_settings(test::seed_case());
  s.tolerances.relative = 1e-11;
  const MeshDynamics dyn(mesh, s);
  const SteadyCycle a = dyn.steady_cycle(*solvers::make_integrator(gear::DynamicsEngine::cvode), 1000.0 * kRpm);
  const SteadyCycle b = dyn.steady_cycle(*solvers::make_integrator(gear::DynamicsEngine::odeint), 1000.0 * kRpm);
  ASSERT_TRUE(a.periodic && b.periodic);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.force.size(); ++i)
    worst = std::max(worst, std::abs(a.force[i] - b.force[i]) / a.static_force);
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(a.dynamic_factor / b.dynamic_factor, 1.0, 1e-6);
}

TEST(MeshDynamics, StiffnessStepsAndMeanStiffness) {
  const GearMesh mesh = case_mesh(test::seed_case());
  const MeshDynamics dyn(mesh, dynamics_settings(test::seed_case()));
  const PathOfContact& p = mesh.pair().path();
  const double split = p.b - p.a, eps = 1e-9 * p.base_pitch;
  // At u = B - A the leading pair leaves: the stiffness steps down (double -> single) ...
  EXPECT_GT(dyn.stiffness(split - eps) / dyn.stiffness(split + eps), 1.4);
  // ... and back up at the end of the cycle (a pair enters at A while the other is at D).
  EXPECT_LT(dyn.stiffness(p.base_pitch - 10.0 * eps), dyn.stiffness(0.0));
  // Tabulated stiffness equals the potential-energy model inside the segments.
  for (double u : {0.1 * split, 0.5 * split, split + 0.5 * (p.base_pitch - split)}) {
    double k = 0.0;
    for (double s = p.a + u; s <= p.e; s += p.base_pitch) k += mesh.stiffness().pair(s).stiffness;
    EXPECT_NEAR(dyn.stiffness(u) / k, 1.0, 1e-6) << u;  // cubic B-spline on 129 points
  }
  // Natural frequency from the mean stiffness and the equivalent mass: 2750 Hz (ISO 6336-1's
  // estimate with c_gamma_alpha: about 2.94 kHz).
  EXPECT_NEAR(dyn.natural_frequency(),
              std::sqrt(dyn.mean_stiffness() / dyn.equivalent_mass()) / (2.0 * std::numbers::pi), 1e-9);
  EXPECT_NEAR(dyn.natural_frequency(), 2750.0, 30.0);
}

TEST(MeshDynamics, ResonanceNearTheNaturalFrequency) {
  // With contacts kept (zeta = 0.2: no contact loss) the dynamic factor peaks within 10% of
  // sqrt(k_mean/m_e)/(2 pi); with the default zeta = 0.07 contact loss softens the mesh and the
  // peak moves lower (validation/dynamics-m6z30).
  const Case c = with_damping(0.2);
  const GearMesh mesh = case_mesh(c);
  const MeshDynamics dyn(mesh, dynamics_settings(c));
  const auto cvode = solvers::make_integrator(gear::DynamicsEngine::cvode);
  double best = 0.0, best_f = 0.0;
  for (double rpm = 4000.0; rpm <= 7000.0; rpm += 200.0) {
    const SteadyCycle s = dyn.steady_cycle(*cvode, rpm * kRpm);
    EXPECT_FALSE(s.contact_lost) << rpm;
    if (s.dynamic_factor > best) best = s.dynamic_factor, best_f = s.mesh_frequency;
  }
  EXPECT_NEAR(best_f / dyn.natural_frequency(), 1.0, 0.10);
}

TEST(MeshDynamics, LowSpeedTendsToTheQuasiStaticResponse) {
  const GearMesh mesh = case_mesh(test::seed_case());
  const MeshDynamics dyn(mesh, dynamics_settings(test::seed_case()));
  const SteadyCycle s = dyn.steady_cycle(*solvers::make_integrator(gear::DynamicsEngine::cvode), 30.0 * kRpm);
  EXPECT_NEAR(s.dynamic_factor_quasi_static, 1.0, 1e-3);
  // The absolute factor stays at the engagement impact of the stiffness step, k2/k1 = 1.70.
  EXPECT_NEAR(s.dynamic_factor, dyn.quasi_static_peak() / mesh.normal_force(), 1e-3 * s.dynamic_factor);
  EXPECT_FALSE(s.contact_lost);
}

namespace {
// The seed pair under compatibility sharing with the dynamics' own linear pairs (Hertz term the
// stiffness model's constant) and a long linear tip relief of `amount` on both gears.
Case relieved_case(double amount) {
  Case c = test::seed_case();
  c.mesh.load_sharing = LoadSharing::compatibility;
  c.mesh.hertz_approach = HertzApproach::linear;
  const PathOfContact p = SpurPair(c.gear_pair).path();
  if (amount > 0.0) {
    c.mesh.modification[0].tip = {amount, ReliefShape::linear, 0.0, p.e - p.d};
    c.mesh.modification[1].tip = {amount, ReliefShape::linear, 0.0, p.b - p.a};
  }
  return c;
}
}  // namespace

// Per-pair contact without modifications is the lumped k(t) g(x): the same steady cycle.
TEST(MeshDynamics, PerPairContactWithoutReliefIsTheLumpedMesh) {
  const Case lumped = test::seed_case(), per_pair = relieved_case(0.0);
  const GearMesh a_mesh = case_mesh(lumped), b_mesh = case_mesh(per_pair);
  const MeshDynamics a(a_mesh, dynamics_settings(lumped)), b(b_mesh, dynamics_settings(per_pair));
  const auto cvode = solvers::make_integrator(gear::DynamicsEngine::cvode);
  const SteadyCycle x = a.steady_cycle(*cvode, 1000.0 * kRpm), y = b.steady_cycle(*cvode, 1000.0 * kRpm);
  ASSERT_EQ(x.force.size(), y.force.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < x.force.size(); ++i) {
    worst = std::max(worst, std::abs(x.force[i] - y.force[i]) / x.static_force);
    // The per-pair static solve without relief is F / sum k_j exactly (the lumped one reads k from
    // its B-spline).
    const PathOfContact& p = b_mesh.pair().path();
    double k = 0.0;
    for (double s = y.position[i]; s <= p.e + 1e-12 * p.line_length; s += p.base_pitch)
      k += b_mesh.stiffness().pair(s).stiffness;
    EXPECT_NEAR(y.static_deflection[i], b_mesh.normal_force() / k, 1e-10 * y.static_deflection[i]);
  }
  // Tolerance: the integrators' (rtol 1e-8); the two evaluate one sum in a different order and
  // the per-pair stiffness through its own spline (1e-6).
  EXPECT_LT(worst, 1e-4);
  EXPECT_NEAR(a.quasi_static_peak(), b.quasi_static_peak(), 1e-6 * a.quasi_static_peak());
}

// A long relief of the single pair's deflection takes up the engagement: the low-speed peak is
// the static force (no impulse at B and D), and each pair's dynamic load tends to its static
// compatibility load; a relief half as large leaves part of the impulse.
TEST(MeshDynamics, ReliefRemovesTheEngagementImpulse) {
  const Case plain = relieved_case(0.0);
  const GearMesh plain_mesh = case_mesh(plain);
  const double design = plain_mesh.analysis().at(plain_mesh.pair().path().c).transmission_error;
  const Case c = relieved_case(design);
  const GearMesh mesh = case_mesh(c);
  const MeshDynamics dyn(mesh, dynamics_settings(c));
  const MeshDynamics unmodified(plain_mesh, dynamics_settings(plain));
  EXPECT_GT(unmodified.quasi_static_peak() / mesh.normal_force(), 1.6);  // k2/k1 = 1.70
  // Measured 1.05: the model's pair stiffness varies along the path, so a linear relief matches
  // the deflection only on average (exactly 1 with constant stiffness).
  EXPECT_LT(dyn.quasi_static_peak() / mesh.normal_force(), 1.1);
  const SteadyCycle s = dyn.steady_cycle(*solvers::make_integrator(gear::DynamicsEngine::cvode), 30.0 * kRpm);
  EXPECT_LT(s.dynamic_factor, 1.1);
  const PathOfContact& p = mesh.pair().path();
  for (double s_at : {p.a + 0.3 * (p.b - p.a), p.c, p.d + 0.6 * (p.e - p.d)}) {
    const double static_load = mesh.analysis().at(s_at).pair_at(s_at).share * mesh.normal_force();
    // Tolerance: the cycle's 256 samples interpolated linearly, and the decaying transients (1 %).
    EXPECT_NEAR(dyn.pair_force(s, s_at), static_load, 0.01 * mesh.normal_force()) << s_at;
  }
  const Case half = relieved_case(0.5 * design);
  const GearMesh half_mesh = case_mesh(half);
  const MeshDynamics partial(half_mesh, dynamics_settings(half));
  EXPECT_GT(partial.quasi_static_peak(), dyn.quasi_static_peak());
  EXPECT_LT(partial.quasi_static_peak(), unmodified.quasi_static_peak());
}
