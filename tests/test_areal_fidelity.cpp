// The areal fidelity of the mesh cycle (contact/areal/mesh_areal.hpp) and its flanks: the isotropic
// Gaussian surface's statistics (surface/synthetic_surface.hpp gaussian_surface), the extruded
// flanks against the profile fidelity on the same flanks (the two solve the same line contact), and
// its refusals at the key.
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/input_error.hpp"
#include "contact/mesh_contact.hpp"
#include "runs/mesh_cycle.hpp"
#include "surface/synthetic_surface.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

using namespace geartrib;

namespace {
Case areal_case(const std::vector<io::CaseChange>& changes) {
  return io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-areal.toml", changes));
}
const std::vector<double>& values(const contact::MeshContactResult& r, const std::string& name) {
  const contact::Series* s = r.find(name);
  if (!s) throw std::logic_error("no series " + name);
  return s->values;
}
}  // namespace

TEST(GaussianSurface, RqExactAndTheProfileAutocorrelationInBothDirections) {
  // ACF Rq^2 exp(-r^2/lambda^2): at a lag of lambda e^-1 = 0.368, at lambda/2 e^-1/4 = 0.779, in
  // either direction (isotropic). 1024 x 1024 points, lambda 16 points: about 4000 correlation areas,
  // the estimates' scatter about 0.02 (1/sqrt(4000) x 1.3).
  surface::GaussianSurfaceSpec s;
  s.nx = s.ny = 1024;
  s.dx = s.dy = 1e-6;
  s.rq = 0.3e-6;
  s.correlation_length = 16e-6;
  s.seed = 9;
  const surface::HeightGrid g = surface::gaussian_surface(s);
  double var = 0.0, mean = 0.0;
  for (double z : g.z) mean += z, var += z * z;
  EXPECT_NEAR(mean / static_cast<double>(g.size()), 0.0, 1e-20);
  EXPECT_NEAR(std::sqrt(var / static_cast<double>(g.size())), s.rq, 1e-15);
  for (bool along_x : {true, false}) {
    EXPECT_NEAR(test::autocorrelation(g, 16, along_x), std::exp(-1.0), 0.04) << along_x;
    EXPECT_NEAR(test::autocorrelation(g, 8, along_x), std::exp(-0.25), 0.04) << along_x;
  }
  // Periodic along y: the last row is the first row's neighbour, correlated as rows one point apart
  // are (exp(-1/256) = 0.996; rows of an open field that far apart would not be: about 0).
  double cross = 0.0, first = 0.0, last = 0.0;
  for (int i = 0; i < g.nx; ++i)
    cross += g.at(i, g.ny - 1) * g.at(i, 0), first += g.at(i, 0) * g.at(i, 0),
        last += g.at(i, g.ny - 1) * g.at(i, g.ny - 1);
  EXPECT_GT(cross / std::sqrt(first * last), 0.98);
  // Refused: a correlation length under two spacings, no points.
  s.correlation_length = 1.5e-6;
  EXPECT_THROW(surface::gaussian_surface(s), std::invalid_argument);
}

TEST(ArealFidelity, ExtrudedFlanksAgreeWithTheProfileFidelity) {
  // The profile repeated across the face is the line contact the deterministic fidelity solves:
  // the same flanks' real area at A, C and E within 1 % (the maps sample the profiles' element means
  // by linear interpolation at the contact point's arc, the strip averages the profile over each
  // element: measured equal to 1e-4 at 0.5 um), the peak pressure the hardness in both (45 steel,
  // 1.17 GPa).
  const Case areal = areal_case({{"areal.lay", "extruded"},
                                 {"positions", "3"},
                                 {"areal.points", "4"},
                                 {"element_size", "1um"},
                                 {"contact.outputs", "[\"real_area\", \"plastic_fraction\"]"}});
  const Case profile = areal_case({{"contact.fidelity", "deterministic"},
                                   {"positions", "3"},
                                   {"element_size", "1um"},
                                   {"contact.outputs", "[\"real_area\", \"plastic_fraction\"]"}});
  const contact::MeshContactResult a = runs::run_mesh_cycle(areal), d = runs::run_mesh_cycle(profile);
  EXPECT_EQ(a.fidelity, "areal");
  const auto &ra = values(a, "real_area_ratio"), &rd = values(d, "real_area_ratio");
  ASSERT_EQ(ra.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(ra[k] / rd[k], 1.0, 0.01) << k;
    EXPECT_NEAR(values(a, "max_pressure_Pa")[k], values(d, "max_pressure_Pa")[k],
                1e-6 * values(d, "max_pressure_Pa")[k]);
  }
  EXPECT_EQ(values(a, "flag_not_converged"), std::vector<double>(3, 0.0));
  EXPECT_FALSE(a.statistical.empty());  // the statistical model beside it, on the same profiles
}

