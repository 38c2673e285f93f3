// Persson's interfacial separation (contact/persson_contact.hpp): the spectra's closed-form moments
// against quadrature of their C(q) and against the Gaussian autocorrelation's derivatives, the
// self-affine fit's round trip, u(p) against the double integral taken in the other order, its
// small-pressure asymptote against an independent closed form of u0 and beta, monotonicity and the
// inverse, and the mean gap of the areal boundary elements on seeded self-affine maps.
#include "contact/areal/areal_bem.hpp"
#include "contact/persson_contact.hpp"
#include "surface/synthetic_surface.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/expint.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <vector>

using namespace geartrib;
using namespace geartrib::contact;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kEstar = 115e9;
constexpr double kInf = std::numeric_limits<double>::infinity();
using Kronrod = boost::math::quadrature::gauss_kronrod<double, 31>;

// integral_a^b f(ln q) d(ln q), adaptive.
template <class F>
double log_integral(F f, double qa, double qb) {
  return Kronrod::integrate([&](double t) { return f(std::exp(t)); }, std::log(qa), std::log(qb), 20, 1e-13);
}

RoughnessSpectrum gaussian_pair() {  // two ground flanks of different correlation lengths
  return {{SpectrumPart::gaussian(0.4e-6, 8e-6), SpectrumPart::gaussian(0.3e-6, 20e-6)}};
}
RoughnessSpectrum self_affine() { return {{SpectrumPart::self_affine(0.5e-6, 2e5, 4e6, 0.8, 2e4)}}; }

// Persson's u(p) with the integrals in the other order from the class's: over q outside, and inside
// F(x0) = integral_x0^inf (gamma + 3 (1 - gamma) erf^2 x) e^(-x^2)/x dx = gamma E1(x0^2)/2 + 3 (1 - gamma)
// J(x0), J's integrand erf^2(x) e^(-x^2)/x regular at 0. Adaptive Gauss-Kronrod throughout.
double j_integral(double x0) {
  const auto j = [](double x) {
    const double e = std::erf(x);
    return x < 1e-8 ? 4.0 / kPi * x : e * e * std::exp(-x * x) / x;
  };
  return Kronrod::integrate(j, x0, x0 + 12.0, 20, 1e-14);
}
// sqrt(pi) q^2 C w F(w p/E*) at q.
double direct_integrand(const RoughnessSpectrum& c, double q, double p, double gamma) {
  const double w = 1.0 / std::sqrt(kPi * c.moment(3, q)), x0 = w * p / kEstar;
  const double big_f =
      x0 > 30.0 ? 0.0 : gamma * 0.5 * boost::math::expint(1, x0 * x0) + 3.0 * (1.0 - gamma) * j_integral(x0);
  return std::sqrt(kPi) * q * q * c.psd(q) * w * big_f;
}
double direct_separation(const RoughnessSpectrum& c, double qa, double qb, double p, double gamma) {
  return log_integral([&](double q) { return q * direct_integrand(c, q, p, gamma); }, qa, qb);
}
// The same from a lower cut q_a where w ~ (q - q_a)^(-1/2): q = q_a + (q_b - q_a) tau^2.
double direct_separation_from_cut(const RoughnessSpectrum& c, double qa, double qb, double p, double gamma) {
  return Kronrod::integrate(
      [&](double tau) {
        return tau > 0.0 ? 2.0 * (qb - qa) * tau * direct_integrand(c, qa + (qb - qa) * tau * tau, p, gamma) : 0.0;
      },
      0.0, 1.0, 20, 1e-13);
}
}  // namespace

