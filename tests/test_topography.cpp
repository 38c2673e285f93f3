// Measured topography: synthetic surfaces round-trip through every format and their statistics
// come back; the cylinder reduction recovers a hobbed texture; malformed files are reported.
#include "io/input_error.hpp"
#include "io/topography_files.hpp"
#include "surface/cylinder_reduction.hpp"
#include "surface/surface_statistics.hpp"
#include "surface/synthetic_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

using namespace geartrib;
using namespace geartrib::surface;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
std::filesystem::path temp(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("geartrib-topo-" + name);
}

double angle_difference(double a, double b) {  // lines: modulo pi
  double d = std::fmod(std::abs(a - b), std::numbers::pi);
  return std::min(d, std::numbers::pi - d);
}
}  // namespace

TEST(Topography, SelfAffineStatisticsComeBackThroughEveryFormat) {
  SelfAffineSpec spec;
  spec.anisotropy = 4.0;
  spec.lay_angle = 30.0 * kDeg;
  spec.rq = 0.4e-6;
  spec.seed = 7;
  const HeightGrid g = self_affine_surface(spec);
  const SurfaceStatistics ref = surface_statistics(g);
  EXPECT_NEAR(ref.rq / spec.rq, 1.0, 1e-12);  // generated to Rq exactly
  EXPECT_LT(angle_difference(ref.lay_angle, spec.lay_angle), 2.0 * kDeg);
  for (const char* ext : {".xyz", ".csv", ".txt", ".h5"}) {
    const auto path = temp(std::string("sa") + ext);
    io::write_topography(path, g, 1e-6);
    const HeightGrid back = io::read_topography(path);
    const SurfaceStatistics s = surface_statistics(back);
    EXPECT_NEAR(s.rq / spec.rq, 1.0, 0.01) << ext;  // issue: Rq within 1%
    for (auto [a, b] : {std::pair{s.m2_along, ref.m2_along},
                        {s.m2_across, ref.m2_across},
                        {s.m4_along, ref.m4_along},
                        {s.m4_across, ref.m4_across}})
      EXPECT_NEAR(a / b, 1.0, 0.05) << ext;  // spectral moments within 5%
    EXPECT_LT(angle_difference(s.lay_angle, spec.lay_angle), 2.0 * kDeg) << ext;
    EXPECT_NEAR(back.dx / g.dx, 1.0, 1e-9) << ext;
    std::filesystem::remove(path);
  }
}

TEST(Topography, McCoolBesideMeasuredSummits) {
  // An isotropic Gaussian self-affine surface resolved by 8 spacings per shortest wavelength:
  // the eight-neighbour summits agree with McCool's (1986) predictions from m0, m2, m4. 5%: the
  // discrete summit definition depends on the sampling interval (Greenwood 1984); at this
  // resolution the observed differences are 1-2% (validation/topography: 10% at 4 spacings).
  SelfAffineSpec spec;
  spec.nx = spec.ny = 512;
  spec.spacing = 0.25e-6;
  spec.rq = 1e-6;
  spec.rolloff_wavelength = 20e-6;
  spec.cutoff_wavelength = 8 * spec.spacing;
  spec.seed = 3;
  const SurfaceStatistics s = surface_statistics(self_affine_surface(spec));
  EXPECT_GT(s.summits, 500u);
  EXPECT_NEAR(s.summit_density / s.mccool_density, 1.0, 0.05);
  EXPECT_NEAR(s.summit_radius / s.mccool_radius, 1.0, 0.05);
  EXPECT_NEAR(s.summit_sigma / s.mccool_summit_sigma, 1.0, 0.05);
  EXPECT_GT(s.summit_mean_height, 0.0);  // summits sit above the mean plane
}

TEST(Topography, CylinderReductionRecoversHobbedTexture) {
  HobbedSpec spec;
  spec.wavelength = 5e-6;
  spec.tip_radius = 6.6e-6;
  spec.noise_rq = 2e-9;
  spec.seed = 11;
  const HeightGrid g = hobbed_surface(spec);
  const SurfaceStatistics s = surface_statistics(g);
  EXPECT_LT(angle_difference(s.lay_angle, 90.0 * kDeg), 2.0 * kDeg);  // ridges along y
  const CylinderReduction r = reduce_to_cylinders(g, s.lay_angle);
  ASSERT_GE(r.asperities.size(), 8u);
  EXPECT_NEAR(r.mean_tip_radius / spec.tip_radius, 1.0, 0.10);  // issue: within 10%
  EXPECT_NEAR(r.mean_spacing / spec.wavelength, 1.0, 0.05);     // issue: within 5%
}

