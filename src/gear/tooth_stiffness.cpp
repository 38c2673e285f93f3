#include "gear/tooth_stiffness.hpp"

#include "gear/involute.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <cmath>
#include <numbers>

namespace geartrib::gear {

namespace {

// Sainsot, Velex & Duverger (2004), table 1: X* = A/theta_f^2 + B h_f^2 + C h_f/theta_f + D/theta_f + E h_f + F
// for X = L, M, P, Q.
struct FoundationCoefficients {
  double a, b, c, d, e, f;
  double operator()(double h, double theta) const {
    return a / (theta * theta) + b * h * h + c * h / theta + d / theta + e * h + f;
  }
};
constexpr FoundationCoefficients kL{-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045};
constexpr FoundationCoefficients kM{60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086};
constexpr FoundationCoefficients kP{-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236};
constexpr FoundationCoefficients kQ{-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904};

// Half angle of the tooth at the root circle: the constant-width extension below the base
// circle meets the root circle at half-width r_b sin(alpha2); above the base circle, the
// involute half angle alpha2 - inv(alpha_f).
double root_half_angle(const GearBody& g) {
  if (g.root_radius < g.base_radius) return std::asin(g.base_radius * std::sin(g.base_half_angle) / g.root_radius);
  return g.base_half_angle - involute(std::acos(g.base_radius / g.root_radius));
}

}  // namespace

double foundation_rim_ratio(const GearBody& g) {
  return g.bore_radius > 0.0 ? g.root_radius / g.bore_radius : kSolidBodyRimRatio;
}

bool fillet_foundation_in_range(const GearBody& g) {
  const double h = foundation_rim_ratio(g), theta = root_half_angle(g);
  return h >= 1.4 && h <= 7.0 && theta >= 0.01 && theta <= 0.12;
}

ToothCompliance tooth_compliance(const GearBody& g, double roll_angle, const ToothMaterial& mat, double b,
                                 bool plane_strain) {
  const double nu = mat.poisson_ratio;
  const double e_beam = plane_strain ? mat.youngs_modulus / (1.0 - nu * nu) : mat.youngs_modulus;
  const double shear_modulus = mat.youngs_modulus / (2.0 * (1.0 + nu));
  const double rb = g.base_radius, a2 = g.base_half_angle;
  // Involute point at parameter t (= polar angle of its base-circle tangent point, measured
  // from the tooth centre line): half-width x, height y (Tian 2004).
  auto half_width = [&](double t) { return rb * (std::sin(t) + (a2 - t) * std::cos(t)); };
  auto height = [&](double t) { return rb * (std::cos(t) - (a2 - t) * std::sin(t)); };
  const double a1 = roll_angle - a2;  // load angle: force vs normal to the centre line
  const double tc = -a1;
  const double xc = half_width(tc), yc = height(tc);
  const double ca = std::cos(a1), sa = std::sin(a1);
  auto moment = [&](double y) { return ca * (yc - y) - sa * xc; };  // per unit force

  // Involute part, from the contact down to the base circle (t = a2) or to the root circle
  // where that lies above the base circle.
  const double t_end = g.root_radius < rb ? a2 : a2 - std::sqrt(std::pow(g.root_radius / rb, 2) - 1.0);
  ToothCompliance c;
  auto integrand = [&](double t, int part) {
    const double x = half_width(t);
    const double dy = rb * (a2 - t) * std::cos(t);  // |dy/dt|
    const double area = 2.0 * x * b, inertia = 2.0 * x * x * x * b / 3.0;
    switch (part) {
      case 0: {
        const double mm = moment(height(t));
        return mm * mm / (e_beam * inertia) * dy;
      }
      case 1:
        return 1.2 * ca * ca / (shear_modulus * area) * dy;
      default:
        return sa * sa / (e_beam * area) * dy;
    }
  };
  if (t_end > tc) {
    using Gauss = boost::math::quadrature::gauss<double, 30>;
    c.bending = Gauss::integrate([&](double t) { return integrand(t, 0); }, tc, t_end);
    c.shear = Gauss::integrate([&](double t) { return integrand(t, 1); }, tc, t_end);
    c.axial = Gauss::integrate([&](double t) { return integrand(t, 2); }, tc, t_end);
  }
  // Constant section between the base circle and the root circle (closed form).
  if (g.root_radius < rb) {
    const double xb = rb * std::sin(a2), yb = rb * std::cos(a2);
    const double yf = std::sqrt(g.root_radius * g.root_radius - xb * xb);
    const double len = yb - yf;
    const double area = 2.0 * xb * b, inertia = 2.0 * xb * xb * xb * b / 3.0;
    const double m_top = moment(yb), m_bottom = moment(yf);
    // int M^2 dy with dM/dy = -cos(a1)
    const double m2 =
        std::abs(ca) > 1e-12 ? (std::pow(m_bottom, 3) - std::pow(m_top, 3)) / (3.0 * ca) : m_top * m_top * len;
    c.bending += m2 / (e_beam * inertia);
    c.shear += 1.2 * ca * ca * len / (shear_modulus * area);
    c.axial += sa * sa * len / (e_beam * area);
  }
  // Fillet foundation (Sainsot et al. 2004): u_f from the root circle to where the force line
  // crosses the centre line, S_f = 2 r_f theta_f the root thickness. Every body has one: a solid
  // body's at its shaft seat (foundation_rim_ratio).
  const double theta_f = root_half_angle(g);
  const double h = foundation_rim_ratio(g);
  const double uf = (yc - xc * std::tan(a1)) - g.root_radius;
  const double sf = 2.0 * g.root_radius * theta_f;
  const double ratio = uf / sf;
  c.foundation = ca * ca / (mat.youngs_modulus * b) *
                 (kL(h, theta_f) * ratio * ratio + kM(h, theta_f) * ratio +
                  kP(h, theta_f) * (1.0 + kQ(h, theta_f) * std::tan(a1) * std::tan(a1)));
  return c;
}

MeshStiffnessModel::MeshStiffnessModel(const SpurPair& pair, const ToothMaterial& pinion, const ToothMaterial& wheel,
                                       double composite_modulus, bool plane_strain)
    : pair_(pair),
      material_{pinion, wheel},
      hertz_compliance_(2.0 / (std::numbers::pi * pair.spec().face_width * composite_modulus)),
      plane_strain_(plane_strain) {}

PairStiffness MeshStiffnessModel::pair(double s) const {
  PairStiffness p;
  const double b = pair_.spec().face_width;
  p.pinion = tooth_compliance(pair_.pinion(), pair_.roll_angle(0, s), material_[0], b, plane_strain_);
  p.wheel = tooth_compliance(pair_.wheel(), pair_.roll_angle(1, s), material_[1], b, plane_strain_);
  p.hertz_compliance = hertz_compliance_;
  p.stiffness = 1.0 / (p.pinion.total() + p.wheel.total() + p.hertz_compliance);
  return p;
}

}  // namespace geartrib::gear
