// Eight-double vectors (GCC/Clang vector extension; one AVX-512 register, two AVX2 ones) for the engine's
// loops over a model's DOFs when there are more than 8 of them (das3: 11). A DOF-indexed row of up to 16
// values is held as two of them, lo (DOFs 0-7) and hi (8-15), so an n x n accumulator of rows stays in
// registers where a scalar loop over 11 columns kept it in memory (perf on a loop of das3 ROS2 steps:
// the Schur stiffness was 14 % of the step).
#pragma once

#include <cstring>

namespace armrt::detail {

using v8d = double __attribute__((vector_size(64)));

// Row r[0..15] as (lo, hi). Reads 16 doubles: callers pass rows of arrays sized so that 16 values from
// any row start are inside them (data.h's [kMaxElements * kMaxDofs] arrays); lanes past the row hold
// whatever follows it and are never stored.
inline void load_row16(const double* r, v8d& lo, v8d& hi) {
  std::memcpy(&lo, r, sizeof(v8d));
  std::memcpy(&hi, r + 8, sizeof(v8d));
}

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