TEST(Topography, EquivalentSurfaceHasTheVarianceOfTheSum) {
  // Short roll-off wavelength (8 um on a 128 um grid): many independent modes, so the sampled
  // cross term of two independent seeds is small (its standard error ~ 1/sqrt(modes) ~ 1-2%).
  SelfAffineSpec a, b;
  a.seed = 1, b.seed = 2, b.rq = 0.2e-6;
  a.rolloff_wavelength = b.rolloff_wavelength = 8e-6;
  const HeightGrid u = self_affine_surface(a), d = self_affine_surface(b);
  const HeightGrid e = equivalent_surface(u, d);
  // Exact: var(e) = var(u mirrored + d) computed directly; and ~ var(u) + var(d) for independent flanks.
  double mean = 0, var = 0, direct = 0, dmean = 0;
  for (int j = 0; j < e.ny; ++j)
    for (int i = 0; i < e.nx; ++i) dmean += u.at(e.nx - 1 - i, j) + d.at(i, j);
  dmean /= e.size();
  for (double z : e.z) mean += z;
  mean /= e.size();
  for (int j = 0; j < e.ny; ++j)
    for (int i = 0; i < e.nx; ++i) {
      var += std::pow(e.at(i, j) - mean, 2);
      direct += std::pow(u.at(e.nx - 1 - i, j) + d.at(i, j) - dmean, 2);
    }
  EXPECT_NEAR(var / direct, 1.0, 1e-12);
  // The mirror choices: the point-by-point sums they define.
  const HeightGrid ey = equivalent_surface(u, d, Mirror::y), en = equivalent_surface(u, d, Mirror::none);
  EXPECT_EQ(ey.at(3, 5), u.at(3, e.ny - 1 - 5) + d.at(3, 5));
  EXPECT_EQ(en.at(3, 5), u.at(3, 5) + d.at(3, 5));
  EXPECT_EQ(e.at(3, 5), u.at(e.nx - 1 - 3, 5) + d.at(3, 5));
  // Independent flanks: var(e) = Rq_u^2 + Rq_d^2 up to the sampled cross term (5%: about three
  // standard errors of the cross term for this many modes).
  EXPECT_NEAR(var / e.size() / (a.rq * a.rq + b.rq * b.rq), 1.0, 0.05);
}

TEST(Topography, CleanUpOperations) {
  HeightGrid g = make_grid(40, 30, 1e-6, 1e-6);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.at(i, j) = 1e-6 + 2e-3 * i * g.dx - 1e-3 * j * g.dy + 3e3 * std::pow(i * g.dx, 2);
  HeightGrid plane = g;
  remove_form(plane, 2);  // a quadratic form is removed exactly
  for (double z : plane.z) EXPECT_NEAR(z, 0.0, 1e-15);
  g.at(5, 5) = 1.0;  // an outlier
  EXPECT_EQ(remove_outliers(g, 5.0), 1u);
  EXPECT_FALSE(g.ok(5, 5));
  fill_missing(g);
  EXPECT_TRUE(g.ok(5, 5));
  EXPECT_LT(std::abs(g.at(5, 5) - g.at(5, 4)), 1e-7);
}

