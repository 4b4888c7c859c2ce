// Compile-time DOF counts for the engine's small dense loops. The model's number of DOFs is data
// (1..kMaxDofs), but loops of a handful of iterations over DOFs (R^T F, the Cholesky and LU solves,
// the Schur complement) unroll and vectorise only with a compile-time trip count: written with a
// runtime count, forward() was 14 % and a ROS2 step 40 % slower on das2 (armrt_bench). So each such
// function is a template on the count, and dispatch_dofs picks the instantiation once per call.
#pragma once

#include <type_traits>

#include "armrt/model.h"

namespace armrt::detail {

// Calls f(std::integral_constant<int, N>{}) for N == n, 1 <= n <= Max (nothing for other n).
template <int Max, int N = 1, class F>
inline void dispatch_count(int n, F&& f) {
  if constexpr (N <= Max) {
    if (n == N) f(std::integral_constant<int, N>{});
    else dispatch_count<Max, N + 1>(n, static_cast<F&&>(f));
  }
}

// The model's DOF count, 1 <= n <= kMaxDofs (model_init checks n).
template <class F>
inline void dispatch_dofs(int n, F&& f) {
  dispatch_count<kMaxDofs>(n, static_cast<F&&>(f));
}

}  // namespace armrt::detail
