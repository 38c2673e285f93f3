// The registered models: each wraps one law of laws.hpp; Hertz, CEB and the continuous model
// also define their own pressure profiles.
#include "asperity/model.hpp"

#include <algorithm>
#include <cmath>
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

PressureProfile AsperityModel::profile(double, const ContactPair& pair, const Critical& crit, double load,
                                       double area) const {
  const double a = std::sqrt(area / std::numbers::pi);
  return profile_from_mean_pressure(a, area > 0.0 ? load / area : 0.0, crit.peak_pressure, pair.hardness);
}

AsperityState AsperityModel::evaluate(const ContactPair& pair, double delta, Detail detail) const {
  if (!(delta >= 0.0) || !std::isfinite(delta))
    throw std::invalid_argument("interference must be finite and non-negative");
  const Critical crit = critical(pair);
  AsperityState s;
  s.delta = delta;
  s.delta_star = delta / crit.interference;
  const Star<double> st = star(s.delta_star, pair);
  s.load_star = st.load;
  s.area_star = st.area;
  s.load = st.load * crit.load;
  s.area = st.area * crit.area;
  s.contact_radius = std::sqrt(s.area / std::numbers::pi);
  // Mean pressure -> 0 as delta -> 0 (Hertz p_m ~ sqrt(delta)).
  s.mean_pressure = s.area > 0.0 ? s.load / s.area : 0.0;
  if (detail == Detail::load_area) return s;
  const PressureProfile prof = profile(s.delta_star, pair, crit, s.load, s.area);
  s.plastic_radius = prof.core_radius;
  s.plastic_fraction = prof.plastic_fraction();
  s.max_pressure = prof.max_pressure();
  if (detail == Detail::profile) return s;
  const VonMisesMaximum vm = prof.von_mises_maximum(pair.poisson_ratio);
  s.max_von_mises = vm.value;
  s.von_mises_depth = vm.depth;
  return s;
}

namespace {

template <class Law>
class LawModel : public AsperityModel {
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
  Star<double> star(double d, const ContactPair& pair) const override {
    return Law::star(d, constants_.data(), pair);
  }
};

class HertzModel final : public LawModel<HertzLaw> {
 public:
  PressureProfile profile(double, const ContactPair&, const Critical&, double load, double area) const override {
    const double a = std::sqrt(area / std::numbers::pi);
    return hertz_profile(a, area > 0.0 ? 1.5 * load / area : 0.0);
  }
};

class CebModel final : public LawModel<CebLaw> {
 public:
  PressureProfile profile(double d, const ContactPair&, const Critical&, double load, double area) const override {
    const double a = std::sqrt(area / std::numbers::pi);
    const double pm = area > 0.0 ? load / area : 0.0;
    return d <= 1.0 ? hertz_profile(a, 1.5 * pm) : uniform_profile(a, pm);  // CEB: uniform k H once plastic
  }
};

class ContinuousModel final : public LawModel<ContinuousLaw> {
 public:
  PressureProfile profile(double d, const ContactPair& pair, const Critical&, double load,
                          double area) const override {
    const double a = std::sqrt(area / std::numbers::pi);
    if (d <= 1.0) return hertz_profile(a, area > 0.0 ? 1.5 * load / area : 0.0);
    const auto cl = ContinuousLaw::closure(d, constants_.data(), ceb_pressure_factor(pair.poisson_ratio));
    PressureProfile p;
    p.contact_radius = a;
    p.core_radius = a * std::sqrt(cl.plastic_fraction);
    p.core_pressure = cl.core_pressure * pair.hardness;
    p.annulus_peak = hertz_peak_pressure(a, pair.radius, pair.modulus);  // p_e = 2 E_t r_a/(pi R)
    return p;
  }
};

// The model class of each law: the default, or one that defines its own pressure profile.
template <class Law>
struct ModelFor {
  using type = LawModel<Law>;
};
template <>
struct ModelFor<HertzLaw> {
  using type = HertzModel;
};
template <>
struct ModelFor<CebLaw> {
  using type = CebModel;
};
template <>
struct ModelFor<ContinuousLaw> {
  using type = ContinuousModel;
};

constexpr auto kNames = std::apply([](auto... laws) { return std::array{decltype(laws)::name...}; }, LawList{});

}  // namespace

std::span<const std::string_view> asperity_model_names() { return kNames; }

std::unique_ptr<AsperityModel> make_asperity_model(std::string_view name) {
  return visit_law(name, [](auto tag) -> std::unique_ptr<AsperityModel> {
    return std::make_unique<typename ModelFor<typename decltype(tag)::type>::type>();
  });
}

}  // namespace geartrib::asperity