TEST(Topography, MalformedFilesNameTheLine) {
  auto expect_error = [](const std::string& name, const std::string& text, int line, const std::string& what) {
    const auto path = temp(name);
    std::ofstream(path) << text;
    try {
      io::read_topography(path);
      ADD_FAILURE() << name << ": no error";
    } catch (const io::InputError& e) {
      EXPECT_EQ(e.line(), line) << name << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
  };
  expect_error("bad-number.txt", "# spacing: 1 um\n1 2 3\n4 five 6\n", 3, "not a number");
  expect_error("ragged.csv", "# spacing: 1 um\n1,2,3\n4,5\n", 3, "ragged row");
  expect_error("empty.txt", "# spacing: 1 um\n", 1, "no height rows");
  expect_error("all-missing.txt", "# spacing: 1 um\nNaN NaN NaN\nBad Bad Bad\nNaN NaN NaN\n", 4,
               "too few valid points");
  expect_error("no-spacing.txt", "1 2 3\n4 5 6\n7 8 9\n", 0, "spacing missing");
  expect_error("zero-spacing.txt", "# spacing: 0 um\n1 2 3\n", 1, "spacing must be positive");
  expect_error("late-units.txt", "# spacing: 1\n1 2 3\n# units: nm\n4 5 6\n", 3, "must come before");
  expect_error("one-column.txt", "# spacing: 1 um\n1\n2\n3\n", 4, "at least 2 columns");
  expect_error("bad-unit.xyz", "# units: furlong\n0 0 1\n", 1, "unknown unit");
  expect_error("bad-point.xyz", "Wyko export\nX Y Z\n0 0 1\n1 0 2\n1 oops 3\n", 5, "malformed point");
  expect_error("irregular.xyz", "0 0 1\n1 0 2\n2.5 0 3\n0 1 1\n1 1 2\n2.5 1 3\n0 2 1\n1 2 1\n2.5 2 1\n", 1,
               "regular grid");
}

TEST(Topography, ProfilerExportWithHeaderAndMissingPoints) {
  const auto path = temp("wyko.asc");
  std::ofstream out(path);
  out << "Wyko Vision export\nPixel size 0.5 um\nX(um) Y(um) Z(um)\n";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      out << i * 0.5 << '\t' << j * 0.5 << '\t' << ((i + j) % 3 == 0 ? std::string("Bad") : std::to_string(0.1 * i))
          << '\n';
  out.close();
  const HeightGrid g = io::read_topography(path);
  EXPECT_EQ(g.nx, 5);
  EXPECT_EQ(g.ny, 4);
  EXPECT_NEAR(g.dx, 0.5e-6, 1e-15);
  EXPECT_EQ(g.missing(), 7u);  // (i + j) % 3 == 0 on a 5 x 4 grid
  HeightGrid filled = g;
  CleanupOptions fill;
  fill.form_degree = 0;
  fill.fill = true;
  const CleanupReport report = clean_surface(filled, fill);
  EXPECT_EQ(report.missing_in, 7u);
  EXPECT_EQ(report.filled, 7u);
  EXPECT_EQ(filled.missing(), 0u);
  std::filesystem::remove(path);
}

TEST(Topography, GaussianFilterPassesHalfTheAmplitudeAtTheCutOff) {
  // ISO 16610-61: the Gaussian filter passes a sinusoid of wavelength lambda into the waviness
  // with transmission exp(-pi (alpha lambda_c / lambda)^2), alpha^2 = ln 2 / pi; the roughness
  // keeps the rest: 50% at the cut-off, all but exp(-16 ln 2) ~ 1.5e-5 at a quarter of it.
  const double cutoff = 80e-6, dx = 0.5e-6;
  auto kept = [&](double wavelength) { return 1.0 - std::exp(-std::log(2.0) * std::pow(cutoff / wavelength, 2)); };
  for (double wavelength : {cutoff, cutoff / 4.0, 2.0 * cutoff}) {
    HeightGrid g = make_grid(1601, 3, dx, dx);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) g.at(i, j) = 1e-6 * std::cos(2.0 * std::numbers::pi * i * dx / wavelength);
    remove_waviness(g, cutoff);
    // Amplitude in the middle third (away from the renormalised edges, which are not ISO's).
    double amplitude = 0.0;
    for (int i = g.nx / 3; i < 2 * g.nx / 3; ++i) amplitude = std::max(amplitude, std::abs(g.at(i, 1)));
    EXPECT_NEAR(amplitude / 1e-6, kept(wavelength), 0.01)
        << wavelength;  // 1%: sampling of the peak and the discrete kernel
  }
}

