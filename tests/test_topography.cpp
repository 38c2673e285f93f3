// Measured topography: synthetic surfaces round-trip through every format and their statistics
// come back; the cylinder reduction recovers a hobbed texture; malformed files are reported.
#include "config/input_error.hpp"
#include "surface/cylinder_reduction.hpp"
#include "surface/surface_statistics.hpp"
#include "surface/synthetic_surface.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <numbers>
#include <random>

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

// NaN-marked heights (files, arrays) into a grid and back: the valid heights bit for bit, NaN
// exactly where points are missing; a count that is not the grid's is refused.
TEST(Topography, NanMarkedHeightsRoundTrip) {
  surface::HeightGrid g = surface::make_grid(3, 2, 1e-6, 2e-6);
  const std::vector<double> z = {1e-7, std::nan(""), -0.0, 4e-310, -2e-6, std::nan("")};
  surface::set_heights(g, z);
  EXPECT_EQ(g.missing(), 2u);
  EXPECT_FALSE(g.ok(1, 0));
  EXPECT_TRUE(g.ok(0, 1));
  const std::vector<double> back = surface::heights_or_nan(g);
  ASSERT_EQ(back.size(), z.size());
  for (std::size_t k = 0; k < z.size(); ++k) {
    EXPECT_EQ(std::isnan(back[k]), std::isnan(z[k])) << k;
    if (!std::isnan(z[k])) {
      EXPECT_EQ(std::memcmp(&back[k], &z[k], sizeof(double)), 0) << k;
    }
  }
  EXPECT_THROW(surface::set_heights(g, std::vector<double>(5, 0.0)), std::invalid_argument);
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

// --- Input checks (the fuzz findings of tests/corpus/01, 02, 03, 05; docs/guide/surface.md#limits) ---

namespace {

// The InputError `f` throws (a failure when none or another exception).
std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("another exception: ") + e.what();
  }
  return "no error";
}
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::filesystem::path write_text(const std::string& name, const std::string& text) {
  const auto path = temp(name);
  std::ofstream(path) << text;
  return path;
}

// An input of the regression corpus (tests/corpus/FOLDER/NAME; made by the folder's make_inputs.py).
std::filesystem::path corpus(const std::string& folder, const std::string& name) {
  return std::filesystem::path(GEARTRIB_SOURCE_DIR) / "tests" / "corpus" / folder / name;
}
const std::string kAttributes = "01-hdf5-dx-array-stack-overflow",
                  kSizes = "03-unbounded-allocation-from-file-size-fields";

// An HDF5 surface of ny x nx heights z [m] (NaN: missing) at spacing 0.5 um, by geartrib's writer.
std::filesystem::path write_h5(const std::string& name, int ny, int nx, const std::vector<double>& z) {
  HeightGrid g = make_grid(nx, ny, 0.5e-6, 0.5e-6);
  for (std::size_t k = 0; k < g.size(); ++k) {
    g.valid[k] = !std::isnan(z[k]);
    g.z[k] = std::isnan(z[k]) ? 0.0 : z[k];
  }
  const auto path = temp(name);
  io::write_topography(path, g);
  return path;
}

// The same file with height k set to `bad` after writing (the writer refuses what the readers
// refuse): k holds a sentinel whose 8 bytes are replaced in the file's contiguous /z.
std::filesystem::path poke_h5(const std::string& name, int ny, int nx, std::vector<double> z, std::size_t k,
                              double bad) {
  constexpr double kSentinel = 1.2345678901234567e-4;
  z[k] = kSentinel;
  const auto path = write_h5(name, ny, nx, z);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string from(reinterpret_cast<const char*>(&kSentinel), sizeof kSentinel);
  const std::size_t at = bytes.find(from);
  if (at == std::string::npos || bytes.find(from, at + 1) != std::string::npos)
    throw std::logic_error("poke_h5: the sentinel is not in the file exactly once");
  bytes.replace(at, sizeof bad, reinterpret_cast<const char*>(&bad), sizeof bad);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

std::vector<double> rough(std::size_t n, double rq, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, rq);
  std::vector<double> z(n);
  for (double& v : z) v = normal(rng);
  return z;
}

