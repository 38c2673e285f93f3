#include "gear/tooth_contact.hpp"

#include "asperity/cylinder.hpp"
#include "gear/involute.hpp"

#include <fmt/format.h>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace geartrib::gear {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr NamedChoice<ReliefShape> kShapeNames[] = {
    {ReliefShape::linear, "linear"}, {ReliefShape::parabolic, "parabolic"}, {ReliefShape::arc, "arc"}};
constexpr NamedChoice<ReliefDesign> kDesignNames[] = {{ReliefDesign::given, "given"},
                                                      {ReliefDesign::long_relief, "long"}};
constexpr NamedChoice<HertzApproach> kApproachNames[] = {{HertzApproach::weber_banaschek, "weber-banaschek"},
                                                         {HertzApproach::palmgren, "palmgren"},
                                                         {HertzApproach::linear, "linear"}};
const char* kGearKey[2] = {"pinion", "wheel"};
// Steel on steel (E = 206 GPa, nu = 0.3): E_t = E/(2 (1 - nu^2)), the material of Palmgren's fit.
constexpr double kSteelCompositeModulus = 206e9 / (2.0 * (1.0 - 0.09));

// The relief's removal at distance x from its start over length L (0 <= x <= L) [m].
double relief_profile(const Relief& r, double x, double length) {
  if (r.amount <= 0.0 || x <= 0.0) return 0.0;
  const double xi = std::min(x / length, 1.0);
  switch (r.shape) {
    case ReliefShape::linear:
      return r.amount * xi;
    case ReliefShape::parabolic:
      return r.amount * xi * xi;
    case ReliefShape::arc: {
      const double radius = (length * length + r.amount * r.amount) / (2.0 * r.amount);
      const double u = xi * length;
      // R - sqrt(R^2 - u^2) written without the cancellation of two near-equal terms.
      return u * u / (radius + std::sqrt(radius * radius - u * u));
    }
  }
  return 0.0;
}

// Roll length of the circle of diameter d on gear g [m]; NaN below the base circle.
double roll_length_at(const GearBody& g, double diameter) {
  const double r = 0.5 * diameter;
  return r >= g.base_radius ? std::sqrt(r * r - g.base_radius * g.base_radius) : std::nan("");
}

double diameter_at(const GearBody& g, double rho) { return 2.0 * std::hypot(g.base_radius, rho); }
}  // namespace

std::span<const NamedChoice<ReliefShape>> relief_shape_choices() { return kShapeNames; }
std::span<const NamedChoice<ReliefDesign>> relief_design_choices() { return kDesignNames; }
std::span<const NamedChoice<HertzApproach>> hertz_approach_choices() { return kApproachNames; }

void Relief::validate() const {
  using core::KeyedError;
  if (!(amount >= 0.0)) throw KeyedError("amount", "a relief's amount must not be negative");
  if (!(start_diameter >= 0.0)) throw KeyedError("start_diameter", "a diameter must not be negative");
  if (!(length >= 0.0)) throw KeyedError("length", "a relief's roll length must not be negative");
  if (start_diameter > 0.0 && length > 0.0)
    throw KeyedError("length", "give the relief's start as start_diameter or as length, not both");
  if (amount > 0.0 && start_diameter == 0.0 && length == 0.0)
    throw KeyedError("length", "a relief needs its start: start_diameter or length (roll length from the end)");
}

bool ProfileModification::any() const {
  return tip.amount > 0.0 || root.amount > 0.0 || tip_design != ReliefDesign::given || crowning != 0.0 ||
         slope_deviation != 0.0 || base_pitch_deviation != 0.0;
}

std::string ProfileModification::first_given() const {
  if (tip.amount > 0.0) return "tip.amount";
  if (tip_design != ReliefDesign::given) return "tip_design";
  if (root.amount > 0.0) return "root.amount";
  if (crowning != 0.0) return "crowning";
  if (slope_deviation != 0.0) return "slope_deviation";
  if (base_pitch_deviation != 0.0) return "base_pitch_deviation";
  return "";
}

void ProfileModification::validate() const {
  auto check = [](const Relief& r, const char* prefix) {
    try {
      r.validate();
    } catch (const core::KeyedError& e) {
      throw core::KeyedError(std::string(prefix) + e.key(), e.what());
    }
  };
  check(tip, "tip.");
  check(root, "root.");
  if (tip_design != ReliefDesign::given && (tip.amount > 0.0 || tip.length > 0.0 || tip.start_diameter > 0.0))
    throw core::KeyedError("tip_design", "a designed tip relief sets its own amount and start: remove the given ones");
}

