// Flank profiles: one line of heights along the involute (the direction of rolling), generated
// (smooth, ground, hobbed; seeded) or taken from a measured grid, and their ISO 4287 statistics
// with McCool's spectral moments and the profile peaks.
#pragma once

#include "surface/height_grid.hpp"
#include "surface/rough_surface.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace geartrib::surface {

// A flank's profile along the involute (the direction of rolling), root to tip: evenly spaced heights [m].
struct FlankProfile {
  double spacing = 0.0;   // [m]
  std::vector<double> z;  // heights [m], z[k] at k*spacing from the profile's start; positive out of the flank
  double length() const;  // spacing * (z.size() - 1), 0 when fewer than 2 points
};

enum class ProfileKind { smooth, ground, hobbed };

// Generated flank profiles (seeded):
//  - smooth: all zero;
//  - ground: a Gaussian random profile with autocorrelation rq^2 exp(-tau^2/lambda^2) (lambda = correlation_length),
//    made (Hu & Tonder 1992) by convolving seeded white noise (std::mt19937_64(seed), std::normal_distribution) with a
//    Gaussian kernel of standard deviation lambda/2 truncated at +-4 of them (+-2 lambda), then the mean removed and
//    scaled to exactly rq;
//  - hobbed: parallel parabolic ridges z = c - (x - x_k)^2/(2 ridge_radius), ridge_spacing apart, meeting in sharp
//    valleys (feed/generating marks), mean removed, plus a ground-like random component of rq (rq = 0: pure ridges).
//    Ridge positions start at a seeded random phase (the first draw of the generator; the noise follows).
struct GeneratedProfileSpec {
  ProfileKind kind = ProfileKind::ground;
  double spacing = 0.25e-6;           // [m], in [kMinSpacing, kMaxSpacing]
  double rq = 0.3e-6;                 // [m] ground: the profile's Rq (> 0); hobbed: the random component's (>= 0)
  double correlation_length = 10e-6;  // [m] lambda of the Gaussian ACF, >= 2 spacings
  double ridge_spacing = 40e-6;       // [m] hobbed, >= 4 spacings
  double ridge_radius = 400e-6;       // [m] hobbed ridge tip radius
  std::uint64_t seed = 1;
  // Throws core::KeyedError (a std::invalid_argument) whose key is the field (rq, correlation_length,
  // ...) and whose message is the rule; checks the fields the kind uses.
  void validate() const;
};

ProfileKind profile_kind(const std::string& name);  // "smooth" | "ground" | "hobbed"; invalid_argument otherwise
const char* profile_kind_name(ProfileKind k);

// A profile of at least `length` [m]: ceil(length/spacing) + 1 points (a ratio within 1e-9 of a whole number counts
// as that number, so that round-off in length/spacing adds no point). Refuses lengths above kMaxProfilePoints points.
inline constexpr std::size_t kMaxProfilePoints = std::size_t{1} << 24;
FlankProfile generate_profile(const GeneratedProfileSpec& s, double length);

// A measured surface's profile: the grid line along x (along_x) or along y at the fraction `at` in [0, 1] of the
// other axis (nearest line), its own spacing. Throws when that line has a missing point (clean/fill the surface
// first) or fewer than 2 points.
FlankProfile profile_from_grid(const HeightGrid& g, bool along_x, double at);

// Profile statistics about the mean line (ISO 4287 Ra, Rq, Rsk, Rku), spectral moments from finite differences
// (m0 = Rq^2, m2 = mean squared central-difference slope, m4 = mean squared second difference / spacing^4;
// McCool 1986), and the peaks: points higher than both neighbours (a plateau: its first point) and above the mean
// line; summit_radius = 1 / mean of their curvature -(z[i-1] - 2 z[i] + z[i+1]) / spacing^2 (0 when no peak),
// peak_density = peaks per metre of profile length, peak_height = their mean height above the mean line (0 when
// no peak). Fewer than 3 points: invalid_argument.
struct ProfileStatistics {
  double ra = 0, rq = 0, rsk = 0, rku = 0;  // [m], [m], [-], [-]; Rsk = Rku = 0 for a flat profile
  double m0 = 0, m2 = 0, m4 = 0;            // [m^2], [-], [1/m^2]
  double summit_radius = 0;                 // [m]
  double peak_density = 0;                  // [1/m]
  double peak_height = 0;                   // [m]
  int peaks = 0;
};
ProfileStatistics profile_statistics(std::span<const double> z, double spacing);

// A profile's roughness for the statistical model: the spectral form of its moments m0, m2, m4
// (McCool's summits; the profile twin of measured_roughness for an areal surface).
FlankRoughness spectral_roughness(const ProfileStatistics& s);

}  // namespace geartrib::surface
