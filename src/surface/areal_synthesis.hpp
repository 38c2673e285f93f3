// A flank-sized height map from a measured patch smaller than the flank (an interferometer's field,
// 1 mm or less): its areal power spectrum given random phases at a stated seed (anisotropic: the
// lay is kept, every direction's spectrum being the patch's own), or the patch itself tiled. The areal
// counterpart of surface/profile_synthesis.hpp. A synthesis cannot invent what the patch does not
// hold: no wavelength longer than the patch (none that completes less than one period across it),
// no detail finer than its spacing.
#pragma once

#include "surface/height_grid.hpp"

#include <cstdint>
#include <vector>

namespace geartrib::surface {

// A patch's two-sided areal power spectral density C(fx, fy) [m^4]: the periodogram of its even
// extension (the patch mirrored at its sides into 2 Nx x 2 Ny points, continuous across the seams: the
// 2-D DCT-II's power), its mean removed, no window. Normalised so that the full plane's sum of
// C dfx dfy is the patch's variance (Parseval, exactly: the extension holds the patch four times).
// The even extension in place of a window: a Hann window's main lobe folds the lowest bins into the
// mean and leaks power across a lay. On 128^2 cuts of a known self-affine surface with a lay (3:1), a
// synthesis from the Hann periodogram put the slope ratio 3-13 % low and its variance at 61-107 % of
// the cut's; from the mirror's, within 8 % and at 97-98 % (the seams' slope kinks leak ~f^-4, below
// a rough surface's spectrum). (Jacobs, Junge & Pastewka, Surf.
// Topogr. Metrol. Prop. 5 (2017) 013001, eq. 8, for the density's convention.)
// Stored on the half plane fx >= 0 (a real surface's C(-f) = C(f)).
struct ArealSpectrum {
  int nx = 0, ny = 0;     // the extension's points (twice the patch's), the transform's lengths
  double dx = 0, dy = 0;  // [m]
  double patch_rq = 0.0;  // the patch's rms height about its mean [m]
  std::vector<double>
      psd;  // C at fx = i/(nx dx), i = 0..nx/2, fy = l/(ny dy) (l >= ny/2 + 1: l - ny); [l * (nx/2 + 1) + i]