TEST(PerssonSpectrum, GaussianMomentsAreTheAutocorrelations) {
  // C = rq^2 lambda^2/(4 pi) exp(-q^2 lambda^2/4) is the transform of rq^2 exp(-r^2/lambda^2): its
  // profile moments are the autocorrelation's -R''(0) = 2 rq^2/lambda^2 and R''''(0) = 12 rq^2/lambda^4,
  // and its quadrature gives rq^2 (the closed forms to rounding; the quadrature to its tolerance).
  const double rq = 0.4e-6, l = 8e-6;
  const RoughnessSpectrum c{{SpectrumPart::gaussian(rq, l)}};
  EXPECT_NEAR(c.profile_m0() / (rq * rq), 1.0, 1e-14);
  EXPECT_NEAR(c.profile_m2() / (2.0 * rq * rq / (l * l)), 1.0, 1e-14);
  EXPECT_NEAR(c.profile_m4() / (12.0 * rq * rq / std::pow(l, 4)), 1.0, 1e-14);
  EXPECT_NEAR(c.rms_gradient(), std::sqrt(2.0 * c.profile_m2()), 1e-16);
  const double m0 = 2.0 * kPi * log_integral([&](double q) { return q * q * c.psd(q); }, 1e-6 / l, 20.0 / l);
  EXPECT_NEAR(m0 / (rq * rq), 1.0, 1e-10);
  // The partial moments at finite q against the same quadrature.
  for (int n : {1, 3, 5}) {
    const double q = 1.3 / l;
    const double quad = log_integral([&](double k) { return std::pow(k, n + 1) * c.psd(k); }, 1e-6 / l, q);
    EXPECT_NEAR(c.moment(n, q) / quad, 1.0, 1e-9) << n;
  }
}

TEST(PerssonSpectrum, SelfAffineMomentsAreItsIntegrals) {
  const RoughnessSpectrum c = self_affine();
  const SpectrumPart& s = c.parts[0];
  EXPECT_NEAR(c.rms_height() / 0.5e-6, 1.0, 1e-14);
  // C0 (q/q_r)^(-2(1 + H)) on each side of the roll-off, zero outside [q_l, q_1].
  EXPECT_EQ(c.psd(0.5 * s.lower), 0.0);
  EXPECT_EQ(c.psd(1.01 * s.cutoff), 0.0);
  EXPECT_NEAR(c.psd(2.0 * s.rolloff) / c.psd(0.5 * s.rolloff), std::pow(2.0, -3.6), 1e-14);
  for (int n : {1, 3, 5})
    for (double q : {0.5 * s.rolloff, 3.0 * s.rolloff, s.cutoff}) {
      const double quad =
          log_integral([&](double k) { return std::pow(k, n + 1) * c.psd(k); }, s.lower, s.rolloff) +
          (q > s.rolloff ? log_integral([&](double k) { return std::pow(k, n + 1) * c.psd(k); }, s.rolloff, q) : 0.0) -
          (q < s.rolloff ? log_integral([&](double k) { return std::pow(k, n + 1) * c.psd(k); }, q, s.rolloff) : 0.0);
      EXPECT_NEAR(c.moment(n, q) / quad, 1.0, 1e-10) << n << " " << q;
    }
}

TEST(PerssonSpectrum, FitRecoversTheSpectrumOfItsMoments) {
  // A self-affine spectrum from q = 0 has the bandwidth of its q_1/q_r; its moments give it back.
  const RoughnessSpectrum c{{SpectrumPart::self_affine(0.7e-6, 3e4, 9e5, kFittedSpectrumHurst)}};
  const SpectrumPart f = fit_self_affine_spectrum(c.profile_m0(), c.profile_m2(), c.profile_m4());
  EXPECT_NEAR(f.rq / 0.7e-6, 1.0, 1e-12);
  EXPECT_NEAR(f.rolloff / 3e4, 1.0, 1e-9);
  EXPECT_NEAR(f.cutoff / 9e5, 1.0, 1e-9);
  EXPECT_EQ(f.lower, 0.0);
  // Narrower than the plateau alone (m0 m4/m2^2 = 2): no such spectrum. A Gaussian's 3 fits.
  EXPECT_THROW(fit_self_affine_spectrum(1.0, 1.0, 1.9), std::invalid_argument);
  const SpectrumPart g = fit_self_affine_spectrum(1e-12, 2e-12 / 1e-10, 12e-12 / 1e-20);
  EXPECT_GT(g.cutoff / g.rolloff, 1.0);
}

namespace {
// A spectrum's C tabulated on nodes q_a r^k up to q_b (the last node at or past q_b).
SpectrumPart tabulate(const RoughnessSpectrum& c, double qa, double qb, double ratio) {
  std::vector<double> q, v;
  for (double k = qa; q.empty() || q.back() < qb; k *= ratio) q.push_back(k), v.push_back(c.psd(k));
  return SpectrumPart::tabulated(q, v);
}
}  // namespace