// A text height grid of n x n Gaussian heights (in file units) with the given header lines.
std::string grid_text(const std::string& header, int n, double rq) {
  std::string out = header;
  const auto z = rough(static_cast<std::size_t>(n) * n, rq);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) out += fmt::format("{}{:.6g}", i ? " " : "", z[static_cast<std::size_t>(j) * n + i]);
    out += '\n';
  }
  return out;
}

}  // namespace

TEST(Topography, Hdf5SpacingAttributeMustBeOneNumber) {
  // A scalar and a one-element array are one number; an array of two is refused, never read into
  // one double (the stack overflow of corpus 01), and an array dy is no longer replaced by dx.
  EXPECT_NEAR(io::read_topography(corpus(kAttributes, "dx-one-element.h5")).dx, 5e-7, 1e-20);
  const std::string two = input_error([] { io::read_topography(corpus(kAttributes, "dx-array.h5")); });
  EXPECT_TRUE(has(two, "dx-array.h5: key '/z dx': attribute dx holds 2 values, not one number")) << two;
  const std::string dy = input_error([] { io::read_topography(corpus(kAttributes, "dy-array.h5")); });
  EXPECT_TRUE(has(dy, "dy-array.h5: key '/z dy': attribute dy holds 64 values")) << dy;
  const std::string text = input_error([] { io::read_topography(corpus(kAttributes, "dx-string.h5")); });
  EXPECT_TRUE(has(text, "attribute dx is not a floating-point number")) << text;
  // The spacing limits: 1e-12 m and 1000 m are read, beyond them refused.
  EXPECT_NEAR(io::read_topography(corpus(kAttributes, "dx-min.h5")).dx, kMinSpacing, 1e-27);
  EXPECT_NEAR(io::read_topography(corpus(kAttributes, "dx-max.h5")).dx, kMaxSpacing, 1e-12);
  const std::string below = input_error([] { io::read_topography(corpus(kAttributes, "dx-below.h5")); });
  EXPECT_TRUE(has(below, "key '/z dx' = 9.9e-13: spacing 9.9e-13 m outside 1e-12 m to 1000 m")) << below;
  const std::string above = input_error([] { io::read_topography(corpus(kAttributes, "dx-above.h5")); });
  EXPECT_TRUE(has(above, "key '/z dx' = 1000.5: spacing 1000.5 m outside")) << above;
}

TEST(Topography, Hdf5DeclaredSizeIsCheckedBeforeAllocating) {
  // At the limit (8192 x 4096 = kMaxGridPoints) the size passes and the next check speaks (the
  // chunks were never written); one row more is refused on the size. Neither allocates the grid.
  static_assert(8192u * 4096u == kMaxGridPoints);
  const std::string at = input_error([] { io::read_topography(corpus(kSizes, "at-limit.h5")); });
  EXPECT_TRUE(has(at, "key '/z' = 4096 x 8192: the file does not store all of /z's values")) << at;
  const std::string past = input_error([] { io::read_topography(corpus(kSizes, "past-limit.h5")); });
  EXPECT_TRUE(has(past, "key '/z' = 4097 x 8192: more than 33554432 points")) << past;
  // The grids themselves: one point past the limit is refused before any allocation.
  EXPECT_THROW(make_grid(8193, 4096, 1e-6, 1e-6), std::invalid_argument);
  EXPECT_THROW(make_grid(1 << 20, 1 << 20, 1e-6, 1e-6), std::invalid_argument);  // 2^40: no wrap
  EXPECT_EQ(make_grid(8192, 4096, 1e-6, 1e-6).size(), kMaxGridPoints);
}