  double length_x() const { return 0.5 * nx * dx; }  // the patch's sides [m]
  double length_y() const { return 0.5 * ny * dy; }
  // sum over the whole plane of C dfx dfy [m^2]: patch_rq^2.
  double variance() const;
  // The slope variance along x (or y), sum (2 pi f)^2 C dfx dfy [1].
  double slope_variance(bool along_x) const;
  // The mean spacing of the profile elements along x (or y), RSm = 2 pi sqrt(m0/m2) (Rice: the mean
  // distance between the mean line's up-crossings of a Gaussian profile) [m]: the size of the
  // patch's hills and so the scale of a contact spot.
  double element_spacing(bool along_x) const;
  // C at (fx, fy) [1/m] as a synthesis takes it: bilinear between the bins (f and -f the same); zero
  // beyond the patch's Nyquist frequency either way and where a wave completes less than one period
  // across the patch ((fx Lx)^2 + (fy Ly)^2 < 1, L the patch's sides).
  double at(double fx, double fy) const;
};

// Throws std::invalid_argument for a grid with a missing point (fill it first), fewer than 8 points
// either way, or an extension beyond kMaxGridPoints.
ArealSpectrum areal_spectrum(const HeightGrid& patch);

// The radial (angular) average of an areal spectrum: the isotropic spectrum that theories of isotropic
// surfaces take (Persson's: contact::SpectrumPart's tabulated shape), in Persson's convention, C(q)
// [m^4] at q = 2 pi |f| [1/m] with <h^2> = integral C d^2q = 2 pi integral q C dq (the ArealSpectrum's
// C per cycle is (2 pi)^2 times it). Between the nodes C is the power law through them (log-log
// linear), zero outside them. Built as follows:
//  - the bins (the whole plane's, the mean's excluded) gathered in rings about q = 0: the first from
//    half the finer bin spacing dq, each one bin wide (the coarser spacing) until 2^(1/8) times its
//    inner radius is wider, then 2^(1/8) wide (every ring holds bins; ~8 a doubling of q);
//  - a node per ring at the rms wavenumber of its power (sqrt(sum q^2 P/sum P), P = C dfx dfy each
//    bin's share of the variance), and one at each end of the range (the first ring's inner edge, the
//    last's outer edge: the corners of the square of bins) carrying its ring's value;
//  - the values such that the interpolant carries each ring's variance sum P exactly (from sum P over
//    the ring's area; a ring's integral rests mostly on its own node: multiplicative fixed-point
//    steps, converging geometrically);
//  - then q scaled by b and C by a/b^2 so that the variance and the full gradient variance, sum q^2 P =
//    slope_variance(x) + slope_variance(y) (the 2-D gradient that Persson's theory takes: an
//    anisotropic patch's m2 along x plus across), are the spectrum's own to rounding. a is 1 once the
//    rings carry their variance; before b, the rings' interpolant holds the gradient variance to the
//    place of the power inside each ring (0.03-0.15 % measured), so b - 1 is of that order.
// What the average holds is what the patch resolves: nothing longer than twice the patch's side (its
// mirror's half periods, below q = 2 pi/L: the patch's form residue, little once its form is removed)
// and nothing finer than two spacings (the Nyquist wavelength; sqrt 2 spacings in the corners of the
// square of bins). An anisotropic patch's directions are averaged away: the isotropic theories'
// equivalent of it, not its lay. Throws std::invalid_argument for a spectrum without power (a flat patch).
struct RadialSpectrum {
  std::vector<double> q;  // the nodes [1/m], increasing
  std::vector<double> c;  // C(q) at them [m^4], >= 0
  double scale = 1.0;     // a: the values' scaling that made the variance exact (1 once the rings carry theirs)
  double stretch = 1.0;   // b: the nodes' scaling that made the gradient variance exact
};
RadialSpectrum radial_spectrum(const ArealSpectrum& s);

// A map of nx x ny points at spacings dx, dy, periodic both ways (period nx dx by ny dy):
// z = sum_k a_k cos(2 pi f_k . r + phi_k) over the map's wavevectors f_k, a_k^2/2 = C(f_k) dfx dfy
// (C the spectrum's at(), dfx = 1/(nx dx), dfy = 1/(ny dy)), the amplitudes fixed so that the map's
// periodogram is C at every f_k whatever the seed; phases uniform from std::mt19937_64(seed), one
// draw per half-plane bin in storage order (core::uniform01; self-conjugate bins take the sign of
// the draw's cosine). Mean zero. Its variance is what it resolves of the spectrum (resolved_fraction
// of the patch's Rq^2; the rest lies at wavelengths longer than the patch or than the map's sides).
// Throws std::invalid_argument beyond kMaxGridPoints, for a spacing finer than the patch's (detail
// the patch does not hold), or when no wavevector of the map carries power.
struct SynthesisedSurface {
  HeightGrid grid;
  double resolved_fraction = 0.0;  // the map's variance over the patch's Rq^2
};
SynthesisedSurface synthesise_surface(const ArealSpectrum& s, int nx, int ny, double dx, double dy, std::uint64_t seed);

// The patch itself repeated by mirror images (z(x) = z(2 L - x) beyond each side, L its side): heights
// continuous across the seams (the slope changes sign there), bilinear between the patch's points; the
// patch's mean removed. The map's point (i, j) lies at (x0 + i dx, j dy) in the patch's frame. Not
// periodic across the map's sides unless they are multiples of 2 L. Throws std::invalid_argument
// for a patch with a missing point, or beyond kMaxGridPoints.
HeightGrid tile_surface(const HeightGrid& patch, int nx, int ny, double dx, double dy, double x0 = 0.0);

}  // namespace geartrib::surface
