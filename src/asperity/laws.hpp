// Single-asperity elastic-plastic laws (sphere on a rigid flat), written once as functors
// templated on the scalar so that the simulator (double) and Ceres fitting (ceres::Jet) run the
// same code. Each law gives the dimensionless load F* = F/F_c and area A* = A/A_c at
// delta* = delta/delta_c, normalised by its own published critical values, from a parameter
// array holding its named constants (ConstantSpec tables below, in order).
#pragma once

#include "asperity/contact_pair.hpp"
#include "asperity/continuous_defaults.hpp"
#include "asperity/critical.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace geartrib::asperity {

template <class T>
struct Star {
  T load;     // F* = F / F_c
  T area;     // A* = A / A_c
  T plastic;  // share of the contact area whose surface has yielded (0..1)
};

// Share of the contact area whose surface has yielded, at delta* = d:
//   phi_s = 0 for d <= d_0,  phi_s = 1/(1 + (c/(d - d_0))^n) beyond,
// the closure of the continuous model's plastic core, fitted to the project's CalculiX runs
// (validation/fem-reference: yielded share of the contact disc at the surface, perfectly plastic
// 45 steel, delta* 1-100). The published laws, which give no plastic zone of their own, use it
// with the fitted defaults (their documented profile: ContactPair-independent, by delta*).
template <class T>
T surface_yield_share(const T& d, const T& onset, const T& scale, const T& exponent) {
  using std::pow;
  if (!(d > onset)) return T(0.0);
  return 1.0 / (1.0 + pow(scale / (d - onset), exponent));
}
template <class T>
T published_surface_yield_share(const T& d) {
  return surface_yield_share(d, T(fitted::continuous_plastic_onset), T(fitted::continuous_plastic_scale),
                             T(fitted::continuous_plastic_exponent));
}

// Where a law was built for (its stated range): the largest delta* its fit or derivation covers
// (infinity: defined at every interference), the contact radius over the summit radius up to which
// the paraboloid tip it assumes stays one (at a/R = 0.5 a sphere's cap is 7% deeper than the
// paraboloid's, R - sqrt(R^2 - a^2) against a^2/(2R)), and whether, past either, the model
// switches to the fully plastic limit (models.cpp) instead of extrapolating the law.
struct LawRange {
  double fitted_delta_star_max;
  double contact_radius_over_radius_max = 0.5;
  bool switch_to_fully_plastic = false;
  std::string_view past_range;  // what answers past the range, for the user
};

// A named model constant: default value, admissible range (inclusive) and meaning.
struct ConstantSpec {
  std::string_view name;
  double value;
  double lower;
  double upper;
  std::string_view meaning;
};

// The index of the constant named `name` in a law's `constants`, at compile time: each law's
// Index names its constants' places (c[Index::fully_plastic]), a misspelt name does not compile.
template <std::size_t N>
consteval std::size_t constant_index(const std::array<ConstantSpec, N>& constants, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (constants[i].name == name) return i;
  throw std::invalid_argument("no constant of that name");  // not a constant expression: a compile error
}

// ---------------------------------------------------------------------------------------------
// Hertz: purely elastic at any interference (Johnson ch. 4). delta_c is the CEB one.
struct HertzLaw {
  static constexpr std::string_view name = "hertz";
  static constexpr std::string_view citation = "Hertz (1882); Johnson, Contact Mechanics (1985) ch. 4";
  static constexpr std::array<ConstantSpec, 0> constants{};
  // Elastic reference: holds up to first yield only; beyond it the run flags every contact.
  static LawRange range(const double*) { return {1.0, 0.5, false, "flagged only: the elastic reference"}; }
  static void breakpoints(const double*, std::vector<double>&) {}
  template <class T>
  static T yield_peak_pressure(const ContactPair& p, const T*) {
    return T(ceb_pressure_factor(p.poisson_ratio) * p.hardness);
  }
  template <class T>
  static Star<T> star(const T& d, const T*, const ContactPair&) {
    using std::pow;
    return {pow(d, 1.5), d, T(0.0)};
  }
};