TEST(PerssonSpectrum, TabulatedPowerLawsBetweenTheNodes) {
  const std::vector<double> q = {1e4, 3e4, 1e5, 4e5, 1e6};
  const std::vector<double> v = {2e-30, 2e-30, 5e-32, 1e-34, 3e-37};
  const SpectrumPart t = SpectrumPart::tabulated(q, v);
  for (std::size_t k = 0; k < q.size(); ++k) EXPECT_EQ(t.psd(q[k]), v[k]) << k;  // the nodes' own values
  // Log-log linear: at the geometric mean of two nodes' q, the geometric mean of their C.
  for (std::size_t k = 0; k + 1 < q.size(); ++k)
    EXPECT_NEAR(t.psd(std::sqrt(q[k] * q[k + 1])) / std::sqrt(v[k] * v[k + 1]), 1.0, 1e-14) << k;
  EXPECT_EQ(t.psd(0.999 * q.front()), 0.0);
  EXPECT_EQ(t.psd(1.001 * q.back()), 0.0);
  // The moments against adaptive quadrature of psd() segment by segment (to its tolerance), partial
  // ones inside a segment too; rq is the table's.
  for (int n : {1, 3, 5})
    for (double top : {2e4, 1e5, 7e5, kInf}) {
      double quad = 0.0;
      for (std::size_t k = 0; k + 1 < q.size() && q[k] < top; ++k)
        quad += log_integral([&](double x) { return std::pow(x, n + 1) * t.psd(x); }, q[k], std::min(top, q[k + 1]));
      EXPECT_NEAR(t.moment(n, top) / quad, 1.0, 1e-10) << n << " " << top;
    }
  EXPECT_NEAR(t.rq * t.rq / (2.0 * kPi * t.moment(1, kInf)), 1.0, 1e-15);
  // The integrand q^-1 (n + s = -1; here n = 3 on a segment of slope -4): c0 q0^4 ln(q1/q0) exactly;
  // beside it (slopes -4 +- 1e-12) the integral moves by ds ln(2)/2 = 3.5e-13 of itself: within 1e-12,
  // where (2^e - 1)/e taken as written loses 2e-5 to the cancellation.
  const double c0 = 1e-30, q0 = 1e5;
  const SpectrumPart log_case = SpectrumPart::tabulated({q0, 2.0 * q0}, {c0, c0 / 16.0});
  const double exact = c0 * std::pow(q0, 4) * std::log(2.0);
  EXPECT_NEAR(log_case.moment(3, kInf) / exact, 1.0, 1e-15);
  for (double ds : {-1e-12, 1e-12}) {
    const SpectrumPart near = SpectrumPart::tabulated({q0, 2.0 * q0}, {c0, c0 / 16.0 * std::pow(2.0, ds)});
    EXPECT_NEAR(near.moment(3, kInf) / exact, 1.0, 1e-12) << ds;
  }
  // A segment with a zero end carries nothing: between 1e5 and 4e5 below, C = 0.
  const SpectrumPart gap = SpectrumPart::tabulated({1e4, 1e5, 4e5, 1e6}, {1e-30, 1e-31, 0.0, 1e-33});
  EXPECT_EQ(gap.psd(2e5), 0.0);
  EXPECT_EQ(gap.moment(1, kInf), gap.moment(1, 1e5));
}

TEST(PerssonSpectrum, TabulatedRefusesAnInvalidTable) {
  EXPECT_THROW(SpectrumPart::tabulated({1e5}, {1e-30}), std::invalid_argument);                        // one node
  EXPECT_THROW(SpectrumPart::tabulated({1e5, 2e5}, {1e-30}), std::invalid_argument);                   // sizes
  EXPECT_THROW(SpectrumPart::tabulated({2e5, 1e5}, {1e-30, 1e-30}), std::invalid_argument);            // decreasing
  EXPECT_THROW(SpectrumPart::tabulated({1e5, 1e5}, {1e-30, 1e-30}), std::invalid_argument);            // repeated
  EXPECT_THROW(SpectrumPart::tabulated({0.0, 1e5}, {1e-30, 1e-30}), std::invalid_argument);            // q = 0
  EXPECT_THROW(SpectrumPart::tabulated({1e5, kInf}, {1e-30, 1e-30}), std::invalid_argument);           // q infinite
  EXPECT_THROW(SpectrumPart::tabulated({1e5, 2e5}, {-1e-30, 1e-30}), std::invalid_argument);           // C < 0
  EXPECT_THROW(SpectrumPart::tabulated({1e5, 2e5}, {1e-30, kInf}), std::invalid_argument);             // C infinite
  EXPECT_THROW(SpectrumPart::tabulated({1e5, 2e5, 3e5}, {1e-30, 0.0, 1e-30}), std::invalid_argument);  // no power
  EXPECT_NO_THROW(SpectrumPart::tabulated({1e5, 2e5}, {1e-30, 1e-40}));  // the least table: two nodes with power
}

