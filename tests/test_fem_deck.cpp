// CalculiX decks and result files, without running ccx: the mesh is valid (positive element
// areas, the surface on the paraboloid), the deck respects ccx's input limits, and the .frd/.dat
// readers read the fixed-width formats.
#include "fem/asperity_deck.hpp"
#include "fem/ccx_results.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace geartrib::fem;

namespace {
SingleAsperitySpec spec() {
  SingleAsperitySpec s;
  s.modulus = 113.19e9;
  s.yield_strength = 418e6;
  s.critical_interference_over_radius = 8.8e-5;
  s.delta_star = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  s.material = FemMaterial::perfectly_plastic;
  s.refine = 8;
  return s;
}
std::vector<std::string> lines_after(const std::string& text, const std::string& keyword) {
  std::vector<std::string> out;
  std::istringstream in(text.substr(text.find(keyword)));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line) && line[0] != '*') out.push_back(line);
  return out;
}
// Every 8-node element under `keyword` has counter-clockwise corners (positive shoelace area;
// ccx stops with "nonpositive jacobian" otherwise); returns how many elements there are.
int check_element_areas(const std::string& text, const std::string& keyword,
                        const std::map<int, std::pair<double, double>>& node) {
  int count = 0;
  for (const auto& l : lines_after(text, keyword)) {
    std::istringstream in(l);
    std::vector<int> n;
    int v = 0;
    char c = 0;
    in >> v;
    while (in >> c >> v) n.push_back(v);
    EXPECT_EQ(n.size(), 8u);
    if (n.size() != 8u) continue;
    double area = 0.0;
    for (int k = 0; k < 4; ++k) {
      const auto [x0, y0] = node.at(n[k]);
      const auto [x1, y1] = node.at(n[(k + 1) % 4]);
      area += x0 * y1 - x1 * y0;
    }
    EXPECT_GT(area, 0.0);
    ++count;
  }
  return count;
}
}  // namespace

TEST(FemDeck, MeshIsValidAndTheSurfaceIsTheParaboloid) {
  const SingleAsperityDeck d = single_asperity_deck(spec());
  std::map<int, std::pair<double, double>> node;
  for (const auto& l : lines_after(d.text, "*NODE, NSET=NASP")) {
    int id = 0;
    double x = 0, y = 0;
    char c = 0;
    std::istringstream(l) >> id >> c >> x >> c >> y;
    node[id] = {x, y};
  }
  const int count = check_element_areas(d.text, "*ELEMENT, TYPE=CAX8", node);
  EXPECT_EQ(count, d.elements);
  for (std::size_t k = 0; k < d.top_nodes.size(); ++k) {
    const auto [x, y] = node.at(d.top_nodes[k]);
    EXPECT_NEAR(y, -x * x / 2.0, 1e-11 * (x * x + 1e-300));  // y = -r^2/(2R), R = 1 mm; 13 digits printed
  }
  // The first surface cell at the axis is tiny (its face collapses in ccx's wedge expansion).
  EXPECT_LT(d.top_node_r[2], 0.25 * d.tip_element);
}

TEST(FemDeck, RespectsCcxInputLimits) {
  const SingleAsperityDeck d = single_asperity_deck(spec());
  std::istringstream in(d.text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("**", 0) == 0 || line[0] == '*') continue;
    std::istringstream f(line);
    std::string field;
    while (std::getline(f, field, ',')) EXPECT_LE(field.size(), 21u) << line;  // ccx cuts fields beyond 20 characters
  }
  // One step per level (ccx 2.20 can stall on *TIME POINTS); NLGEOM from the first step.
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (auto p = d.text.find(what); p != std::string::npos; p = d.text.find(what, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("*STEP"), 10u);
  EXPECT_EQ(count("*STEP, NLGEOM"), 1u);
  EXPECT_EQ(count("*TIME POINTS"), 0u);
  EXPECT_NE(d.text.find("*STEP, NLGEOM"), std::string::npos);  // plastic runs: large deformation
  EXPECT_NE(d.text.find("*PLASTIC"), std::string::npos);
  SingleAsperitySpec bad = spec();
  bad.delta_star = {2, 1};
  EXPECT_THROW(single_asperity_deck(bad), std::invalid_argument);
  bad = spec();
  bad.delta_star = {1e4};
  EXPECT_THROW(single_asperity_deck(bad), std::invalid_argument);  // beyond the small-slope paraboloid
}

