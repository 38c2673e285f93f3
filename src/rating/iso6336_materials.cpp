#include "rating/iso6336_materials.hpp"

#include "core/keyed_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace geartrib::rating {

namespace {

constexpr double kMPa = 1e6;

constexpr NamedChoice<MaterialGroup> kGroups[] = {
    {MaterialGroup::normalized, "normalized"},
    {MaterialGroup::through_hardened_carbon, "through-hardened-carbon"},
    {MaterialGroup::through_hardened_alloy, "through-hardened-alloy"},
    {MaterialGroup::case_hardened, "case-hardened"},
};
constexpr NamedChoice<MaterialQuality> kQualities[] = {
    {MaterialQuality::ML, "ML"}, {MaterialQuality::MQ, "MQ"}, {MaterialQuality::ME, "ME"}};

// One line of ISO 6336-5: sigma = A x + B [N/mm^2] for x (HV) in [lo, hi].
struct Line {
  double a, b, lo, hi;
  const char* figure;
};

// ISO 6336-5:2016 Table 1's lines A x + B, x = HV (the St lines are written for HBW; St is rated on
// the number given), contact then bending, each ML, MQ, ME. Source: two public transcriptions of
// the 2016 table (docs/theory/ratings.md). Eh MQ bending: 425 N/mm^2, the value for a core of at
// least 25 HRC with the lower Jominy band (the standard allows 461 and 500 for harder cores).
struct GroupLines {
  MaterialGroup group;
  std::array<Line, 3> contact, bending;
};
const GroupLines kLines[] = {
    {MaterialGroup::normalized,
     {Line{1.000, 190, 110, 210, "Fig. 1 (St)"}, Line{1.000, 190, 110, 210, "Fig. 1 (St)"},
      Line{1.520, 250, 110, 210, "Fig. 1 (St)"}},
     {Line{0.455, 69, 110, 210, "Fig. 17 (St)"}, Line{0.455, 69, 110, 210, "Fig. 17 (St)"},
      Line{0.386, 147, 110, 210, "Fig. 17 (St)"}}},
    {MaterialGroup::through_hardened_carbon,
     {Line{0.963, 283, 135, 210, "Fig. 5 (V, carbon)"}, Line{0.925, 360, 135, 210, "Fig. 5 (V, carbon)"},
      Line{0.838, 432, 135, 210, "Fig. 5 (V, carbon)"}},
     {Line{0.250, 108, 115, 215, "Fig. 21 (V, carbon)"}, Line{0.240, 163, 115, 215, "Fig. 21 (V, carbon)"},
      Line{0.283, 202, 115, 215, "Fig. 21 (V, carbon)"}}},
    {MaterialGroup::through_hardened_alloy,
     {Line{1.313, 188, 200, 360, "Fig. 6 (V, alloy)"}, Line{1.313, 373, 200, 360, "Fig. 6 (V, alloy)"},
      Line{2.213, 260, 200, 390, "Fig. 6 (V, alloy)"}},
     {Line{0.423, 104, 200, 360, "Fig. 22 (V, alloy)"}, Line{0.425, 187, 200, 360, "Fig. 22 (V, alloy)"},
      Line{0.358, 231, 200, 390, "Fig. 22 (V, alloy)"}}},
    {MaterialGroup::case_hardened,
     {Line{0.0, 1300, 600, 800, "Fig. 9 (Eh)"}, Line{0.0, 1500, 600, 800, "Fig. 9 (Eh)"},
      Line{0.0, 1650, 600, 800, "Fig. 9 (Eh)"}},
     {Line{0.0, 312, 660, 800, "Fig. 25 (Eh)"}, Line{0.0, 425, 660, 800, "Fig. 25 (Eh)"},
      Line{0.0, 525, 660, 800, "Fig. 25 (Eh)"}}},
};
const GroupLines& lines_of(MaterialGroup g) {
  for (const auto& l : kLines)
    if (l.group == g) return l;
  throw std::invalid_argument("ISO 6336-5: no allowable stress lines for material group 'none'");
}

Allowable from_line(const Line& l, const MaterialGrade& g, double given, const char* what) {
  if (given > 0.0) return {given, true, fmt::format("{} given", what)};
  const double x = std::clamp(g.surface_hardness, l.lo, l.hi);
  return {(l.a * x + l.b) * kMPa, g.surface_hardness >= l.lo && g.surface_hardness <= l.hi,
          fmt::format("ISO 6336-5 {}, {}: {:g} HV + {:g} N/mm^2 for {:g}..{:g} HV", l.figure,
                      material_quality_name(g.quality), l.a, l.b, l.lo, l.hi)};
}

// log-log between (n0, f0) and (n1, f1), constant f0 below n0.
double log_log(double n, double n0, double f0, double n1, double f1) {
  if (n <= n0) return f0;
  return f0 * std::pow(f1 / f0, std::log(n / n0) / std::log(n1 / n0));
}

// The long-life branch beyond the knee n1 (factor 1 there): 1 (optimum) or down to 0.85 at 1e10.
double long_life(double n, double n1, bool optimum) {
  if (optimum) return 1.0;
  return log_log(std::min(n, 1e10), n1, 1.0, 1e10, 0.85);
}

}  // namespace

