// The lubricated mesh cycle: lubricant properties, film formulas and corrections, the regime map,
// mixed-lubrication load sharing, friction, flash temperature, ISO/TS 6336-22 film and wear,
// against hand values, identities and the limits the physics must reach.
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "gear/gear_mesh.hpp"
#include "io/units.hpp"
#include "lubrication/ehl_film.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/lubricant.hpp"
#include "lubrication/mixed_lubrication.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geartrib {
namespace {

using namespace lubrication;
constexpr double kC = 273.15;

Lubricant vg220() { return io::load_lubricant(test::source_dir() / "lubricants/mineral-vg220.toml"); }

TEST(Lubricant, WaltherPassesThroughItsTwoPoints) {
  const Lubricant l = vg220();
  // The fit's definition: exact at 40 and 100 degC to rounding (1e-12 relative: two log10 round trips).
  EXPECT_NEAR(kinematic_viscosity(l, kC + 40.0) / l.kinematic_viscosity_40, 1.0, 1e-12);
  EXPECT_NEAR(kinematic_viscosity(l, kC + 100.0) / l.kinematic_viscosity_100, 1.0, 1e-12);
  // Viscosity falls with temperature everywhere in the data range.
  double last = INFINITY;
  for (double t = l.min_temperature; t <= l.max_temperature; t += 5.0) {
    const double nu = kinematic_viscosity(l, t);
    EXPECT_LT(nu, last);
    last = nu;
  }
}

TEST(Lubricant, TemperatureViscosityCoefficientIsTheLogDerivative) {
  const Lubricant l = vg220();
  for (double t : {kC + 40.0, kC + 70.0, kC + 110.0}) {
    const double h = 1e-3;  // central difference: truncation ~ h^2 beta''' ~ 1e-9 relative
    const double numeric =
        -(std::log(oil_state(l, t + h).dynamic_viscosity) - std::log(oil_state(l, t - h).dynamic_viscosity)) /
        (2.0 * h);
    EXPECT_NEAR(oil_state(l, t).temperature_viscosity / numeric, 1.0, 1e-6);
  }
}

TEST(Lubricant, DensityIsLinearThroughFifteenDegrees) {
  const Lubricant l = vg220();
  EXPECT_DOUBLE_EQ(density(l, kC + 15.0), l.density_15);
  EXPECT_NEAR(density(l, kC + 115.0), l.density_15 * (1.0 - 100.0 * l.density_temperature_coefficient), 1e-9);
}

TEST(Lubricant, PressureViscosityFollowsTheIsoTemperatureLaw) {
  Lubricant l = vg220();
  // Correlation: alpha(T)/alpha(T') = (1 + 516 (1/T - 1/311))/(1 + 516 (1/T' - 1/311)) (ISO/TR 15144-1).
  const double t1 = kC + 60.0, t2 = kC + 90.0;
  const double expected = (1.0 + 516.0 * (1.0 / t1 - 1.0 / 311.0)) / (1.0 + 516.0 * (1.0 / t2 - 1.0 / 311.0));
  EXPECT_NEAR(pressure_viscosity_coefficient(l, t1) / pressure_viscosity_coefficient(l, t2), expected, 1e-12);
  // At 311 K the temperature factor is 1 and alpha is 2.657e-8 eta_38^0.1348, eta at 38 degC in Pa s
  // (1e-20 1/Pa: rounding of a 2e-8 value).
  const double eta38 = kinematic_viscosity(l, kC + 38.0) * density(l, kC + 38.0);
  EXPECT_NEAR(pressure_viscosity_coefficient(l, 311.0), 2.657e-8 * std::pow(eta38, 0.1348), 1e-20);
  // A measured alpha is returned at its own temperature.
  l.pressure_viscosity = 2.1e-8;
  l.pressure_viscosity_temperature = kC + 40.0;
  EXPECT_DOUBLE_EQ(pressure_viscosity_coefficient(l, kC + 40.0), 2.1e-8);
  // The correlation gives mineral oils' measured order at 40 degC: 1.5e-8 to 3e-8 1/Pa (e.g. FVA 3
  // 2.24e-8, lubricants/fva3.toml).
  const double alpha40 = pressure_viscosity_coefficient(vg220(), kC + 40.0);
  EXPECT_GT(alpha40, 1.5e-8);
  EXPECT_LT(alpha40, 3e-8);
}

TEST(Units, TemperatureAndViscosityUnitsConvertOnce) {
  EXPECT_DOUBLE_EQ(io::parse_quantity("70 degC", io::Dimension::temperature), 343.15);
  EXPECT_DOUBLE_EQ(io::parse_quantity("343.15 K", io::Dimension::temperature), 343.15);
  EXPECT_DOUBLE_EQ(io::parse_quantity("40 mPa s", io::Dimension::dynamic_viscosity), 0.04);
  EXPECT_DOUBLE_EQ(io::parse_quantity("220 cSt", io::Dimension::kinematic_viscosity), 220e-6);
  EXPECT_DOUBLE_EQ(io::parse_quantity("20 1/GPa", io::Dimension::inverse_pressure), 20e-9);
  EXPECT_THROW(io::parse_quantity("70 degC", io::Dimension::pressure), std::invalid_argument);
}

// Hand values of the four formulas at U = 1e-11, G = 5000, W = 1e-4 (Python, double precision).
TEST(EhlFilm, FormulasGiveTheirPublishedExpressions) {
  const EhlGroups g{1e-11, 5000.0, 1e-4};
  const std::pair<FilmFormula, double> cases[] = {{FilmFormula::dowson_higginson, 1.740562715463822e-05},
                                                  {FilmFormula::pan_hamrock_min, 1.633148889974558e-05},
                                                  {FilmFormula::pan_hamrock_central, 1.803832110437179e-05},
                                                  {FilmFormula::dowson_toyoda, 2.3288666885907575e-05}};
  for (const auto& [f, h] : cases) EXPECT_NEAR(smooth_film(f, g, 1.0) / h, 1.0, 1e-13) << film_law(f).name;
  // Central films exceed minimum films of the same authors (Pan & Hamrock: by ~10% here).
  EXPECT_GT(smooth_film(FilmFormula::pan_hamrock_central, g, 1.0), smooth_film(FilmFormula::pan_hamrock_min, g, 1.0));
  // No entrainment, no film.
  EXPECT_EQ(smooth_film(FilmFormula::dowson_higginson, {0.0, 5000.0, 1e-4}, 1.0), 0.0);
}

TEST(EhlFilm, GroupsUseTheReducedModulus) {
  // U = eta u/(E'R), G = alpha E', W = w/(E'R): E' = 2 E* (226.4 GPa for the seed's steels).
  const EhlGroups g = ehl_groups(0.04, 2e-8, 3.0, 1.5e5, 7.7e-3, 226.4e9);
  EXPECT_DOUBLE_EQ(g.speed, 0.04 * 3.0 / (226.4e9 * 7.7e-3));
  EXPECT_DOUBLE_EQ(g.material, 2e-8 * 226.4e9);
  EXPECT_DOUBLE_EQ(g.load, 1.5e5 / (226.4e9 * 7.7e-3));
}

TEST(EhlFilm, InletHeatingReachesIsothermalAndFalls) {
  for (auto m : {InletHeating::gupta, InletHeating::murch_wilson})
    EXPECT_DOUBLE_EQ(inlet_heating_factor(m, 0.0, 0.5, 1e-3), 1.0);  // no thermal loading: isothermal
  EXPECT_DOUBLE_EQ(inlet_heating_factor(InletHeating::none, 10.0, 0.5, 1e-3), 1.0);
  double last = 1.0;
  for (double l : {0.1, 1.0, 10.0, 100.0}) {
    const double phi = inlet_heating_factor(InletHeating::gupta, l, 0.5, 1e-3);
    EXPECT_LT(phi, last);
    last = phi;
  }
  // Gupta: sliding lowers the factor; Murch-Wilson at L = 1: 3.94/4.94.
  EXPECT_LT(inlet_heating_factor(InletHeating::gupta, 5.0, 1.0, 1e-3),
            inlet_heating_factor(InletHeating::gupta, 5.0, 0.0, 1e-3));
  EXPECT_DOUBLE_EQ(inlet_heating_factor(InletHeating::murch_wilson, 1.0, 0.0, 0.0), 3.94 / 4.94);
  EXPECT_DOUBLE_EQ(inlet_heating_factor(InletHeating::gupta, 1e6, 1.0, 1e-2), kMinInletHeatingFactor);
}

TEST(EhlRegime, MapCornersAndAGearContact) {
  // Gear contact (U 4.6e-11, G 4520, W 8.5e-5): elastic-piezoviscous.
  EXPECT_EQ(ehl_regime({4.6e-11, 4520.0, 8.5e-5}), EhlRegime::elastic_piezoviscous);
  // Light load, soft fluid, fast: rigid-isoviscous (g_V, g_E small).
  EXPECT_EQ(ehl_regime({1e-6, 1.0, 1e-6}), EhlRegime::rigid_isoviscous);
  // No pressure-viscosity, elastic: elastic-isoviscous (soft EHL, rubber).
  EXPECT_EQ(ehl_regime({1e-10, 1e-6, 1e-3}), EhlRegime::elastic_isoviscous);
  // Piezoviscous, stiff and lightly loaded: rigid-piezoviscous.
  EXPECT_EQ(ehl_regime({1e-10, 5000.0, 1e-5}), EhlRegime::rigid_piezoviscous);  // g_V 15.8, g_E 1
}

// A stand-in for the asperity side: separation falls linearly from 3 um (no load) to 0.5 um (all).
double linear_separation(double share) { return 3e-6 - 2.5e-6 * share; }

TEST(MixedLubrication, ShareSolvesTheScaledFilmEquation) {
  const double e = 0.16, h = 1e-6;
  const LoadShare s = share_load(h, e, linear_separation);
  ASSERT_GT(s.asperity_share, 0.0);
  ASSERT_LT(s.asperity_share, 1.0);
  EXPECT_NEAR(s.asperity_share + s.film_share, 1.0, 1e-15);
  // h_film = h_smooth gamma1^e with gamma1 = 1/film_share, equal to the asperities' separation.
  EXPECT_NEAR(s.film_thickness / (h * std::pow(1.0 / s.film_share, e)), 1.0, 1e-12);
  EXPECT_NEAR(s.film_thickness / linear_separation(s.asperity_share), 1.0, 1e-10);
}

TEST(MixedLubrication, LimitsThickFilmAndNoFilm) {
  // A smooth film above the highest summits: the film carries all.
  const LoadShare thick = share_load(4e-6, 0.16, linear_separation);
  EXPECT_EQ(thick.asperity_share, 0.0);
  EXPECT_EQ(thick.film_thickness, 4e-6);
  // No film (no speed or no viscosity): exactly the dry contact.
  const LoadShare dry = share_load(0.0, 0.16, linear_separation);
  EXPECT_EQ(dry.asperity_share, 1.0);
  EXPECT_EQ(dry.film_thickness, linear_separation(1.0));
  // In between, the asperities' share falls monotonically as the smooth film grows.
  double last = 1.0;
  for (double h : test::log_space(1e-12, 2.9e-6, 40)) {
    const double a = share_load(h, 0.16, linear_separation).asperity_share;
    EXPECT_LE(a, last) << h;
    last = a;
  }
}

TEST(Friction, EyringCappedByTheLimitingShearStress) {
  OilState oil;
  oil.dynamic_viscosity = 0.04;
  oil.pressure_viscosity = 2e-8;
  oil.eyring_stress = 5e6;
  oil.limiting_shear_coefficient = 0.075;
  EXPECT_EQ(film_shear_stress(oil, 1e9, 0.0, 1e-6), 0.0);  // pure rolling: no shear
  // Barely sheared: Newtonian, tau = eta v/h.
  const double slow = film_shear_stress(oil, 1e6, 1e-9, 1e-6);
  EXPECT_NEAR(slow / (0.04 * std::exp(2e-8 * 1e6) * 1e-9 / 1e-6), 1.0, 1e-9);
  // Hard sheared at high pressure: the limiting shear stress.
  EXPECT_DOUBLE_EQ(film_shear_stress(oil, 1e9, 5.0, 1e-7), 0.075 * 1e9);
  // The mixed coefficient weights boundary and film by their shares.
  const MixedFriction f = mixed_friction(oil, {0.3, 0.7, 1e-7}, 0.1, 1.5e5, 2e-4, 5.0);
  EXPECT_NEAR(f.coefficient, 0.3 * 0.1 + 0.7 * f.film_coefficient, 1e-15);
}

TEST(FlashTemperature, BlokIdentitiesAndZeroAtThePitchPoint) {
  const double b = thermal_contact_coefficient(48.0, 7850.0, 470.0);
  // Equal bodies: the ISO/TS 6336-20 form 1.11 mu w |sqrt v1 - sqrt v2| / (2 B sqrt b).
  const double iso = 1.11 * 0.05 * 1.5e5 * std::abs(std::sqrt(2.0) - std::sqrt(5.0)) / (2.0 * b * std::sqrt(2e-4));
  EXPECT_NEAR(blok_flash_temperature(0.05, 1.5e5, 2e-4, 2.0, 5.0, b, b) / iso, 1.0, 1e-14);
  EXPECT_EQ(blok_flash_temperature(0.05, 1.5e5, 2e-4, 3.0, 3.0, b, b), 0.0);  // pure rolling
  // Linear in mu and in w.
  EXPECT_NEAR(blok_flash_temperature(0.1, 1.5e5, 2e-4, 2.0, 5.0, b, b) / iso, 2.0, 1e-14);
}

TEST(IsoFilm, HyIsDowsonHiggins1966AtTheBulkTemperature) {
  // With no flash temperature (S_GF = 1) and W = 2 pi p^2/E'^2 = w/(E' R) for a Hertz line contact,
  // h_Y = 1.6 R G^0.6 U^0.7 W^-0.13 (Dowson & Higginson 1966).
  const double e = 226.4e9, rho = 7.7e-3, w = 1.5e5, u = 3.0;
  const double p_h = std::sqrt(w * e / (2.0 * std::numbers::pi * rho));
  OilState oil;
  oil.dynamic_viscosity = 0.04;
  oil.pressure_viscosity = 2e-8;
  const EhlGroups g = ehl_groups(0.04, 2e-8, u, w, rho, e);
  const double expected = 1.6 * rho * std::pow(g.material, 0.6) * std::pow(g.speed, 0.7) * std::pow(g.load, -0.13);
  EXPECT_NEAR(iso_film_hy(rho, e, p_h, 2.0 * u, oil, oil) / expected, 1.0, 1e-12);
}

TEST(IsoFriction, MeanCoefficientInTheStandardsUnits) {
  // mu_m = 0.045 (w/(v rho))^0.2 eta^-0.05 X_R X_L with X_R = 2.2 (Ra/rho)^0.25: w 200 N/mm,
  // v_Sigma 10 m/s, rho 10 mm, eta 40 mPa s, Ra 0.5 um, X_L 1 (hand evaluation in those units).
  const double x_r = 2.2 * std::pow(0.5 / 10.0, 0.25);
  const double expected = 0.045 * std::pow(200.0 / (10.0 * 10.0), 0.2) * std::pow(40.0, -0.05) * x_r;
  EXPECT_NEAR(iso_mean_friction(2e5, 10.0, 0.01, 0.04, 0.5e-6, 1.0) / expected, 1.0, 1e-13);
}

// The lubricated default case through the whole mesh cycle.
contact::MeshContactResult run(const Case& c) {
  const gear::GearMesh mesh(c);
  return contact::run_mesh_contact(c, mesh, nullptr, {}, 41);
}
Case with(const std::vector<io::CaseChange>& changes) {
  return io::load_case(test::source_dir() / "gears/m6z30.toml", changes);
}

TEST(LubricatedCycle, VanishingViscosityGivesTheDryResult) {
  // eta -> 0: the film's share vanishes (below double precision) and the asperities carry the Hertz
  // load exactly as in the dry scene.
  const auto lubricated =
      run(with({{"lubricant.dynamic_viscosity", "1e-30"}, {"lubricant.pressure_viscosity_coefficient", "2e-8"}}));
  const auto dry = run(test::seed_case());
  EXPECT_FALSE(dry.lubrication_summary.has_value());
  for (double a : lubricated.find("asperity_load_share")->values) EXPECT_EQ(a, 1.0);
  for (const char* q : {"real_area_ratio", "plastic_area_fraction", "max_asperity_von_mises_Pa"})
    EXPECT_EQ(lubricated.find(q)->values, dry.find(q)->values) << q;
}

TEST(LubricatedCycle, ThickFilmLeavesTheAsperitiesNothing) {
  const auto r =
      run(with({{"lubricant.dynamic_viscosity", "50 Pa s"}, {"lubricant.pressure_viscosity_coefficient", "2e-8"}}));
  for (double a : r.find("asperity_load_share")->values) EXPECT_LT(a, 1e-3);
  for (double l : r.find("lambda")->values) EXPECT_GT(l, 3.0);
}

TEST(LubricatedCycle, AsperityShareFallsWithSpeedAndRisesWithLoad) {
  double last = 1.0;
  for (const char* speed : {"30 rpm", "100 rpm", "300 rpm", "1000 rpm", "3000 rpm"}) {
    const auto r = run(with({{"speed", speed}}));
    const double share = contact::path_mean(r.find("asperity_load_share")->values);
    EXPECT_LT(share, last) << speed;
    last = share;
  }
  const auto light = run(with({{"torque", "300 N m"}}));
  const auto heavy = run(with({{"torque", "3000 N m"}}));
  EXPECT_LT(contact::path_mean(light.find("asperity_load_share")->values),
            contact::path_mean(heavy.find("asperity_load_share")->values));
}

TEST(LubricatedCycle, WearAndFlashVanishAtThePitchPointOnly) {
  // 41 positions over the symmetric 30/30 pair put position 20 at C (to rounding: |v1 - v2| ~ 1e-15 m/s).
  const auto r = run(test::lubricated_case());
  for (const char* q : {"wear_depth_pinion_m", "wear_depth_wheel_m", "flash_temperature_K", "power_loss_W"}) {
    const auto& v = r.find(q)->values;
    const double top = *std::max_element(v.begin(), v.end());
    ASSERT_GT(top, 0.0) << q;
    EXPECT_LT(v[20], 1e-9 * top) << q;  // rounding of v1 - v2 at C, not a tolerance on physics
    for (std::size_t i = 0; i < v.size(); ++i)
      if (i != 20) {
        EXPECT_GT(v[i], 0.0) << q << " at " << i;
      }
  }
  // Contact temperature = bulk + flash, the ISO one with the ISO mean coefficient.
  const auto& sum = *r.lubrication_summary;
  const auto& flash = r.find("flash_temperature_K")->values;
  const auto& contact = r.find("contact_temperature_K")->values;
  for (std::size_t i = 0; i < flash.size(); ++i) EXPECT_DOUBLE_EQ(contact[i], sum.bulk_temperature + flash[i]);
  // The loss factor from the path and Ohlendorf's closed form agree to the shape of the load
  // sharing (Ohlendorf assumes a uniform load per pair; ISO method B shares it): within 10%.
  EXPECT_NEAR(sum.loss_factor_path / sum.loss_factor_ohlendorf, 1.0, 0.10);
}

}  // namespace
}  // namespace geartrib