TEST(PerssonSpectrum, TabulatedGaussianGivesTheGaussiansMoments) {
  // A Gaussian tabulated on nodes r apart (h = ln r) from q lambda/2 = 1e-4 to 28.3 against its closed
  // forms (incomplete gamma functions). Linear interpolation of f = ln C in t = ln q lies below f by
  // f'' t'(h - t')/2 on a segment, h^2 f''/12 on average; f'' = -(q lambda)^2 here, so to leading order
  // M_n errs by -(h^2/12) lambda^2 M_(n+2)/M_n (its weight's mean q^2): -h^2 (n + 1)/6 of the whole
  // (M_(n+2)/M_n = 2 (n + 1)/lambda^2). The table's errors within 1 % of that (the next order, h^4, and
  // the ends: (q_a lambda/2)^2 = 1e-8 of m0 below the first node; a partial top inside a segment),
  // measured within 0.4 %.
  const double rq = 0.4e-6, l = 8e-6, r = 1.01, h = std::log(r);
  const RoughnessSpectrum g{{SpectrumPart::gaussian(rq, l)}};
  const SpectrumPart t = tabulate(g, 2e-4 / l, 56.6 / l, r);
  for (int n : {1, 3, 5})
    for (double top : {1.3 / l, kInf}) {
      if (n == 5 && top < kInf) continue;  // M_7 has no closed form here
      const double weight_q2 = n < 5 ? g.moment(n + 2, top) / g.moment(n, top) : 2.0 * (n + 1) / (l * l);
      const double predicted = -h * h / 12.0 * l * l * weight_q2;
      EXPECT_NEAR((t.moment(n, top) / g.moment(n, top) - 1.0) / predicted, 1.0, 0.01) << n << " " << top;
    }
}

TEST(PerssonSeparation, OnATabulatedGaussianAsOnTheGaussian) {
  // The two ground flanks' Gaussians tabulated on nodes 1.01 apart (their sum's C) from q lambda/2 = 1e-5
  // of the longer correlation: u(p) within 3e-4 of the analytic parts' at loads from 1e-6 to 0.5 E* h'_rms
  // (the table's moments err by -(ln r)^2 (n + 1)/6 ~ 1e-4 at most, above; the first node's cut removes
  // ~q_a lambda/2 = 1e-5 of u0's integrand, q^2 C w -> 2 sqrt(C(0)/pi) being flat as q -> 0), u0 and h'_rms
  // within 1e-4. Measured: u within 1.4e-5 (light) to 8.9e-5 (0.5), u0 1.5e-5, h'_rms 2.8e-5.
  const RoughnessSpectrum g = gaussian_pair();
  const RoughnessSpectrum t{{tabulate(g, 2e-5 / 20e-6, 56.6 / 8e-6, 1.01)}};
  const PerssonSeparation exact(g, kEstar), table(t, kEstar);
  EXPECT_NEAR(table.rms_gradient() / exact.rms_gradient(), 1.0, 1e-4);
  EXPECT_NEAR(table.decay_length() / exact.decay_length(), 1.0, 1e-4);
  for (double r : {1e-6, 1e-4, 1e-2, 0.1, 0.5}) {
    const double p = r * kEstar * exact.rms_gradient();
    EXPECT_NEAR(table.separation(p) / exact.separation(p), 1.0, 3e-4) << r;
  }
}

