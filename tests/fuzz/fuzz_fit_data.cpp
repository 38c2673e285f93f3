// libFuzzer harness: the observations of `geartrib fit --data` (CSV with units and provenance).
#include "fit/fit_files.hpp"
#include "fuzz_support.hpp"

using namespace geartrib;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = fuzz::write_input("data.csv", data, size);
  fuzz::expect_accepted_or_refused([&] {
    const fit::FitData d = io::read_fit_data(path);
    for (double v : d.delta_star) fuzz::expect_finite(v, "delta*");
    for (double w : d.weight) fuzz::expect_finite(w, "weight");
  });
  return 0;
}