// ---------------------------------------------------------------------------------------------
// Chang, Etsion & Bogy (1987): Hertz up to delta_c, then volume conservation of the plastically
// deformed tip, A = pi R delta (2 - delta_c/delta), at a uniform mean pressure k H. Published
// with a load jump of 3/2 at delta* = 1.
struct CebLaw {
  static constexpr std::string_view name = "ceb";
  static constexpr std::string_view citation = "Chang, Etsion & Bogy, J. Tribol. 109 (1987) 257";
  static constexpr std::array<ConstantSpec, 0> constants{};
  // Volume conservation holds at any interference; its plastic pressure stays k H (< H).
  static LawRange range(const double*) {
    return {std::numeric_limits<double>::infinity(), 0.5, false,
            "defined at every interference (plastic pressure k H)"};
  }
  static void breakpoints(const double*, std::vector<double>& out) {
    out.insert(out.end(), {1.0, fitted::continuous_plastic_onset});
  }
  template <class T>
  static T yield_peak_pressure(const ContactPair& p, const T*) {
    return T(ceb_pressure_factor(p.poisson_ratio) * p.hardness);
  }
  template <class T>
  static Star<T> star(const T& d, const T*, const ContactPair&) {
    using std::pow;
    if (d <= 1.0) return {pow(d, 1.5), d, T(0.0)};
    const T area = 2.0 * d - 1.0;
    return {1.5 * area, area, published_surface_yield_share(d)};  // F/F_c = (k H A) / ((2/3) k H A_c)
  }
};

// ---------------------------------------------------------------------------------------------
// Kogut & Etsion (2002), FEM fits for 1 <= delta* <= 110 (nu = 0.3 based):
//   1 <= d <= 6:   F* = 1.03 d^1.425, A* = 0.93 d^1.136
//   6 <= d <= 110: F* = 1.40 d^1.263, A* = 0.94 d^1.146
//   d > 110: fully plastic, F = 2 pi R delta H (F* = 3 d / k), A = 2 pi R delta (A* = 2 d).
// As published it jumps at d = 1 (area down by 7%), 6 and 110. The law below keeps the published
// branches; the model (models.cpp) replaces the jump at 110 by the continuous switch to the fully
// plastic limit that every law with a fitted range uses.
struct KogutEtsionLaw {
  static constexpr std::string_view name = "kogut-etsion";
  static constexpr std::string_view citation = "Kogut & Etsion, J. Appl. Mech. 69 (2002) 657";
  static constexpr std::array<ConstantSpec, 10> constants{{
      {"load_coefficient_1", 1.03, 0.1, 10.0, "F* coefficient for 1 <= delta* <= 6"},
      {"load_exponent_1", 1.425, 1.0, 2.0, "F* exponent for 1 <= delta* <= 6"},
      {"area_coefficient_1", 0.93, 0.1, 10.0, "A* coefficient for 1 <= delta* <= 6"},
      {"area_exponent_1", 1.136, 0.5, 2.0, "A* exponent for 1 <= delta* <= 6"},
      {"load_coefficient_2", 1.40, 0.1, 10.0, "F* coefficient for 6 <= delta* <= 110"},
      {"load_exponent_2", 1.263, 1.0, 2.0, "F* exponent for 6 <= delta* <= 110"},
      {"area_coefficient_2", 0.94, 0.1, 10.0, "A* coefficient for 6 <= delta* <= 110"},
      {"area_exponent_2", 1.146, 0.5, 2.0, "A* exponent for 6 <= delta* <= 110"},
      {"surface_yield", 6.0, 1.0, 100.0, "delta* where the plastic zone reaches the surface"},
      {"fully_plastic", 110.0, 2.0, 1000.0,
       "delta* of fully plastic contact (the end of the fitted range: the continuous switch to the fully plastic limit starts here)"},
  }};
  struct Index {
    static constexpr std::size_t load_coefficient_1 = constant_index(constants, "load_coefficient_1"),
                                 load_exponent_1 = constant_index(constants, "load_exponent_1"),
                                 area_coefficient_1 = constant_index(constants, "area_coefficient_1"),
                                 area_exponent_1 = constant_index(constants, "area_exponent_1"),
                                 load_coefficient_2 = constant_index(constants, "load_coefficient_2"),
                                 load_exponent_2 = constant_index(constants, "load_exponent_2"),
                                 area_coefficient_2 = constant_index(constants, "area_coefficient_2"),
                                 area_exponent_2 = constant_index(constants, "area_exponent_2"),
                                 surface_yield = constant_index(constants, "surface_yield"),
                                 fully_plastic = constant_index(constants, "fully_plastic");
  };
  // Fitted 1 <= delta* <= 110 (the constant fully_plastic); the model switches to the fully
  // plastic limit there.
  static LawRange range(const double* c) {
    return {c[Index::fully_plastic], 0.5, true, "continuous switch to the fully plastic limit"};
  }
  static void breakpoints(const double* c, std::vector<double>& out) {
    out.insert(out.end(), {1.0, c[Index::surface_yield], c[Index::fully_plastic], fitted::continuous_plastic_onset});
  }
  template <class T>
  static T yield_peak_pressure(const ContactPair& p, const T*) {
    return T(ceb_pressure_factor(p.poisson_ratio) * p.hardness);
  }
  template <class T>
  static Star<T> star(const T& d, const T* c, const ContactPair& p) {
    using std::pow;
    if (d <= 1.0) return {pow(d, 1.5), d, T(0.0)};
    const T share = published_surface_yield_share(d);
    using I = Index;
    if (d <= c[I::surface_yield])
      return {c[I::load_coefficient_1] * pow(d, c[I::load_exponent_1]),
              c[I::area_coefficient_1] * pow(d, c[I::area_exponent_1]), share};
    if (d <= c[I::fully_plastic])
      return {c[I::load_coefficient_2] * pow(d, c[I::load_exponent_2]),
              c[I::area_coefficient_2] * pow(d, c[I::area_exponent_2]), share};
    return {3.0 * d / ceb_pressure_factor(p.poisson_ratio), 2.0 * d, share};
  }
};

