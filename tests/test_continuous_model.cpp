// The seed's continuous elastic-plastic model (section 2), re-derived per ERRATA.
#include "asperity/model.hpp"
#include "asperity/pressure_profile.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace geartrib;
using namespace geartrib::asperity;

namespace {
constexpr double kPi = std::numbers::pi;
}

TEST(ContinuousModel, ElasticAnnulusShareIsHertzAtZeroCore) {
  // ERRATA: F_Te = int_{r_p}^{r_a} p(r) 2 pi r dr with p = p_e sqrt(1 - r^2/r_a^2),
  // p_e = 2 E_t r_a/(pi R), equals 4 E_t (r_a^2 - r_p^2)^(3/2)/(3 R), and at r_p = 0 the Hertz
  // load 4 E_t r_a^3/(3 R). Checked through the profile's load (core pressure 0).
  const ContactPair p = test::seed_pair();
  const double ra = 10e-9;
  const double pe = hertz_peak_pressure(ra, p.radius, p.modulus);
  for (double rp : {0.0, 3e-9, 7e-9, 9.99e-9}) {
    const PressureProfile prof{ra, rp, 0.0, pe};
    const double expected = 4.0 * p.modulus * std::pow(ra * ra - rp * rp, 1.5) / (3.0 * p.radius);
    EXPECT_NEAR(prof.load() / expected, 1.0, 1e-12) << rp;
  }
  const PressureProfile hertz{ra, 0.0, 0.0, pe};
  EXPECT_NEAR(hertz.load() / hertz_load(ra * ra / p.radius, p.radius, p.modulus), 1.0, 1e-12);
}

TEST(ContinuousModel, PressureContinuousAtThePlasticCore) {
  // The seed's claim, kept: the core pressure sigma_rp equals the annulus pressure at r_p, and
  // the law's load (F* = 3 A* m/(2 k)) is the integral of that profile.
  const auto m = make_asperity_model("continuous");
  const ContactPair p = test::seed_pair();
  const double k = ceb_pressure_factor(p.poisson_ratio);
  for (double d : {1.5, 3.0, 6.0, 20.0, 300.0, 1e5}) {
    const AsperityState s = m->evaluate(p, d * m->critical(p).interference, Detail::profile);
    const PressureProfile prof = m->profile(s.plastic_fraction, s.load, s.area);
    const auto cl = ContinuousLaw::closure(d, m->constants().data(), k);
    EXPECT_NEAR(prof.load() / s.load, 1.0, 1e-10) << d;
    EXPECT_NEAR(s.mean_pressure / (cl.mean_pressure * p.hardness), 1.0, 1e-10) << d;
    if (cl.plastic_fraction > 0.0) {  // sigma_rp = 3 p_m/(2 + phi)
      EXPECT_NEAR(prof.core_pressure / (3.0 * s.mean_pressure / (2.0 + cl.plastic_fraction)), 1.0, 1e-10) << d;
    }
    const double rho = prof.core_radius / prof.contact_radius;
    if (rho > 0.0 && rho < 1.0) {
      EXPECT_NEAR(prof.annulus_peak * std::sqrt(1.0 - rho * rho) / prof.core_pressure, 1.0, 1e-10) << d;
    }
  }
}

TEST(ContinuousModel, HertzBelowFirstYield) {
  const auto m = make_asperity_model("continuous");
  const ContactPair p = test::seed_pair();
  for (double d : {1e-9, 1e-3, 0.5, 1.0}) {
    const Star<double> s = m->star(d, p);
    EXPECT_DOUBLE_EQ(s.load, std::pow(d, 1.5));
    EXPECT_DOUBLE_EQ(s.area, d);
  }
}

TEST(ContinuousModel, ContinuousAtBreakpoints) {
  // Relative jump below 1e-6 across delta* = 1 and the surface-yield onset (its breakpoints) and
  // 6 (the Kogut-Etsion one the model must not reproduce), probing +-1e-10: the smooth slope
  // contributes ~1e-10.
  const auto m = make_asperity_model("continuous");
  const ContactPair p = test::seed_pair();
  const double dc = m->critical(p).interference;
  const double onset = m->constant("plastic_onset");
  for (double d : {1.0, onset, 6.0}) {
    const AsperityState lo = m->evaluate(p, (d - 1e-10) * dc, Detail::load_area);
    const AsperityState hi = m->evaluate(p, (d + 1e-10) * dc, Detail::load_area);
    EXPECT_LT(std::abs(hi.load / lo.load - 1.0), 1e-6) << d;
    EXPECT_LT(std::abs(hi.area / lo.area - 1.0), 1e-6) << d;
    EXPECT_LT(std::abs(hi.mean_pressure / lo.mean_pressure - 1.0), 1e-6) << d;
  }
}

