// moment_arm_dot: (R by DOF, v per DOF) -> R^T v per element, eight elements per multiply-add: shared by the
// Jacobian solve (step_jacobian.cc) and the fibre limiter (fibre_limiter.cc).
#pragma once

#include <cstring>

#include "armrt/model.h"
#include "lanes.h"

namespace armrt::detail {

// out[i] = sum_j R[j][i] v[j], the per-element dot products with moment arms by DOF (data.h): eight elements
// per multiply-add, each block of eight over the DOFs its run crosses (Model::element_runs; the other terms
// are zero, so the sums are the same to the bit), in DOF order. out has room for the last block's ghost
// lanes (zeros).
template <int nq>
void moment_arm_dot(const Model& m, const double* R, const double* v, double* out) {
  using detail::v8d;
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    for (int i = run.begin; i < run.end; i += 8) {
      v8d acc = {};
      for (int j = run.dof_lo; j <= run.dof_hi; ++j) {
        v8d rj;
        std::memcpy(&rj, R + j * kMaxElements + i, sizeof(v8d));
        acc += rj * v[j];
      }
      std::memcpy(out + i, &acc, sizeof(v8d));
    }
  }
}

}  // namespace armrt::detail
