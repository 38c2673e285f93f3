#include "solvers/cvode_integrator.hpp"
#include "solvers/sundials_owned.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace geartrib::solvers {

namespace {
struct Data {
  const OdeSystem* system;
  std::vector<double> y, dydt;
};

int rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* d = static_cast<Data*>(user);
  const double* yp = N_VGetArrayPointer(y);
  d->y.assign(yp, yp + d->system->size);
  d->system->rhs(t, d->y, d->dydt);
  double* out = N_VGetArrayPointer(ydot);
  for (int i = 0; i < d->system->size; ++i) out[i] = d->dydt[static_cast<std::size_t>(i)];
  return 0;
}

}  // namespace

long CvodeIntegrator::integrate(const OdeSystem& system, double t0, double t1, std::vector<double>& y,
                                const std::vector<double>& sample_times, std::vector<std::vector<double>>& samples,
                                const OdeTolerances& tol) const {
  const int n = system.size;
  SUNContext raw = nullptr;
  if (SUNContext_Create(nullptr, &raw) != 0) throw std::runtime_error("SUNContext_Create failed");
  auto ctx = owned(raw, [](SUNContext c) { SUNContext_Free(&c); });
  auto yv = owned(N_VNew_Serial(n, ctx.get()), N_VDestroy);
  for (int i = 0; i < n; ++i) NV_Ith_S(yv.get(), i) = y[static_cast<std::size_t>(i)];
  auto mem = owned(CVodeCreate(CV_BDF, ctx.get()), [](void* m) { CVodeFree(&m); });
  auto mat = owned(SUNDenseMatrix(n, n, ctx.get()), SUNMatDestroy);
  auto ls = owned(SUNLinSol_Dense(yv.get(), mat.get(), ctx.get()), SUNLinSolFree);
  Data data{&system, {}, std::vector<double>(static_cast<std::size_t>(n))};
  auto check = [](int flag, const char* what) {
    if (flag < 0)
      throw std::runtime_error(std::string("CVODE: ") + what + " failed (flag " + std::to_string(flag) + ")");
  };
  check(CVodeInit(mem.get(), rhs, t0, yv.get()), "CVodeInit");
  check(CVodeSetUserData(mem.get(), &data), "CVodeSetUserData");
  check(CVodeSStolerances(mem.get(), tol.relative, tol.absolute), "CVodeSStolerances");
  check(CVodeSetLinearSolver(mem.get(), ls.get(), mat.get()), "CVodeSetLinearSolver");
  check(CVodeSetMaxNumSteps(mem.get(), 1000000), "CVodeSetMaxNumSteps");
  check(CVodeSetStopTime(mem.get(), t1), "CVodeSetStopTime");  // the right-hand side jumps at t1
  check(CVodeSetErrHandlerFn(
            mem.get(), [](int, const char*, const char*, char*, void*) {}, nullptr),
        "CVodeSetErrHandlerFn");
  realtype t = t0;
  for (double ts : sample_times) {
    if (ts <= t0) {
      samples.push_back(y);
      continue;
    }
    check(CVode(mem.get(), ts, yv.get(), &t, CV_NORMAL), "CVode");
    std::vector<double> s(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) s[static_cast<std::size_t>(i)] = NV_Ith_S(yv.get(), i);
    samples.push_back(std::move(s));
  }
  if (t < t1) check(CVode(mem.get(), t1, yv.get(), &t, CV_NORMAL), "CVode");
  for (int i = 0; i < n; ++i) y[static_cast<std::size_t>(i)] = NV_Ith_S(yv.get(), i);
  long steps = 0;
  CVodeGetNumSteps(mem.get(), &steps);
  return steps;
}

}  // namespace geartrib::solvers