TEST(Topography, ResamplingKeepsAPlaneAndBinsAScatteredCloud) {
  // Bilinear resampling reproduces a plane exactly.
  HeightGrid g = make_grid(21, 11, 1e-6, 1e-6);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.at(i, j) = 3e-3 * i * g.dx - 2e-3 * j * g.dy;
  const HeightGrid r = resample(g, 0.7e-6);
  EXPECT_EQ(r.nx, 29);  // floor(20 / 0.7) + 1
  for (int j = 0; j < r.ny; ++j)
    for (int i = 0; i < r.nx; ++i) EXPECT_NEAR(r.at(i, j), 3e-3 * i * r.dx - 2e-3 * j * r.dy, 1e-18);
  // A jittered cloud off any lattice: an error without resampling, a grid with it.
  const auto path = temp("jitter.xyz");
  {
    std::ofstream out(path);
    out << "# units: um\n";
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i)
        out << i + 0.3 * std::sin(7.0 * i + j) << ' ' << j + 0.3 * std::cos(3.0 * j + i) << ' ' << 0.01 * i << '\n';
  }
  EXPECT_THROW(io::read_topography(path), io::InputError);
  io::TopographyReadOptions o;
  o.resample = 2e-6;
  const HeightGrid b = io::read_topography(path, o);
  EXPECT_NEAR(b.dx, 2e-6, 1e-18);
  EXPECT_EQ(b.missing(), 0u);  // every 2 um cell holds points
  // z = 0.01 x (x in um): the cell means rise by 0.02 um per 2 um cell (to the jitter's spread).
  EXPECT_NEAR((b.at(5, 5) - b.at(4, 5)) / 0.02e-6, 1.0, 0.2);  // 20%: jitter of 0.3 um in 2 um cells
  std::filesystem::remove(path);
}

