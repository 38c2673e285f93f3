// Ownership of SUNDIALS objects (N_Vector, SUNMatrix, solver memory) by std::unique_ptr with
// the library's destroy function; a null pointer (failed allocation) throws.
#pragma once

#include <memory>
#include <stdexcept>

namespace geartrib::solvers {

template <class T, class D>
std::unique_ptr<T, D> owned(T* p, D destroy) {
  if (!p) throw std::runtime_error("SUNDIALS allocation failed");
  return std::unique_ptr<T, D>(p, destroy);
}

}  // namespace geartrib::solvers