TEST(ContinuousModel, TendsToFullyPlastic) {
  // F -> 2 pi R delta H and A -> 2 pi R delta, approached from below.
  const auto m = make_asperity_model("continuous");
  const ContactPair p = test::seed_pair();
  const double dc = m->critical(p).interference;
  double prev = 0.0;
  for (double d : {1e2, 1e3, 1e4, 1e5, 1e6}) {
    const AsperityState s = m->evaluate(p, d * dc, Detail::load_area);
    const double fp_load = 2.0 * kPi * p.radius * s.delta * p.hardness;
    const double ratio = s.load / fp_load;
    EXPECT_LT(ratio, 1.0);
    EXPECT_GT(ratio, prev) << d;
    prev = ratio;
  }
  EXPECT_GT(prev, 0.9999);  // within 1e-4 of fully plastic at delta* = 1e6
  const AsperityState s = m->evaluate(p, 1e6 * dc);
  EXPECT_NEAR(s.area / (2.0 * kPi * p.radius * s.delta), 1.0, 1e-4);
  EXPECT_NEAR(s.plastic_fraction, 1.0, 1e-6);
  EXPECT_NEAR(s.max_pressure / p.hardness, 1.0, 1e-4);
}

TEST(ContinuousModel, WithinTenPercentOfKogutEtsionAndJacksonGreen) {
  // Seed section 2: "for delta* < 40 all three models agree well". Load and area compared at
  // the same physical interference (JG's delta_c differs by 0.08%), 1 <= delta* <= 40. The
  // largest gap, 7.5% in area just above delta* = 1, is Kogut-Etsion's own 7% area jump there.
  const auto cont = make_asperity_model("continuous");
  const auto ke = make_asperity_model("kogut-etsion");
  const auto jg = make_asperity_model("jackson-green");
  const ContactPair p = test::seed_pair();
  const double dc = cont->critical(p).interference;
  for (double d : test::log_space(1.0, 40.0, 400)) {
    const AsperityState c = cont->evaluate(p, d * dc, Detail::load_area);
    for (const auto* other : {ke.get(), jg.get()}) {
      const AsperityState o = other->evaluate(p, d * dc, Detail::load_area);
      EXPECT_LT(std::abs(c.load / o.load - 1.0), 0.10) << other->name() << " load at " << d;
      EXPECT_LT(std::abs(c.area / o.area - 1.0), 0.10) << other->name() << " area at " << d;
    }
  }
}

TEST(ContinuousModel, PeakPressureNeverExceedsHardness) {
  // An elastic-perfectly plastic contact cannot carry more than about H anywhere; with the
  // default closure the profile's peak stays at or below H over the whole range.
  const auto m = make_asperity_model("continuous");
  const ContactPair p = test::seed_pair();
  const double dc = m->critical(p).interference;
  for (double d : test::log_space(1e-3, 1e6, 600)) {
    const AsperityState s = m->evaluate(p, d * dc, Detail::profile);
    const PressureProfile prof = m->profile(s.plastic_fraction, s.load, s.area);
    EXPECT_LE(prof.max_pressure(), p.hardness * (1.0 + 1e-12)) << d;
  }
}

TEST(ContinuousModel, ConstantsChangeTheCurve) {
  auto m = make_asperity_model("continuous");
  const ContactPair p = test::seed_pair();
  const double before = m->star(10.0, p).load;
  m->set_constant("pressure_scale", 30.0);  // a later rise of the mean pressure: less load
  EXPECT_LT(m->star(10.0, p).load, before);
  m->set_constant("plastic_scale", 30.0);  // a later plastic core: less yielded surface, same load
  EXPECT_LT(m->star(10.0, p).plastic, 0.5);
  EXPECT_THROW(m->set_constant("plastic_exponent", 0.1), std::invalid_argument);  // outside [0.2, 20]
  EXPECT_THROW(m->set_constant("plastic_onset", 0.5),
               std::invalid_argument);  // the surface cannot yield before delta_c
}