TEST(PerssonSeparation, AgreesWithTheIntegralsInTheOtherOrder) {
  // The class integrates d(U_el/A0)/dp over ln p on a table, then interpolates; the direct form
  // integrates over q the inner integral over p (adaptive Gauss-Kronrod). They agree to the table's
  // interpolation of ln u (1.3e-7 measured, allowed 1e-6) and, where u has fallen to a few
  // hundredths of rq, to the q quadrature's (4e-5 measured at u = 0.003 rq, allowed 1e-4); on a
  // spectrum with a lower cut, to 1e-5.
  const RoughnessSpectrum c = gaussian_pair();
  const PerssonSeparation s(c, kEstar);
  const double g = s.rms_gradient();
  for (double r : {1e-8, 1e-4, 1e-2, 0.1, 0.5}) {
    const double p = r * kEstar * g;
    const double direct = direct_separation(c, 1e-9 / 20e-6, 15.0 / 8e-6, p, kPerssonSeparationGamma);
    EXPECT_NEAR(s.separation(p) / direct, 1.0, r < 0.3 ? 1e-6 : 1e-4) << r;
  }
  const RoughnessSpectrum a = self_affine();
  const PerssonSeparation t(a, kEstar);
  for (double r : {1e-6, 1e-2, 0.2}) {
    const double p = r * kEstar * t.rms_gradient();
    const SpectrumPart& q = a.parts[0];
    // The direct form panel by panel: w's singularity at q_l, the roll-off's kink.
    const double direct = direct_separation_from_cut(a, q.lower, q.rolloff, p, kPerssonSeparationGamma) +
                          direct_separation(a, q.rolloff, q.cutoff, p, kPerssonSeparationGamma);
    EXPECT_NEAR(t.separation(p) / direct, 1.0, 1e-5) << r;
  }
}

TEST(PerssonSeparation, SmallPressureAsymptote) {
  // As p -> 0 the inner integral is gamma (-ln x0 - gamma_E/2) + 3 (1 - gamma) J(0) + o(1), so
  // u = u0 ln(beta E*/p) with u0 = gamma K and ln beta = -<ln w>_K + 3 (1 - gamma) J(0)/gamma -
  // gamma_E/2 (K = integral sqrt(pi) q^2 C w dq, <.>_K its weighted mean): Persson's p = beta E*
  // exp(-u/u0). Computed here from the spectrum by quadrature, apart from the class's table.
  const RoughnessSpectrum c = gaussian_pair();
  const double gamma = kPerssonSeparationGamma;
  const PerssonSeparation s(c, kEstar, gamma);
  const auto k = [&](double q) {
    const double w = 1.0 / std::sqrt(kPi * c.moment(3, q));
    return q * std::sqrt(kPi) * q * q * c.psd(q) * w;
  };
  const double qa = 1e-9 / 20e-6, qb = 15.0 / 8e-6;
  const double big_k = log_integral(k, qa, qb);
  const double k_ln_w =
      log_integral([&](double q) { return k(q) * std::log(1.0 / std::sqrt(kPi * c.moment(3, q))); }, qa, qb);
  const double ln_beta =
      -k_ln_w / big_k + 3.0 * (1.0 - gamma) * j_integral(0.0) / gamma - 0.5 * boost::math::constants::euler<double>();
  EXPECT_NEAR(s.decay_length() / (gamma * big_k), 1.0, 1e-7);
  EXPECT_NEAR(std::log(s.prefactor()), ln_beta, 1e-6);
  // u(p) - u0 ln(beta E*/p) -> 0: o(1) falls as the load does (the wavelengths near q = 0 whose w p/E*
  // is not small: sqrt(p) for a spectrum flat at q -> 0).
  double last = kInf;
  for (double r : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const double p = r * kEstar * s.rms_gradient();
    const double err = std::abs(s.separation(p) - gamma * big_k * (ln_beta + std::log(kEstar / p))) / s.rms_height();
    EXPECT_LT(err, last) << r;
    last = err;
  }
  EXPECT_LT(last, 1e-5);
}

TEST(PerssonSeparation, MonotoneAndInvertedFromFreeSurfacesToCompleteContact) {
  for (const RoughnessSpectrum& c : {gaussian_pair(), self_affine()}) {
    const PerssonSeparation s(c, kEstar);
    const double scale = kEstar * s.rms_gradient();
    double last = kInf;
    for (double lg = -30.0; lg <= 0.6; lg += 0.01) {
      const double p = std::pow(10.0, lg) * scale, u = s.separation(p);
      ASSERT_LT(u, last) << lg;
      ASSERT_GT(u, 0.0) << lg;
      if (u > 1e-12 * s.rms_height()) {
        EXPECT_NEAR(s.pressure(u) / p, 1.0, 1e-9) << lg;
      }
      last = u;
    }
    EXPECT_EQ(s.separation(0.0), kInf);
    EXPECT_EQ(s.pressure(0.0), kInf);
    EXPECT_EQ(s.pressure(kInf), 0.0);
    // Complete contact: at p = 2 E* h'_rms every wavelength is closed to exp(-2 (p/(E* h'_rms))^2) = e^-8.
    EXPECT_LT(s.separation(2.0 * scale), 1e-3 * s.rms_height());
    EXPECT_GT(s.separation(1e-3 * scale), s.rms_height());  // light load: the surfaces a few rq apart
  }
}