// ---------------------------------------------------------------------------------------------
// Jackson & Green (2005), FEM-based, Hertz up to delta* = 1.9, then
//   F* = exp(-1/4 d^(5/12)) d^(3/2) + 4 H_G/(C S_y) [1 - exp(-1/25 d^(5/9))] d
//   A* = d (d/1.9)^B,  B = 0.14 exp(23 S_y/E)
//   H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)]
// with delta_c = (pi C S_y/(2 E_t))^2 R, C = 1.295 exp(0.736 nu).
struct JacksonGreenLaw {
  static constexpr std::string_view name = "jackson-green";
  static constexpr std::string_view citation = "Jackson & Green, J. Tribol. 127 (2005) 343";
  static constexpr std::array<ConstantSpec, 6> constants{{
      {"elastic_limit", 1.9, 1.0, 10.0, "delta* up to which the contact is Hertzian"},
      {"hardness_limit", 2.84, 2.0, 3.5, "H_G/S_y of a small contact, a/R -> 0"},
      {"hardness_coefficient", 0.82, 0.1, 5.0, "coefficient of (a/R)^-exponent in H_G"},
      {"hardness_exponent", 0.7, 0.1, 2.0, "exponent of a/R in H_G"},
      {"area_coefficient", 0.14, 0.01, 1.0, "B = coefficient exp(slope S_y/E)"},
      {"area_slope", 23.0, 0.0, 100.0, "B = coefficient exp(slope S_y/E)"},
  }};
  struct Index {
    static constexpr std::size_t elastic_limit = constant_index(constants, "elastic_limit"),
                                 hardness_limit = constant_index(constants, "hardness_limit"),
                                 hardness_coefficient = constant_index(constants, "hardness_coefficient"),
                                 hardness_exponent = constant_index(constants, "hardness_exponent"),
                                 area_coefficient = constant_index(constants, "area_coefficient"),
                                 area_slope = constant_index(constants, "area_slope");
  };
  // Jackson & Green's finite-element runs and fits cover 0 < delta* <= 110; beyond it the area
  // law, extrapolated, outgrows the fully plastic 2 pi R delta and the mean pressure falls far
  // below the hardness, so the model switches to the fully plastic limit there.
  static LawRange range(const double*) { return {110.0, 0.5, true, "continuous switch to the fully plastic limit"}; }
  static void breakpoints(const double* c, std::vector<double>& out) {
    out.insert(out.end(), {c[Index::elastic_limit], fitted::continuous_plastic_onset});
  }
  template <class T>
  static T yield_peak_pressure(const ContactPair& p, const T*) {
    return T(jackson_green_yield_factor(p.poisson_ratio) * p.yield_strength);
  }
  template <class T>
  static Star<T> star(const T& d, const T* c, const ContactPair& p) {
    using std::exp, std::pow, std::sqrt;
    using I = Index;
    if (d <= c[I::elastic_limit]) return {pow(d, 1.5), d, published_surface_yield_share(d)};
    const double cy = jackson_green_yield_factor(p.poisson_ratio);
    const double sqrt_dc_over_r = std::numbers::pi * cy * p.yield_strength / (2.0 * p.modulus);
    const T b = c[I::area_coefficient] * exp(c[I::area_slope] * (p.yield_strength / p.youngs_modulus));
    const T area = d * pow(d / c[I::elastic_limit], b);
    const T a_over_r = sqrt(area) * sqrt_dc_over_r;  // a/R = sqrt(A*/pi * pi delta_c / R) / 1
    const T hg =
        c[I::hardness_limit] * (1.0 - exp(-c[I::hardness_coefficient] * pow(a_over_r, -c[I::hardness_exponent])));
    const T load =
        exp(-0.25 * pow(d, 5.0 / 12.0)) * pow(d, 1.5) + 4.0 * hg / cy * (1.0 - exp(-pow(d, 5.0 / 9.0) / 25.0)) * d;
    return {load, area, published_surface_yield_share(d)};
  }
};

