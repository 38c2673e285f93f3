// Areal rough contact by FFT boundary elements: a rigid flat pressed on a height map (the
// composite surface of two rough bodies, Johnson 1985 section 13.1) of an elastic half-space of
// composite modulus E*, with the pressure capped at the hardness (elastic-perfectly-plastic).
//
// The displacement of the surface under a pressure field is the convolution u = K p:
//  - a periodic direction by its Fourier multiplier, 2/(E* |q|) (Stanley & Kato 1997, J. Tribol.
//    119:481), the mean pressure's rigid mode set aside (the surface's mean displacement is zero);
//  - an open direction by the influence of each element's uniform pressure (Love 1929: Johnson
//    eq. 3.25; one periodic direction: its Fourier transform along that direction, 2 K_0(|q| x)/
//    (pi E*), integrated over the element), zero-padded to twice the window (DC-FFT: Liu, Wang &
//    Liu 2000, Wear 243:101), which makes the cyclic convolution the linear one exactly.
// The contact conditions (p >= 0, gap >= 0, p gap = 0; p <= H where the flat has flattened the
// surface plastically) are met by Polonsky & Keer's conjugate gradients (1999, Wear 231:206),
// preconditioned by the kernel's inverse (ArealOptions::precondition), on the
// set of elements whose pressure lies strictly between 0 and H, the capped ones held at H as
// Almqvist et al. (2007, Wear 262:980) do: an elastic-perfectly-plastic half-space in the
// "saturated" sense, the plastic deformation being the flat's interpenetration at the capped
// elements. Load (mean pressure) or approach control; capped under load control, every step
// projected on the loads that balance and kept only where it lowers the energy (gradient projection,
// Bertsekas 1976: docs/theory/areal-contact.md).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace geartrib::contact::areal {

// The window's grid: heights at x = i dx, y = j dy, row-major (j * nx + i), and in each direction
// either periodic (the window repeats) or open (nothing beyond it: zero-padded).
struct ArealGrid {
  int nx = 0, ny = 0;
  double dx = 0.0, dy = 0.0;  // [m]
  bool periodic_x = true, periodic_y = true;
  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  double area() const { return nx * dx * ny * dy; }  // [m^2]
  void validate() const;                             // core::KeyedError naming the field
};

// The bytes a solve on the grid holds at its peak (the padded transforms, the fields, the
// kernel): the bound a caller checks against the memory it may use before allocating.
double areal_solve_bytes(const ArealGrid& g);

// The solver's settings.
struct ArealOptions {
  double composite_modulus = 0.0;                             // E* [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
  double poisson_ratio = 0.3;                                 // of the body whose subsurface stress is asked for
  double hardness = std::numeric_limits<double>::infinity();  // the pressure cap H [Pa]; inf: elastic
  // The contact conditions' residual at which the iteration stops: the rms over the grid of the gap
  // where there is pressure, the interpenetration where there is none and the gap where the pressure
  // is capped, over the heights' rms (a flat surface: over a thousandth of the displacement the load
  // makes over the window, or of the approach). Under load control the load is also exact to 1e-9.
  double tolerance = 1e-8;
  int max_iterations = 20000;
  // Conjugate gradients preconditioned by the inverse of the kernel's symbol on the whole grid
  // (E* |q|/2 periodic), restricted to the free set (as the profile solver's: Dostal 2009; Vollebregt
  // 2014, J. Comput. Phys. 257:333): two more transforms an iteration, far fewer iterations. The
  // elastic iteration and the capped one under approach control; false: Polonsky & Keer's own.
  bool precondition = true;
  void validate() const;  // core::KeyedError naming the field
};