TEST(FemResults, ReadsFrdAndDatFormats) {
  const auto dir = std::filesystem::temp_directory_path();
  {
    std::ofstream frd(dir / "geartrib-test.frd");
    frd << "    1C\n"
        << "  100CL  101 2.000000000         2                     0    1           1\n"
        << " -4  DISP        4    1\n"
        << " -5  D1          1    2    1    0\n"
        << " -1         1 1.00000E-03-2.50000E-04 0.00000E+00\n"
        << " -1        12-1.00000E+00 3.00000E+02 0.00000E+00\n"
        << " -3\n";
    std::ofstream dat(dir / "geartrib-test.dat");
    dat << "\n total force (fx,fy,fz) for set NFLAT and time  0.2000000E+01\n\n   1.0E-05  -3.5E+00   0.0E+00\n";
  }
  const auto f = read_frd(dir / "geartrib-test.frd");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "DISP");
  EXPECT_DOUBLE_EQ(f[0].time, 2.0);
  EXPECT_DOUBLE_EQ(f[0].values.at(1)[1], -2.5e-4);  // adjacent fixed-width fields without a space
  EXPECT_DOUBLE_EQ(f[0].values.at(12)[0], -1.0);
  const auto t = read_dat_totals(dir / "geartrib-test.dat");
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t[0][0], 2.0);
  EXPECT_DOUBLE_EQ(t[0][2], -3.5);
}

TEST(FemDeck, LevelsAreGroupedIntoRunsThatResolveTheirFirstContact) {
  const auto runs = plan_runs({1, 2, 6, 10, 20, 50, 100});
  ASSERT_EQ(runs.size(), 3u);  // [1, 2], [6, 10, 20], [50, 100]: each within a factor 4
  EXPECT_EQ(runs[0], (std::vector<double>{1, 2}));
  EXPECT_EQ(runs[1], (std::vector<double>{6, 10, 20}));
  EXPECT_EQ(runs[2], (std::vector<double>{50, 100}));
  SingleAsperitySpec s = spec();
  s.delta_star = {1, 4};
  const SingleAsperityDeck d = single_asperity_deck(s);
  EXPECT_NEAR(d.tip_element, std::sqrt(s.critical_interference_over_radius) / s.refine,
              1e-15);  // a(delta* = 1) / refine
}

TEST(FemDeck, CylinderMeshIsValidAndFollowsTheProfile) {
  CylindersSpec s;
  for (int k = 0; k < 3; ++k) s.cylinders.push_back({(k - 1) * 0.5e-6, k == 1 ? -2e-9 : 0.0, 6.6e-6});
  s.youngs_modulus = 206e9;
  s.yield_strength = 418e6;
  s.unit = 0.5797e-9;
  s.levels = {2, 4, 6};
  s.refine = 6;
  const CylindersDeck d = cylinders_deck(s);
  std::map<int, std::pair<double, double>> node(d.node_xy.begin(), d.node_xy.end());
  const int count = check_element_areas(d.text, "*ELEMENT, TYPE=CPE8", node);
  EXPECT_EQ(count, d.elements);
  // The surface is the highest of the parabolas (mm): the middle tip 2 nm low, the outer at 0.
  for (std::size_t k = 0; k < d.top_x.size(); ++k) {
    double y = -4e-3;
    for (const auto& c : s.cylinders)
      y = std::max(y, c.tip * 1e3 - std::pow(d.top_x[k] - c.centre * 1e3, 2) / (2.0 * c.radius * 1e3));
    EXPECT_NEAR(d.top_y[k], y, 1e-15);
  }
  s.levels = {10000};
  EXPECT_THROW(cylinders_deck(s), std::invalid_argument);  // approach beyond half the asperity height
}

TEST(FemResults, ContactIntervalsPlaceTheEdgesWhereTheGapOpens) {
  // A gap that opens as (|x| - 1)^(3/2) outside a zone of penetration: edges at -1 and 1.
  std::vector<double> x, gap;
  for (int i = -30; i <= 30; ++i) {
    const double xi = 0.1 * i + 0.013;
    x.push_back(xi);
    gap.push_back(std::abs(xi) < 1.0 ? -1e-3 * (1.0 - xi * xi) : std::pow(std::abs(xi) - 1.0, 1.5));
  }
  const auto zones = contact_intervals(x, gap);
  ASSERT_EQ(zones.size(), 1u);
  EXPECT_NEAR(zones[0].first, -1.0, 1e-9);  // exact for the 3/2 power law
  EXPECT_NEAR(zones[0].second, 1.0, 1e-9);
}