TEST(Topography, Hdf5HeightsMustBeFiniteNaNMarksMissing) {
  auto z = rough(64, 0.3e-6);
  z[10] = std::numeric_limits<double>::quiet_NaN();
  const HeightGrid g = io::read_topography(write_h5("nan.h5", 8, 8, z));
  EXPECT_EQ(g.missing(), 1u);  // the documented marker
  for (double bad : {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 1.0000001}) {
    z[10] = 0.0;  // z[19]: row 2, column 3
    const std::string e = input_error([&] { io::read_topography(poke_h5("inf.h5", 8, 8, z, 19, bad)); });
    EXPECT_TRUE(has(e, "inf.h5: key '/z[2][3]'")) << e;
    EXPECT_TRUE(has(e, "beyond +-1 m")) << e;
  }
  z[19] = -1.0;  // at the limit
  EXPECT_NO_THROW(io::read_topography(write_h5("one-metre.h5", 8, 8, z)));
}

TEST(Topography, HeaderNumbersAreReadWithTheirExponent) {
  // '# spacing: 5e-1' is 0.5 in the file's unit (um), as '0.5' is; the 'e' is never a unit.
  for (const char* spacing : {"0.5", "5e-1", "5E-1", "0.5 um", "5e-1 um", "5e-1um", "5e-7 m"}) {
    const HeightGrid g =
        io::read_topography(write_text("exp.txt", grid_text(fmt::format("# spacing: {}\n", spacing), 4, 0.3)));
    EXPECT_NEAR(g.dx, 0.5e-6, 1e-18) << spacing;
  }
  const HeightGrid mm = io::read_topography(write_text("exp.txt", grid_text("# spacing: 5e-1 mm\n", 4, 0.3)));
  EXPECT_NEAR(mm.dx, 0.5e-3, 1e-15);
  const HeightGrid nm =
      io::read_topography(write_text("exp.txt", grid_text("# units: nm\n# dx: 5e2\n# dy: 2.5e+2\n", 4, 300)));
  EXPECT_NEAR(nm.dx, 0.5e-6, 1e-18);
  EXPECT_NEAR(nm.dy, 0.25e-6, 1e-18);
  const std::string e =
      input_error([] { io::read_topography(write_text("exp.txt", grid_text("# spacing: 5e-1 furlong\n", 4, 0.3))); });
  EXPECT_TRUE(has(e, "exp.txt:1: key 'spacing' = 5e-1 furlong")) << e;
  const std::string tiny =
      input_error([] { io::read_topography(write_text("exp.txt", grid_text("# spacing: 1e-320\n", 4, 0.3))); });
  EXPECT_TRUE(has(tiny, "spacing must be positive: 0 m after the unit")) << tiny;
}

TEST(Topography, TextLengthLimits) {
  // Spacing: 1e-12 m read, 0.99e-12 m refused with the unit hint; heights: 1 m read, beyond refused.
  EXPECT_NO_THROW(io::read_topography(write_text("lim.txt", grid_text("# spacing: 1e-12 m\n", 4, 0.3))));
  const std::string fine =
      input_error([] { io::read_topography(write_text("lim.txt", grid_text("# spacing: 0.99e-6\n", 4, 0.3))); });
  EXPECT_TRUE(has(fine,
                  "lim.txt:1: key 'spacing' = 0.99e-6: spacing 9.9e-13 m outside 1e-12 m to 1000 m; lengths were "
                  "read in um (no '# units:' line)"))
      << fine;
  EXPECT_NO_THROW(io::read_topography(write_text("lim.txt", "# units: m\n# spacing: 1e-6\n1 0 0\n0 -1 0\n0 0 1\n")));
  const std::string high =
      input_error([] { io::read_topography(write_text("lim.txt", "# spacing: 1\n1 2 3\n4 1e308 6\n7 8 9\n")); });
  EXPECT_TRUE(has(high, "lim.txt:3: 1e308: height 1e+302 m beyond +-1 m; lengths were read in um")) << high;
  const std::string metre = input_error(
      [] { io::read_topography(write_text("lim.txt", "# units: m\n# spacing: 1e-6\n1.000001 0 0\n0 -1 0\n0 0 1\n")); });
  EXPECT_TRUE(has(metre, "beyond +-1 m; lengths were read in m as the file's '# units:' line says")) << metre;
  const std::string far = input_error([] { io::read_topography(write_text("far.xyz", "0 0 1\n1e10 0 2\n")); });
  EXPECT_TRUE(has(far, "far.xyz:2: key 'x' = 1e10: coordinate 10000 m beyond +-1000 m")) << far;
}

