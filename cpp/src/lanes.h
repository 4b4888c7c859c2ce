// Eight-double vectors (GCC/Clang vector extension; one AVX-512 register, two AVX2 ones). The engine's loops
// over elements take eight at a time from the moment arms by DOF (data.h); its loops over more than 8 DOFs
// (das3: 11, the Cholesky factorisation in skeleton.cc) hold a DOF-indexed row of up to 16 values as two of
// them, lo (DOFs 0-7) and hi (8-15), so an n x n matrix stays in registers.
#pragma once

#include <cstring>

namespace armrt::detail {

using v8d = double __attribute__((vector_size(64)));

// Row r[0..n-1] (n <= 16) as (lo, hi), lanes past n zero: for rows of arrays of unknown size.
inline void load_row(const double* r, int n, v8d& lo, v8d& hi) {
  double buf[16] = {};
  std::memcpy(buf, r, n * sizeof(double));
  std::memcpy(&lo, buf, sizeof(v8d));
  std::memcpy(&hi, buf + 8, sizeof(v8d));
}

// Sum of the eight lanes as a tree (three dependent adds, not seven).
inline double lane_sum(v8d v) {
  return ((v[0] + v[4]) + (v[2] + v[6])) + ((v[1] + v[5]) + (v[3] + v[7]));
}

}  // namespace armrt::detail
