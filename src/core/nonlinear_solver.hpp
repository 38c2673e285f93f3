// A square nonlinear system F(y) = 0 with a dense Jacobian, and the interface of a solver for
// it. The physics states its systems this way; the solver (SUNDIALS KINSOL, src/solvers/) is
// plugged in by the caller, so the physics library links no solver.
#pragma once

#include <Eigen/Dense>

#include <functional>
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
};

struct NonlinearSolveSummary {
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0.0;  // max-norm of F at the returned y
  std::string message;
};

class NonlinearSolver {
 public:
  virtual ~NonlinearSolver() = default;
  // Solves from the initial guess in y; y holds the last iterate on return.
  virtual NonlinearSolveSummary solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                                      const NonlinearSolveOptions& options) const = 0;
};

}  // namespace geartrib