// ---------------------------------------------------------------------------------------------
// Zhao, Maietta & Chang (2000): Hertz until the Hertz mean pressure reaches K H
// (delta_1 = (3 pi K H/(4 E_t))^2 R), fully plastic beyond delta_2 = 54 delta_1, and between
//   A = pi R delta [1 - 2 x^3 + 3 x^2],  x = (delta - delta_1)/(delta_2 - delta_1)
//   p_m = H [1 - (1 - K) ln(delta_2/delta) / ln(delta_2/delta_1)].
struct ZmcLaw {
  static constexpr std::string_view name = "zmc";
  static constexpr std::string_view citation = "Zhao, Maietta & Chang, J. Tribol. 122 (2000) 86";
  static constexpr std::array<ConstantSpec, 2> constants{{
      {"mean_pressure_factor", 0.6, 0.1, 1.0, "K: Hertz mean pressure K H at first yield"},
      {"fully_plastic", 54.0, 2.0, 1000.0, "delta_2/delta_1, onset of fully plastic flow"},
  }};
  struct Index {
    static constexpr std::size_t mean_pressure_factor = constant_index(constants, "mean_pressure_factor"),
                                 fully_plastic = constant_index(constants, "fully_plastic");
  };
  // Defined at every interference: fully plastic (p = H, A = 2 pi R delta) from delta_2 on.
  static LawRange range(const double*) {
    return {std::numeric_limits<double>::infinity(), 0.5, false,
            "defined at every interference (fully plastic from delta_2)"};
  }
  static void breakpoints(const double* c, std::vector<double>& out) {
    out.insert(out.end(), {1.0, c[Index::fully_plastic], fitted::continuous_plastic_onset});
  }
  template <class T>
  static T yield_peak_pressure(const ContactPair& p, const T* c) {
    return 1.5 * c[Index::mean_pressure_factor] * p.hardness;
  }
  template <class T>
  static Star<T> star(const T& d, const T* c, const ContactPair&) {
    using std::log, std::pow;
    if (d <= 1.0) return {pow(d, 1.5), d, T(0.0)};
    const T& k = c[Index::mean_pressure_factor];
    const T& d2 = c[Index::fully_plastic];  // delta_2/delta_1
    const T share = published_surface_yield_share(d);
    if (d >= d2) return {2.0 * d / k, 2.0 * d, share};  // F_c = K H A_c
    const T x = (d - 1.0) / (d2 - 1.0);
    const T area = d * (1.0 + 3.0 * x * x - 2.0 * x * x * x);
    const T pm_over_h = 1.0 - (1.0 - k) * log(d2 / d) / log(d2);
    return {area * pm_over_h / k, area, share};
  }
};