std::span<const NamedChoice<MaterialGroup>> material_group_choices() { return kGroups; }
const char* material_group_name(MaterialGroup g) {
  return g == MaterialGroup::none ? "none" : choice_name(material_group_choices(), g);
}
std::span<const NamedChoice<MaterialQuality>> material_quality_choices() { return kQualities; }
const char* material_quality_name(MaterialQuality q) { return choice_name(material_quality_choices(), q); }

void MaterialGrade::validate() const {
  if (group == MaterialGroup::none) return;
  if (!(surface_hardness >= 50.0 && surface_hardness <= 1200.0))
    throw core::KeyedError("surface_hardness", "must lie in [50, 1200] HV");
  if (!(contact_limit >= 0.0 && contact_limit <= 3e9))
    throw core::KeyedError("contact_limit", "must lie in [0, 3000] MPa");
  if (!(bending_limit >= 0.0 && bending_limit <= 1.5e9))
    throw core::KeyedError("bending_limit", "must lie in [0, 1500] MPa");
}

Allowable contact_allowable(const MaterialGrade& g) {
  return from_line(lines_of(g.group).contact[static_cast<std::size_t>(g.quality)], g, g.contact_limit, "sigma_Hlim");
}
Allowable bending_allowable(const MaterialGrade& g) {
  return from_line(lines_of(g.group).bending[static_cast<std::size_t>(g.quality)], g, g.bending_limit, "sigma_Flim");
}

double contact_life_factor(MaterialGroup, double n, bool optimum) {
  // ISO 6336-2 Table 2, steels without pitting permitted: 1.6 up to 1e5, 1.0 at 5e7.
  if (n <= 5e7) return log_log(n, 1e5, 1.6, 5e7, 1.0);
  return long_life(n, 5e7, optimum);
}

double bending_life_factor(MaterialGroup g, double n, bool optimum) {
  // ISO 6336-3 Table 3: 2.5 up to 1e4 (St, V) or 1e3 (Eh), 1.0 at 3e6.
  const double n0 = g == MaterialGroup::case_hardened ? 1e3 : 1e4;
  if (n <= 3e6) return log_log(n, n0, 2.5, 3e6, 1.0);
  return long_life(n, 3e6, optimum);
}

namespace {
// C_ZL of ISO 6336-2 eq. (23)-(25): 0.83 below 850 N/mm^2, 0.91 above 1200, linear between.
double c_zl(double contact_limit) {
  const double s = std::clamp(contact_limit / kMPa, 850.0, 1200.0);
  return 0.83 + 0.08 * (s - 850.0) / 350.0;
}
}  // namespace

double lubricant_factor(double contact_limit, double viscosity_40) {
  const double c = c_zl(contact_limit), nu = viscosity_40 * 1e6;  // mm^2/s
  return c + 4.0 * (1.0 - c) / std::pow(1.2 + 134.0 / nu, 2);     // ISO 6336-2 eq. (22)
}

double speed_factor(double contact_limit, double v) {
  const double c = c_zl(contact_limit) + 0.02;             // C_Zv, eq. (27)
  return c + 2.0 * (1.0 - c) / std::sqrt(0.8 + 32.0 / v);  // eq. (26)
}

