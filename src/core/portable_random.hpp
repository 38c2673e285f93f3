// Seeded draws that are the same on every platform: std::mt19937_64 is specified bit for bit, the
// std distributions' algorithms are not (they are implementation-defined).
#pragma once

#include <random>

namespace geartrib::core {

// A uniform draw on [0, 1) from the generator's top 53 bits.
inline double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace geartrib::core
