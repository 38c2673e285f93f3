// The mixed-lubrication closure: the mean gap and bearing area of the composite heights against
// quadrature, the asperity pressure of the sharing (asperity model, bearing area, their blend),
// measured traction curves, Persson's separation law in the closure (at the mean gap, the flanks'
// spectrum, the datum it refuses, the mesh cycle's film against his u), and, through the mesh cycle,
// the named points where they stand and the roughness lambda is computed with.
#include "case/asperity_setup.hpp"
#include "case/contact_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/input_error.hpp"
#include "contact/asperity_pressure.hpp"
#include "contact/greenwood_williamson.hpp"
#include "contact/mesh_contact.hpp"
#include "contact/mesh_lubrication.hpp"
#include "contact/persson_contact.hpp"
#include "contact/surface_model.hpp"
#include "gear/gear_mesh.hpp"
#include "lubrication/film_closure.hpp"
#include "lubrication/lubricant.hpp"
#include "runs/mesh_cycle.hpp"
#include "solvers/integrators.hpp"
#include "surface/areal_synthesis.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace geartrib {
namespace {

using namespace lubrication;

// E[(h - z)+] and P(z > h) by the midpoint rule over the density (a derivation independent of the
// closed forms: the integral of the definition).
double gap_by_quadrature(const CompositeHeights& s, double h, bool bearing) {
  const int n = 200000;
  const bool gaussian = s.distribution == surface::HeightDistribution::gaussian;
  const double lo = gaussian ? -12.0 * s.sigma : -s.sigma, hi = gaussian ? 12.0 * s.sigma : 60.0 * s.sigma;
  const double dz = (hi - lo) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = lo + (i + 0.5) * dz;
    const double density =
        gaussian ? std::exp(-0.5 * z * z / (s.sigma * s.sigma)) / (s.sigma * std::sqrt(2.0 * std::numbers::pi))
                 : std::exp(-(z + s.sigma) / s.sigma) / s.sigma;
    sum += (bearing ? (z > h ? 1.0 : 0.0) : std::max(h - z, 0.0)) * density * dz;
  }
  return sum;
}

TEST(FilmClosure, MeanGapAndBearingAreaAgainstTheirIntegrals) {
  for (auto distribution : {surface::HeightDistribution::gaussian, surface::HeightDistribution::exponential}) {
    const CompositeHeights s{1.4e-6, distribution};
    for (double t : {-3.0, -1.0, -0.3, 0.0, 0.4, 1.0, 2.5, 5.0}) {
      const double h = t * s.sigma;
      // Midpoint rule with 200000 cells (1.2e-4 sigma wide for the Gaussian, 3e-4 for the
      // exponential): the kink of (h - z)+ costs up to about a cell squared times the density
      // (9e-8 sigma at most; observed 8.7e-9), the step of the bearing indicator up to half a cell
      // times the density (<= 1/sigma).
      EXPECT_NEAR(mean_gap(s, h) / s.sigma, gap_by_quadrature(s, h, false) / s.sigma, 1e-7) << t;
      EXPECT_NEAR(bearing_area_fraction(s, h), gap_by_quadrature(s, h, true), 1.6e-4) << t;
    }
  }
}

TEST(FilmClosure, MeanGapLimitsAndInverse) {
  const CompositeHeights s{1e-6, surface::HeightDistribution::gaussian};
  EXPECT_NEAR(mean_gap(s, 0.0), s.sigma / std::sqrt(2.0 * std::numbers::pi), 1e-20);  // sigma phi(0)
  EXPECT_NEAR(mean_gap(s, 10e-6) / 10e-6, 1.0, 1e-15);  // far above the heights: the separation
  // Positive and rising at every separation, also deep below the mean plane (no cancellation to 0 or below).
  double last = 0.0;
  for (double t = -30.0; t <= 10.0; t += 0.25) {
    const double g = mean_gap(s, t * s.sigma);
    EXPECT_GT(g, last) << t;
    last = g;
  }
  // The bearing area's inverse.
  for (double a : {1e-12, 1e-3, 0.2, 0.5, 0.9, 1.0 - 1e-9})
    EXPECT_NEAR(bearing_area_fraction(s, bearing_area_height(s, a)) / a, 1.0, 1e-9) << a;
  EXPECT_EQ(film_gap(FilmGap::dry_offset, s, 0.3e-6, -0.5e-6), 0.8e-6);
  EXPECT_EQ(film_gap(FilmGap::dry_offset, s, 0.3e-6, 0.5e-6), 0.3e-6);  // a positive dry separation: no shift
  EXPECT_EQ(film_gap(FilmGap::mean_plane, s, -0.3e-6, 0.0), -0.3e-6);
}