TEST(Topography, PointCloudLatticeAtMostFourCellsAPoint) {
  // 11 points covering every x and y of their lattice: 4 x 11 = 44 cells is 4 a point (read, the
  // rest missing); 5 x 9 = 45 cells is one past (refused before the lattice is allocated).
  auto cloud = [](int nx, int ny, int points) {
    std::string out;
    for (int k = 0; k < points; ++k) out += fmt::format("{} {} {}\n", k % nx, k % ny, 0.1 * (k % 3));
    return out;
  };
  const HeightGrid g = io::read_topography(write_text("at.xyz", cloud(4, 11, 11)));
  EXPECT_EQ(g.nx * g.ny, 44);
  EXPECT_EQ(g.size() - g.missing(), 11u);
  const std::string past = input_error([&] { io::read_topography(write_text("past.xyz", cloud(5, 9, 11))); });
  EXPECT_TRUE(has(past, "past.xyz:1: key 'lattice' = 5 x 9 from 11 points: fewer than one point per 4 lattice cells"))
      << past;
  // A resampling spacing that would give too many points names the file and the key.
  io::TopographyReadOptions o;
  o.resample = 1e-11;
  const std::string fine = input_error([&] { io::read_topography(write_text("at.xyz", cloud(4, 11, 11)), o); });
  EXPECT_TRUE(has(fine, "at.xyz: key 'resample' = 1e-11 m: spacing 1e-11 m gives")) << fine;
}

TEST(Topography, ImplausibleUnitDrawsAWarningNamingTheFix) {
  CleanupOptions clean;
  clean.form_degree = 0;
  // Heights in metres (Rq 3e-7) read as um: Rq 3e-13 m, a warning naming '# units:' and --unit.
  const auto metres = write_text("metres.txt", grid_text("# spacing: 0.5 um\n", 16, 0.3e-6));
  const io::LoadedSurface as_um = io::load_surface(metres, {}, clean);
  ASSERT_EQ(as_um.warnings.size(), 1u);
  EXPECT_TRUE(has(as_um.warnings[0], "metres.txt: warning: Rq ")) << as_um.warnings[0];
  EXPECT_TRUE(has(as_um.warnings[0], "'# units: <unit>' line or --unit")) << as_um.warnings[0];
  io::TopographyReadOptions si;
  si.unit = 1.0;
  EXPECT_TRUE(io::load_surface(metres, si, clean).warnings.empty());
  // The bounds: Rq just inside 1 nm and 100 um passes, just outside (0.99 nm, 101 um) warns.
  auto rq_warnings = [&](double rq_um) {
    const auto path = write_text("rq.txt", grid_text("# spacing: 0.5 um\n", 16, 1.0));
    HeightGrid g = io::read_topography(path);
    double mean = 0.0, var = 0.0;
    for (double z : g.z) mean += z / g.size();
    for (double z : g.z) var += (z - mean) * (z - mean) / g.size();
    for (double& z : g.z) z = (z - mean) / std::sqrt(var) * rq_um * 1e-6;
    return io::unit_warnings("rq.txt", g, 1e-6, false).size();
  };
  EXPECT_EQ(rq_warnings(1.0001e-3), 0u);
  EXPECT_EQ(rq_warnings(99.99), 0u);
  EXPECT_EQ(rq_warnings(0.99e-3), 1u);
  EXPECT_EQ(rq_warnings(101.0), 1u);
  // Spacing: a cloud in metres at 10 um read as um (1e-11 m); an HDF5 file names its metres.
  std::string cloud = "X(m) Y(m) Z(m)\n";
  const auto z = rough(144, 0.3e-6);
  for (int k = 0; k < 144; ++k) cloud += fmt::format("{:g} {:g} {:g}\n", (k % 12) * 1e-5, (k / 12) * 1e-5, z[k]);
  const auto w = io::load_surface(write_text("coarse.xyz", cloud), {}, clean).warnings;
  ASSERT_EQ(w.size(), 2u);
  EXPECT_TRUE(has(w[0], "coarse.xyz: warning: spacing 1e-11 m x 1e-11 m is implausible")) << w[0];
  const auto h5 = io::load_surface(write_h5("um-heights.h5", 8, 8, rough(64, 0.2)), {}, clean).warnings;
  ASSERT_EQ(h5.size(), 1u);
  EXPECT_TRUE(has(h5[0], "an HDF5 topography holds metres")) << h5[0];
}

