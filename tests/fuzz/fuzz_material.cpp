// libFuzzer harness: a material file (TOML with units).
#include "config/case_file.hpp"
#include "fuzz_support.hpp"

using namespace geartrib;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = fuzz::write_input("material.toml", data, size);
  fuzz::expect_accepted_or_refused([&] {
    const Material m = io::load_material(path);
    fuzz::expect_finite(m.youngs_modulus, "modulus");
    fuzz::expect_finite(m.poisson_ratio, "Poisson's ratio");
    fuzz::expect_finite(m.yield_strength, "yield strength");
  });
  return 0;
}
