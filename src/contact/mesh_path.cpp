#include "contact/mesh_path.hpp"

namespace geartrib::contact {

namespace {

gear::MeshAnalysis::PairStiffness pair_stiffness(const gear::GearMesh& mesh, const PathOptions& o) {
  const bool stiffness = o.stiffness || mesh.analysis().method() != gear::LoadSharing::iso;
  return stiffness ? gear::MeshAnalysis::PairStiffness::computed : gear::MeshAnalysis::PairStiffness::omitted;
}

// ISO/TS 6336-22's named points where they stand, B and D with the single pair's load.
void add_named_points(PathState& p, const gear::GearMesh& mesh, gear::MeshAnalysis::PairStiffness stiffness) {
  const gear::PathOfContact& path = p.path;
  const std::pair<const char*, double> points[] = {
      {"A", path.a}, {"AB", 0.5 * (path.a + path.b)}, {"B", path.b}, {"C", path.c},
      {"D", path.d}, {"DE", 0.5 * (path.d + path.e)}, {"E", path.e}};
  for (const auto& [name, s] : points) {
    const gear::PairLoad own = mesh.analysis().at(s, true, stiffness).pair_at(s);
    const gear::FlankGeometry f = mesh.pair().flank(s);
    const gear::FlankKinematics k = mesh.pair().kinematics(s, mesh.pinion_speed());
    p.named.emplace_back(name, PathPoint{s, own.line_load, own.hertz_half_width, own.hertz_peak, f.radius_equivalent,
                                         k.rolling_pinion, k.rolling_wheel, own.share});
  }
}

}  // namespace

PathState path_state(const gear::GearMesh& mesh, const PathOptions& o) {
  PathState p;
  p.path = mesh.pair().path();
  const auto stiffness = pair_stiffness(mesh, o);
  const int n = o.positions;
  for (int i = 0; i < n; ++i) {
    const double s = p.path.a + p.path.length * i / (n - 1);
    const gear::MeshInstant m = mesh.analysis().at(s, false, stiffness);
    const gear::PairLoad& own = m.pair_at(s);
    const gear::FlankGeometry f = mesh.pair().flank(s);
    const gear::FlankKinematics k = mesh.pair().kinematics(s, mesh.pinion_speed());
    p.s.push_back(s);
    p.roll_angle.push_back(mesh.pair().roll_angle(0, s));
    p.gamma.push_back(f.roll_parameter);
    p.rho1.push_back(f.radius_pinion);
    p.rho2.push_back(f.radius_wheel);
    p.radius.push_back(f.radius_equivalent);
    p.share.push_back(own.share);
    p.line_load.push_back(own.line_load);
    p.hertz_p0.push_back(own.hertz_peak);
    p.half_width.push_back(own.hertz_half_width);
    p.v1.push_back(k.rolling_pinion);
    p.v2.push_back(k.rolling_wheel);
    p.entrainment.push_back(k.entrainment);
    p.sliding.push_back(k.sliding);
    p.slide_to_roll.push_back(k.slide_to_roll);
    if (stiffness == gear::MeshAnalysis::PairStiffness::computed) p.stiffness.push_back(m.mesh_stiffness);
    if (mesh.tooth_contact()) p.transmission_error.push_back(m.transmission_error);
  }
  if (o.named_points) add_named_points(p, mesh, stiffness);
  return p;
}

void apply_dynamics(PathState& p, const gear::GearMesh& mesh, const gear::DynamicsSettings& settings,
                    const OdeIntegrator& integrator) {
  const gear::MeshDynamics dyn(mesh, settings);
  const gear::SteadyCycle cycle = dyn.steady_cycle(integrator, mesh.pinion_speed());
  const double width = mesh.pair().spec().face_width;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dynamic = dyn.pair_force(cycle, p.s[i]) / width;
    p.dynamic_factor.push_back(p.line_load[i] > 0.0 ? dynamic / p.line_load[i] : 1.0);
    p.line_load[i] = dynamic;
    const gear::PairLoad l = mesh.analysis().pair_load(p.s[i], dynamic);
    p.hertz_p0[i] = l.hertz_peak;
    p.half_width[i] = l.hertz_half_width;
  }
  for (auto& [name, point] : p.named) {
    // B and D on the single pair's side: a hair inside [B, D], where the pair at E has left (at B)
    // or the pair at A not yet arrived (at D); the force is continuous there.
    const double inside = 1e-9 * p.path.length;
    const double at = name == "B" ? point.s + inside : name == "D" ? point.s - inside : point.s;
    point.line_load = dyn.pair_force(cycle, at) / width;
    const gear::PairLoad l = mesh.analysis().pair_load(point.s, point.line_load);
    point.hertz_p0 = l.hertz_peak;
    point.half_width = l.hertz_half_width;
  }
}

}  // namespace geartrib::contact