TEST(FilmClosure, MeanGapHeightInvertsTheMeanGap) {
  for (auto distribution : {surface::HeightDistribution::gaussian, surface::HeightDistribution::exponential})
    for (double t : {1e-8, 1e-4, 0.01, 0.3, 1.0, 3.0, 30.0}) {
      const CompositeHeights s{1.4e-6, distribution};
      const double g = t * s.sigma;
      EXPECT_NEAR(mean_gap(s, mean_gap_height(s, g)) / g, 1.0, 1e-11) << t;
    }
  EXPECT_EQ(mean_gap_height(CompositeHeights{0.0, surface::HeightDistribution::gaussian}, 2e-6), 2e-6);
  EXPECT_THROW(mean_gap_height(CompositeHeights{1e-6, surface::HeightDistribution::gaussian}, 0.0),
               std::invalid_argument);
}

// The seed's rough surface and its GW table.
struct SeedSurface {
  Case c = test::lubricated_case();
  surface::EquivalentSurface surface = contact::case_equivalent_surface(c);
  asperity::ContactPair pair = asperity::contact_pair(c);
  std::unique_ptr<asperity::AsperityModel> model = asperity::make_case_model(c, c.asperity.model);
  contact::GreenwoodWilliamson gw{surface, *model, pair, 2e9, contact::GreenwoodWilliamsonOptions{}};
  CompositeHeights heights{surface.surface_sigma, surface::HeightDistribution::gaussian};
};

TEST(AsperityPressure, ItsTwoModelsAndTheirBlend) {
  const SeedSurface s;
  const double h_mean = s.pair.hardness;
  const contact::AsperityPressure gw(s.gw, s.heights, h_mean, 0.0);
  const contact::AsperityPressure bearing(s.gw, s.heights, h_mean, 1.0);
  const contact::AsperityPressure half(s.gw, s.heights, h_mean, 0.5);
  for (double p : {1e3, 1e6, 1e8, 4e8, 8e8}) {
    // The asperity model alone: GW's separation, moved from the summit plane to the mean plane.
    EXPECT_EQ(gw.separation(p), s.gw.separation_for_pressure(p) + s.surface.summit_mean_height);
    // The bearing area alone: H A_b(h) = p (A_b(onset) ~ 1e-18 is below the tolerance).
    EXPECT_NEAR(h_mean * bearing_area_fraction(s.heights, bearing.separation(p)) / p, 1.0, 1e-9) << p;
    // The blend carries p at its separation, between the two.
    const double h = half.separation(p);
    EXPECT_NEAR(half.pressure(h) / p, 1.0, 1e-9) << p;
    EXPECT_GE(h, std::min(gw.separation(p), bearing.separation(p)));
    EXPECT_LE(h, std::max(gw.separation(p), bearing.separation(p)));
  }
  // Monotone in h, zero from the onset up.
  double last = std::numeric_limits<double>::infinity();
  for (double t = -4.0; t < 12.0; t += 0.05) {
    const double p = half.pressure(t * s.heights.sigma);
    EXPECT_LE(p, last) << t;
    last = p;
  }
  EXPECT_EQ(half.pressure(half.onset()), 0.0);
  EXPECT_EQ(half.separation(0.0), half.onset());
  // The bearing area cannot exceed the hardness: saturated, flagged, not extrapolated.
  EXPECT_TRUE(bearing.saturated(1.2 * h_mean));
  EXPECT_FALSE(bearing.saturated(0.5 * h_mean));
  EXPECT_TRUE(std::isfinite(bearing.separation(1.2 * h_mean)));
}

