// Newton's method with line search from SUNDIALS KINSOL (dense direct linear solver: Eigen's LU;
// the system's analytic Jacobian). SUNDIALS 6. With a workspace (make_workspace), KINSOL's memory
// and the last factorised Jacobian persist between solves: with max_jacobian_age > 1 the next
// solve starts from that Jacobian (modified Newton), which KINSOL refreshes when it stops helping.
#pragma once

#include "core/nonlinear_solver.hpp"

namespace geartrib::solvers {

class KinsolSolver final : public NonlinearSolver {
 public:
  NonlinearSolveSummary solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                              const NonlinearSolveOptions& options) const override;
  std::unique_ptr<NonlinearSolverWorkspace> make_workspace(int size) const override;
  NonlinearSolveSummary solve(const NonlinearSystem& system, Eigen::VectorXd& y, const NonlinearSolveOptions& options,
                              NonlinearSolverWorkspace* workspace) const override;
};

}  // namespace geartrib::solvers