TEST(Topography, WavinessCutOffBoundedByTheGrid) {
  HeightGrid g = make_grid(48, 20, 0.5e-6, 0.5e-6);
  g.z = rough(g.size(), 0.3e-6);
  const double side = 47 * 0.5e-6;
  HeightGrid a = g, b = g, c = g, d = g;
  EXPECT_NO_THROW(remove_waviness(a, side));  // the longer side: allowed
  EXPECT_NO_THROW(remove_waviness(b, 1e-6));  // two spacings: allowed
  try {
    remove_waviness(c, side * 1.001);
    ADD_FAILURE() << "a cut-off longer than the surface";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(has(e.what(), "is longer than the surface")) << e.what();
  }
  EXPECT_THROW(remove_waviness(d, 0.999e-6), std::invalid_argument);
  HeightGrid e = g;
  EXPECT_THROW(remove_waviness(e, 1e300), std::invalid_argument);  // was an int overflow
  for (const auto& s : {a, b})
    for (double z : s.z) EXPECT_TRUE(std::isfinite(z));
}

TEST(Topography, WavinessFilterEqualsTheDirectSumOnMaskedGrids) {
  // The filter against the weighted mean summed point by point (the definition), with missing
  // points, for short kernels (summed directly) and long ones (by FFT): to 1e-12 of the heights.
  HeightGrid g = make_grid(300, 41, 0.5e-6, 0.7e-6);
  g.z = rough(g.size(), 1e-6, 9);
  std::mt19937 rng(4);
  for (auto& v : g.valid) v = rng() % 7 != 0;
  for (int j = 10; j < 20; ++j)
    for (int i = 100; i < 180; ++i) g.valid[static_cast<std::size_t>(j) * g.nx + i] = 0;  // a hole
  const double alpha = std::sqrt(std::log(2.0) / std::numbers::pi);
  for (double cutoff : {5e-6, 20e-6, 140e-6}) {  // kernels of 21, 81 and 561 x (the FFT) weights
    HeightGrid f = g;
    const HeightGrid waviness = remove_waviness(f, cutoff);
    const int hx = std::min(static_cast<int>(std::ceil(cutoff / g.dx)), g.nx - 1);
    const int hy = std::min(static_cast<int>(std::ceil(cutoff / g.dy)), g.ny - 1);
    auto weight = [&](int k, double h) { return std::exp(-std::numbers::pi * std::pow(k * h / (alpha * cutoff), 2)); };
    double worst = 0.0;
    for (int j = 0; j < g.ny; j += 3)
      for (int i = 0; i < g.nx; i += 7) {
        if (!g.ok(i, j)) continue;
        double s = 0.0, w = 0.0;
        for (int jj = std::max(0, j - hy); jj <= std::min(g.ny - 1, j + hy); ++jj)
          for (int ii = std::max(0, i - hx); ii <= std::min(g.nx - 1, i + hx); ++ii)
            if (g.ok(ii, jj)) {
              const double wt = weight(ii - i, g.dx) * weight(jj - j, g.dy);
              s += wt * g.at(ii, jj), w += wt;
            }
        worst = std::max(worst, std::abs(waviness.at(i, j) - s / w));
        EXPECT_NEAR(f.at(i, j), g.at(i, j) - waviness.at(i, j), 1e-20);
      }
    EXPECT_LT(worst, 1e-12 * 1e-6) << cutoff;
  }
}