TEST(AsperityPressure, PerssonsLawAtTheMeanGap) {
  // Persson's pressure at the mean gap of the heights at h, less its value at the onset: the closure's
  // separation h has mean gap u(p + p_on), and carries p; monotone; the blend with the bearing area
  // carries p between the two.
  const SeedSurface s;
  const contact::RoughnessSpectrum spectrum{
      {contact::SpectrumPart::gaussian(1e-6, 10e-6), contact::SpectrumPart::gaussian(1e-6, 10e-6)}};
  const contact::PerssonSeparation law(spectrum, s.pair.modulus);
  const CompositeHeights heights{spectrum.rms_height(), surface::HeightDistribution::gaussian};
  const double hardness = s.pair.hardness;
  const contact::AsperityPressure persson(law, heights, hardness, 0.0);
  const contact::AsperityPressure bearing(law, heights, hardness, 1.0);
  const contact::AsperityPressure half(law, heights, hardness, 0.5);
  const double p_on = contact::AsperityPressure::kPerssonOnsetPressure * s.pair.modulus;
  for (double p : {1e3, 1e6, 1e8, 1e9, 3e9}) {
    const double h = persson.separation(p);
    EXPECT_NEAR(mean_gap(heights, h) / law.separation(p + p_on), 1.0, 1e-11) << p;
    EXPECT_NEAR(persson.pressure(h) / p, 1.0, 1e-9) << p;
    const double b = half.separation(p);
    EXPECT_NEAR(half.pressure(b) / p, 1.0, 1e-9) << p;
    EXPECT_GE(b, std::min(h, bearing.separation(p)));
    EXPECT_LE(b, std::max(h, bearing.separation(p)));
  }
  double last = std::numeric_limits<double>::infinity();
  for (double t = -4.0; t < 40.0; t += 0.05) {
    const double p = half.pressure(t * heights.sigma);
    EXPECT_LE(p, last) << t;
    last = p;
  }
  EXPECT_EQ(persson.pressure(persson.onset()), 0.0);
  EXPECT_EQ(persson.separation(0.0), persson.onset());
  // The onset: where Persson's pressure has fallen to 1e-15 E*, tens of sigma above the mean plane.
  EXPECT_GT(persson.onset(), 10.0 * heights.sigma);
}

TEST(AsperityPressure, FlankSpectrumFromGroundProfilesOrFittedToTheSummitModel) {
  // Flanks given by Ra: the self-affine spectrum whose moments give back the summit model (McCool's
  // relations forward on the fitted spectrum: eta, beta and sigma of the equivalent surface).
  const Case c = test::lubricated_case();
  const surface::EquivalentSurface e = contact::case_equivalent_surface(c);
  const contact::FlankSpectrum f = contact::flank_spectrum({&c.pinion.flank, &c.wheel.flank}, e);
  ASSERT_EQ(f.spectrum.parts.size(), 1u);
  EXPECT_EQ(f.sources(), "fitted");
  EXPECT_FALSE(f.fell_back);
  EXPECT_EQ(f.spectrum.parts[0].hurst, contact::kFittedSpectrumHurst);
  const double m0 = f.spectrum.profile_m0(), m2 = f.spectrum.profile_m2(), m4 = f.spectrum.profile_m4();
  EXPECT_NEAR(std::sqrt(m0) / e.surface_sigma, 1.0, 1e-12);
  EXPECT_NEAR(m4 / (6.0 * std::numbers::pi * std::sqrt(3.0) * m2) / e.summit_density, 1.0, 1e-9);
  EXPECT_NEAR(0.375 * std::sqrt(std::numbers::pi / m4) / e.summit_radius, 1.0, 1e-12);
  // Two generated ground profiles: their Gaussian spectra, summed.
  const Case g = io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-mixed-ehl.toml"));
  const contact::FlankSpectrum fg =
      contact::flank_spectrum({&g.pinion.flank, &g.wheel.flank}, contact::case_equivalent_surface(g));
  ASSERT_EQ(fg.spectrum.parts.size(), 2u);
  EXPECT_EQ(fg.sources(), "generated");
  EXPECT_EQ(fg.spectrum.parts[1].correlation_length, g.wheel.flank.profile->correlation_length);
  EXPECT_NEAR(fg.spectrum.rms_height(), std::hypot(g.pinion.flank.profile->rq, g.wheel.flank.profile->rq), 1e-20);
  // A GW product below 0.0214 makes a bandwidth m0 m4/m2^2 below 2: no self-affine spectrum has it.
  const Case narrow =
      io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", {{"roughness.eta_sigma_beta", "0.02"}}));
  EXPECT_THROW(
      contact::flank_spectrum({&narrow.pinion.flank, &narrow.wheel.flank}, contact::case_equivalent_surface(narrow)),
      std::invalid_argument);
}

