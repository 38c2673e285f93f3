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

// A Gaussian random surface with autocorrelation rq^2 exp(-x^2/lambda_x^2 - y^2/lambda_y^2): the
// areal counterpart of a generated ground profile (surface/flank_profile.hpp), every line along x
// through it having that profile's autocorrelation; isotropic when lambda_y = lambda_x, a lay along y
// when lambda_y > lambda_x (ground flanks: Peklenik's gamma = lambda_y/lambda_x). White noise
// convolved with exp(-x^2/(2 s_x^2) - y^2/(2 s_y^2)), s = lambda/2, taken separably and truncated at
// 4 s; periodic along y (the rows wrap: a window periodic across a face; a kernel longer than the
// period wraps onto itself), open along x (the noise runs on beyond the ends); scaled to rq exactly.
struct GaussianSurfaceSpec {
  int nx = 256, ny = 64;
  double dx = 0.5e-6, dy = 0.5e-6;    // [m]
  double rq = 0.3e-6;                 // [m]
  double correlation_length = 10e-6;  // lambda_x [m], at least two spacings each way
  double correlation_length_y = 0.0;  // lambda_y [m]; 0: lambda_x (isotropic)
  std::uint64_t seed = 1;
  double lambda_y() const { return correlation_length_y > 0.0 ? correlation_length_y : correlation_length; }
};
HeightGrid gaussian_surface(const GaussianSurfaceSpec& s);  // std::invalid_argument naming the rule

// A superfinished (plateau) flank: a ground surface (`ground`, its lay along y) whose peaks the
// finishing has cut flat where the area above the cut is `plateau` of the whole (ISO 13565-3's
// material ratio Rmq at the plateau-valley transition), the grinding's deepest valleys left, and the
// finishing's own fine isotropic texture (`fine_rq`, `fine_correlation`, seed + 1) on it: the
// stratified surface of plateau honing and isotropic superfinishing (Pawlus, Wear 176 (1994) 247, by
// truncating a Gaussian surface). Mean zero.
struct SuperfinishedSpec {
  GaussianSurfaceSpec ground;
  double plateau = 0.8;            // the area cut flat, in (0, 1)
  double fine_rq = 0.02e-6;        // [m], >= 0
  double fine_correlation = 2e-6;  // [m], at least two spacings
  void validate() const;           // std::invalid_argument naming the rule
};
HeightGrid superfinished_surface(const SuperfinishedSpec& s);

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