TEST(Topography, FillingIsRingByRingAndLinear) {
  // Against the pass-by-pass definition on a random mask.
  HeightGrid g = make_grid(30, 20, 1e-6, 1e-6);
  g.z = rough(g.size(), 1e-6, 3);
  std::mt19937 rng(8);
  for (auto& v : g.valid) v = rng() % 5 == 0;
  HeightGrid reference = g;
  while (reference.missing() > 0) {
    HeightGrid next = reference;
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        if (reference.ok(i, j)) continue;
        double s = 0.0;
        int c = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int ii = i + di, jj = j + dj;
            if ((di || dj) && ii >= 0 && ii < g.nx && jj >= 0 && jj < g.ny && reference.ok(ii, jj))
              s += reference.at(ii, jj), ++c;
          }
        if (c) next.at(i, j) = s / c, next.valid[static_cast<std::size_t>(j) * g.nx + i] = 1;
      }
    reference = next;
  }
  fill_missing(g);
  for (std::size_t k = 0; k < g.size(); ++k) EXPECT_EQ(g.z[k], reference.z[k]) << k;
  // 9 valid points in a corner of 2000 x 2000 (once ~2000 passes over 4e6 points): one pass a ring.
  HeightGrid big = make_grid(2000, 2000, 1e-6, 1e-6);
  std::fill(big.valid.begin(), big.valid.end(), 0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) big.at(i, j) = 1e-6, big.valid[static_cast<std::size_t>(j) * big.nx + i] = 1;
  fill_missing(big);
  EXPECT_EQ(big.missing(), 0u);
  EXPECT_EQ(big.at(1999, 1999), 1e-6);
}

TEST(Topography, GeneratorsRefuseWhatWouldGiveNaN) {
  SelfAffineSpec s;
  s.nx = s.ny = 32;
  s.spacing = 1e-300;  // was exit 0 writing NaN
  EXPECT_THROW(self_affine_surface(s), std::invalid_argument);
  s.spacing = kMinSpacing;
  s.cutoff_wavelength = 4 * kMinSpacing;
  s.rolloff_wavelength = 10 * kMinSpacing;
  for (double z : self_affine_surface(s).z) ASSERT_TRUE(std::isfinite(z));
  SelfAffineSpec wide;
  wide.nx = wide.ny = 32;
  wide.cutoff_wavelength = 1.0;  // no wavevector of the grid inside the spectrum: was 0/0
  wide.rolloff_wavelength = 2.0;
  EXPECT_THROW(self_affine_surface(wide), std::invalid_argument);
  HobbedSpec h;
  h.tip_radius = 1e-300;  // ridges of 1e288 m
  EXPECT_THROW(hobbed_surface(h), std::invalid_argument);
}

// The writer refuses what every reader refuses (issue 30, finding 13: gt.write_surface wrote files
// gt.read_surface refused): heights beyond +-kMaxHeight, fewer than 9 valid points; nothing written.
TEST(Topography, WriterRefusesWhatTheReadersRefuse) {
  for (const char* ext : {".x3p", ".h5", ".csv", ".xyz"}) {
    HeightGrid g = make_grid(4, 4, 0.5e-6, 0.5e-6);
    g.z[5] = 1.5 * kMaxHeight;
    const auto huge = temp(std::string("huge") + ext);
    EXPECT_THROW(io::write_topography(huge, g), std::invalid_argument) << ext;
    EXPECT_FALSE(std::filesystem::exists(huge)) << ext;
    g.z[5] = -kMaxHeight;  // the edge: written and read back
    for (std::size_t k = 9; k < g.size(); ++k) g.valid[k] = 0;
    const auto edge = temp(std::string("edge") + ext);
    io::write_topography(edge, g);
    const HeightGrid back = io::read_topography(edge);
    EXPECT_EQ(back.size() - back.missing(), 9u) << ext;
    g.valid[8] = 0;  // 8 valid points
    const auto sparse = temp(std::string("sparse") + ext);
    EXPECT_THROW(io::write_topography(sparse, g), std::invalid_argument) << ext;
    EXPECT_FALSE(std::filesystem::exists(sparse)) << ext;
  }
}