double roughness_factor(double contact_limit, double mean_rz, double relative_radius) {
  const double s = std::clamp(contact_limit / kMPa, 850.0, 1200.0);
  const double c_zr = 0.32 - 0.0002 * s;  // eq. (31)-(33): 0.15 below 850, 0.08 above 1200
  const double rz10 = mean_rz * 1e6 * std::cbrt(10.0 / (relative_radius * 1e3));  // eq. (29), um
  return std::pow(3.0 / rz10, c_zr);                                              // eq. (28)
}

double slip_layer_thickness(MaterialGroup g, double proof_stress) {
  // ISO 6336-3 Table 4 [mm]: Eh 0.0030; V by sigma_0.2 500/600/800/1000 N/mm^2: 0.0281, 0.0194,
  // 0.0064, 0.0014; St by sigma_S 300/400: 0.0833, 0.0445. Linear between rows, the end rows beyond.
  auto table = [](double s, std::span<const double> x, std::span<const double> y) {
    if (s <= x.front()) return y.front();
    for (std::size_t i = 1; i < x.size(); ++i)
      if (s <= x[i]) return y[i - 1] + (y[i] - y[i - 1]) * (s - x[i - 1]) / (x[i] - x[i - 1]);
    return y.back();
  };
  const double s = proof_stress / kMPa;
  static constexpr double vx[] = {500, 600, 800, 1000}, vy[] = {0.0281, 0.0194, 0.0064, 0.0014};
  static constexpr double sx[] = {300, 400}, sy[] = {0.0833, 0.0445};
  switch (g) {
    case MaterialGroup::case_hardened:
      return 0.0030e-3;
    case MaterialGroup::normalized:
      return table(s, sx, sy) * 1e-3;
    default:
      return table(s, vx, vy) * 1e-3;
  }
}

bool slip_layer_in_range(MaterialGroup g, double proof_stress) {
  const double s = proof_stress / kMPa;
  switch (g) {
    case MaterialGroup::case_hardened:
      return true;
    case MaterialGroup::normalized:
      return s >= 300.0 && s <= 400.0;
    default:
      return s >= 500.0 && s <= 1000.0;
  }
}

double relative_notch_sensitivity(MaterialGroup g, double proof_stress, double q_s) {
  // ISO 6336-3 eq. (43)-(45): (1 + sqrt(rho' chi*))/(1 + sqrt(rho' chi*_T)), chi* = (1 + 2 q_s)/5
  // [1/mm], chi*_T at the test gear's q_sT = 2.5.
  const double rho = slip_layer_thickness(g, proof_stress) * 1e3;  // mm
  const double chi = (1.0 + 2.0 * q_s) / 5.0, chi_t = (1.0 + 2.0 * 2.5) / 5.0;
  return (1.0 + std::sqrt(rho * chi)) / (1.0 + std::sqrt(rho * chi_t));
}

double relative_surface_factor(MaterialGroup g, double root_rz) {
  // ISO 6336-3 eq. (46)-(49) for Rz in [1, 40] um (beyond 40, the value at 40); below 1 um the
  // standard's constants 1.120 (V, Eh) and 1.070 (St).
  const double rz = std::min(root_rz * 1e6, 40.0);
  if (g == MaterialGroup::normalized) return rz < 1.0 ? 1.070 : 5.306 - 4.203 * std::pow(rz + 1.0, 0.01);
  if (rz < 1.0) return 1.120;
  return 1.674 - 0.529 * std::pow(rz + 1.0, 0.1);
}

double contact_size_factor(MaterialGroup g, double module) {
  const double m = module * 1e3;
  if (g != MaterialGroup::case_hardened || m <= 10.0) return 1.0;
  return std::max(0.9, 1.05 - 0.005 * m);
}

double bending_size_factor(MaterialGroup g, double module) {
  // ISO 6336-3 Table 5: St, V 1.03 - 0.006 m_n for 5 < m_n < 30 mm (0.85 beyond); Eh 1.05 - 0.01 m_n
  // for 5 < m_n < 25 mm (0.8 beyond); 1 up to 5 mm.
  const double m = module * 1e3;
  if (m <= 5.0) return 1.0;
  if (g == MaterialGroup::case_hardened) return std::max(0.8, 1.05 - 0.01 * m);
  return std::max(0.85, 1.03 - 0.006 * m);
}

}  // namespace geartrib::rating