TEST(ArealFidelity, PerssonBesideIsItsOwnStage) {
  // `geartrib tradeoff`'s ladder times Persson's theory by its stage: both rolling fidelities record
  // it, last (it runs as they write), beside its three series.
  const std::vector<io::CaseChange> cheap = {{"positions", "3"}, {"element_size", "1um"}};
  std::vector<io::CaseChange> areal = cheap, profile = cheap;
  areal.insert(areal.end(), {{"areal.lay", "extruded"}, {"areal.points", "4"}});
  profile.push_back({"contact.fidelity", "deterministic"});
  for (const auto& changes : {areal, profile}) {
    const contact::MeshContactResult r = runs::run_mesh_cycle(areal_case(changes));
    ASSERT_FALSE(r.stages.empty()) << r.fidelity;
    EXPECT_EQ(r.stages.back().name, "persson_beside") << r.fidelity;
    EXPECT_GE(r.stages.back().seconds, 0.0) << r.fidelity;
    EXPECT_EQ(values(r, "statistical_persson_real_area_ratio").size(), 3u) << r.fidelity;
  }
}

TEST(ArealFidelity, RefusesAtTheKey) {
  auto key_of = [](const Case& c) {
    try {
      runs::run_mesh_cycle(c);
    } catch (const io::InputError& e) {
      return e.key();
    } catch (const std::exception& e) {
      return std::string("other: ") + e.what();
    }
    return std::string("none");
  };
  // A window narrower than the flanks' correlation length (10 um).
  EXPECT_EQ(key_of(areal_case({{"positions", "2"}, {"areal.window", "8um"}, {"areal.points", "16"}})), "areal.window");
  // An isotropic map of a hobbed flank.
  EXPECT_EQ(key_of(areal_case({{"positions", "2"}, {"pinion.flank.profile.kind", "hobbed"}})), "areal.lay");
  // The correlation length across fewer than two points.
  EXPECT_EQ(key_of(areal_case({{"positions", "2"}, {"areal.window", "256um"}, {"areal.points", "16"}})),
            "areal.points");
}

TEST(ArealFidelity, DirectionalLayOfRatioOneIsTheIsotropicMap) {
  // The directional map's correlation across the face is lay_ratio times that along the involute:
  // at 1 it is the isotropic map, bit for bit; a long lay changes the answer.
  const std::vector<io::CaseChange> base = {
      {"positions", "2"}, {"areal.points", "32"}, {"areal.window", "32um"}, {"element_size", "1um"}};
  auto with = [&](std::vector<io::CaseChange> more) {
    more.insert(more.end(), base.begin(), base.end());
    return runs::run_mesh_cycle(areal_case(more));
  };
  const contact::MeshContactResult iso = with({{"areal.lay", "isotropic"}});
  const contact::MeshContactResult one = with({{"areal.lay", "directional"}, {"areal.lay_ratio", "1"}});
  const contact::MeshContactResult long_lay = with({{"areal.lay", "directional"}, {"areal.lay_ratio", "8"}});
  EXPECT_EQ(values(iso, "real_area_ratio"), values(one, "real_area_ratio"));
  EXPECT_EQ(values(iso, "contact_spots"), values(one, "contact_spots"));
  EXPECT_NE(values(iso, "real_area_ratio"), values(long_lay, "real_area_ratio"));
  // Persson beside it on the maps' full gradient, the same factor (2) for both. (The 45 steel flanks
  // are fully plastic in Persson's theory, A = p/H, whatever the gradient: a lay's does not show here.)
  auto persson = [](const contact::MeshContactResult& r) {
    for (const auto& s : r.statistical)
      if (s.name == "statistical_persson_real_area_ratio") return s.values;
    throw std::logic_error("no Persson series");
  };
  EXPECT_EQ(persson(iso), persson(one));
  // On case-hardened flanks (16MnCr5) Persson is elastic-plastic, and the lay's smaller full gradient
  // ((1 + 1/64) against 2 times the profiles' slope variance) gives it more real area at every position.
  const std::vector<io::CaseChange> hard = {{"pinion.material", "../materials/16MnCr5.toml"},
                                            {"wheel.material", "../materials/16MnCr5.toml"}};
  std::vector<io::CaseChange> a = hard, b = hard;
  a.push_back({"areal.lay", "isotropic"});
  b.insert(b.end(), {{"areal.lay", "directional"}, {"areal.lay_ratio", "8"}});
  const auto pa = persson(with(a)), pb = persson(with(b));
  for (std::size_t k = 0; k < pa.size(); ++k) EXPECT_GT(pb[k], 1.05 * pa[k]) << k;
}

