#include "rating/load_capacity.hpp"

#include "core/keyed_error.hpp"
#include "gear/iso6336_stiffness.hpp"
#include "gear/tooth_root.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace geartrib::rating {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kUm = 1e-6, kMPa = 1e6;

// ISO 1328-1:1995 5.3's rounding of a tolerance [um].
double round_tolerance(double um) {
  if (um > 10.0) return std::round(um);
  if (um >= 5.0) return 0.5 * std::round(2.0 * um);
  return 0.1 * std::round(10.0 * um);
}

// ISO 6336-1 Table 8's running-in allowance y_alpha of one gear from f_pb [um] at v [m/s].
double running_in_allowance(MaterialGroup g, double contact_limit, double f_pb, double v) {
  if (g == MaterialGroup::case_hardened) return std::min(0.075 * f_pb, 3.0);  // eq. (77)
  const double s = contact_limit / kMPa, y = 160.0 / s * f_pb;                // eq. (74)
  if (v <= 5.0) return y;
  return std::min(y, (v <= 10.0 ? 12800.0 : 6400.0) / s);  // eqs. (75), (76)
}

// ISO 6336-1 eq. (31): the running-in amount C_ay standing in for an unmodified tip [um].
double running_in_amount(double contact_limit) { return std::pow(contact_limit / kMPa / 97.0 - 18.45, 2) / 18.0 + 1.5; }

constexpr NamedChoice<RatingSettings::LongLife> kLongLife[] = {{RatingSettings::LongLife::optimum, "optimum"},
                                                               {RatingSettings::LongLife::normal, "normal"}};
constexpr NamedChoice<RatingSettings::OilSupply> kOilSupply[] = {{RatingSettings::OilSupply::dip, "dip"},
                                                                 {RatingSettings::OilSupply::spray, "spray"}};

}  // namespace

std::span<const NamedChoice<RatingSettings::LongLife>> long_life_choices() { return kLongLife; }
std::span<const NamedChoice<RatingSettings::OilSupply>> oil_supply_choices() { return kOilSupply; }

void RatingSettings::validate() const {
  using core::KeyedError;
  if (!(application_factor >= 1.0 && application_factor <= 10.0))
    throw KeyedError("application_factor", "K_A must lie in [1, 10]");
  if (!(face_load_factor == 0.0 || (face_load_factor >= 1.0 && face_load_factor <= 10.0)))
    throw KeyedError("face_load_factor", "K_Hbeta must lie in [1, 10] (or be 0: not given, 1 assumed)");
  if (accuracy_grade < 1 || accuracy_grade > 12)
    throw KeyedError("accuracy_grade", "ISO 1328-1 grades run from 1 to 12");
  if (!(load_cycles >= 1.0 && load_cycles <= 1e12)) throw KeyedError("load_cycles", "must lie in [1, 1e12]");
  for (int g = 0; g < 2; ++g) {
    if (!(flank_rz[g] >= 0.0 && flank_rz[g] <= 100e-6)) throw KeyedError("flank_rz", "must lie in [0, 100] um");
    if (!(root_rz[g] >= 0.0 && root_rz[g] <= 100e-6)) throw KeyedError("root_rz", "must lie in [0, 100] um");
  }
}

namespace {
// ISO 1328-1:1995 5.2.3: m and d in the formulas are the geometric means of their size ranges'
// limits (a value on a limit belongs to the lower range) [mm].
double range_mean(double x, std::span<const double> limits) {
  for (std::size_t i = 1; i < limits.size(); ++i)
    if (x <= limits[i]) return std::sqrt(limits[i - 1] * limits[i]);
  return std::sqrt(limits[limits.size() - 2] * limits.back());
}
double module_mean(double m) {
  static constexpr double limits[] = {0.5, 2, 3.5, 6, 10, 16, 25, 40, 70};
  return range_mean(m * 1e3, limits);
}
double diameter_mean(double d) {
  static constexpr double limits[] = {5, 20, 50, 125, 280, 560, 1000, 1600, 2500, 4000, 6000, 8000, 10000};
  return range_mean(d * 1e3, limits);
}
}  // namespace

