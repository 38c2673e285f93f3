// A square nonlinear system F(y) = 0 with a dense Jacobian, and the interface of a solver for
// it. The physics states its systems this way; the solver (SUNDIALS KINSOL, src/solvers/) is
// plugged in by the caller, so the physics library links no solver.
#pragma once

#include <Eigen/Dense>

#include <functional>
#include <memory>
#include <string>

namespace geartrib {

struct NonlinearSystem {
  int size = 0;
  std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& f)> residual;
  std::function<void(const Eigen::VectorXd& y, Eigen::MatrixXd& jacobian)> jacobian;
};

struct NonlinearSolveOptions {
  double residual_tolerance = 1e-10;  // max-norm of F at convergence
  int max_iterations = 200;
  // Iterations a factorised Jacobian serves: 1 is Newton's method (a fresh Jacobian every step);
  // more is modified Newton, the solver refreshing it earlier when a step fails to reduce F.
  int max_jacobian_age = 1;
};

struct NonlinearSolveSummary {
  bool converged = false;
  int iterations = 0;
  int jacobian_evaluations = 0;  // Jacobians evaluated and factorised
  double residual_norm = 0.0;    // max-norm of F at the returned y
  std::string message;
};

// What a solver keeps between the solves of a sequence of related systems of one size (the same
// contact at neighbouring positions): its buffers and the last factorised Jacobian, which the next
// solve starts from (modified Newton across solves; refreshed as soon as it fails to reduce F).
// Made by the solver that uses it; used by one thread at a time.
class NonlinearSolverWorkspace {
 public:
  virtual ~NonlinearSolverWorkspace() = default;
};

class NonlinearSolver {
 public:
  virtual ~NonlinearSolver() = default;
  // Solves from the initial guess in y; y holds the last iterate on return.
  virtual NonlinearSolveSummary solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                                      const NonlinearSolveOptions& options) const = 0;
  // A workspace for systems of `size` unknowns, or nullptr when the solver keeps nothing.
  virtual std::unique_ptr<NonlinearSolverWorkspace> make_workspace(int size) const {
    (void)size;
    return nullptr;
  }
  // The same solve, reusing and updating the workspace (from make_workspace of this solver, for
  // this size; nullptr: as above). The answer meets the same tolerance either way.
  virtual NonlinearSolveSummary solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                                      const NonlinearSolveOptions& options, NonlinearSolverWorkspace* workspace) const {
    (void)workspace;
    return solve(system, y, options);
  }
};

}  // namespace geartrib
