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
// The autocorrelation of the grid's heights at a lag of k points along x (or y, cyclic), over Rq^2.
double autocorrelation(const surface::HeightGrid& g, int k, bool along_x) {
  double sum = 0.0, var = 0.0;
  std::size_t n = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      var += g.at(i, j) * g.at(i, j);
      if (along_x && i + k >= g.nx) continue;
      sum += g.at(i, j) * (along_x ? g.at(i + k, j) : g.at(i, (j + k) % g.ny)), ++n;
    }
  return sum / static_cast<double>(n) / (var / static_cast<double>(g.size()));
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
    EXPECT_NEAR(autocorrelation(g, 16, along_x), std::exp(-1.0), 0.04) << along_x;
    EXPECT_NEAR(autocorrelation(g, 8, along_x), std::exp(-0.25), 0.04) << along_x;
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
