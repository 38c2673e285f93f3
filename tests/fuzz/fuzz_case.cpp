// libFuzzer harness: a case file and its --set changes. Input: optional change lines
// ("KEY=VALUE", one per line), a line "---", then the case TOML (no "---": all TOML). The case is
// written to <scratch>/gears/case.toml beside links to the source tree's materials/ and
// lubricants/, so that the shipped cases' relative paths resolve.
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "fuzz_support.hpp"

#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace geartrib;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool linked = [] {
    fs::create_directories(fuzz::scratch() / "gears");
    for (const char* dir : {"materials", "lubricants"}) {
      std::error_code ignored;
      fs::create_directory_symlink(fs::path(GEARTRIB_SOURCE_DIR) / dir, fuzz::scratch() / dir, ignored);
    }
    return true;
  }();
  (void)linked;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto split = text.find("\n---\n");
  std::vector<std::string> lines;
  std::string toml = text;
  if (split != std::string::npos) {
    toml = text.substr(split + 5);
    std::size_t start = 0;
    const std::string head = text.substr(0, split);
    while (start <= head.size()) {
      const auto end = std::min(head.find('\n', start), head.size());
      if (end > start) lines.push_back(head.substr(start, end - start));
      start = end + 1;
    }
  }
  const auto path =
      fuzz::write_input("gears/case.toml", reinterpret_cast<const std::uint8_t*>(toml.data()), toml.size());
  fuzz::expect_accepted_or_refused([&] {
    std::vector<io::CaseChange> changes;
    for (const auto& l : lines) changes.push_back(io::parse_case_change(l));
    const Case c = io::prepare_case(io::load_case(path, changes));
    fuzz::expect_finite(c.gear_pair.module, "module");
    fuzz::expect_finite(c.gear_pair.face_width, "face width");
    fuzz::expect_finite(c.operating.pinion_torque, "torque");
    fuzz::expect_finite(c.operating.pinion_speed, "speed");
    fuzz::expect_finite(c.pinion.material.youngs_modulus, "pinion modulus");
    fuzz::expect_finite(c.wheel.material.youngs_modulus, "wheel modulus");
  });
  return 0;
}
