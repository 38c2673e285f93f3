// libFuzzer harness: a topography file in every format. The first byte chooses the format (by the
// extension the reader dispatches on), the rest is the file; read, cleaned, and its statistics
// computed as `geartrib surface stats` does.
#include "fuzz_support.hpp"
#include "surface/surface_statistics.hpp"
#include "topography/topography_files.hpp"

using namespace geartrib;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kNames[] = {"t.xyz", "t.asc", "t.csv", "t.txt", "t.grd", "t.h5", "t.x3p"};
  const auto path = fuzz::write_input(kNames[data[0] % 7], data + 1, size - 1);
  fuzz::expect_accepted_or_refused([&] {
    const io::LoadedSurface s = io::load_surface(path, {}, {});
    const surface::SurfaceStatistics st = surface::surface_statistics(s.grid);
    fuzz::expect_finite(st.rq, "Rq");
    fuzz::expect_finite(st.ra, "Ra");
  });
  return 0;
}
