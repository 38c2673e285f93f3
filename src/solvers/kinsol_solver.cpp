#include "solvers/kinsol_solver.hpp"
#include "solvers/sundials_owned.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

namespace geartrib::solvers {

namespace {

struct Callbacks {
  const NonlinearSystem* system;
  Eigen::VectorXd y, f;
  Eigen::MatrixXd j;
};

int residual(N_Vector y, N_Vector f, void* data) {
  auto* c = static_cast<Callbacks*>(data);
  const int n = c->system->size;
  c->y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), n);
  c->system->residual(c->y, c->f);
  if (!c->f.allFinite()) return 1;  // recoverable: KINSOL's line search backs off
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(f), n) = c->f;
  return 0;
}

int jacobian(N_Vector y, N_Vector, SUNMatrix jac, void* data, N_Vector, N_Vector) {
  auto* c = static_cast<Callbacks*>(data);
  const int n = c->system->size;
  c->y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), n);
  c->system->jacobian(c->y, c->j);
  if (!c->j.allFinite()) return 1;
  for (int col = 0; col < n; ++col) {
    realtype* column = SUNDenseMatrix_Column(jac, col);
    for (int row = 0; row < n; ++row) column[row] = c->j(row, col);
  }
  return 0;
}

}  // namespace

NonlinearSolveSummary KinsolSolver::solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                                          const NonlinearSolveOptions& options) const {
  const int n = system.size;
  if (y.size() != n) throw std::invalid_argument("initial guess has the wrong size");
  SUNContext raw_ctx = nullptr;
  if (SUNContext_Create(nullptr, &raw_ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
  auto ctx = owned(raw_ctx, [](SUNContext c) { SUNContext_Free(&c); });
  auto yv = owned(N_VNew_Serial(n, ctx.get()), N_VDestroy);
  auto scale = owned(N_VNew_Serial(n, ctx.get()), N_VDestroy);
  N_VConst(1.0, scale.get());
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(yv.get()), n) = y;
  auto mat = owned(SUNDenseMatrix(n, n, ctx.get()), SUNMatDestroy);
  auto ls = owned(SUNLinSol_Dense(yv.get(), mat.get(), ctx.get()), SUNLinSolFree);
  auto mem = owned(KINCreate(ctx.get()), [](void* m) { KINFree(&m); });

  Callbacks cb{&system, Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::MatrixXd(n, n)};
  auto check = [](int flag, const char* what) {
    if (flag < 0) throw std::runtime_error(std::string("KINSOL: ") + what + " failed");
  };
  check(KINInit(mem.get(), residual, yv.get()), "KINInit");
  check(KINSetUserData(mem.get(), &cb), "KINSetUserData");
  check(KINSetLinearSolver(mem.get(), ls.get(), mat.get()), "KINSetLinearSolver");
  check(KINSetJacFn(mem.get(), jacobian), "KINSetJacFn");
  check(KINSetFuncNormTol(mem.get(), options.residual_tolerance), "KINSetFuncNormTol");
  check(KINSetScaledStepTol(mem.get(), 1e-15), "KINSetScaledStepTol");
  check(KINSetNumMaxIters(mem.get(), options.max_iterations), "KINSetNumMaxIters");
  check(KINSetMaxSetupCalls(mem.get(), 1), "KINSetMaxSetupCalls");  // exact Newton: fresh Jacobian each step
  check(KINSetErrHandlerFn(
            mem.get(), [](int, const char*, const char*, char*, void*) {}, nullptr),
        "KINSetErrHandlerFn");

  const int flag = KINSol(mem.get(), yv.get(), KIN_LINESEARCH, scale.get(), scale.get());
  long iters = 0;
  KINGetNumNonlinSolvIters(mem.get(), &iters);
  y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(yv.get()), n);
  NonlinearSolveSummary s;
  s.iterations = static_cast<int>(iters);
  Eigen::VectorXd f(n);
  system.residual(y, f);
  s.residual_norm = f.lpNorm<Eigen::Infinity>();
  s.converged = flag >= 0 && s.residual_norm <= options.residual_tolerance * 10.0;
  char* name = KINGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  s.message = name ? name : "";
  std::free(name);
  return s;
}

}  // namespace geartrib::solvers
