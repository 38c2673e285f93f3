// Rough line contact across the Hertzian strip of one tooth-pair position, two fidelities:
//  - uncoupled: the smooth Hertz pressure p0 sqrt(1 - x^2/b^2) imposed on the rough surface and
//    the Greenwood-Williamson quantities integrated across the strip;
//  - coupled: rough line contact in the spirit of Greenwood & Tripp (1967): the bulk elastic
//    (plane-strain half-space) deformation and the asperity pressure solved together, Newton's
//    method through the NonlinearSolver the caller supplies (SUNDIALS KINSOL in the tool).
#pragma once

#include "asperity/side_contact.hpp"
#include "contact/greenwood_williamson.hpp"
#include "core/nonlinear_solver.hpp"

#include <memory>
#include <vector>

namespace geartrib::contact {

enum class StripFidelity { uncoupled, coupled };
// How the uncoupled strip reads the rough surface at a nominal pressure: cubic cells in the
// pressure (GreenwoodWilliamson::at_pressure, no transcendental call per point) or the table's
// inversion and log-linear interpolation (exact to the table; the reference).
enum class StripLookup { cubic, exact };

struct StripOptions {
  // The resolutions' ranges (the case file's contact.strip_points and contact.coupled_nodes).
  static constexpr int kMinStripPoints = 8, kMaxStripPoints = 100000;   // 8: one Gauss panel
  static constexpr int kMinCoupledNodes = 16, kMaxCoupledNodes = 4000;  // 4000: the dense Jacobian's memory
  StripFidelity fidelity = StripFidelity::uncoupled;
  StripLookup lookup = StripLookup::cubic;
  int strip_points = 64;    // uncoupled: Gauss points across the Hertz strip
  int coupled_nodes = 128;  // coupled: pressure elements across the contact
  void validate() const;    // throws core::KeyedError naming the field
};

// Strip results per unit face width. The nominal width is the smooth Hertz width 2b in both
// fidelities, so their ratios compare.
struct StripResult {
  double line_load = 0.0;                   // integral of the nominal pressure [N/m]
  double hertz_half_width = 0.0;            // b [m]
  double max_nominal_pressure = 0.0;        // [Pa]
  double contact_half_width = 0.0;          // half-width of the region carrying 99.9% of the load [m]
  double real_area_per_width = 0.0;         // integral of A_r/A_n [m]
  double real_area_ratio = 0.0;             // real_area_per_width / (2b)
  double contacts_per_width = 0.0;          // [1/m]
  double plastic_area_fraction = 0.0;       // plastic share of the real contact area
  double plastic_contact_fraction = 0.0;    // share of contacting asperities beyond delta_c
  double mean_real_pressure = 0.0;          // line load / real area per width [Pa]
  double min_separation = 0.0;              // separation at the centre of the strip [m]
  int solver_iterations = 0;                // coupled: Newton iterations
  std::vector<double> x, nominal_pressure;  // coupled: the pressure across the strip [m], [Pa]
                                            // (uncoupled: Hertz's, not stored)
};

// What a sequence of coupled solves (the positions of a path, in order) carries from one solve to
// the next: the last converged solution, the next solve's first guess (scaled to its Hertz
// half-width), the solve's buffers and the solver's workspace with its factorised Jacobian, which
// the next solve starts from (modified Newton). Optional: without one a solve starts cold, from
// the Hertz pressure; either way it meets the same tolerance. Used by one thread at a time.
class CoupledStripState {
 public:
  CoupledStripState();
  ~CoupledStripState();
  CoupledStripState(CoupledStripState&&) noexcept;
  CoupledStripState& operator=(CoupledStripState&&) noexcept;
  int warm_solves() const;  // solves converged from the previous solution
  int cold_solves() const;  // solves started from the Hertz pressure (the first, and any warm start that failed)
  int jacobians() const;    // Jacobians evaluated and factorised over all solves

 private:
  friend class RoughLineContact;
  struct Data;
  std::unique_ptr<Data> data_;
};

class RoughLineContact {
 public:
  // solver: required for the coupled fidelity (nullptr otherwise).
  RoughLineContact(const GreenwoodWilliamson& gw, double composite_modulus, double face_width,
                   const StripOptions& options, const NonlinearSolver* solver);
  // line_load w [N/m] on equivalent radius R [m]. Throws std::runtime_error when the coupled
  // solve does not converge (never returns an unconverged answer). asperity_share in [0, 1]: the
  // share of the load the asperities carry in mixed lubrication (the film carries the rest);
  // uncoupled, the asperities take that share of the Hertz pressure over the same width
  // (Johnson, Greenwood & Poon 1972); coupled, the coupled contact of that share of the load.
  // state (coupled; optional): carried from the previous position's solve (see CoupledStripState).
  StripResult solve(double line_load, double radius, double asperity_share = 1.0,
                    CoupledStripState* state = nullptr) const;

 private:
  StripResult uncoupled(double w, double radius, double share) const;
  StripResult coupled(double w, double radius, CoupledStripState::Data& state) const;

  const GreenwoodWilliamson& gw_;
  // The uncoupled rule's nodes theta_i < 0 (composite 8-point Gauss-Legendre over (-pi/2, pi/2),
  // symmetric: each stands for its mirror too), in ascending cos: cos and weight d(theta) cos(theta).
  std::vector<double> node_cos_, node_weight_;
  double modulus_;
  double face_width_;
  StripOptions options_;
  const NonlinearSolver* solver_;
};

// The highest asperity expected in the nominal contact zone of a strip (2b x face width) at the
// strip's centre: the summit height exceeded by one summit of eta 2b L on average
// (GreenwoodWilliamson::highest_summit), pressed by the centre's separation. In side contact
// (mu > 0) it is evaluated as a tilted paraboloid pair (side_contact.hpp) at the same approach.
// With a stress table its von Mises maximum is read off the table (asperity/von_mises_table.hpp).
struct HighestAsperity {
  double interference = 0.0;   // [m]; 0 when it does not touch
  double peak_pressure = 0.0;  // [Pa]
  double von_mises = 0.0;      // largest von Mises stress of the elastic field on the axis [Pa]
  double plastic_fraction = 0.0;
};
HighestAsperity highest_asperity(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width,
                                 const asperity::SideContactGeometry* side = nullptr,
                                 asperity::VonMisesTable* stress_table = nullptr);
// Its interference [m] (<= 0: it does not touch): the highest summit of the strip's nominal area
// 2b x face width, pressed by the separation at the strip's centre.
double highest_asperity_interference(const GreenwoodWilliamson& gw, const StripResult& strip, double face_width);

}  // namespace geartrib::contact