namespace {
// gears/m6z30-measured.toml lubricated (the oil of gears/m6z30.toml) with Persson's closure.
Case measured_persson(std::vector<io::CaseChange> changes = {}) {
  changes.insert(changes.begin(), {{"lubricant.file", "../lubricants/mineral-vg220.toml"},
                                   {"operating.oil_temperature", "70 degC"},
                                   {"lubrication.asperity_pressure", "persson"}});
  return io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-measured.toml", changes));
}
}  // namespace

TEST(AsperityPressure, FlankSpectrumFromMeasuredPatches) {
  // Measured areal flanks: each patch's radial spectrum, tabulated, holding the patch's variance and
  // full gradient variance (m2x + m2y of its areal spectrum, surface::radial_spectrum: to rounding); the
  // two added.
  const Case c = measured_persson();
  ASSERT_TRUE(c.pinion.flank.patch.has_value());  // kept for Persson's spectrum (no areal patch lay here)
  ASSERT_TRUE(c.wheel.flank.patch.has_value());
  const surface::EquivalentSurface e = contact::case_equivalent_surface(c);
  const contact::FlankSpectrum f = contact::flank_spectrum({&c.pinion.flank, &c.wheel.flank}, e);
  EXPECT_EQ(f.sources(), "measured");
  ASSERT_EQ(f.spectrum.parts.size(), 2u);
  for (std::size_t g = 0; g < 2; ++g) {
    const contact::SpectrumPart& part = f.spectrum.parts[g];
    EXPECT_EQ(part.shape, contact::SpectrumPart::Shape::tabulated) << g;
    const surface::ArealSpectrum a = surface::areal_spectrum(*(g == 0 ? c.pinion : c.wheel).flank.patch);
    const contact::RoughnessSpectrum one{{part}};
    EXPECT_NEAR(one.rms_height() / a.patch_rq, 1.0, 1e-12) << g;
    EXPECT_NEAR(one.rms_gradient() / std::sqrt(a.slope_variance(true) + a.slope_variance(false)), 1.0, 1e-12) << g;
  }
  // The patch's variance is the cleaned surface's Rq^2: the spectrum's rq is the flanks' composite Rq.
  const double rq = std::hypot(c.pinion.flank.measured->rq, c.wheel.flank.measured->rq);
  EXPECT_NEAR(f.spectrum.rms_height() / rq, 1.0, 1e-12);
  // The moments' fit asked for instead: these summits' band (eta sigma_s beta 0.015) is narrower than
  // any self-affine spectrum's; with summit radii of 3 um (0.030) one fits, and it is the pair's.
  EXPECT_THROW(contact::flank_spectrum({&c.pinion.flank, &c.wheel.flank}, e, lubrication::PerssonSpectrum::moments),
               std::invalid_argument);
  const Case wide = measured_persson({{"pinion.flank.summit_radius", "3 um"}, {"wheel.flank.summit_radius", "3 um"}});
  const contact::FlankSpectrum m =
      contact::flank_spectrum({&wide.pinion.flank, &wide.wheel.flank}, contact::case_equivalent_surface(wide),
                              lubrication::PerssonSpectrum::moments);
  EXPECT_EQ(m.sources(), "fitted");
  ASSERT_EQ(m.spectrum.parts.size(), 1u);
  EXPECT_EQ(m.spectrum.parts[0].shape, contact::SpectrumPart::Shape::self_affine);
  // A measured pinion beside a ground wheel: each its own, added, the source said per flank.
  const Case ground = io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-mixed-ehl.toml"));
  const contact::FlankSpectrum mixed = contact::flank_spectrum({&c.pinion.flank, &ground.wheel.flank}, e);
  EXPECT_EQ(mixed.sources(), "measured/generated");
  ASSERT_EQ(mixed.spectrum.parts.size(), 2u);
  EXPECT_EQ(mixed.spectrum.parts[1].correlation_length, ground.wheel.flank.profile->correlation_length);
  // A measured pinion beside a flank given by Ra: the pair's fit (one flank's own is not added to a fit
  // of the composite moments that hold it), and it says so.
  const Case ra = test::lubricated_case();
  const contact::FlankSpectrum fallback =
      contact::flank_spectrum({&c.pinion.flank, &ra.wheel.flank}, contact::case_equivalent_surface(ra));
  EXPECT_EQ(fallback.sources(), "fitted");
  EXPECT_TRUE(fallback.fell_back);
}

