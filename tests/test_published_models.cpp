// CEB, Kogut-Etsion, Jackson-Green and ZMC against their published equations. The expected
// values were evaluated from the papers' formulas outside this code (Python, double precision,
// nu = 0.3, S_y = 418 MPa, E = 206 GPa, E_t = 113.19 GPa); agreement to 1e-9 relative is
// rounding only.
#include "asperity/model.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace geartrib;
using namespace geartrib::asperity;

namespace {
constexpr double kRel = 1e-9;
struct Expected {
  double delta_star, load_star, area_star;
};
void expect_star(const AsperityModel& m, const Expected& e) {
  const Star<double> s = m.star(e.delta_star, test::seed_pair());
  EXPECT_NEAR(s.load / e.load_star, 1.0, kRel) << m.name() << " F* at " << e.delta_star;
  EXPECT_NEAR(s.area / e.area_star, 1.0, kRel) << m.name() << " A* at " << e.delta_star;
}
}  // namespace

TEST(PublishedModels, KogutEtsion2002) {
  // F* = 1.03 d^1.425, A* = 0.93 d^1.136 (1..6); F* = 1.40 d^1.263, A* = 0.94 d^1.146 (6..110).
  const auto m = make_asperity_model("kogut-etsion");
  for (const Expected& e : {Expected{2, 2.765699356, 2.043868845}, Expected{6, 13.23435428, 7.119717618},
                            Expected{10, 25.65240191, 13.15612083}, Expected{50, 195.8516123, 83.2046271},
                            Expected{100, 470.0326599, 184.1313993}})
    expect_star(*m, e);
  // Published: fully plastic beyond 110, F = 2 pi R delta H, A = 2 pi R delta (the law itself).
  const ContactPair p = test::seed_pair();
  const Star<double> fp = m->law_star(200.0, p);
  EXPECT_NEAR(fp.load / (3.0 * 200.0 / ceb_pressure_factor(p.poisson_ratio)), 1.0, 1e-12);
  EXPECT_NEAR(fp.area / 400.0, 1.0, 1e-12);
  // The model replaces the published jump at 110 by the continuous switch (SwitchToFullyPlastic):
  // at 200 it lies between the 6-110 branch's value at 110 scaled and the limit,
  // X_fp (X_law(110)/X_fp(110))^(110/200), e.g. area 400 (205.38/220)^0.55.
  const Star<double> s = m->star(200.0, p);
  EXPECT_NEAR(s.area / (400.0 * std::pow(0.94 * std::pow(110.0, 1.146) / 220.0, 0.55)), 1.0, 1e-12);
}

TEST(PublishedModels, JacksonGreen2005) {
  // C = 1.295 exp(0.736 nu) = 1.614961, B = 0.14 exp(23 S_y/E) = 0.1466887.
  const auto m = make_asperity_model("jackson-green");
  for (const Expected& e : {Expected{2, 2.829126882, 2.015105043}, Expected{6, 13.00236894, 7.10243419},
                            Expected{10, 25.88399612, 12.75847191}, Expected{50, 201.9230714, 80.77921599},
                            Expected{100, 457.414992, 178.8493284}})
    expect_star(*m, e);
  // Its own critical interference: delta_c = (pi C S_y/(2 E_t))^2 R.
  const ContactPair p = test::seed_pair();
  const double s = std::numbers::pi * 1.614960818 * 418e6 / (2.0 * p.modulus);
  EXPECT_NEAR(m->critical(p).interference / (s * s * p.radius), 1.0, 1e-9);
}

TEST(PublishedModels, ChangEtsionBogy1987) {
  // Above delta_c: A = pi R delta (2 - delta_c/delta), F = k H A (volume conservation).
  const auto m = make_asperity_model("ceb");
  const ContactPair p = test::seed_pair();
  const double dc = m->critical(p).interference, k = 0.454 + 0.41 * 0.3;
  for (double d : {1.5, 3.0, 50.0}) {
    const AsperityState s = m->evaluate(p, d * dc, Detail::load_area);
    const double area = std::numbers::pi * p.radius * s.delta * (2.0 - 1.0 / d);
    EXPECT_NEAR(s.area / area, 1.0, 1e-12) << d;
    EXPECT_NEAR(s.load / (k * p.hardness * area), 1.0, 1e-12) << d;
  }
}

TEST(PublishedModels, ZhaoMaiettaChang2000) {
  // K = 0.6, delta_2 = 54 delta_1; values from A = pi R delta (1 - 2x^3 + 3x^2) and
  // p_m = H [1 - (1 - K) ln(54/d)/ln 54], F* = F/(K H A_c).
  const auto m = make_asperity_model("zmc");
  for (const Expected& e :
       {Expected{2, 2.2340405758624207, 2.002109123638977}, Expected{10, 14.910598333960312, 10.767143346520953},
        Expected{30, 73.89876736048001, 47.11634436481122}})
    expect_star(*m, e);
  // Its own delta_1 = (3 pi K H/(4 E_t))^2 R, where the Hertz mean pressure is K H.
  const ContactPair p = test::seed_pair();
  const double s = 3.0 * std::numbers::pi * 0.6 * p.hardness / (4.0 * p.modulus);
  EXPECT_NEAR(m->critical(p).interference / (s * s * p.radius), 1.0, 1e-12);
  // Continuous at delta_1 and delta_2 by construction: mean pressure K H at delta_1, H at delta_2.
  const double d1 = m->critical(p).interference;
  EXPECT_NEAR(m->evaluate(p, d1, Detail::load_area).mean_pressure / (0.6 * p.hardness), 1.0, 1e-12);
  EXPECT_NEAR(m->evaluate(p, 54.0 * d1, Detail::load_area).mean_pressure / p.hardness, 1.0, 1e-12);
}

TEST(PublishedModels, HertzIsHertz) {
  const auto m = make_asperity_model("hertz");
  const ContactPair p = test::seed_pair();
  const double delta = 3e-10;
  const AsperityState s = m->evaluate(p, delta);
  EXPECT_NEAR(s.load / (4.0 / 3.0 * p.modulus * std::sqrt(p.radius) * std::pow(delta, 1.5)), 1.0, 1e-12);
  EXPECT_NEAR(s.contact_radius / std::sqrt(p.radius * delta), 1.0, 1e-12);
  EXPECT_NEAR(s.max_pressure / (2.0 * p.modulus * s.contact_radius / (std::numbers::pi * p.radius)), 1.0, 1e-12);
  EXPECT_EQ(s.plastic_fraction, 0.0);
}

TEST(Registry, NamesFactoryAndConstants) {
  for (auto name : asperity_model_names()) EXPECT_EQ(make_asperity_model(name)->name(), name);
  EXPECT_THROW(make_asperity_model("greenwood"), std::invalid_argument);
  auto m = make_asperity_model("kogut-etsion");
  EXPECT_DOUBLE_EQ(m->constant("fully_plastic"), 110.0);
  m->set_constant("fully_plastic", 120.0);
  EXPECT_DOUBLE_EQ(m->constant("fully_plastic"), 120.0);
  EXPECT_THROW(m->set_constant("fully_plastic", -1.0), std::invalid_argument);
  EXPECT_THROW(m->set_constant("no_such", 1.0), std::invalid_argument);
}
