#include "solvers/kinsol_solver.hpp"
#include "solvers/sundials_owned.hpp"

#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace geartrib::solvers {

namespace {

struct Callbacks {
  const NonlinearSystem* system = nullptr;
  Eigen::VectorXd y, f;  // the last residual evaluation: at y, F = f
  Eigen::VectorXd yj;    // where the last Jacobian was evaluated
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
  c->yj = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), n);
  c->system->jacobian(c->yj, c->j);
  if (!c->j.allFinite()) return 1;
  Eigen::Map<Eigen::MatrixXd>(SUNDenseMatrix_Data(jac), n, n) = c->j;  // column-major, as Eigen's
  return 0;
}

// Eigen's dense LU (blocked, partial pivoting) as KINSOL's linear solver. SUNDIALS' own dense LU
// is unblocked: it took 80% of a coupled strip's time. The factors stay here between KINSol calls
// of a workspace, which the next solve may start from (KINSetNoInitSetup).
struct EigenLu {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  bool factorised = false;
};

int lu_setup(SUNLinearSolver ls, SUNMatrix a) {
  auto* c = static_cast<EigenLu*>(ls->content);
  const auto n = static_cast<Eigen::Index>(SUNDenseMatrix_Rows(a));
  c->lu.compute(Eigen::Map<const Eigen::MatrixXd>(SUNDenseMatrix_Data(a), n, n));
  const auto pivots = c->lu.matrixLU().diagonal();
  c->factorised = pivots.allFinite() && (pivots.array() != 0.0).all();
  return c->factorised ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;  // singular: recoverable, as SUNDIALS' dense LU
}

int lu_solve(SUNLinearSolver ls, SUNMatrix, N_Vector x, N_Vector b, realtype) {
  auto* c = static_cast<EigenLu*>(ls->content);
  if (!c->factorised) return SUNLS_LUFACT_FAIL;  // KINSOL then sets the Jacobian up and retries
  const auto n = static_cast<Eigen::Index>(N_VGetLength(b));
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(x), n) =
      c->lu.solve(Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(b), n));
  return SUNLS_SUCCESS;
}

SUNLinearSolver eigen_lu_solver(SUNContext ctx, int n) {
  SUNLinearSolver ls = SUNLinSolNewEmpty(ctx);
  if (!ls) return nullptr;
  ls->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  ls->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  ls->ops->initialize = [](SUNLinearSolver) { return SUNLS_SUCCESS; };  // keeps the factors (each KINSol calls it)
  ls->ops->setup = lu_setup;
  ls->ops->solve = lu_solve;
  ls->ops->free = [](SUNLinearSolver s) {
    if (!s) return SUNLS_SUCCESS;
    delete static_cast<EigenLu*>(s->content);
    s->content = nullptr;
    SUNLinSolFreeEmpty(s);
    return SUNLS_SUCCESS;
  };
  auto* c = new EigenLu;
  c->lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  ls->content = c;
  return ls;
}