TEST(AsperityPressure, MeasuredPatchKeptOnlyWhereTakenAndRefusals) {
  // The patch is kept where Persson's closure takes the flanks' own spectra, not otherwise.
  EXPECT_FALSE(measured_persson({{"lubrication.persson_spectrum", "moments"}}).pinion.flank.patch.has_value());
  EXPECT_FALSE(measured_persson({{"lubrication.asperity_pressure", "auto"}}).pinion.flank.patch.has_value());
  // "flanks" given where a flank has no spectrum of its own (flanks given by Ra): refused at the key.
  try {
    io::prepare_case(
        io::load_case(test::source_dir() / "gears/m6z30.toml",
                      {{"lubrication.asperity_pressure", "persson"}, {"lubrication.persson_spectrum", "flanks"}}));
    ADD_FAILURE() << "flanks without a spectrum of their own was not refused";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "lubrication.persson_spectrum");
  }
  // A patch with missing points (outliers masked, not filled) has no areal spectrum: refused at fill.
  try {
    measured_persson({{"pinion.flank.topography.outliers", "2"}, {"pinion.flank.topography.fill", "false"}});
    ADD_FAILURE() << "a patch with missing points was not refused";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "pinion.flank.topography.fill");
  }
}

TEST(AsperityPressure, AutomaticWeightIsContinuousInThePlasticFraction) {
  using contact::bearing_area_weight;
  using lubrication::AsperityPressureModel;
  EXPECT_EQ(bearing_area_weight(AsperityPressureModel::automatic, 0.3), 0.0);
  EXPECT_EQ(bearing_area_weight(AsperityPressureModel::automatic, 0.9), 0.0);
  EXPECT_EQ(bearing_area_weight(AsperityPressureModel::automatic, 0.99), 1.0);
  EXPECT_EQ(bearing_area_weight(AsperityPressureModel::automatic, 1.0), 1.0);
  EXPECT_NEAR(bearing_area_weight(AsperityPressureModel::automatic, 0.945), 0.5, 1e-12);
  EXPECT_NEAR(bearing_area_weight(AsperityPressureModel::automatic, 0.9 + 1e-12), 0.0, 1e-9);
  EXPECT_EQ(bearing_area_weight(AsperityPressureModel::asperity_model, 1.0), 0.0);
  EXPECT_EQ(bearing_area_weight(AsperityPressureModel::bearing_area, 0.1), 1.0);
  // The seed's flanks (plasticity index 121) are fully plastic at the default case's pressures; the
  // fraction rises with the pressure (the lightest load decides).
  const SeedSurface s;
  EXPECT_GT(contact::smallest_plastic_fraction(s.gw, {3.9e8, 5.9e8}), 0.99);
  double last = 0.0;
  for (double p : test::log_space(1e2, 1e9, 30)) {
    const double f = contact::smallest_plastic_fraction(s.gw, {p});
    EXPECT_GE(f, last) << p;
    last = f;
  }
}

TEST(TractionCurves, InterpolatesAlongAndBetweenCurvesAndFlagsBeyond) {
  auto curve = [](const char* name, double p, double t, std::vector<double> c) {
    TractionCurve k;
    k.name = name;
    k.hertz_pressure = p;
    k.temperature = t;
    k.entrainment_speed = 5.0;
    k.slide_to_roll = {0.0, 0.05, 0.2};
    k.coefficient = std::move(c);
    return k;
  };
  const TractionCurves grid({curve("a", 1e9, 313.15, {0.0, 0.04, 0.05}), curve("b", 2e9, 313.15, {0.0, 0.06, 0.07}),
                             curve("c", 1e9, 353.15, {0.0, 0.02, 0.03}), curve("d", 2e9, 353.15, {0.0, 0.03, 0.05})});
  EXPECT_NEAR(grid.at(0.05, 1e9, 313.15).coefficient, 0.04, 1e-15);   // a node
  EXPECT_NEAR(grid.at(0.025, 1e9, 313.15).coefficient, 0.02, 1e-15);  // along a curve
  EXPECT_NEAR(grid.at(-0.05, 1e9, 313.15).coefficient, 0.04, 1e-15);  // |SRR|
  // The centre of the grid at SRR 0.05: the mean of the four curves' 0.04, 0.06, 0.02, 0.03.
  const TractionValue mid = grid.at(0.05, 1.5e9, 333.15);
  EXPECT_NEAR(mid.coefficient, 0.0375, 1e-15);
  EXPECT_FALSE(mid.outside);
  EXPECT_TRUE(grid.at(0.3, 1.5e9, 333.15).outside);                  // SRR beyond the measured
  EXPECT_TRUE(grid.at(0.05, 3e9, 333.15).outside);                   // pressure beyond
  EXPECT_NEAR(grid.at(0.05, 3e9, 313.15).coefficient, 0.06, 1e-15);  // the nearest curve's value
  // Bad curves: out of order, outside [0, 1], not a grid.
  EXPECT_THROW(TractionCurves({curve("x", 1e9, 313.15, {0.0, 0.04, 1.5})}), std::invalid_argument);
  auto unordered = curve("y", 1e9, 313.15, {0.0, 0.04, 0.05});
  unordered.slide_to_roll = {0.0, 0.2, 0.1};
  EXPECT_THROW(TractionCurves({unordered}), std::invalid_argument);
  EXPECT_THROW(TractionCurves({curve("a", 1e9, 313.15, {0.0, 0.04, 0.05}), curve("b", 2e9, 353.15, {0.0, 0.06, 0.07})}),
               std::invalid_argument);
}