FlankModification::FlankModification(const SpurPair& pair, int gear, const ProfileModification& m, double design_relief)
    : m_(m), tip_(m.tip) {
  const GearBody& g = pair.gear(gear);
  const PathOfContact& p = pair.path();
  const std::string key = std::string(kGearKey[gear]) + ".";
  tip_end_ = std::sqrt(g.tip_radius * g.tip_radius - g.base_radius * g.base_radius);
  root_end_ = std::max(0.0, g.form_roll_length);
  // The active profile: the pinion's rho1 = s over [A, E], the wheel's rho2 = T1T2 - s.
  active_low_ = gear == 0 ? p.a : p.line_length - p.e;
  active_high_ = gear == 0 ? p.e : p.line_length - p.a;
  if (m.tip_design != ReliefDesign::given) {
    // Long relief: from the point of single contact (the pinion's D, the wheel's B) to the tip.
    const double single = gear == 0 ? p.d : p.line_length - p.b;
    tip_.amount = design_relief;
    tip_.start_diameter = 0.0;
    tip_.length = std::max(0.0, active_high_ - single);
    if (!(p.b < p.d))
      throw GeometryError(key + "tip_relief.design",
                          fmt::format("the pair has no single-contact zone to start a designed relief (contact ratio "
                                      "{:.4g}, at least 2): give the relief's amount and start",
                                      p.contact_ratio));
  }
  auto resolve = [&](const Relief& r, const std::string& k, double end, double sign) {
    if (r.amount <= 0.0) return end;
    const double start = r.start_diameter > 0.0 ? roll_length_at(g, r.start_diameter) : end - sign * r.length;
    const double form = root_end_;
    if (!(start >= form - 1e-12 && start <= tip_end_ + 1e-12)) {
      const std::string field = r.start_diameter > 0.0 ? "start_diameter" : "length";
      throw GeometryError(
          key + k + "." + field,
          fmt::format("the relief starts off the flank: at diameter {:.6g} mm, outside the involute from the root form "
                      "diameter {:.6g} mm to the tip {:.6g} mm",
                      1e3 * (std::isnan(start) ? r.start_diameter : diameter_at(g, start)), 1e3 * diameter_at(g, form),
                      1e3 * 2.0 * g.tip_radius));
    }
    // A relief must have a length, and an arc must be longer than its amount (else the circle
    // tangent at the start cannot reach the amount at the end).
    const double length = sign * (end - start);
    if (!(length > 0.0))
      throw GeometryError(key + k + "." + (r.start_diameter > 0.0 ? "start_diameter" : "length"),
                          "the relief starts at the end of the profile: it has no length");
    if (r.shape == ReliefShape::arc && !(length > r.amount))
      throw GeometryError(key + k + ".shape",
                          fmt::format("an arc relief of {:.4g} um over {:.4g} um of roll length: the circle tangent at "
                                      "its start cannot reach the amount; give a longer relief",
                                      1e6 * r.amount, 1e6 * length));
    // A relief that reaches across the active profile leaves no unmodified flank to carry the load.
    const bool past = sign > 0.0 ? start <= active_low_ + 1e-12 : start >= active_high_ - 1e-12;
    if (past)
      throw GeometryError(
          key + k + "." + (r.start_diameter > 0.0 ? "start_diameter" : "length"),
          fmt::format("the relief is longer than the active flank: it starts at diameter {:.6g} mm, beyond the active "
                      "profile's other end at {:.6g} mm",
                      1e3 * diameter_at(g, start), 1e3 * diameter_at(g, sign > 0.0 ? active_low_ : active_high_)));
    return start;
  };
  tip_start_ = resolve(tip_, "tip_relief", tip_end_, 1.0);
  root_start_ = resolve(m.root, "root_relief", root_end_, -1.0);
  if (tip_.amount > 0.0 && m.root.amount > 0.0 && root_start_ > tip_start_)
    throw GeometryError(
        key + "root_relief." + (m.root.start_diameter > 0.0 ? "start_diameter" : "length"),
        fmt::format("the root relief (from diameter {:.6g} mm) overlaps the tip relief (from {:.6g} mm)",
                    1e3 * diameter_at(g, root_start_), 1e3 * diameter_at(g, tip_start_)));
}

double FlankModification::at(double rho) const {
  double e = 0.0;
  if (tip_.amount > 0.0) e += relief_profile(tip_, rho - tip_start_, tip_end_ - tip_start_);
  if (m_.root.amount > 0.0) e += relief_profile(m_.root, root_start_ - rho, root_start_ - root_end_);
  const double span = active_high_ - active_low_;
  if (span > 0.0) {
    const double u = (rho - 0.5 * (active_low_ + active_high_)) / span;  // -1/2 .. 1/2 over the active profile
    e += m_.crowning * 4.0 * u * u;
    e -= m_.slope_deviation * u;
  }
  return e;
}