TEST(FemResults, ARimNodeBarelyOpenIsSkipped) {
  // As in a penalty contact: the node just inside the true edge shows a tiny positive gap; the
  // edge comes from the next two nodes, which follow the 3/2 law from the true edge at 1.
  const std::vector<double> x{0.0, 0.5, 0.95, 1.1, 1.3};
  std::vector<double> gap{-1e-3, -8e-4, 1e-6};
  for (double xi : {1.1, 1.3}) gap.push_back(std::pow(xi - 1.0, 1.5));
  const auto zones = contact_intervals(x, gap);
  ASSERT_EQ(zones.size(), 1u);
  EXPECT_NEAR(zones[0].second, 1.0, 1e-9);
}

TEST(FemResults, SurfaceYieldShareIsTheYieldedAreaOverTheContactDisc) {
  // Surface nodes at (k + 1/2) h: the midpoints between them, where a yielded/unyielded boundary
  // is placed, fall on multiples of h, so boundaries at 0.5 a and the edge a = 1 are exact.
  const double a = 1.0, h = 0.01;
  std::vector<double> r;
  for (int k = 0; k < 200; ++k) r.push_back((k + 0.5) * h);  // out to 2 a: nodes beyond the edge do not count
  auto share = [&](auto yielded_at) {
    std::vector<bool> y;
    for (double x : r) y.push_back(yielded_at(x));
    return surface_yield_share(r, y, a);
  };
  EXPECT_NEAR(share([](double) { return true; }), 1.0, 1e-12);                          // the whole disc
  EXPECT_NEAR(share([](double x) { return x > 0.5; }), 0.75, 1e-12);                    // annulus 0.5 a..a
  EXPECT_NEAR(share([](double x) { return x > 0.5 && x < 1.5; }), 0.75, 1e-12);         // yield beyond a ignored
  EXPECT_NEAR(share([](double x) { return x < 0.5; }), 0.25, 1e-12);                    // a core disc
  EXPECT_NEAR(share([](double x) { return x > 0.3 && x < 0.6; }), 0.36 - 0.09, 1e-12);  // a ring inside
  EXPECT_EQ(share([](double) { return false; }), 0.0);                                  // nothing
  EXPECT_EQ(share([](double x) { return x > 1.0; }), 0.0);                              // only outside the contact
  // The contact edge inside a node's ring: that ring is cut at a (0.995 a: a node at 0.995, its ring 0.99..1.0).
  std::vector<bool> all(r.size(), true);
  EXPECT_NEAR(surface_yield_share(r, all, 0.993), 1.0, 1e-12);
  std::vector<bool> last(r.size(), false);
  last[99] = true;  // the node at 0.995 owns 0.99..1.00
  EXPECT_NEAR(surface_yield_share(r, last, 0.993), (0.993 * 0.993 - 0.99 * 0.99) / (0.993 * 0.993), 1e-12);
  // An uneven mesh with a node on the axis: an annulus from 0.5 a is found within one ring.
  std::vector<double> q{0.0};
  while (q.back() < 1.5) q.push_back(q.back() + 0.013 + 0.02 * q.back());
  std::vector<bool> outer;
  for (double x : q) outer.push_back(x >= 0.5);
  EXPECT_NEAR(surface_yield_share(q, outer, a), 0.75, 2.0 * 0.5 * 0.03);
  EXPECT_EQ(surface_yield_share(q, outer, 0.0), 0.0);  // no contact
  EXPECT_THROW(surface_yield_share(q, std::vector<bool>(3, true), a), std::invalid_argument);
}

TEST(FemResults, SurfaceYieldedNodesDropOneNodeFlipsOfTheExtrapolatedStrain) {
  // As ccx's nodal PE along a surface: zero, a yielded run with one node extrapolated negative
  // inside it, zero, and one stray positive node; 1e-7 is below the threshold.
  const std::vector<double> peeq{0, 1e-7, 0, 3e-6, 5e-5, -1.4e-3, 1.6e-3, 2e-4, 0, 0, 4e-6, 0, 0};
  const std::vector<bool> want{false, false, false, true, true, true, true, true, false, false, false, false, false};
  EXPECT_EQ(surface_yielded_nodes(peeq), want);
  EXPECT_EQ(surface_yielded_nodes({2e-6, 0, 0, 2e-6}),
            (std::vector<bool>{true, false, false, true}));  // end nodes as they are
  EXPECT_TRUE(surface_yielded_nodes({}).empty());
}