contact::MeshContactResult run(const Case& c, int positions = 41) {
  const gear::GearMesh mesh = gear::case_mesh(c);
  return runs::run_mesh_contact(c, mesh, nullptr, {}, positions);
}
Case with(const std::vector<io::CaseChange>& changes) {
  return io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", changes));
}

TEST(LubricatedSummary, PerssonRunOnMeasuredFlanksTakesTheirSpectrum) {
  // End to end: gears/m6z30-measured.toml lubricated with Persson's closure runs on the patches' radial
  // spectrum (its rq and h'_rms, the verdict naming it), not the fit (refused on these summits, above).
  const Case c = measured_persson();
  const auto r = run(c, 21);
  ASSERT_TRUE(r.lubrication_summary.has_value());
  const auto& sum = *r.lubrication_summary;
  const contact::RoughnessSpectrum measured =
      contact::flank_spectrum({&c.pinion.flank, &c.wheel.flank}, contact::case_equivalent_surface(c)).spectrum;
  EXPECT_EQ(sum.persson_spectrum, "measured");
  EXPECT_NEAR(sum.persson_rms_height / measured.rms_height(), 1.0, 1e-12);
  EXPECT_NEAR(sum.persson_rms_gradient / measured.rms_gradient(), 1.0, 1e-12);
  EXPECT_NE(r.verdict.find("the measured patches' radial spectra"), std::string::npos);
  ASSERT_NE(r.find("persson_plastic_area_fraction"), nullptr);
}

TEST(LubricatedSummary, NamedPointsStandWhereTheyAreBAndDOnTheSinglePairSide) {
  const Case c = with({});
  const auto r = run(c, 401);
  const auto& sum = *r.lubrication_summary;
  ASSERT_EQ(sum.points.size(), 7u);
  const gear::GearMesh mesh = gear::case_mesh(c);
  const double full = mesh.normal_force() / c.gear_pair.face_width;  // one pair carries all
  const auto& s = r.find("s_m")->values;
  const auto& film = r.find("mean_gap_m")->values;
  for (const auto& p : sum.points) {
    if (p.name != "B" && p.name != "D") continue;
    EXPECT_NEAR(p.line_load / full, 1.0, 1e-12) << p.name;
    // The single-pair side's limit: the grid's two nearest positions inside [B, D] extrapolated to
    // B (or D) linearly; the values are smooth there, the step 0.15 mm leaves an O(step^2) residue.
    std::size_t k = 0;
    if (p.name == "B") {
      while (s[k] < p.s) ++k;
    } else {
      k = s.size() - 1;
      while (s[k] > p.s) --k;
    }
    const std::size_t j = p.name == "B" ? k + 1 : k - 1;
    const double limit = film[k] + (p.s - s[k]) * (film[j] - film[k]) / (s[j] - s[k]);
    EXPECT_NEAR(p.mean_gap / limit, 1.0, 1e-3) << p.name;
    // ...and well away from the double-pair side's value just before B (after D).
    const double other = film[p.name == "B" ? k - 1 : k + 1];
    EXPECT_GT(std::abs(other / limit - 1.0), 0.05) << p.name;
  }
}

