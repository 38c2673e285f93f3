#include "lubrication/ehl_film.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace geartrib::lubrication {

namespace {
constexpr std::array<FilmLaw, 4> kLaws{{
    {"dowson-higginson", 2.65, 0.70, 0.54, -0.13, false, "Dowson & Higginson 1977"},
    {"pan-hamrock-min", 1.714, 0.694, 0.568, -0.128, false, "Pan & Hamrock 1989"},
    {"pan-hamrock-central", 2.922, 0.692, 0.470, -0.166, true, "Pan & Hamrock 1989"},
    {"dowson-toyoda", 3.06, 0.69, 0.56, -0.10, true, "Dowson & Toyoda 1979"},
}};
constexpr auto kFormulaNames = [] {
  std::array<NamedChoice<FilmFormula>, kLaws.size()> names{};
  for (std::size_t i = 0; i < kLaws.size(); ++i) names[i] = {static_cast<FilmFormula>(i), kLaws[i].name};
  return names;
}();
constexpr NamedChoice<InletHeating> kInletNames[] = {
    {InletHeating::none, "none"}, {InletHeating::murch_wilson, "murch-wilson"}, {InletHeating::gupta, "gupta"}};
}  // namespace

EhlGroups ehl_groups(double eta0, double alpha, double u, double w, double radius, double e) {
  return {eta0 * u / (e * radius), alpha * e, w / (e * radius)};
}

MoesGroups moes_groups(const EhlGroups& g) {
  const double two_u = 2.0 * g.speed;
  return {g.load / std::sqrt(two_u), g.material * std::pow(two_u, 0.25)};
}

EhlGroups groups_from_moes(const MoesGroups& m, double load) {
  const double ratio = load / m.load;
  const double speed = 0.5 * ratio * ratio;
  return {speed, m.material * std::pow(2.0 * speed, -0.25), load};
}

const FilmLaw& film_law(FilmFormula f) { return kLaws[static_cast<std::size_t>(f)]; }

std::span<const NamedChoice<FilmFormula>> film_formula_choices() { return kFormulaNames; }
const char* film_formula_name(FilmFormula f) { return choice_name(film_formula_choices(), f); }

double smooth_film(FilmFormula f, const EhlGroups& g, double radius) {
  if (!(g.speed > 0.0) || !(g.load > 0.0)) return 0.0;  // no entrainment (or no viscosity): no film
  const FilmLaw& l = film_law(f);
  return radius * l.k * std::pow(g.speed, l.speed_exponent) * std::pow(g.material, l.material_exponent) *
         std::pow(g.load, l.load_exponent);
}

std::span<const NamedChoice<InletHeating>> inlet_heating_choices() { return kInletNames; }
const char* inlet_heating_name(InletHeating model) { return choice_name(inlet_heating_choices(), model); }

double thermal_loading(double beta, double eta0, double u, double k_f) { return beta * eta0 * u * u / k_f; }

double inlet_heating_factor(InletHeating model, double l, double srr, double ph_over_e) {
  switch (model) {
    case InletHeating::none:
      return 1.0;
    case InletHeating::murch_wilson:
      return 3.94 / (3.94 + std::pow(l, 0.62));
    case InletHeating::gupta: {
      const double phi = (1.0 - 13.2 * ph_over_e * std::pow(l, 0.42)) /
                         (1.0 + 0.213 * (1.0 + 2.23 * std::pow(std::abs(srr), 0.83)) * std::pow(l, 0.64));
      return std::clamp(phi, kMinInletHeatingFactor, 1.0);
    }
  }
  return 1.0;
}

EhlRegime ehl_regime(const EhlGroups& g) {
  if (!(g.speed > 0.0)) return EhlRegime::elastic_piezoviscous;  // no film: dry contact, the elastic limit
  const double su = std::sqrt(g.speed);
  const double gv = g.material * std::pow(g.load, 1.5) / su, ge = g.load / su;
  const double ir = 4.9, vr = 1.66 * std::pow(gv, 2.0 / 3.0), ie = 2.45 * std::pow(ge, 0.8),
               ep = 1.654 * std::pow(gv, 0.54) * std::pow(ge, 0.06);
  const bool elastic = ie > ir, piezoviscous = vr > ir;
  if (!elastic) return piezoviscous ? EhlRegime::rigid_piezoviscous : EhlRegime::rigid_isoviscous;
  if (!piezoviscous) return EhlRegime::elastic_isoviscous;
  if (ep >= vr) return EhlRegime::rigid_piezoviscous;
  if (ep <= ie) return EhlRegime::elastic_isoviscous;
  return EhlRegime::elastic_piezoviscous;
}

const char* ehl_regime_name(EhlRegime r) {
  switch (r) {
    case EhlRegime::rigid_isoviscous:
      return "rigid-isoviscous";
    case EhlRegime::rigid_piezoviscous:
      return "rigid-piezoviscous";
    case EhlRegime::elastic_isoviscous:
      return "elastic-isoviscous";
    case EhlRegime::elastic_piezoviscous:
      return "elastic-piezoviscous";
  }
  return "";
}

}  // namespace geartrib::lubrication
