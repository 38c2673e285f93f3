// Cost of one single-asperity evaluation, by model and by detail (load and area only, or the
// full stress outputs). Run: ./build/tests/geartrib_bench
#include "asperity/side_contact.hpp"
#include "case/asperity_setup.hpp"
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"

#include <benchmark/benchmark.h>

using namespace geartrib;
using namespace geartrib::asperity;

namespace {
const Case& seed_case() {
  static const Case c =
      io::prepare_case(io::load_case(std::filesystem::path(GEARTRIB_SOURCE_DIR) / "gears/m6z30.toml"));
  return c;
}

void evaluate(benchmark::State& state, std::string_view name, Detail detail) {
  const ContactPair p = contact_pair(seed_case());
  const auto m = make_asperity_model(name);
  const double dc = m->critical(p).interference;
  double d = 0.5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(m->evaluate(p, d * dc, detail));
    d = d < 1e3 ? d * 1.7 : 0.5;  // sweep the elastic, elastic-plastic and plastic ranges
  }
}

void side(benchmark::State& state) {
  const ContactPair p = contact_pair(seed_case());
  const auto m = make_asperity_model("continuous");
  const auto g = side_contact_geometry(1.65e-6, 1.75e-6, 0.1);
  const double dc = m->critical(p).interference;
  for (auto _ : state) benchmark::DoNotOptimize(evaluate_side_contact(*m, p, g, 5.0 * dc, Detail::load_area));
}
}  // namespace

BENCHMARK_CAPTURE(evaluate, continuous_load_area, "continuous", Detail::load_area);
BENCHMARK_CAPTURE(evaluate, continuous_full, "continuous", Detail::full);
BENCHMARK_CAPTURE(evaluate, kogut_etsion_load_area, "kogut-etsion", Detail::load_area);
BENCHMARK_CAPTURE(evaluate, kogut_etsion_full, "kogut-etsion", Detail::full);
BENCHMARK_CAPTURE(evaluate, jackson_green_load_area, "jackson-green", Detail::load_area);
BENCHMARK_CAPTURE(evaluate, zmc_load_area, "zmc", Detail::load_area);
BENCHMARK_CAPTURE(evaluate, hertz_full, "hertz", Detail::full);
BENCHMARK(side);

BENCHMARK_MAIN();