TEST(LubricatedSummary, WithDynamicsBAndDStillCarryTheSinglePairsLoad) {
  // The dynamic load splits by the pairs' stiffnesses: at B itself the pair leaving at E still
  // counts; the named B must take the single pair's side (the whole mesh force), well above the
  // two-pair side just before it (about half the force), and D likewise after it.
  const Case c = with({{"mesh.dynamics", "odeint"}, {"speed", "300 rpm"}});
  const gear::GearMesh mesh = gear::case_mesh(c);
  const auto integrator = solvers::make_integrator(gear::DynamicsEngine::odeint);
  const auto r = runs::run_mesh_contact(c, mesh, nullptr, {}, 201, integrator.get());
  ASSERT_NE(r.find("dynamic_load_factor"), nullptr);
  const auto& s = r.find("s_m")->values;
  const auto& w = r.find("line_load_N_per_m")->values;
  for (const auto& p : r.lubrication_summary->points) {
    if (p.name != "B" && p.name != "D") continue;
    // The grid point on the two-pair side next to the point.
    std::size_t k = 0;
    while (k + 1 < s.size() && s[k + 1] < p.s) ++k;
    const double two_pair = p.name == "B" ? w[k] : w[k + 1];
    EXPECT_GT(p.line_load, 1.2 * two_pair) << p.name;  // the two-pair side carries about half
  }
}

TEST(LubricatedSummary, LambdaAndIsoTakeTheFlanksRoughness) {
  // Ra given: Rq = 1.2533 Ra per flank, as the summit model's sigma.
  const auto r = run(with({}));
  const auto& sum = *r.lubrication_summary;
  EXPECT_NEAR(sum.composite_rq, std::hypot(0.8e-6, 0.8e-6) * surface::kRqOverRaGaussian, 1e-18);
  EXPECT_NEAR(sum.mean_ra, 0.8e-6, 1e-18);
  EXPECT_NEAR(sum.summit_model_sigma / sum.composite_rq, 1.0, 1e-12);
  // Measured flanks (the shipped dry case run lubricated): their own Rq and Ra, whatever the summit
  // model rebuilds (1.87 um here against the measured 1.41 um).
  const Case m = io::prepare_case(
      io::load_case(test::source_dir() / "gears/m6z30-measured.toml",
                    {{"lubricant", "../lubricants/mineral-vg220.toml"}, {"oil_temperature", "70 degC"}}));
  const auto rm = run(m);
  ASSERT_TRUE(rm.lubrication_summary.has_value());
  const auto& ms = *rm.lubrication_summary;
  EXPECT_GT(ms.summit_model_sigma / ms.composite_rq, contact::kRoughnessDisagreementFactor);
  EXPECT_TRUE(std::any_of(rm.warnings.begin(), rm.warnings.end(),
                          [](const std::string& w) { return w.find("summit model's composite sigma") != w.npos; }));
  EXPECT_NEAR(ms.composite_rq, std::hypot(m.pinion.flank.measured->rq, m.wheel.flank.measured->rq), 1e-18);
  EXPECT_NEAR(ms.mean_ra, 0.5 * (m.pinion.flank.measured->ra + m.wheel.flank.measured->ra), 1e-18);
  const auto& lambda = rm.find("lambda_smooth_film")->values;
  const auto& film = rm.find("film_m")->values;
  for (std::size_t i = 0; i < film.size(); ++i) EXPECT_DOUBLE_EQ(lambda[i], film[i] / ms.composite_rq);
}

TEST(LubricatedCycle, TractionCurveIsTheFilmsTraction) {
  // The default oil with one measured curve, linear in SRR (0.02 + 0.05 SRR, so that the table's
  // linear interpolation is exact), run with lubrication.traction = curve: the film's coefficient
  // is the curve at each position's |SRR|, the friction the shares' mix with the boundary mu.
  const auto dir = std::filesystem::temp_directory_path() / "geartrib-traction-curve-test";
  std::filesystem::create_directories(dir);
  const auto oil = dir / "oil.toml";
  {
    std::ifstream in(test::source_dir() / "lubricants/mineral-vg220.toml");
    std::ofstream out(oil);
    out << in.rdbuf() << "\n[traction_curves.linear]\nsource = \"test\"\nhertz_pressure = \"1 GPa\"\n"
        << "temperature = \"80 degC\"\nentrainment_speed = \"3 m/s\"\nslide_to_roll = [0.0, 2.0]\n"
        << "coefficient = [0.02, 0.12]\n";
  }
  const Case c = with({{"lubricant", oil.string()}, {"lubrication.traction", "curve"}});
  const auto r = run(c, 41);
  const auto& srr = r.find("srr")->values;
  const auto& share = r.find("asperity_load_share")->values;
  const auto& film = r.find("film_traction_coefficient")->values;
  const auto& mu = r.find("friction_coefficient")->values;
  const auto& vs = r.find("sliding_m_per_s")->values;
  for (std::size_t i = 0; i < srr.size(); ++i) {
    const double curve = std::abs(vs[i]) > 1e-9 ? 0.02 + 0.05 * std::abs(srr[i]) : 0.0;  // nothing slides at C
    EXPECT_NEAR(film[i], curve, 1e-15) << i;
    EXPECT_NEAR(mu[i], share[i] * 0.1 + (1.0 - share[i]) * curve, 1e-15) << i;
  }
  // One curve at one pressure: every other pressure is beyond what was measured, flagged.
  const auto* flag = r.find("flag_traction_curve_extrapolated");
  ASSERT_NE(flag, nullptr);
  EXPECT_GT(contact::path_mean(flag->values), 0.9);
  std::filesystem::remove_all(dir);
}