double single_pitch_tolerance(int q, double m, double d) {
  const double mm = module_mean(m), dm = diameter_mean(d);
  return round_tolerance((0.3 * (mm + 0.4 * std::sqrt(dm)) + 4.0) * std::pow(2.0, 0.5 * (q - 5))) * kUm;
}

double profile_form_tolerance(int q, double m, double d) {
  const double mm = module_mean(m), dm = diameter_mean(d);
  return round_tolerance((2.5 * std::sqrt(mm) + 0.17 * std::sqrt(dm) + 0.5) * std::pow(2.0, 0.5 * (q - 5))) * kUm;
}

bool RatingResult::assumed_any() const {
  return std::any_of(factors.begin(), factors.end(), [](const RatingFactor& f) { return f.assumed; });
}

const RatingFactor* find_factor(const std::vector<RatingFactor>& factors, const std::string& symbol, int gear) {
  for (const auto& f : factors)
    if (f.symbol == symbol && f.gear == gear) return &f;
  return nullptr;
}

LoadCapacity iso6336_load_capacity(const LoadCapacityInputs& in, bool pitting, bool bending) {
  in.settings.validate();
  const gear::SpurPair& pair = *in.pair;
  const gear::GearPairSpec& spec = pair.spec();
  const gear::PathOfContact& path = pair.path();
  const RatingSettings& set = in.settings;
  for (int g = 0; g < 2; ++g)
    if (in.grade[g].group == MaterialGroup::none)
      throw core::KeyedError(g == 0 ? "pinion.material" : "wheel.material",
                             "the material file has no [rating] table (ISO 6336-5 group, quality, hardness)");
  if (pitting && !(in.viscosity_40 > 0.0))
    throw core::KeyedError("viscosity_40",
                           "the pitting rating needs the oil's nu40 (Z_L): give the case a [lubricant]");

  LoadCapacity out;
  auto add = [&](std::string symbol, int gear, double value, std::string unit, std::string clause, bool assumed = false,
                 std::string note = {}) {
    out.factors.push_back(
        {std::move(symbol), gear, value, std::move(unit), std::move(clause), assumed, std::move(note)});
    return value;
  };
  auto finding = [&](std::string what) { out.findings.push_back(std::move(what)); };
  // An allowable of gear g in the table, flagged where its hardness left ISO 6336-5's line.
  auto allowable = [&](const char* symbol, int g, const Allowable& lim) {
    add(symbol, g, lim.value, "Pa", lim.clause, in.grade[g].assumed, in.grade[g].source);
    if (!lim.in_range)
      finding(fmt::format("{}: hardness outside ISO 6336-5's line for {} (taken at the line's end)",
                          g == 0 ? "pinion" : "wheel", symbol));
  };

  const double m = spec.module, alpha = spec.pressure_angle, b = spec.face_width;
  const double alpha_w = pair.operating_pressure_angle();
  const int z1 = spec.teeth[0], z2 = spec.teeth[1];
  const double u = static_cast<double>(z2) / z1;
  const double r1 = pair.pinion().pitch_radius, d1 = 2.0 * r1;
  const double ft = in.pinion_torque / r1, w = ft / b;
  const double v = r1 * in.pinion_speed;
  const double eps = path.contact_ratio;
  const double k_a = set.application_factor;
  std::array<Allowable, 2> contact_limit, bending_limit;
  for (int g = 0; g < 2; ++g) {
    contact_limit[g] = contact_allowable(in.grade[g]);
    bending_limit[g] = bending_allowable(in.grade[g]);
  }

  add("F_t", -1, ft, "N", "ISO 6336-1 eq. (3): 2 T1/d1");
  add("v", -1, v, "m/s", "ISO 6336-1: pitch-line velocity at d1");
  add("eps_alpha", -1, eps, "1", "ISO 21771: g_alpha/p_bt (geartrib's path)");
  add("K_A", -1, k_a, "1", "ISO 6336-1 6 (given)", false);
  if (eps < 1.0 || eps >= 2.05)
    finding(fmt::format("eps_alpha = {:.3f} outside [1, 2.05): Y_DT = 1 and the spur K_Halpha taken beyond their range",
                        eps));

  // --- ISO 6336-1: K_v method B (clause 6.5) ---
  const gear::IsoMeshStiffness stiffness = gear::iso6336_mesh_stiffness(pair, k_a * w);
  const double c1 = stiffness.single, cg = stiffness.mesh;
  add("c'", -1, c1, "N/m^2", "ISO 6336-1 9 (method B): single stiffness per face width");
  add("c_gamma_alpha", -1, cg, "N/m^2", "ISO 6336-1 eq. (89): c'(0.75 eps_alpha + 0.25)");
  double f_pb = 0.0, f_fa = 0.0;
  if (m < 0.5e-3 || m > 70e-3)
    finding("ISO 1328-1: the module lies outside its 0.5..70 mm: the end range's tolerances taken");
  for (int g = 0; g < 2; ++g) {
    const double d = 2.0 * pair.gear(g).pitch_radius;
    if (d < 5e-3 || d > 10.0)
      finding(
          fmt::format("ISO 1328-1: the {}'s reference diameter lies outside its 5..10000 mm: the end range's "
                      "tolerances taken",
                      g == 0 ? "pinion" : "wheel"));
    f_pb = std::max(f_pb, single_pitch_tolerance(set.accuracy_grade, m, d) * std::cos(alpha));
    f_fa = std::max(f_fa, profile_form_tolerance(set.accuracy_grade, m, d));
  }
  add("Q", -1, set.accuracy_grade, "1", "ISO 1328-1:1995 accuracy grade (given or default 6)");
  add("f_pb", -1, f_pb, "m", "ISO 1328-1:1995 f_pt of grade Q x cos(alpha) (ISO/TR 10064-1), the larger gear's");
  add("f_falpha", -1, f_fa, "m", "ISO 1328-1:1995 f_falpha of grade Q, the larger gear's");
  // Running-in: y_p = y_alpha of f_pb, y_f the same rule on f_falpha; the mean of the two gears'.
  double y_a = 0.0, y_f = 0.0;
  for (int g = 0; g < 2; ++g) {
    y_a += 0.5 * running_in_allowance(in.grade[g].group, contact_limit[g].value, f_pb / kUm, v) * kUm;
    y_f += 0.5 * running_in_allowance(in.grade[g].group, contact_limit[g].value, f_fa / kUm, v) * kUm;
  }
  add("y_alpha", -1, y_a, "m", "ISO 6336-1 Table 8 (eqs. 74-77), the mean of the two gears'");
  add("y_f", -1, y_f, "m", "ISO 6336-1 6.5.9: the same rule on f_falpha");
  const double f_pb_eff = std::max(0.0, f_pb - y_a), f_fa_eff = std::max(0.0, f_fa - y_f);
  double c_a = std::max(in.tip_relief[0], in.tip_relief[1]);
  const bool relief_given = c_a > 0.0;
  if (!relief_given)
    c_a = 0.5 * (running_in_amount(contact_limit[0].value) + running_in_amount(contact_limit[1].value)) * kUm;
  add("C_a", -1, c_a, "m",
      relief_given ? "tip relief of the case (the larger gear's)" : "ISO 6336-1 eq. (31): running-in amount C_ay");
  const double load = k_a * w;  // K_A F_t/b [N/m]
  const double b_p = c1 * f_pb_eff / load, b_f = c1 * f_fa_eff / load, b_k = std::abs(1.0 - c1 * c_a / load);
  // Reduced mass per face width on the line of action, eq. (30): the pinion's (d_m1/d_b1)^2 for both
  // gears, the wheel's scaled by u^2, each disc of d_m = (d_a + d_f)/2 less its bore (q = d_i/d_m).
  auto disc = [&](int g) {
    const gear::GearBody& gb = pair.gear(g);
    const double q = 2.0 * gb.bore_radius / (gb.tip_radius + gb.root_radius);
    return in.material[g]->density * (1.0 - std::pow(q, 4));
  };
  const gear::GearBody& pin = pair.pinion();
  const double d_m1 = pin.tip_radius + pin.root_radius, d_b1 = 2.0 * pin.base_radius;
  const double m_red = kPi / 8.0 * std::pow(d_m1 / d_b1, 2) * d_m1 * d_m1 / (1.0 / disc(0) + 1.0 / (disc(1) * u * u));
  add("m_red", -1, m_red, "kg/m", "ISO 6336-1 eq. (30): reduced mass per face width (discs of d_m less the bores)");
  const double n_ratio = in.pinion_speed * z1 / std::sqrt(cg / m_red);  // N = n1/n_E1, eqs. (8)-(9)
  add("N", -1, n_ratio, "1", "ISO 6336-1 eq. (8): resonance ratio n1/n_E1");
  const double load_mm = load / 1e3;                                                    // N/mm
  const double n_s = load_mm < 100.0 ? 0.5 + 0.35 * std::sqrt(load_mm / 100.0) : 0.85;  // eq. (11)
  // Table 7 (spur: eps_gamma = eps_alpha).
  const double eg = eps;
  const double cv1 = 0.32, cv2 = eg <= 2.0 ? 0.34 : 0.57 / (eg - 0.3), cv3 = eg <= 2.0 ? 0.23 : 0.096 / (eg - 1.56);
  const double cv4 = eg <= 2.0 ? 0.90 : (0.57 - 0.05 * eg) / (eg - 1.44), cv5 = 0.47;
  const double cv6 = eg <= 2.0 ? 0.47 : 0.12 / (eg - 1.74);
  const double cv7 = eg <= 1.5 ? 0.75 : (eg <= 2.5 ? 0.125 * std::sin(kPi * (eg - 2.0)) + 0.875 : 1.0);
  auto main_resonance = [&] { return cv1 * b_p + cv2 * b_f + cv4 * b_k + 1.0; };  // eq. (13)
  auto supercritical = [&] { return cv5 * b_p + cv6 * b_f + cv7; };               // eq. (15)
  double k_v = 1.0;
  std::string range;
  if (n_ratio <= n_s) {
    k_v = n_ratio * (cv1 * b_p + cv2 * b_f + cv3 * b_k) + 1.0;  // eq. (12)
    range = "subcritical, eq. (12)";
  } else if (n_ratio <= 1.15) {
    k_v = main_resonance();
    range = "main resonance, eq. (13)";
  } else if (n_ratio < 1.5) {
    k_v = supercritical() + (main_resonance() - supercritical()) / 0.35 * (1.5 - n_ratio);  // eq. (14)
    range = "intermediate, eq. (14)";
  } else {
    k_v = supercritical();
    range = "supercritical, eq. (15)";
  }
  if (n_ratio > n_s && n_ratio <= 1.15)
    finding("the pair runs in its main resonance range (K_v eq. 13): ISO 6336-1 advises against it");
  out.dynamic_factor = add("K_v", -1, k_v, "1", "ISO 6336-1 6.5 method B, " + range);
  const bool k_hb_given = set.face_load_factor > 0.0;
  const double k_hb = k_hb_given ? set.face_load_factor : 1.0;
  add("K_Hbeta", -1, k_hb, "1", "ISO 6336-1 7 (given)", !k_hb_given,
      k_hb_given ? "" : "not given: 1 (an ideal lead on stiff shafts) assumed");
  // K_Fbeta = K_Hbeta^N_F, eq. (54), b/h the smaller gear's, at least 3.
  double bh = INFINITY;
  for (int g = 0; g < 2; ++g) bh = std::min(bh, b / (pair.gear(g).tip_radius - pair.gear(g).root_radius));
  bh = std::max(bh, 3.0);
  const double n_f = bh * bh / (1.0 + bh + bh * bh);
  const double k_fb = std::pow(k_hb, n_f);
  add("K_Fbeta", -1, k_fb, "1", "ISO 6336-1 eq. (54): K_Hbeta^N_F");
  // K_Halpha, K_Falpha (method B, clause 8.3): eqs. (71)-(73) with their limits.
  const double f_th = ft * k_a * k_v * k_hb;
  const double term = cg * (f_pb - y_a) / (f_th / b);
  const double k_alpha =
      eg <= 2.0 ? 0.5 * eg * (0.9 + 0.4 * term) : 0.9 + 0.4 * std::sqrt(2.0 * (eg - 1.0) / eg) * term;
  const double z_eps = std::sqrt((4.0 - eps) / 3.0);
  const double y_eps = 0.25 + 0.75 / eps;
  const double k_ha = std::clamp(k_alpha, 1.0, std::max(1.0, eg / (eps * z_eps * z_eps)));
  const double k_fa = std::clamp(k_alpha, 1.0, std::max(1.0, eg / (eps * y_eps)));
  out.transverse_factor =
      add("K_Halpha", -1, k_ha, "1", "ISO 6336-1 eqs. (71)-(72), limited to [1, eps_gamma/(eps_alpha Z_eps^2)]");
  add("K_Falpha", -1, k_fa, "1", "ISO 6336-1 eqs. (71)-(73), limited to [1, eps_gamma/(eps_alpha Y_eps)]");

  // --- ISO 6336-2: pitting ---
  if (pitting) {
    const double z_h = std::sqrt(2.0 * std::cos(alpha_w) / (std::cos(alpha) * std::cos(alpha) * std::sin(alpha_w)));
    add("Z_H", -1, z_h, "1", "ISO 6336-2 eq. (9), spur");
    const double e_r = composite_modulus(*in.material[0], *in.material[1]);
    const double z_e = std::sqrt(e_r / kPi);
    add("Z_E", -1, z_e, "Pa^0.5", "ISO 6336-2 eq. (10)");
    add("Z_eps", -1, z_eps, "1", "ISO 6336-2 eq. (11), spur");
    add("Z_beta", -1, 1.0, "1", "ISO 6336-2 eq. (12), spur: 1");
    // Z_B, Z_D (eqs. 5-6): M1, M2 as the ratio of the curvature products at C and at the inner
    // point of single contact (B on the pinion, D on the wheel), which is what eqs. (5)-(6) evaluate.
    auto curvature_product = [&](double s) { return s * (path.line_length - s); };
    const double m1 = std::sqrt(curvature_product(path.c) / curvature_product(path.b));
    const double m2 = std::sqrt(curvature_product(path.c) / curvature_product(path.d));
    const std::array<double, 2> z_bd = {std::max(1.0, m1), std::max(1.0, m2)};
    add("Z_B", 0, z_bd[0], "1", "ISO 6336-2 eqs. (5), (7): M1 at the pinion's inner point of single contact");
    add("Z_D", 1, z_bd[1], "1", "ISO 6336-2 eqs. (6), (7): M2 at the wheel's");
    const double s_h0 = z_h * z_e * z_eps * std::sqrt(ft / (d1 * b) * (u + 1.0) / u);
    add("sigma_H0", -1, s_h0, "Pa", "ISO 6336-2 eq. (2): nominal contact stress at C");
    const double rho_c = path.c * (path.line_length - path.c) / path.line_length;
    std::array<double, 2> rz = {0.0, 0.0};
    bool rz_assumed = false;
    for (int g = 0; g < 2; ++g) {
      rz[g] = set.flank_rz[g] > 0.0 ? set.flank_rz[g] : kRzOverRa * in.flank_ra[g];
      rz_assumed = rz_assumed || !(set.flank_rz[g] > 0.0);
    }
    const double rz_mean = 0.5 * (rz[0] + rz[1]);
    // Z_L, Z_v and Z_R take the lower sigma_Hlim of the pair (ISO 6336-2 9, 10, 11: the softer material).
    const double s_lim = std::min(contact_limit[0].value, contact_limit[1].value);
    const double z_l = add("Z_L", -1, lubricant_factor(s_lim, in.viscosity_40), "1",
                           "ISO 6336-2 eq. (22), C_ZL of the lower sigma_Hlim");
    const double z_v = add("Z_v", -1, speed_factor(s_lim, v), "1", "ISO 6336-2 eq. (26), C_Zv of the lower sigma_Hlim");
    const double z_r = add("Z_R", -1, roughness_factor(s_lim, rz_mean, rho_c), "1",
                           "ISO 6336-2 eqs. (28)-(33), Rz10 at rho_red,C, C_ZR of the lower sigma_Hlim", rz_assumed,
                           rz_assumed ? "flank Rz = 6 Ra (assumed)" : "");
    for (int g = 0; g < 2; ++g) {
      const double s_h = z_bd[g] * s_h0 * std::sqrt(k_a * k_v * k_hb * k_ha);
      add("sigma_H", g, s_h, "Pa", "ISO 6336-2 eqs. (3)-(4): Z_B|Z_D sigma_H0 sqrt(K_A K_v K_Hbeta K_Halpha)");
      const Allowable& lim = contact_limit[g];
      allowable("sigma_Hlim", g, lim);
      const double n_l = g == 0 ? set.load_cycles : set.load_cycles / u;
      const double z_nt =
          contact_life_factor(in.grade[g].group, n_l, set.long_life == RatingSettings::LongLife::optimum);
      add("Z_NT", g, z_nt, "1",
          fmt::format("ISO 6336-2 Table 2 at N_L = {:.3g} ({} long life)", n_l,
                      set.long_life == RatingSettings::LongLife::optimum ? "optimum" : "normal"));
      add("Z_W", g, 1.0, "1", "ISO 6336-2 12: 1 (equal hardness; a hard pinion's Z_W on a soft wheel is not applied)");
      const double z_x = add("Z_X", g, contact_size_factor(in.grade[g].group, m), "1",
                             "ISO 6336-2 13: 1, case-hardened 1.05 - 0.005 m_n above 10 mm");
      const double s_hg = lim.value * z_nt * z_l * z_v * z_r * z_x;
      add("sigma_HG", g, s_hg, "Pa", "ISO 6336-2 eq. (19): sigma_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X");
      out.contact_stress[g] = s_h;
      out.pitting_safety[g] = add("S_H", g, s_hg / s_h, "1", "ISO 6336-2 eq. (18): sigma_HG/sigma_H");
    }
  }

  // --- ISO 6336-3: bending, method B ---
  if (bending) {
    add("Y_eps", -1, y_eps, "1",
        "DIN 3990-3 / ISO 6336-3:1996: 0.25 + 0.75/eps_alpha (not applied: ISO 6336-3:2006+ method B has none)");
    for (int g = 0; g < 2; ++g) {
      // A root the 30-degree construction does not cover leaves this gear's bending unrated (the
      // other ratings stand), said in a finding naming the key to change.
      gear::RootSection r;
      try {
        r = gear::iso6336_root_section(pair, g);
      } catch (const gear::GeometryError& e) {
        finding(fmt::format("{}: bending not rated: {} ({})", g == 0 ? "pinion" : "wheel", e.what(), e.key()));
        continue;
      }
      const gear::GearBody& gb = pair.gear(g);
      add("d_en", g, r.load_diameter, "m", "ISO 6336-3 eq. (15): outer point of single-pair contact (geartrib's path)");
      add("s_Fn", g, r.chord, "m", "ISO 6336-3 6.2: chord at the 30 deg tangent on the generated fillet");
      add("rho_F", g, r.fillet_radius, "m", "ISO 6336-3 6.2: fillet radius there");
      add("h_Fe", g, r.moment_arm, "m", "ISO 6336-3 6.2: bending moment arm");
      add("alpha_Fen", g, r.load_angle, "rad", "ISO 6336-3 eq. (18)");
      add("Y_F", g, r.form_factor, "1", "ISO 6336-3 eq. (6), method B on the generated root");
      add("Y_S", g, r.stress_correction, "1", "ISO 6336-3 eq. (26)");
      if (!r.stress_correction_in_range)
        finding(
            fmt::format("{}: q_s = {:.2f} outside Y_S's range [1, 8)", g == 0 ? "pinion" : "wheel", r.notch_parameter));
      add("Y_beta", g, 1.0, "1", "ISO 6336-3 eq. (33), spur: 1");
      // Rim factor (eqs. 35-36): 1 for a solid gear or s_R/h_t >= 1.2.
      double y_b = 1.0;
      const double h_t = gb.tip_radius - gb.root_radius;
      if (gb.bore_radius > 0.0) {
        const double s_r = gb.root_radius - gb.bore_radius, ratio = s_r / h_t;
        if (ratio < 1.2) y_b = 1.6 * std::log(2.242 / std::max(ratio, 0.5));
        if (ratio <= 0.5)
          finding(fmt::format("{}: rim s_R/h_t = {:.2f} at or below 0.5, outside Y_B's range",
                              g == 0 ? "pinion" : "wheel", ratio));
      }
      add("Y_B", g, y_b, "1", "ISO 6336-3 eqs. (35)-(36): rim below the root (bore given) or solid");
      add("Y_DT", g, 1.0, "1", "ISO 6336-3 eq. (37): 1 for eps_alpha <= 2.05");
      const double s_f0 = ft / (b * m) * r.form_factor * r.stress_correction * y_b;
      add("sigma_F0", g, s_f0, "Pa", "ISO 6336-3 eq. (3): F_t/(b m_n) Y_F Y_S Y_beta Y_B Y_DT");
      const double s_f = s_f0 * k_a * k_v * k_fb * k_fa;
      add("sigma_F", g, s_f, "Pa", "ISO 6336-3 eq. (2): sigma_F0 K_A K_v K_Fbeta K_Falpha");
      const Allowable& lim = bending_limit[g];
      allowable("sigma_Flim", g, lim);
      add("Y_ST", g, 2.0, "1", "ISO 6336-3 5: stress correction of the reference test gear");
      const double n_l = g == 0 ? set.load_cycles : set.load_cycles / u;
      const double y_nt =
          bending_life_factor(in.grade[g].group, n_l, set.long_life == RatingSettings::LongLife::optimum);
      add("Y_NT", g, y_nt, "1", fmt::format("ISO 6336-3 Table 3 at N_L = {:.3g}", n_l));
      const double y_d =
          relative_notch_sensitivity(in.grade[g].group, in.material[g]->yield_strength, r.notch_parameter);
      if (!slip_layer_in_range(in.grade[g].group, in.material[g]->yield_strength))
        finding(
            fmt::format("{}: proof stress {:.0f} MPa outside ISO 6336-3 Table 4's rows for its group: the end row's "
                        "slip layer taken (Y_deltarelT)",
                        g == 0 ? "pinion" : "wheel", in.material[g]->yield_strength * 1e-6));
      add("Y_deltarelT", g, y_d, "1", "ISO 6336-3 eq. (43), slip layer of Table 4");
      const bool rz_given = set.root_rz[g] > 0.0;
      const double y_r = relative_surface_factor(in.grade[g].group, rz_given ? set.root_rz[g] : kDefaultRootRz);
      add("Y_RrelT", g, y_r, "1", "ISO 6336-3 eqs. (46)-(49)", !rz_given, rz_given ? "" : "root Rz = 10 um (assumed)");
      const double y_x = bending_size_factor(in.grade[g].group, m);
      add("Y_X", g, y_x, "1", "ISO 6336-3 Table 5");
      const double s_fg = lim.value * 2.0 * y_nt * y_d * y_r * y_x;
      add("sigma_FG", g, s_fg, "Pa", "ISO 6336-3 eq. (5): sigma_Flim Y_ST Y_NT Y_deltarelT Y_RrelT Y_X");
      out.root_stress[g] = s_f;
      out.bending_safety[g] = add("S_F", g, s_fg / s_f, "1", "ISO 6336-3 eq. (4): sigma_FG/sigma_F");
    }
  }
  return out;
}

}  // namespace geartrib::rating