// KINSOL's memory, vectors, matrix and linear solver for systems of one size, kept between solves.
class KinsolWorkspace final : public NonlinearSolverWorkspace {
 public:
  explicit KinsolWorkspace(int n) : size(n) {
    SUNContext raw_ctx = nullptr;
    if (SUNContext_Create(nullptr, &raw_ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
    ctx = owned(raw_ctx, free_context);
    y = owned(N_VNew_Serial(n, ctx.get()), N_VDestroy);
    scale = owned(N_VNew_Serial(n, ctx.get()), N_VDestroy);
    N_VConst(1.0, scale.get());
    mat = owned(SUNDenseMatrix(n, n, ctx.get()), SUNMatDestroy);
    ls = owned(eigen_lu_solver(ctx.get(), n), SUNLinSolFree);
    lu = static_cast<EigenLu*>(ls->content);
    mem = owned(KINCreate(ctx.get()), free_kinsol);
    cb.y.resize(n);
    cb.f.resize(n);
    cb.yj.resize(n);
    cb.j.resize(n, n);
    check(KINInit(mem.get(), residual, y.get()), "KINInit");
    check(KINSetUserData(mem.get(), &cb), "KINSetUserData");
    check(KINSetLinearSolver(mem.get(), ls.get(), mat.get()), "KINSetLinearSolver");
    check(KINSetJacFn(mem.get(), jacobian), "KINSetJacFn");
    check(KINSetScaledStepTol(mem.get(), 1e-15), "KINSetScaledStepTol");
    check(KINSetErrHandlerFn(
              mem.get(), [](int, const char*, const char*, char*, void*) {}, nullptr),
          "KINSetErrHandlerFn");
  }
  static void check(int flag, const char* what) {
    if (flag < 0) throw std::runtime_error(std::string("KINSOL: ") + what + " failed");
  }

  int size;
  Callbacks cb;
  EigenLu* lu = nullptr;  // owned by ls
  std::unique_ptr<std::remove_pointer_t<SUNContext>, void (*)(SUNContext)> ctx{nullptr, free_context};
  std::unique_ptr<std::remove_pointer_t<N_Vector>, void (*)(N_Vector)> y{nullptr, N_VDestroy},
      scale{nullptr, N_VDestroy};
  std::unique_ptr<std::remove_pointer_t<SUNMatrix>, void (*)(SUNMatrix)> mat{nullptr, SUNMatDestroy};
  std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, int (*)(SUNLinearSolver)> ls{nullptr, SUNLinSolFree};
  std::unique_ptr<void, void (*)(void*)> mem{nullptr, free_kinsol};

 private:
  static void free_context(SUNContext c) { SUNContext_Free(&c); }
  static void free_kinsol(void* m) { KINFree(&m); }
};

}  // namespace

std::unique_ptr<NonlinearSolverWorkspace> KinsolSolver::make_workspace(int size) const {
  if (size < 1) throw std::invalid_argument("a workspace needs a positive system size");
  return std::make_unique<KinsolWorkspace>(size);
}

NonlinearSolveSummary KinsolSolver::solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                                          const NonlinearSolveOptions& options) const {
  KinsolWorkspace workspace(system.size);
  return solve(system, y, options, &workspace);
}

NonlinearSolveSummary KinsolSolver::solve(const NonlinearSystem& system, Eigen::VectorXd& y,
                                          const NonlinearSolveOptions& options,
                                          NonlinearSolverWorkspace* workspace) const {
  if (!workspace) return solve(system, y, options);
  const int n = system.size;
  if (y.size() != n) throw std::invalid_argument("initial guess has the wrong size");
  auto* w = dynamic_cast<KinsolWorkspace*>(workspace);
  if (!w || w->size != n) throw std::invalid_argument("the workspace is not KINSOL's for this system size");
  void* mem = w->mem.get();
  w->cb.system = &system;
  w->cb.y.setConstant(std::numeric_limits<double>::quiet_NaN());  // no evaluation of this system yet
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(w->y.get()), n) = y;
  KinsolWorkspace::check(KINSetFuncNormTol(mem, options.residual_tolerance), "KINSetFuncNormTol");
  KinsolWorkspace::check(KINSetNumMaxIters(mem, options.max_iterations), "KINSetNumMaxIters");
  // 1: exact Newton, a fresh Jacobian each step; more: modified Newton (KINSOL also refreshes it
  // when the line search fails with an old one, and when the residual stops falling fast).
  KinsolWorkspace::check(KINSetMaxSetupCalls(mem, std::max(1, options.max_jacobian_age)), "KINSetMaxSetupCalls");
  // Start from the last solve's factors when there are some and they may age.
  KinsolWorkspace::check(KINSetNoInitSetup(mem, w->lu->factorised && options.max_jacobian_age > 1),
                         "KINSetNoInitSetup");

  const int flag = KINSol(mem, w->y.get(), KIN_LINESEARCH, w->scale.get(), w->scale.get());
  long iters = 0, jacobians = 0;
  KINGetNumNonlinSolvIters(mem, &iters);
  KINGetNumJacEvals(mem, &jacobians);
  y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(w->y.get()), n);
  NonlinearSolveSummary s;
  s.iterations = static_cast<int>(iters);
  s.jacobian_evaluations = static_cast<int>(jacobians);
  // F at the returned y: KINSOL's last evaluation is normally there (the accepted step).
  if (w->cb.y != y || !w->cb.f.allFinite()) {
    w->cb.y = y;
    system.residual(w->cb.y, w->cb.f);
  }
  s.residual_norm = w->cb.f.lpNorm<Eigen::Infinity>();
  s.converged = flag >= 0 && s.residual_norm <= options.residual_tolerance * 10.0;
  char* name = KINGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  s.message = name ? name : "";
  std::free(name);
  return s;
}

}  // namespace geartrib::solvers
