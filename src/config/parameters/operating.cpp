// The operating point's keys, declared beside OperatingPoint (case/case.hpp) and the FZG load stages.
#include "config/parameters/declare.hpp"

#include "config/fzg_load_stages.hpp"

#include <fmt/format.h>

namespace geartrib::io::parameters {

namespace {

// The FZG tests and their lever arms, as operating.fzg_test's meaning.
std::string fzg_tests_text() {
  std::string s = "The FZG test of operating.fzg_load_stage, which names the lever arm the stage's weights hang on:";
  for (const FzgTest& t : fzg_tests())
    s += fmt::format("{} {}: {}, {:g} m arm", s.back() == ':' ? "" : ";", t.name, t.what, t.lever_arm);
  return s;
}

}  // namespace

// [operating]: load, speed, oil and bulk temperatures.
void declare_operating(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  using K = ParameterKind;
  // [operating]
  add(quantity(
          "operating.pinion_torque", D::torque, [](auto& c, int) -> auto& { return c.operating.pinion_torque; }))
      .range(1e-9, 1e10)
      .plausible(1e-6, 1e7)
      .required(kGeometryPart)
      .alias({"torque"})
      .doc("Pinion torque T1; or give operating.fzg_load_stage with operating.fzg_test instead");
  add(integer(
          "operating.fzg_load_stage", [](auto& c, int) -> auto& { return c.operating.fzg_load_stage; }))
      .range(kFzgMinLoadStage, kFzgMaxLoadStage)
      .no_default()
      .alias({"fzg_load_stage"})
      .doc(
          "FZG load stage: sets the pinion torque from the FZG rig's load-stage table of operating.fzg_test's lever "
          "arm (gears/fzg/load-stages.csv); instead of operating.pinion_torque");
  add(text(
          "operating.fzg_test", K::choice, [](auto& c, int) -> auto& { return c.operating.fzg_test; }))
      .choices(fzg_test_names(), "FZG test")
      .no_default()
      .alias({"fzg_test"})
      .doc(fzg_tests_text());
  add(quantity(
          "operating.pinion_speed", D::angular_speed, [](auto& c, int) -> auto& { return c.operating.pinion_speed; }))
      .range(1e-6, 1e6)
      .plausible(0.1 * kRpm, 1e5 * kRpm)
      .required(kGeometryPart)
      .alias({"speed"})
      .doc("Pinion speed n1");

  add(quantity(
          "operating.oil_temperature", D::temperature,
          [](auto& c, int) -> auto& { return c.operating.oil_temperature; }))
      .range(100.0, 1000.0)
      .no_default()
      .alias({"oil_temperature"})
      .doc("Oil (inlet) temperature; required with [lubricant]");
  add(quantity(
          "operating.bulk_temperature", D::temperature,
          [](auto& c, int) -> auto& { return c.operating.bulk_temperature; }))
      .range(0.0, 2000.0)
      .alias({"bulk_temperature"})
      .doc(
          "Flanks' bulk temperature theta_M (film viscosity, contact temperature); 0: the ISO/TS 6336-20 "
          "estimate oil + 0.47 x mean flash temperature");
}

}  // namespace geartrib::io::parameters