// ---------------------------------------------------------------------------------------------
// The seed's continuous elastic-plastic model (section 2), re-derived (ERRATA): a plastic core
// r < r_p at a uniform pressure sigma_rp and an elastic annulus carrying the Hertz-type pressure
// p_e sqrt(1 - r^2/r_a^2), continuous at r_p as the seed states (p_e sqrt(1 - phi) = sigma_rp).
// The closure the seed omits (x = delta* - 1 > 0):
//   r_a^2 = R delta g,  g = 1 + x^na/(da^na + x^na)                         (1 -> 2)
//   p_m/H = m = 2k/3 + (1 - 2k/3) x^ns/(ds^ns + x^ns)                         (Hertz 2kH/3 -> H)
//   (r_p/r_a)^2 = phi = surface_yield_share(delta*, d0, dp, np)             (0 -> 1)
// so F* = 3 A* m/(2 k), A* = delta* g: Hertz at delta* = 1 and 2 pi R delta H when g = 2, m = 1;
// and sigma_rp = 3 p_m/(2 + phi) (two_zone_profile). phi is the yielded share of the contact area
// at the surface. (The seed's printed annulus amplitude p_e = 2 E_t r_a/(pi R) cannot be
// continuous at r_p with a core that matches the surface yield: docs/theory/departures-from-the-thesis.md.)
// Defaults: validation/fem-reference/refit-continuous.sh writes continuous_defaults.hpp (one
// source): phi fitted to the project's CalculiX surface-yield share, g and m to the Kogut-Etsion
// 2002 and Jackson-Green 2005 FEM-based load and area.
struct ContinuousLaw {
  static constexpr std::string_view name = "continuous";
  static constexpr std::string_view citation =
      "the thesis's continuous model (its section 2), closure re-derived (docs/theory/departures-from-the-thesis.md); area and load fitted to KE 2002 / JG 2005, plastic core to the project's CalculiX surface yield";
  static constexpr std::array<ConstantSpec, 7> constants{{
      {"area_scale", fitted::continuous_area_scale, 0.1, 1e4,
       "da: delta* - 1 at which r_a^2 is halfway from R delta to 2 R delta"},
      {"area_exponent", fitted::continuous_area_exponent, 0.2, 5.0, "na: steepness of the contact-radius growth"},
      {"plastic_onset", fitted::continuous_plastic_onset, 1.0, 100.0, "d0: delta* at which the surface first yields"},
      {"plastic_scale", fitted::continuous_plastic_scale, 0.01, 1e4,
       "dp: delta* - d0 at which half the contact area has yielded at the surface"},
      {"plastic_exponent", fitted::continuous_plastic_exponent, 0.2, 20.0, "np: steepness of the surface-yield growth"},
      {"pressure_scale", fitted::continuous_pressure_scale, 0.01, 1e4,
       "ds: delta* - 1 at which the mean pressure is halfway from 2 k H/3 to H"},
      {"pressure_exponent", fitted::continuous_pressure_exponent, 0.2, 5.0,
       "ns: steepness of the mean-pressure growth"},
  }};
  struct Index {
    static constexpr std::size_t area_scale = constant_index(constants, "area_scale"),
                                 area_exponent = constant_index(constants, "area_exponent"),
                                 plastic_onset = constant_index(constants, "plastic_onset"),
                                 plastic_scale = constant_index(constants, "plastic_scale"),
                                 plastic_exponent = constant_index(constants, "plastic_exponent"),
                                 pressure_scale = constant_index(constants, "pressure_scale"),
                                 pressure_exponent = constant_index(constants, "pressure_exponent");
  };
  // Fitted to the KE/JG curves up to delta* = 110 (and KE's fully plastic branch beyond); the
  // closure reaches the fully plastic limit by itself (g -> 2, m -> 1, phi -> 1), so no switch.
  static LawRange range(const double*) {
    return {110.0, 0.5, false, "flagged only: the closure reaches the fully plastic limit itself"};
  }
  static void breakpoints(const double* c, std::vector<double>& out) {
    out.insert(out.end(), {1.0, c[Index::plastic_onset]});
  }
  template <class T>
  static T yield_peak_pressure(const ContactPair& p, const T*) {
    return T(ceb_pressure_factor(p.poisson_ratio) * p.hardness);
  }
  template <class T>
  struct Closure {
    T area_factor;       // g = r_a^2 / (R delta)
    T plastic_fraction;  // phi = (r_p/r_a)^2, the yielded share at the surface
    T mean_pressure;     // m = p_m / H
  };
  // x^n/(c^n + x^n) in the form 1/(1 + (c/x)^n), stable for large x.
  template <class T>
  static T rise(const T& x, const T& scale, const T& exponent) {
    using std::pow;
    return 1.0 / (1.0 + pow(scale / x, exponent));
  }
  template <class T>
  static Closure<T> closure(const T& d, const T* c, double k) {
    const T x = d - 1.0;                 // > 0: callers handle d <= 1 as Hertz
    const double hertz = 2.0 * k / 3.0;  // Hertz mean pressure at first yield over H
    using I = Index;
    return {1.0 + rise(x, c[I::area_scale], c[I::area_exponent]),
            surface_yield_share(d, c[I::plastic_onset], c[I::plastic_scale], c[I::plastic_exponent]),
            hertz + (1.0 - hertz) * rise(x, c[I::pressure_scale], c[I::pressure_exponent])};
  }
  template <class T>
  static Star<T> star(const T& d, const T* c, const ContactPair& p) {
    using std::pow;
    if (d <= 1.0) return {pow(d, 1.5), d, T(0.0)};
    const double k = ceb_pressure_factor(p.poisson_ratio);
    const Closure<T> cl = closure(d, c, k);
    const T area = d * cl.area_factor;
    return {1.5 * area * cl.mean_pressure / k, area, cl.plastic_fraction};
  }
};

