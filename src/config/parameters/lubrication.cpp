// The lubrication's keys, declared beside lubrication::LubricationSettings (lubrication/lubrication_settings.hpp).
#include "config/parameters/declare.hpp"

#include "lubrication/ehl_film.hpp"
#include "lubrication/film_closure.hpp"
#include "lubrication/flank_temperature.hpp"
#include "lubrication/mixed_lubrication.hpp"

namespace geartrib::io::parameters {

// [lubricant]: a file or the fixed form; [lubrication]: the models along the path.
void declare_lubrication(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  using K = ParameterKind;
  // [lubricant]: a file, or the oil at the oil temperature given here (the fixed form).
  add(text(
          "lubricant.file", K::text, [](auto& c, int) -> auto& { return c.lubrication.lubricant_file; }))
      .alias({"lubricant"})
      .field("lubrication.lubricant_file")
      .doc(
          "Lubricant file (lubricants/*.toml, relative to the case); or give dynamic_viscosity and "
          "pressure_viscosity_coefficient here");
  add(quantity(
          "lubricant.dynamic_viscosity", D::dynamic_viscosity,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.fixed_dynamic_viscosity; }))
      .range(0.0, 1e4, true, false)
      .no_default()
      .alias({"viscosity"})
      .field("lubrication.lubricant.fixed_dynamic_viscosity")
      .doc("Fixed form: eta at the oil temperature (the film uses it at every temperature)");
  add(quantity(
          "lubricant.pressure_viscosity_coefficient", D::inverse_pressure,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.pressure_viscosity; }))
      .range(1e-12, 1e-6)
      .no_default()
      .alias({"alpha"})
      .field("lubrication.lubricant.pressure_viscosity")
      .doc("Fixed form: pressure-viscosity coefficient alpha at the oil temperature");
  add(quantity(
          "lubricant.temperature_viscosity_coefficient", D::inverse_temperature,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.fixed_temperature_viscosity; }))
      .range(0.0, 1.0)
      .field("lubrication.lubricant.fixed_temperature_viscosity")
      .doc(
          "Fixed form: beta = -d ln(eta)/dT for the inlet-heating correction (typical mineral oil at 70 degC; "
          "assumed)");
  add(quantity(
          "lubricant.thermal_conductivity", D::thermal_conductivity,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.thermal_conductivity; }))
      .range(1e-3, 1e3)
      .field("lubrication.lubricant.thermal_conductivity")
      .doc("Fixed form: the oil's thermal conductivity (typical mineral oil; assumed)");
  add(quantity(
          "lubricant.eyring_stress", D::pressure,
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.eyring_stress; }))
      .range(1e3, 1e10)
      .field("lubrication.lubricant.eyring_stress")
      .doc("Fixed form: Eyring stress tau_0 of the film's traction (typical; assumed)");
  add(number(
          "lubricant.limiting_shear_coefficient",
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.limiting_shear_coefficient; }))
      .range(0.0, 1.0, true, false)
      .field("lubrication.lubricant.limiting_shear_coefficient")
      .doc("Fixed form: limiting shear stress over pressure (typical mineral oil; assumed)");
  add(mapped_choice(
          "lubricant.base_oil", lubrication::base_oil_names(),
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.base_oil; },
          [](const std::string& t) { return lubrication::base_oil_from_name(t); },
          [](lubrication::BaseOil b) { return std::string(lubrication::base_oil_name(b)); }))
      .field("lubrication.lubricant.base_oil")
      .doc(
          "Fixed form: base stock, for the ISO lubricant factor X_L (an ester needs lubricant.iso_lubricant_factor: "
          "the standard tabulates none)");
  add(number(
          "lubricant.iso_lubricant_factor",
          [](auto& c, int) -> auto& { return c.lubrication.lubricant.iso_lubricant_factor; }))
      .range(0.0, 2.0)
      .field("lubrication.lubricant.iso_lubricant_factor")
      .doc("Fixed form: the ISO lubricant factor X_L itself; 0: the base stock's tabulated value");

  // [lubrication]: the models along the path.
  add(named_choice(
          "lubrication.film_formula", lubrication::film_formula_choices(), "film formula",
          [](auto& c, int) -> auto& { return c.lubrication.film_formula; }))
      .alias({"film_formula"})
      .doc("Smooth EHL film: Dowson-Higginson minimum, Pan-Hamrock minimum or central, Dowson-Toyoda central");
  add(named_choice(
          "lubrication.inlet_heating", lubrication::inlet_heating_choices(), "inlet-heating correction",
          [](auto& c, int) -> auto& { return c.lubrication.inlet_heating; }))
      .alias({"inlet_heating"})
      .doc("Inlet shear-heating correction of the film: Gupta et al. 1992, Murch-Wilson 1975 or none");
  add(quantity(
          "lubrication.wear_coefficient", D::inverse_pressure,
          [](auto& c, int) -> auto& { return c.lubrication.wear_coefficient; }))
      .range(0.0, 1e-9)
      .alias({"wear_coefficient"})
      .doc("Archard's dimensional wear coefficient k of the asperity contacts (order of mild wear; assumed)");
  add(quantity(
          "lubrication.scuffing_temperature", D::temperature,
          [](auto& c, int) -> auto& { return c.lubrication.scuffing_temperature; }))
      .range(0.0, 2000.0)
      .doc("Scuffing temperature theta_S for the ISO/TS 6336-20 flash-temperature safety; 0: none");
  add(named_choice(
          "lubrication.film_gap", lubrication::film_gap_choices(), "film gap",
          [](auto& c, int) -> auto& { return c.lubrication.film_gap; }))
      .alias({"film_gap"})
      .doc(
          "What the shared film's thickness equals: the mean gap between the rough flanks (Patir & Cheng), the "
          "separation of their mean planes (JGP 1972), or the gap counted from the dry contact (geartrib 0.1)");
  add(named_choice(
          "lubrication.asperity_pressure", lubrication::asperity_pressure_model_choices(), "asperity pressure model",
          [](auto& c, int) -> auto& { return c.lubrication.asperity_pressure; }))
      .alias({"asperity_pressure"})
      .doc(
          "Asperity pressure in the load sharing: auto (the asperity model, or the bearing area at the hardness "
          "where its plastic area fraction exceeds 0.99, blended from 0.9), asperity-model, bearing-area, or persson "
          "(Persson's interfacial separation law on the flanks' spectrum, blended with the bearing area as auto by "
          "his own plastic fraction; film_gap must be mean-gap)");
  add(named_choice(
          "lubrication.persson_spectrum", lubrication::persson_spectrum_choices(), "Persson spectrum",
          [](auto& c, int) -> auto& { return c.lubrication.persson_spectrum; }))
      .alias({"persson_spectrum"})
      .doc(
          "Persson's closure: the power spectrum his law takes. flanks: each flank's own, added (a measured areal "
          "topography's radial average, a generated ground profile's Gaussian; where a flank has neither, the "
          "moments' fit for the pair); moments: the self-affine spectrum fitted to the statistical model's "
          "moments, for comparison");
  add(named_choice(
          "lubrication.traction", lubrication::film_traction_choices(), "film traction model",
          [](auto& c, int) -> auto& { return c.lubrication.traction; }))
      .alias({"traction"})
      .doc(
          "Film traction: thermal Eyring (Johnson & Greenwood 1980), isothermal Eyring, or the lubricant's measured "
          "traction curves");
  add(named_choice(
          "lubrication.mean_friction", lubrication::mean_friction_law_choices(), "gear-mean friction law",
          [](auto& c, int) -> auto& { return c.lubrication.mean_friction; }))
      .alias({"mean_friction"})
      .doc(
          "Gear-mean friction law of the bulk-temperature estimate: iso-flash (ISO/TS 6336-20's own), iso "
          "(ISO/TS 6336-21/-22), schlenk, fernandes; all are reported");
}

}  // namespace geartrib::io::parameters
