// The registered models: each wraps one law of laws.hpp; every model's pressure profile is the
// two-zone profile with its plastic share (pressure_profile.hpp).
#include "asperity/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace geartrib::asperity {

double AsperityModel::constant(std::string_view name) const {
  const auto specs = constant_specs();
  for (std::size_t i = 0; i < specs.size(); ++i)
    if (specs[i].name == name) return constants_[i];
  throw std::invalid_argument("model '" + std::string(this->name()) + "' has no constant '" + std::string(name) + "'");
}

void AsperityModel::set_constant(std::string_view name, double value) {
  const auto specs = constant_specs();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (specs[i].name != name) continue;
    if (!(value >= specs[i].lower && value <= specs[i].upper))
      throw std::invalid_argument("constant '" + std::string(name) + "' of model '" + std::string(this->name()) +
                                  "' must lie in [" + std::to_string(specs[i].lower) + ", " +
                                  std::to_string(specs[i].upper) + "]");
    constants_[i] = value;
    return;
  }
  std::string known;
  for (const auto& s : specs) known += (known.empty() ? "" : ", ") + std::string(s.name);
  throw std::invalid_argument("model '" + std::string(this->name()) + "' has no constant '" + std::string(name) +
                              "' (known: " + (known.empty() ? "none" : known) + ")");
}

double AsperityModel::switch_delta_star(const ContactPair& pair) const {
  return switch_delta_star(pair, critical(pair));
}

double AsperityModel::switch_delta_star(const ContactPair& pair, const Critical& crit) const {
  const LawRange r = range();
  if (!r.switch_to_fully_plastic) return std::numeric_limits<double>::infinity();
  // a^2 = 2 R delta = (lim R)^2  =>  delta/R = lim^2/2, and delta_c/R = (pi p_y/(2 E_t))^2.
  const double dc_over_r = crit.interference / pair.radius;
  return std::min(r.fitted_delta_star_max,
                  0.5 * r.contact_radius_over_radius_max * r.contact_radius_over_radius_max / dc_over_r);
}

std::vector<double> AsperityModel::breakpoints(const ContactPair& pair) const {
  std::vector<double> out;
  law_breakpoints(out);
  const double ds = switch_delta_star(pair);
  if (std::isfinite(ds)) out.push_back(ds);
  return out;
}

Star<double> AsperityModel::star(double d, const ContactPair& pair) const {
  return star(d, pair, switch_delta_star(pair));
}

Star<double> AsperityModel::star(double d, const ContactPair& pair, double ds) const {
  if (!(d > ds)) return law_star(d, pair);
  // Fully plastic limit in the law's normalisation: A* = 2 d, F* = H A/F_c = 3 d H/p_y (F_c = 2/3 p_y A_c).
  const double load_per_d = 3.0 * pair.hardness / yield_peak_pressure(pair);
  const Star<double> at = law_star(ds, pair);
  const double decay = ds / d;
  return {load_per_d * d * std::pow(at.load / (load_per_d * ds), decay),
          2.0 * d * std::pow(at.area / (2.0 * ds), decay), law_star(d, pair).plastic};
}

PressureProfile AsperityModel::profile(double plastic_share, double load, double area) const {
  const double a = std::sqrt(area / std::numbers::pi);
  return two_zone_profile(a, area > 0.0 ? load / area : 0.0, plastic_share);
}

AsperityState AsperityModel::evaluate(const ContactPair& pair, double delta, Detail detail,
                                      VonMisesTable* stress_table) const {
  if (!(delta >= 0.0) || !std::isfinite(delta))
    throw std::invalid_argument("interference must be finite and non-negative");
  const Critical crit = critical(pair);
  AsperityState s;
  s.delta = delta;
  s.delta_star = delta / crit.interference;
  const double ds = switch_delta_star(pair, crit);
  const Star<double> st = star(s.delta_star, pair, ds);
  s.load_star = st.load;
  s.area_star = st.area;
  s.load = st.load * crit.load;
  s.area = st.area * crit.area;
  s.contact_radius = std::sqrt(s.area / std::numbers::pi);
  // Mean pressure -> 0 as delta -> 0 (Hertz p_m ~ sqrt(delta)).
  s.mean_pressure = s.area > 0.0 ? s.load / s.area : 0.0;
  s.plastic_fraction = std::clamp(st.plastic, 0.0, 1.0);
  const LawRange r = range();
  s.beyond_fitted_range = s.delta_star > r.fitted_delta_star_max;
  s.beyond_paraboloid = s.contact_radius > r.contact_radius_over_radius_max * pair.radius;
  s.fully_plastic_limit = s.delta_star > ds;
  if (detail == Detail::load_area) return s;
  const PressureProfile prof = profile(s.plastic_fraction, s.load, s.area);
  s.plastic_radius = prof.core_radius;
  s.max_pressure = prof.max_pressure();
  if (detail == Detail::profile) return s;
  if (stress_table && stress_table->poisson_ratio() != pair.poisson_ratio)
    throw std::invalid_argument("the von Mises table was built for another Poisson's ratio");
  const VonMisesMaximum vm = stress_table ? stress_table->at(s.contact_radius, s.mean_pressure, s.plastic_fraction)
                                          : prof.von_mises_maximum(pair.poisson_ratio);
  s.max_von_mises = vm.value;
  s.von_mises_depth = vm.depth;
  return s;
}

namespace {

template <class Law>
class LawModel final : public AsperityModel {
 public:
  LawModel() {
    for (const auto& c : Law::constants) constants_.push_back(c.value);
  }
  std::string_view name() const override { return Law::name; }
  std::string_view citation() const override { return Law::citation; }
  std::span<const ConstantSpec> constant_specs() const override { return Law::constants; }
  double yield_peak_pressure(const ContactPair& pair) const override {
    return Law::template yield_peak_pressure<double>(pair, constants_.data());
  }
  Star<double> law_star(double d, const ContactPair& pair) const override {
    return Law::star(d, constants_.data(), pair);
  }
  LawRange range() const override { return Law::range(constants_.data()); }

 protected:
  void law_breakpoints(std::vector<double>& out) const override { Law::breakpoints(constants_.data(), out); }
};

constexpr auto kNames = std::apply([](auto... laws) { return std::array{decltype(laws)::name...}; }, LawList{});

}  // namespace

std::span<const std::string_view> asperity_model_names() { return kNames; }

std::unique_ptr<AsperityModel> make_asperity_model(std::string_view name) {
  return visit_law(name, [](auto tag) -> std::unique_ptr<AsperityModel> {
    return std::make_unique<LawModel<typename decltype(tag)::type>>();
  });
}

}  // namespace geartrib::asperity