// The surface's displacement under a pressure on the grid, u = K p, by FFT.
class ElasticKernel {
 public:
  ElasticKernel(const ArealGrid& grid, double composite_modulus);
  ~ElasticKernel();
  ElasticKernel(const ElasticKernel&) = delete;
  ElasticKernel& operator=(const ElasticKernel&) = delete;
  const ArealGrid& grid() const { return grid_; }
  double modulus() const { return e_star_; }  // E* [Pa]
  // u = K p: p and u of grid().size() [Pa -> m]; u may not alias p. Uses the kernel's own
  // transform arrays: one thread at a time per kernel.
  void apply(std::span<const double> p, std::span<double> u) const;
  // z = M g with the kernel's inverse (below), returning g.M g [m Pa]; z may not alias g.
  double precondition(std::span<const double> g, std::span<double> z) const;
  // The transform's own array, for a caller that writes K's input and reads its output in place
  // (no copy either way): the window's row j at window_row(j), nx values. apply_in_place() turns
  // the pressure the rows hold into u = K p there (until the next application) and returns p.K p
  // [m Pa] by Parseval's sum over the spectrum. One thread at a time per kernel.
  double* window_row(int j) const;
  double apply_in_place() const;
  // The same with the kernel's inverse, M = K^-1 on the (padded) grid, its rigid mode set aside:
  // the rows' g turned into M g, returning g.M g [m Pa]. M is symmetric positive semi-definite.
  double precondition_in_place() const;
  // The displacement of an element under a unit pressure on itself [m/Pa].
  double self_influence() const { return self_; }
  // The padded transform's sizes (twice the window along an open direction).
  int padded_nx() const { return mx_; }
  int padded_ny() const { return my_; }
  // Two of these per application (one forward, one inverse): counted, for the cost per iteration.
  static long transforms();

 private:
  ArealGrid grid_;
  int mx_ = 0, my_ = 0;
  std::vector<double> kernel_hat_;   // real (the kernel is even), my_ x (mx_/2 + 1), scaled by 1/(mx_ my_)
  std::vector<double> inverse_hat_;  // the inverse's multiplier, likewise (0 where the kernel's is not positive)
  double transform_in_place(const std::vector<double>& multiplier) const;
  double transform(std::span<const double> in, std::span<double> out, const std::vector<double>& multiplier) const;
  struct Transforms;  // FFTW's arrays and plans (core/fftw_planner.hpp, internal)
  std::unique_ptr<Transforms> fft_;
  double self_ = 0.0;
  double e_star_ = 0.0;
};

enum class Control { mean_pressure, approach };

// One contact solution on the grid.
struct ArealSolution {
  std::vector<double> pressure;      // [Pa]
  std::vector<double> displacement;  // the surface's elastic displacement, into the body [m]
  std::vector<double> gap;           // the flat's distance to the deformed surface [m]; < 0: plastic
                                     // interpenetration where the pressure is capped
  double mean_pressure = 0.0;        // over the window [Pa]
  double approach = 0.0;             // the flat below the highest undeformed point [m]
  double contact_fraction = 0.0;     // A/A0: elements with pressure
  double plastic_fraction = 0.0;     // of the window, elements at the cap
  double peak_pressure = 0.0;        // [Pa]
  int iterations = 0;
  double residual = 0.0;  // as ArealOptions::tolerance measures it
  bool converged = false;
};

// The contact of the flat on heights h (grid().size(), [m]) under the mean pressure [Pa] (below
// the hardness) or at the approach [m] (a periodic or a fully open window). `start`: a pressure
// field to start from (a previous load's), or empty. Throws core::KeyedError on a value it cannot
// solve ("mean_pressure", "approach").
ArealSolution solve_contact(const ElasticKernel& kernel, std::span<const double> heights, Control control, double value,
                            const ArealOptions& options, std::span<const double> start = {});

// The contact spots: connected sets of elements with pressure (4-neighbours, across a periodic
// direction's edge too).
struct ContactSpots {
  std::vector<int> label;    // per element: its spot (0..count-1), -1 out of contact
  std::vector<double> area;  // each spot's area [m^2], largest first (labels renumbered to match)
  std::vector<double> load;  // each spot's load [N]
};
ContactSpots contact_spots(const ArealGrid& g, std::span<const double> pressure);

// The stress under the surface from its pressure (the normal pressure alone: no traction), on planes
// at the given depths: the von Mises stress's maximum on each and where. Each Fourier mode's field is
// the plane-strain one of a harmonic pressure P cos(ks), from the Airy function
// (P/k^2)(1 + kz) e^{-kz} cos(ks) (docs/theory/areal-contact.md), turned to the mode's direction. The
// mean pressure adds sigma_zz = -pbar and, along an open direction (the zero-padded window's, its
// images a window away), the images' lateral stress, the q -> 0 limit along it; a window periodic
// both ways takes sigma_zz alone (its lateral stress is the body's beyond the window).
struct SubsurfacePlane {
  double depth = 0.0;        // [m]
  double max_von_mises = 0;  // [Pa]
  double x = 0.0, y = 0.0;   // where [m]
};
std::vector<SubsurfacePlane> subsurface_von_mises(const ElasticKernel& kernel, std::span<const double> pressure,
                                                  double poisson_ratio, std::span<const double> depths,
                                                  std::vector<std::vector<double>>* fields = nullptr);

}  // namespace geartrib::contact::areal
