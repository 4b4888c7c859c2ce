// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model tests/data/pendulum2.json --out cpp/tests/generated`
// from the model file pendulum2.json (sha256 2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96).
// Change the model file or the generator and regenerate instead.

#include <cmath>
#include <cstring>

#include "pendulum2.h"

namespace armrt::generated::pendulum2 {

// Eight doubles, one SIMD register with AVX-512 (two with AVX2): a length and its moment arms.
using v8d = double __attribute__((vector_size(64)));

void muscle_lengths(const double* q, double* L) {
  double moment_arm[10];
  muscle_paths(q, L, moment_arm);
}

void muscle_paths(const double* q, double* L, double* moment_arm) {
  const double q0 = q[0];
  const double q1 = q[1];
  const v8d g_one = {0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e0 = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e1 = {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d g0 = q1*g_one - e1;
  const v8d g1 = q0*g_one - e0;
  { const v8d a = (0.26000000000000001*g_one) + (-0.029999999999999999*g1);
    std::memcpy(moment_arm + 0, &a, 2 * sizeof(double)); L[0] = a[2]; }
  { const v8d a = (0.25*g_one) + (-0.02*g1);
    std::memcpy(moment_arm + 2, &a, 2 * sizeof(double)); L[1] = a[2]; }
  { const v8d a = (0.23999999999999999*g_one) + (0.025000000000000001*g1);
    std::memcpy(moment_arm + 4, &a, 2 * sizeof(double)); L[2] = a[2]; }
  { const v8d a = (0.080000000000000002*g_one) + (-0.01*g0);
    std::memcpy(moment_arm + 6, &a, 2 * sizeof(double)); L[3] = a[2]; }
  { const v8d a = (0.080000000000000002*g_one) + (0.01*g0);
    std::memcpy(moment_arm + 8, &a, 2 * sizeof(double)); L[4] = a[2]; }
}

void gh_directions(const double* q, double* d) {
  (void)q;
  d[0] = 0.0; d[1] = 0.0; d[2] = 0.0;
  d[3] = 0.0; d[4] = 0.0; d[5] = 0.0;
  d[6] = 0.0; d[7] = 0.0; d[8] = 0.0;
  d[9] = 0.0; d[10] = 0.0; d[11] = 0.0;
  d[12] = 0.0; d[13] = 0.0; d[14] = 0.0;
}

}  // namespace armrt::generated::pendulum2
