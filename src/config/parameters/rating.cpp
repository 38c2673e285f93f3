// The ratings' keys ([rating], {gear}.flank_rz, {gear}.root_rz), declared beside RatingRequest
// (case/case.hpp) and rating::RatingSettings (rating/load_capacity.hpp).
#include "config/parameters/declare.hpp"

#include <algorithm>

namespace geartrib::io::parameters {

void declare_rating(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  {
    Parameter methods;
    methods.key = "rating.methods";
    methods.kind = ParameterKind::choice_list;
    methods.choices = {"pitting", "bending", "scuffing", "micropitting"};
    methods.get = [](const Case& c, int) {
      ParameterValue v;
      if (c.rating.pitting) v.list.emplace_back("pitting");
      if (c.rating.bending) v.list.emplace_back("bending");
      if (c.rating.scuffing) v.list.emplace_back("scuffing");
      if (c.rating.micropitting) v.list.emplace_back("micropitting");
      return v;
    };
    methods.set = [](Case& c, int, const ParameterValue& v) {
      auto has = [&](const char* n) { return std::find(v.list.begin(), v.list.end(), n) != v.list.end(); };
      c.rating.pitting = has("pitting");
      c.rating.bending = has("bending");
      c.rating.scuffing = has("scuffing");
      c.rating.micropitting = has("micropitting");
    };
    add(std::move(methods))
        .alias({"ratings"})
        .doc(
            "The ratings a run computes (/rating): ISO 6336-2 pitting, ISO 6336-3 bending (method B), ISO/TS 6336-20/-21 "
            "scuffing (flash and integral temperature; lubricated), ISO/TS 6336-22 micropitting (lubricated); empty: "
            "none (geartrib rate: all the case's data allow)");
  }
  add(number(
          "rating.application_factor", [](auto& c, int) -> auto& { return c.rating.settings.application_factor; }))
      .field("rating.settings.application_factor")
      .range(1.0, 10.0)
      .alias({"K_A"})
      .doc("Application factor K_A (ISO 6336-1 6): the driver's and the load's overloads");
  add(number(
          "rating.face_load_factor", [](auto& c, int) -> auto& { return c.rating.settings.face_load_factor; }))
      .field("rating.settings.face_load_factor")
      .range(0.0, 10.0)
      .alias({"K_Hbeta"})
      .doc("Face load factor K_Hbeta (ISO 6336-1 7), given; 0: 1 assumed (ideal lead, stiff shafts), marked so");
  add(integer(
          "rating.accuracy_grade", [](auto& c, int) -> auto& { return c.rating.settings.accuracy_grade; }))
      .field("rating.settings.accuracy_grade")
      .range(1, 12)
      .alias({"accuracy_grade"})
      .doc("ISO 1328-1:1995 accuracy grade Q: the pitch and profile-form tolerances of K_v and K_Halpha");
  add(number(
          "rating.load_cycles", [](auto& c, int) -> auto& { return c.rating.settings.load_cycles; }))
      .field("rating.settings.load_cycles")
      .range(1.0, 1e12)
      .alias({"load_cycles"})
      .doc("Load cycles N_L of the pinion (the wheel's N_L/u) for the life factors Z_NT and Y_NT");
  add(named_choice(
          "rating.long_life", rating::long_life_choices(), "long-life branch",
          [](auto& c, int) -> auto& { return c.rating.settings.long_life; }))
      .field("rating.settings.long_life")
      .doc(
          "The life factors beyond the knee: optimum (1: optimum lubrication, material, manufacture and experience) or "
          "normal (down to 0.85 at 1e10 cycles), ISO 6336-2/-3");
  add(named_choice(
          "rating.oil_supply", rating::oil_supply_choices(), "oil supply",
          [](auto& c, int) -> auto& { return c.rating.settings.oil_supply; }))
      .field("rating.settings.oil_supply")
      .doc("Oil supply of the scuffing methods' bulk temperature: dip (X_S = 1.0) or spray (X_S = 1.2)");
  add(quantity(
          "{gear}.flank_rz", D::length,
          [](auto& c, int g) -> auto& { return c.rating.settings.flank_rz[static_cast<std::size_t>(g)]; }))
      .range(0.0, 100e-6)
      .field("rating.settings.flank_rz[{gear}]")
      .doc("Peak-to-valley roughness Rz of the flank for Z_R (ISO 6336-2); 0: 6 Ra (assumed)");
  add(quantity(
          "{gear}.root_rz", D::length,
          [](auto& c, int g) -> auto& { return c.rating.settings.root_rz[static_cast<std::size_t>(g)]; }))
      .range(0.0, 100e-6)
      .field("rating.settings.root_rz[{gear}]")
      .doc("Peak-to-valley roughness Rz of the root fillet for Y_RrelT (ISO 6336-3); 0: 10 um (assumed)");
}

}  // namespace geartrib::io::parameters