TEST(PerssonSeparation, MeanGapOfTheArealBoundaryElements) {
  // Seeded periodic self-affine maps (H = 0.8, roll-off at a sixteenth of the window, the shortest
  // wavelength four spacings; realised spectrum = generating one, surface::self_affine_surface),
  // 256^2, elastic, under load: the mean of the gap over the map is Persson's u. The theory's
  // spectrum is the map's: q_l = 2 pi/L, the map's lowest wavenumber (the excluded q = 0 cell moves u
  // by 0.3 %). Measured (this grid, 3 seeds' mean; 512^2 with eight spacings a wavelength within 0.8 %):
  // Persson above the boundary elements by 5.0 % at p = 0.01 E* h'_rms (2.8 % contact), 2.5 % at
  // 0.03, 1.7 % at 0.1. Allowed 8 %: Almqvist et al. (2011) find the theory within a few percent of
  // their numerics at such loads, and the GFMD check's band (validation/areal-gfmd) is 8 %; a seed
  // alone scatters by 3 % here. Lighter loads are not asserted: a finite map's mean gap stops growing
  // once a few summits carry the load (the highest of its 65536 points), where the theory's u keeps
  // growing as -u0 ln p (measured +12 % at 1e-3, +21 % at 1e-4).
  const int n = 256;
  const double e = 1e11, dx = 1e-6, rq = 1e-6, length = n * dx;
  surface::SelfAffineSpec spec;
  spec.nx = spec.ny = n;
  spec.spacing = dx;
  spec.rq = rq;
  spec.hurst = 0.8;
  spec.rolloff_wavelength = length / 16.0;
  spec.cutoff_wavelength = 4.0 * dx;
  const RoughnessSpectrum c{{SpectrumPart::self_affine(
      rq, 2.0 * kPi / spec.rolloff_wavelength, 2.0 * kPi / spec.cutoff_wavelength, spec.hurst, 2.0 * kPi / length)}};
  const PerssonSeparation persson(c, e);
  areal::ArealGrid grid;
  grid.nx = grid.ny = n;
  grid.dx = grid.dy = dx;
  const areal::ElasticKernel kernel(grid, e);
  areal::ArealOptions options;
  options.composite_modulus = e;
  // p/(E* h'_rms): the lighter three measured and printed, not asserted (above).
  const std::vector<double> loads = {1e-4, 1e-3, 3e-3, 0.01, 0.03, 0.1};
  std::vector<double> mean_gap(loads.size(), 0.0);
  const int seeds = 3;
  for (int seed = 1; seed <= seeds; ++seed) {
    spec.seed = static_cast<std::uint64_t>(seed);
    const surface::HeightGrid h = surface::self_affine_surface(spec);
    std::vector<double> start;
    for (std::size_t i = 0; i < loads.size(); ++i) {
      const areal::ArealSolution sol = areal::solve_contact(kernel, h.z, areal::Control::mean_pressure,
                                                            loads[i] * e * persson.rms_gradient(), options, start);
      ASSERT_TRUE(sol.converged) << "p/(E* h'_rms) " << loads[i] << ", seed " << seed << ": " << sol.iterations
                                 << " iterations, residual " << sol.residual;
      double g = 0.0;
      for (double v : sol.gap) g += v;
      mean_gap[i] += g / static_cast<double>(sol.gap.size()) / seeds;
      start = sol.pressure;
    }
  }
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const double u = persson.separation(loads[i] * e * persson.rms_gradient());
    std::cout << "p/(E* h'_rms) " << loads[i] << ": Persson u " << u / rq << " rq, boundary elements "
              << mean_gap[i] / rq << " rq (" << 100.0 * (u / mean_gap[i] - 1.0) << " %)\n";
    if (loads[i] >= 0.01) {
      EXPECT_NEAR(u / mean_gap[i], 1.0, 0.08) << loads[i];
    }
  }
}
