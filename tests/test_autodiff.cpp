// The laws are templated on the scalar: Ceres' Jet carries derivatives through the same code
// the simulator runs. Check the Jet derivatives against central finite differences.
#include "asperity/laws.hpp"
#include "test_support.hpp"

#include <ceres/jet.h>
#include <gtest/gtest.h>

using namespace geartrib;
using namespace geartrib::asperity;

namespace {

template <class Law>
void check_derivatives(double d) {
  constexpr int N = static_cast<int>(Law::constants.size()) + 1;  // delta* and every constant
  using Jet = ceres::Jet<double, N>;
  const ContactPair p = test::seed_pair();
  std::array<Jet, N - 1> c;
  std::array<double, N - 1> cd;
  for (int i = 0; i < N - 1; ++i) {
    cd[i] = Law::constants[i].value;
    c[i] = Jet(cd[i], i + 1);
  }
  const Star<Jet> s = Law::star(Jet(d, 0), c.data(), p);
  auto value = [&](int which, double h) {
    auto cc = cd;
    double dd = d;
    if (which == 0) dd += h;
    else cc[which - 1] += h;
    return Law::star(dd, cc.data(), p);
  };
  for (int i = 0; i < N; ++i) {
    const double x = i == 0 ? d : cd[i - 1];
    const double h = 1e-6 * std::max(1.0, std::abs(x));
    const Star<double> hi = value(i, h), lo = value(i, -h);
    const double fd_load = (hi.load - lo.load) / (2 * h), fd_area = (hi.area - lo.area) / (2 * h);
    // Central differences with h ~ 1e-6 x: truncation O(h^2) and rounding O(eps/h) both below
    // 1e-7 relative to the function's scale.
    EXPECT_NEAR(s.load.v[i], fd_load, 1e-6 * std::max(1.0, std::abs(s.load.a)))
        << Law::name << " d=" << d << " i=" << i;
    EXPECT_NEAR(s.area.v[i], fd_area, 1e-6 * std::max(1.0, std::abs(s.area.a)))
        << Law::name << " d=" << d << " i=" << i;
  }
}

}  // namespace

TEST(Autodiff, ContinuousLawDerivativesMatchFiniteDifferences) {
  for (double d : {0.5, 1.5, 6.0, 40.0, 3000.0}) check_derivatives<ContinuousLaw>(d);
}

TEST(Autodiff, PublishedLawsDerivativesMatchFiniteDifferences) {
  for (double d : {0.5, 3.0, 20.0}) {  // inside branches, away from the published breakpoints
    check_derivatives<KogutEtsionLaw>(d);
    check_derivatives<JacksonGreenLaw>(d);
    check_derivatives<ZmcLaw>(d);
    check_derivatives<CebLaw>(d);
  }
}