std::pair<double, double> LineContactApproach::approach_and_slope(double force) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  switch (model) {
    case HertzApproach::linear:
      return {force > 0.0 ? linear_compliance * force : 0.0, linear_compliance};
    case HertzApproach::palmgren: {
      if (!(force > 0.0)) return {0.0, kInfinity};
      // 3.84e-5 mm (F/N)^0.9 / (l/mm)^0.8, steel's; other materials by the compliance ratio^0.9.
      const double delta = 1e-3 * 3.84e-5 * std::pow(kSteelCompositeModulus / composite_modulus * force, 0.9) /
                           std::pow(1e3 * face_width, 0.8);
      return {delta, 0.9 * delta / force};
    }
    case HertzApproach::weber_banaschek: {
      if (!(force > 0.0)) return {0.0, kInfinity};
      const double w = force / face_width;
      const double a = asperity::hertz_half_width(w, radius, composite_modulus);
      double value = 0.0, slope = 0.0;
      for (int i = 0; i < 2; ++i) {
        const double nu = poisson_ratio[i];
        const double compliance = (1.0 - nu * nu) / youngs_modulus[i];
        const double log_term = std::log(2.0 * depth[i] / a) - nu / (2.0 * (1.0 - nu));
        value += compliance * std::max(log_term, 0.5);
        // d/dF [F g(F)] with a ~ sqrt(F): g - 1/2; on the floor g = 1/2 the term is linear.
        slope += compliance * (log_term > 0.5 ? log_term - 0.5 : 0.5);
      }
      return {2.0 * w / kPi * value, 2.0 / (kPi * face_width) * slope};
    }
  }
  return {0.0, 0.0};
}

bool LineContactApproach::in_range(double force) const {
  if (model == HertzApproach::palmgren) {
    // Palmgren fitted steel rollers: E_t of steel on steel within 10 %.
    return std::abs(composite_modulus / kSteelCompositeModulus - 1.0) <= 0.1;
  }
  if (model != HertzApproach::weber_banaschek || !(force > 0.0)) return true;
  const double a = asperity::hertz_half_width(force / face_width, radius, composite_modulus);
  return a <= 0.25 * std::min(depth[0], depth[1]);
}

std::pair<double, double> PairContact::load_and_compliance(double y, double guess) const {
  if (!(y > 0.0)) return {0.0, compliance + hertz.slope(0.0)};
  // y(F) = compliance F + approach(F) rises and is concave (the approach's slope falls with the
  // load): Newton converges from either side (from above it steps below the root, then rises
  // onto it), bracketed by [0, y/compliance] (doubled while short).
  double hi = compliance > 0.0 ? y / compliance : 1.0;
  while (deflection(hi) < y) hi *= 2.0;
  const double start = guess > 0.0 && guess < hi ? guess : hi;
  const std::uintmax_t limit = 100;
  std::uintmax_t iterations = limit;
  const double f = boost::math::tools::newton_raphson_iterate(
      [&](double x) {
        const auto [approach, slope] = hertz.approach_and_slope(x);
        return std::make_pair(compliance * x + approach - y, compliance + slope);
      },
      start, 0.0, hi, 50, iterations);
  if (iterations >= limit)
    throw std::runtime_error("compatibility: a pair's load did not converge in 100 Newton steps");
  return {f, compliance + hertz.slope(f)};
}