TEST(Topography, CleanUpMasksOutliersOnACurvedFlank) {
  // A curved (quadratic) flank with small roughness and two spikes: the spikes are found against
  // the form-free surface, though they are small against the form itself.
  SelfAffineSpec spec;
  spec.nx = spec.ny = 64;
  spec.rq = 0.1e-6;
  HeightGrid g = self_affine_surface(spec);
  HeightGrid roughness_only = g;
  remove_form(roughness_only, 2);  // what the clean-up should give, the form being removed exactly
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.at(i, j) += 5e3 * std::pow((i - 32) * g.dx, 2) + 1e-2 * j * g.dy;
  g.at(10, 10) += 2e-6;
  g.at(40, 20) -= 2e-6;
  CleanupOptions o;
  o.outlier_limit = 6.0;
  o.fill = true;
  const CleanupReport r = clean_surface(g, o);
  EXPECT_EQ(r.outliers, 2u);
  EXPECT_EQ(r.filled, 2u);
  EXPECT_EQ(g.missing(), 0u);
  const SurfaceStatistics s = surface_statistics(g);
  // 2%: the two spikes are replaced by their neighbours' mean, not by the original heights.
  EXPECT_NEAR(s.rq / surface_statistics(roughness_only).rq, 1.0, 0.02);
  CleanupOptions bad;
  bad.outlier_limit = 1.0;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

TEST(Topography, SpectralMomentsMatchTheGeneratingSpectrum) {
  // The slope and curvature variances measured by finite differences against the moments of the
  // spectrum the surface was generated from, m_n(dir) = sum C(q) (q . dir)^n / sum C(q) x Rq^2,
  // summed over the grid's wavevectors (an independent computation from the specification).
  // The shortest wavelength is 16 spacings so that the central differences resolve it
  // (transfer sin(q h)/(q h) >= 0.974 for slopes, and >= 0.975 for curvatures, at the cut-off).
  for (auto [anisotropy, lay_deg] : {std::pair{1.0, 0.0}, std::pair{3.0, 30.0}}) {
    SelfAffineSpec spec;
    spec.nx = spec.ny = 512;
    spec.spacing = 0.25e-6;
    spec.rq = 1e-6;
    spec.cutoff_wavelength = 16 * spec.spacing;
    spec.rolloff_wavelength = 32e-6;
    spec.anisotropy = anisotropy;
    spec.lay_angle = lay_deg * kDeg;
    spec.seed = 21;
    const SurfaceStatistics s = surface_statistics(self_affine_surface(spec));
    // Expected moments along and across the lay from the generating spectrum.
    const double qr = 2.0 * std::numbers::pi / spec.rolloff_wavelength,
                 qs = 2.0 * std::numbers::pi / spec.cutoff_wavelength;
    // Along the measured lay (for the isotropic surface any direction; the realised one is used).
    const double c = std::cos(s.lay_angle), sn = std::sin(s.lay_angle);
    double w0 = 0, a2 = 0, a4 = 0, c2 = 0, c4 = 0;
    for (int j = 0; j < spec.ny; ++j)
      for (int i = -spec.nx / 2; i < spec.nx / 2; ++i) {
        const double qx = 2.0 * std::numbers::pi * i / (spec.nx * spec.spacing);
        const double qy = 2.0 * std::numbers::pi * (j <= spec.ny / 2 ? j : j - spec.ny) / (spec.ny * spec.spacing);
        const double along = qx * c + qy * sn, across = -qx * sn + qy * c;
        const double q = std::hypot(anisotropy * along, across);
        if (!(q > 0.0 && q <= qs)) continue;
        const double psd = q < qr ? 1.0 : std::pow(q / qr, -2.0 * (1.0 + spec.hurst));
        w0 += psd, a2 += psd * along * along, a4 += psd * std::pow(along, 4), c2 += psd * across * across,
            c4 += psd * std::pow(across, 4);
      }
    const double m0 = spec.rq * spec.rq;
    // 5% (the figure): the finite differences' transfer at the short cut-off (<= 2.6%;
    // observed deviations 0.1-2.1%). The amplitudes are sqrt(C), so no sampling error enters.
    EXPECT_NEAR(s.m2_along / (m0 * a2 / w0), 1.0, 0.05) << anisotropy;
    EXPECT_NEAR(s.m4_along / (m0 * a4 / w0), 1.0, 0.05) << anisotropy;
    EXPECT_NEAR(s.m2_across / (m0 * c2 / w0), 1.0, 0.05) << anisotropy;
    EXPECT_NEAR(s.m4_across / (m0 * c4 / w0), 1.0, 0.05) << anisotropy;
    if (anisotropy > 1.0) {
      EXPECT_LT(angle_difference(s.lay_angle, spec.lay_angle), 2.0 * kDeg);
    }
  }
}

TEST(Topography, ExtremeSurfacesGiveFiniteStatistics) {
  // A flat surface: zero roughness, no summits, everything finite; the contact models refuse it.
  HeightGrid flat = make_grid(16, 16, 1e-6, 1e-6);
  SurfaceStatistics s = surface_statistics(flat);
  EXPECT_EQ(s.rq, 0.0);
  EXPECT_EQ(s.summits, 0u);
  for (double v : {s.ra, s.rsk, s.rku, s.rz, s.lay_angle, s.m2_along, s.m4_across, s.mccool_density})
    EXPECT_TRUE(std::isfinite(v));
  EXPECT_THROW(measured_roughness(s), std::invalid_argument);
  // Nanometre and millimetre scales: the statistics scale exactly (heights x k: Rq x k, m2 x k^2,
  // summit radius / k; a property of the definitions).
  SelfAffineSpec spec;
  spec.nx = spec.ny = 64;
  const HeightGrid g = self_affine_surface(spec);
  const SurfaceStatistics ref = surface_statistics(g);
  for (double k : {1e-6, 1e3}) {
    HeightGrid h = g;
    for (double& z : h.z) z *= k;
    const SurfaceStatistics t = surface_statistics(h);
    EXPECT_NEAR(t.rq / (k * ref.rq), 1.0, 1e-12);
    EXPECT_NEAR(t.m2_across / (k * k * ref.m2_across), 1.0, 1e-12);
    EXPECT_NEAR(t.summit_radius * k / ref.summit_radius, 1.0, 1e-12);
    EXPECT_EQ(t.summits, ref.summits);
  }
  // Nearly all points missing: the statistics use the valid ones, or refuse with a clear error.
  HeightGrid sparse = g;
  std::fill(sparse.valid.begin(), sparse.valid.end(), 0);
  EXPECT_THROW(surface_statistics(sparse), std::invalid_argument);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) sparse.valid[static_cast<std::size_t>(j) * sparse.nx + i] = 1;
  EXPECT_TRUE(std::isfinite(surface_statistics(sparse).rq));
}