// ---------------------------------------------------------------------------------------------
// The one list of laws: the model registry (models.cpp) and the fitting (src/fit/) both visit it.
using LawList = std::tuple<HertzLaw, CebLaw, KogutEtsionLaw, JacksonGreenLaw, ZmcLaw, ContinuousLaw>;

template <class Law>
struct LawTag {
  using type = Law;
};

// Calls f(LawTag<Law>{}) for the law named `name`; throws std::invalid_argument (listing the
// known names) for an unknown one.
template <class F>
auto visit_law(std::string_view name, F&& f) {
  using Result = decltype(f(LawTag<HertzLaw>{}));
  std::optional<std::conditional_t<std::is_void_v<Result>, int, Result>> out;
  bool found = false;
  std::string known;
  auto visit_one = [&]<class Law>(LawTag<Law>) {
    known += (known.empty() ? "" : ", ") + std::string(Law::name);
    if (found || Law::name != name) return;
    found = true;
    if constexpr (std::is_void_v<Result>) f(LawTag<Law>{});
    else out.emplace(f(LawTag<Law>{}));
  };
  // In LawList's order. (Not std::apply over a fold of lambdas: clang 14, and so clang-tidy, crashes on it.)
  [&]<class... Laws>(std::tuple<Laws...>*) { (visit_one(LawTag<Laws>{}), ...); }(static_cast<LawList*>(nullptr));
  if (!found) throw std::invalid_argument("unknown asperity model '" + std::string(name) + "' (known: " + known + ")");
  if constexpr (!std::is_void_v<Result>) return std::move(*out);
}

}  // namespace geartrib::asperity