CompatibilitySolution solve_compatibility(std::span<const PairContact> pairs, double force) {
  if (pairs.empty()) throw std::invalid_argument("compatibility: no pair in contact");
  if (!(force >= 0.0)) throw std::invalid_argument("compatibility: the force must not be negative");
  CompatibilitySolution out;
  out.loads.assign(pairs.size(), 0.0);
  std::size_t first = 0;
  for (std::size_t j = 1; j < pairs.size(); ++j)
    if (pairs[j].separation < pairs[first].separation) first = j;
  const double low = pairs[first].separation;
  out.approach = low;
  if (force == 0.0) return out;
  // sum_j F_j(delta - e_j) - F rises and is convex in delta (each F_j the inverse of a concave
  // y_j): Newton from above (the pair nearest contact carrying everything, widened past the inner
  // inversion's rounding) descends onto the root, bracketed by [low, high].
  // Each pair's load from the last evaluation starts its next inversion.
  std::vector<double> guess(pairs.size(), 0.0);
  // In the approach beyond the first contact, u = delta - low >= 0 (a relative tolerance there
  // holds whatever the separations' datum).
  auto residual = [&](double u) {
    const double delta = low + u;
    double sum = 0.0, slope = 0.0;
    for (std::size_t j = 0; j < pairs.size(); ++j) {
      const auto [f, dy] = pairs[j].load_and_compliance(delta - pairs[j].separation, guess[j]);
      guess[j] = f;
      sum += f;
      if (f > 0.0) slope += 1.0 / dy;
    }
    return std::make_pair(sum - force, slope);
  };
  double high = pairs[first].deflection(force) * (1.0 + 1e-9) + 1e-18;
  while (residual(high).first < 0.0) high *= 2.0;
  // Start: every pair loaded, each linearised by its secant at an equal share of F.
  double inverse_sum = 0.0, weighted = 0.0;
  const double share = force / static_cast<double>(pairs.size());
  for (const PairContact& p : pairs) {
    const double secant = p.deflection(share) / share;
    inverse_sum += 1.0 / secant;
    weighted += p.separation / secant;
  }
  const double start = std::clamp((force + weighted) / inverse_sum - low, 0.0, high);
  const std::uintmax_t limit = 100;
  std::uintmax_t iterations = limit;
  out.approach = low + boost::math::tools::newton_raphson_iterate(residual, start, 0.0, high, 50, iterations);
  if (iterations >= limit) throw std::runtime_error("compatibility: the approach did not converge in 100 Newton steps");
  for (std::size_t j = 0; j < pairs.size(); ++j) {
    const auto [f, dy] = pairs[j].load_and_compliance(out.approach - pairs[j].separation, guess[j]);
    out.loads[j] = f;
    if (f > 0.0) {
      out.tangent_stiffness += 1.0 / dy;
      out.hertz_in_range = out.hertz_in_range && pairs[j].hertz.in_range(f);
    }
  }
  // The loads sum to F to the roots' tolerance (~1e-14 relative).
  return out;
}

double tooth_centre_depth(const GearBody& g, double rho) {
  const double r = std::hypot(g.base_radius, rho);
  const double alpha = std::atan2(rho, g.base_radius);  // pressure angle at r
  const double psi = g.base_half_angle - involute(alpha);
  // A pointed tooth (psi <= 0) has no centre line beyond the point: the depth floors at 1 % of r.
  return std::max(r * std::sin(psi) / std::cos(alpha - psi), 0.01 * r);
}

LoadedToothContact::LoadedToothContact(const SpurPair& pair, const MeshStiffnessModel& stiffness,
                                       const ToothMaterial& pinion, const ToothMaterial& wheel,
                                       double composite_modulus, const ProfileModification (&m)[2],
                                       HertzApproach approach, double design_relief)
    : pair_(pair),
      compliance_(
          [&](double s) {
            const PairStiffness ps = stiffness.pair(s);
            return ps.pinion.total() + ps.wheel.total();
          },
          pair.path().a, pair.path().e, kCompliancePoints),
      hertz_compliance_(stiffness.pair(pair.path().c).hertz_compliance),
      material_{pinion, wheel},
      composite_modulus_(composite_modulus),
      flank_{FlankModification(pair, 0, m[0], design_relief), FlankModification(pair, 1, m[1], design_relief)},
      approach_(approach) {}

double LoadedToothContact::separation(double s, int k) const {
  const double rho1 = s, rho2 = pair_.path().line_length - s;
  const double pitch = k * (flank_[1].base_pitch_deviation() - flank_[0].base_pitch_deviation());
  return flank_[0].at(rho1) + flank_[1].at(rho2) + pitch;
}

std::vector<PairContact> LoadedToothContact::pairs(const std::vector<double>& positions) const {
  std::vector<PairContact> out;
  const double width = pair_.spec().face_width;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const double s = positions[k];
    PairContact c;
    c.separation = separation(s, static_cast<int>(k));
    c.compliance = teeth_compliance(s);
    LineContactApproach& h = c.hertz;
    h.model = approach_;
    h.face_width = width;
    h.radius = pair_.flank(s).radius_equivalent;
    h.composite_modulus = composite_modulus_;
    h.linear_compliance = hertz_compliance_;
    const double rho[2] = {s, pair_.path().line_length - s};
    for (int i = 0; i < 2; ++i) {
      h.youngs_modulus[i] = material_[i].youngs_modulus;
      h.poisson_ratio[i] = material_[i].poisson_ratio;
      h.depth[i] = tooth_centre_depth(pair_.gear(i), rho[i]);
    }
    out.push_back(c);
  }
  return out;
}

double LoadedToothContact::teeth_compliance(double s) const {
  const PathOfContact& p = pair_.path();
  return compliance_(std::clamp(s, p.a, p.e));
}

CompatibilitySolution LoadedToothContact::solve(const std::vector<double>& positions, double force) const {
  const std::vector<PairContact> p = pairs(positions);
  return solve_compatibility(p, force);
}

}  // namespace geartrib::gear