TEST(LubricatedCycle, PerssonsClosureFillsHisMeanGap) {
  // Ground flanks of 0.3 um on case-hardened steel (lambda about 1.4: the film and the asperities
  // share), Persson's closure elastic (his plastic fraction 0.70 under the whole load, below the
  // blend's 0.9): at every position the film's thickness is his u at the asperities' share of the
  // Hertz peak, and the spread covers the asperity model's closure at the mean gap (auto's own share).
  const std::vector<io::CaseChange> flanks = {{"contact.fidelity", "uncoupled"},
                                              {"pinion.flank.profile.rq", "0.3 um"},
                                              {"wheel.flank.profile.rq", "0.3 um"},
                                              {"pinion.material", "../materials/16MnCr5.toml"},
                                              {"wheel.material", "../materials/16MnCr5.toml"}};
  auto changes = flanks;
  changes.push_back({"lubrication.asperity_pressure", "persson"});
  const Case c = io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-mixed-ehl.toml", changes));
  const Case a = io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-mixed-ehl.toml", flanks));
  const auto r = run(c, 41);
  const auto ra = run(a, 41);
  EXPECT_EQ(r.lubrication_summary->bearing_area_weight, 0.0);
  const contact::PerssonSeparation law(
      contact::flank_spectrum({&c.pinion.flank, &c.wheel.flank}, contact::case_equivalent_surface(c)).spectrum,
      gear::case_mesh(c).composite_modulus());
  const double p_on = contact::AsperityPressure::kPerssonOnsetPressure * law.modulus();
  const auto& share = r.find("asperity_load_share")->values;
  const auto& gap = r.find("mean_gap_m")->values;
  const auto& p0 = r.find("hertz_p0_Pa")->values;
  const auto& spread = r.find("asperity_share_closure_spread")->values;
  const auto& gw_share = ra.find("asperity_load_share")->values;
  ASSERT_NE(r.find("persson_plastic_area_fraction"), nullptr);
  ASSERT_NE(r.find("flag_persson_plastic"), nullptr);
  for (std::size_t i = 0; i < share.size(); ++i) {
    if (!(p0[i] > 0.0)) continue;
    EXPECT_GT(share[i], 0.0) << i;
    EXPECT_LT(share[i], 1.0) << i;
    EXPECT_NEAR(gap[i] / law.separation(share[i] * p0[i] + p_on), 1.0, 1e-9) << i;
    EXPECT_GE(spread[i] + 1e-12, std::abs(share[i] - gw_share[i])) << i;
  }
  // Persson's law with another film datum is refused at the key.
  changes.push_back({"lubrication.film_gap", "mean-plane"});
  try {
    io::load_case(test::source_dir() / "gears/m6z30-mixed-ehl.toml", changes);
    ADD_FAILURE() << "persson with the mean-plane datum was not refused";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.key(), "lubrication.film_gap");
    EXPECT_NE(e.rule().find("mean-gap"), std::string::npos);
  }
}

TEST(LubricatedSummary, NoLubricantRunsALubricatedCaseDry) {
  const auto dry =
      run(io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30.toml", {{"lubricant", "none"}})));
  EXPECT_FALSE(dry.lubrication_summary.has_value());
  EXPECT_TRUE(dry.lubrication.empty());
  const auto seed = run(test::seed_case());
  EXPECT_EQ(dry.find("real_area_ratio")->values, seed.find("real_area_ratio")->values);
}

}  // namespace
}  // namespace geartrib
