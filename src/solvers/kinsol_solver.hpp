// Newton's method with line search from SUNDIALS KINSOL (dense direct linear solver, the
// system's analytic Jacobian). SUNDIALS 6.
#pragma once

#include "core/nonlinear_solver.hpp"

namespace geartrib::solvers {

class KinsolSolver final : public NonlinearSolver {
 public:
  NonlinearSolveSummary solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                              const NonlinearSolveOptions& options) const override;
};

}  // namespace geartrib::solvers
