// Synthetic surfaces, seeded: the test data of the topography tools (no measured flank ships with
// the project).
#pragma once

#include "surface/height_grid.hpp"

#include <cstdint>

namespace geartrib::surface {

// Random-phase self-affine surface (Persson; Jacobs, Junge & Pastewka 2017): power spectrum
// flat below the roll-off wavenumber, ~ q^-2(1+H) up to the short-wavelength cut-off, zero
// beyond; anisotropic when `anisotropy` > 1 (correlation that much longer along the lay direction
// `lay_angle` from the x axis); scaled to the root-mean-square height `rq`.
struct SelfAffineSpec {
  int nx = 256, ny = 256;
  double spacing = 0.5e-6;  // [m]
  double rq = 0.3e-6;       // [m]
  double hurst = 0.8;
  double rolloff_wavelength = 30e-6;  // [m]
  double cutoff_wavelength = 2e-6;    // [m], >= 2 spacings
  double anisotropy = 1.0;
  double lay_angle = 0.0;  // [rad]
  std::uint64_t seed = 1;
};
HeightGrid self_affine_surface(const SelfAffineSpec& s);

// An isotropic Gaussian random surface with autocorrelation rq^2 exp(-r^2/lambda^2): the areal
// counterpart of a generated ground profile (surface/flank_profile.hpp), every line through it having
// that profile's autocorrelation. White noise convolved with exp(-r^2/(2 s^2)), s = lambda/2, taken
// separably and truncated at 4 s; periodic along y (the rows wrap: a window periodic across a face),
// open along x (the noise runs on beyond the ends); scaled to rq exactly.
struct GaussianSurfaceSpec {
  int nx = 256, ny = 64;
  double dx = 0.5e-6, dy = 0.5e-6;    // [m]
  double rq = 0.3e-6;                 // [m]
  double correlation_length = 10e-6;  // lambda [m], at least two spacings each way
  std::uint64_t seed = 1;
};
HeightGrid gaussian_surface(const GaussianSurfaceSpec& s);  // std::invalid_argument naming the rule

// A hobbed-like directional texture: parallel parabolic ridges y = h - (x - c)^2/(2 R) along the
// lay (the y axis), `wavelength` apart, meeting in sharp valleys, plus seeded Gaussian noise of
// `noise_rq`.
struct HobbedSpec {
  int nx = 512, ny = 64;
  double spacing = 0.1e-6;     // [m]
  double wavelength = 5e-6;    // ridge spacing [m]
  double tip_radius = 6.6e-6;  // [m]
  double noise_rq = 0.0;       // [m]
  std::uint64_t seed = 1;
};
HeightGrid hobbed_surface(const HobbedSpec& s);

}  // namespace geartrib::surface
