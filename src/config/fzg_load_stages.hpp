// The FZG back-to-back rig's load stages: the pinion torque of each stage 1..14 for the rig's two
// lever arms, and the tests that name an arm. The table is compiled in at build time from its data
// file, gears/fzg/load-stages.csv (the one source of the numbers, with each row's provenance and
// status; gears/fzg/README.md); a case names `operating.fzg_load_stage` and `operating.fzg_test`
// instead of a torque (io::load_case resolves them).
#pragma once

#include "gear/spur_pair.hpp"
#include "material/material.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace geartrib::io {

inline constexpr int kFzgMinLoadStage = 1;
inline constexpr int kFzgMaxLoadStage = 14;

// One row of the table: the pinion torque [N m] at the 0.5 m and the 0.35 m lever arm, and whether
// each is sourced (false: printed by the sources but contradicted by the arms' ratio, refused).
struct FzgLoadStage {
  int stage = 0;
  double torque_long_arm = 0.0;  // 0.5 m arm [N m]
  bool long_arm_sourced = false;
  double torque_short_arm = 0.0;  // 0.35 m arm [N m]
  bool short_arm_sourced = false;
};
const std::array<FzgLoadStage, kFzgMaxLoadStage>& fzg_load_stages();

// An FZG test and the lever arm its load stages hang on.
struct FzgTest {
  std::string_view name;   // as a case names it: "A/8.3/90", "PT-C", "GF-C/8.3/90"
  double lever_arm = 0.0;  // [m]: 0.5 or 0.35
  std::string_view what;   // the test, its gear and its standard
};
const std::vector<FzgTest>& fzg_tests();
std::vector<std::string> fzg_test_names();

// The pinion torque [N m] of load stage `stage` in test `test`, with a phrase saying where it came
// from ("FZG load stage 10 of GF-C/8.3/90, 0.35 m arm (gears/fzg/load-stages.csv)"). Throws
// std::invalid_argument naming the rule for an unknown test, a stage outside 1..14 or an entry the
// table marks unconfirmed.
struct FzgTorque {
  double torque = 0.0;  // [N m]
  std::string origin;
};
FzgTorque fzg_pinion_torque(std::string_view test, int stage);

// The FZG type C test gear pair (z 16/24, m 4.5 mm, b 14 mm, x 0.1817/0.1715, a 91.5 mm, the
// published tip diameters, the rig's 30 mm shafts as bores), as gears/fzg-c.toml gives it with its
// sources (a test holds the two equal): the micropitting rating's test gear.
gear::GearPairSpec fzg_c_gear_pair();
// The C gear's case-carburised 16MnCr5 as materials/16MnCr5.toml gives it (elastic, case and thermal
// values; a test holds the two equal).
Material fzg_c_test_material();

}  // namespace geartrib::io