TEST(ArealFidelity, ExtrudedRunningInAgreesWithTheProfileFidelitysOnTheSameFlanks) {
  // Maps that are the profiles repeated across the face stay so as they run in (every row the same
  // contact, the same plastic deformation): the profile fidelity's running-in on the same flanks. The
  // first two meshes' new plastic deformation and mean real area within 3 % (the maps hold the
  // profiles' element means and are lowered at their points, the profile fidelity's profiles at their
  // 0.125 um spacing: measured 0.6 % and 0.3 % on the first mesh, 2.1 % and 0.3 % on the second).
  const std::vector<io::CaseChange> common = {{"running_in.meshes", "2"},
                                              {"element_size", "1um"},
                                              {"positions", "50"},
                                              {"running_in.tolerance", "0.1nm"},
                                              {"contact.outputs", "[\"real_area\", \"plastic_fraction\"]"}};
  std::vector<io::CaseChange> a = common, d = common;
  a.insert(a.end(), {{"areal.lay", "extruded"}, {"areal.points", "4"}});
  d.push_back({"contact.fidelity", "deterministic"});
  const contact::MeshContactResult ra = runs::run_mesh_cycle(areal_case(a)), rd = runs::run_mesh_cycle(areal_case(d));
  ASSERT_TRUE(ra.running_in && rd.running_in);
  EXPECT_EQ(ra.running_in->meshes, 2);
  auto column = [](const contact::RunningInResult& r, const std::string& name) {
    for (const auto& s : r.history)
      if (s.name == name) return s.values;
    throw std::logic_error("no history column " + name);
  };
  const auto pa = column(*ra.running_in, "new_plastic_deformation_m"),
             pd = column(*rd.running_in, "new_plastic_deformation_m");
  const auto aa = column(*ra.running_in, "real_area_ratio_mean"), ad = column(*rd.running_in, "real_area_ratio_mean");
  ASSERT_EQ(pa.size(), 3u);  // before the first mesh, and after each
  for (std::size_t m = 1; m < 3; ++m) {
    EXPECT_NEAR(pa[m] / pd[m], 1.0, 0.03) << m;
    EXPECT_NEAR(aa[m] / ad[m], 1.0, 0.03) << m;
  }
  EXPECT_LT(pa[2], 0.5 * pa[1]);  // running in: the second mesh deforms far less than the first
  // The maps' rows stayed equal: the pinion's final profile is the same whatever row was kept.
  EXPECT_FALSE(ra.running_in->final[0].empty());
}

TEST(ArealFidelity, PatchLayMapsAMeasuredPatchAndRefusesOneSmallerThanASpot) {
  // gears/m6z30-measured.toml's 96 um patches (self-affine, a lay along x: along the involute)
  // synthesised or tiled into the flanks' maps.
  auto measured = [](const std::vector<io::CaseChange>& more) {
    std::vector<io::CaseChange> changes = {{"contact.fidelity", "areal"},
                                           {"areal.lay", "patch"},
                                           {"positions", "2"},
                                           {"areal.points", "32"},
                                           {"areal.window", "32um"},
                                           {"element_size", "1um"},
                                           {"contact.outputs", "[\"real_area\"]"}};
    changes.insert(changes.end(), more.begin(), more.end());  // later changes win
    return changes;
  };
  auto run = [](const std::vector<io::CaseChange>& changes) {
    return runs::run_mesh_cycle(
        io::prepare_case(io::load_case(test::source_dir() / "gears/m6z30-measured.toml", changes)));
  };
  const contact::MeshContactResult synth = run(measured({}));
  const contact::MeshContactResult tiled = run(measured({{"areal.patch", "tiled"}}));
  for (const auto* r : {&synth, &tiled}) {
    const auto& area = values(*r, "real_area_ratio");
    ASSERT_EQ(area.size(), 2u);
    for (double a : area) EXPECT_GT(a, 0.0);
  }
  EXPECT_NE(values(synth, "real_area_ratio"), values(tiled, "real_area_ratio"));
  auto key_of = [&](const std::vector<io::CaseChange>& changes) {
    try {
      run(changes);
    } catch (const io::InputError& e) {
      return e.key();
    } catch (const std::exception& e) {
      return std::string("other: ") + e.what();
    }
    return std::string("none");
  };
  // Elements finer than the patch's 0.25 um spacing; points across the face finer than it.
  EXPECT_EQ(key_of(measured({{"element_size", "0.2um"}})), "contact.element_size");
  EXPECT_EQ(key_of(measured({{"areal.points", "256"}})), "areal.points");
  // A patch shorter than one of its hills along x: 12 x 200 points of 0.25 um (3 um x 50 um), ridges
  // 5 um apart across y with a 1 um ripple along x; its profile elements along x are RSm = 2 pi
  // sqrt(m0/m2x) = 4.6 um apart (its summits are there: the statistics take it).
  const auto dir = std::filesystem::temp_directory_path() / "geartrib-small-patch";
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "small.txt");
    f << "# units: um\n# spacing: 0.25 um\n";
    const double pi = 3.14159265358979;
    for (int j = 0; j < 200; ++j) {
      for (int i = 0; i < 12; ++i)
        f << (i ? " " : "") << 0.5 * std::sin(2.0 * pi * j * 0.25 / 5.0) + 0.05 * std::sin(2.0 * pi * i * 0.25);
      f << "\n";
    }
  }
  EXPECT_EQ(key_of(measured({{"pinion.flank.topography.file", (dir / "small.txt").string()}})),
            "pinion.flank.topography.file");
  std::filesystem::remove_all(dir);
}
