// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model tests/data/pendulum2.json --out cpp/tests/generated`
// from the model file pendulum2.json (sha256 2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96).
// Change the model file or the generator and regenerate instead.

#include <cmath>
#include <cstring>

#include "pendulum2.h"

namespace armrt::generated::pendulum2 {

// muscle_paths writes its moment arms in rows of 160 (model_def.h): the engine must agree.
static_assert(kMaxElements == 160, "rebuild this model: the engine's kMaxElements changed");

// Eight doubles, one SIMD register with AVX-512 (two with AVX2): a length and its moment arms.
using v8d = double __attribute__((vector_size(64)));

void muscle_lengths(const double* q, double* L) {
  double moment_arm[2 * kMaxElements];
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
    moment_arm[0 * kMaxElements + 0] = a[0]; moment_arm[1 * kMaxElements + 0] = a[1]; L[0] = a[2]; }
  { const v8d a = (0.25*g_one) + (-0.02*g1);
    moment_arm[0 * kMaxElements + 1] = a[0]; moment_arm[1 * kMaxElements + 1] = a[1]; L[1] = a[2]; }
  { const v8d a = (0.23999999999999999*g_one) + (0.025000000000000001*g1);
    moment_arm[0 * kMaxElements + 2] = a[0]; moment_arm[1 * kMaxElements + 2] = a[1]; L[2] = a[2]; }
  { const v8d a = (0.080000000000000002*g_one) + (-0.01*g0);
    moment_arm[0 * kMaxElements + 3] = a[0]; moment_arm[1 * kMaxElements + 3] = a[1]; L[3] = a[2]; }
  { const v8d a = (0.080000000000000002*g_one) + (0.01*g0);
    moment_arm[0 * kMaxElements + 4] = a[0]; moment_arm[1 * kMaxElements + 4] = a[1]; L[4] = a[2]; }
}

void gh_directions(const double* q, double* d) {
  (void)q;
  using v3d = double __attribute__((vector_size(32)));  // x, y, z and an unused lane
  double gx[5], gy[5], gz[5];
  gx[0] = 0.0; gy[0] = 0.0; gz[0] = 0.0;
  gx[1] = 0.0; gy[1] = 0.0; gz[1] = 0.0;
  gx[2] = 0.0; gy[2] = 0.0; gz[2] = 0.0;
  gx[3] = 0.0; gy[3] = 0.0; gz[3] = 0.0;
  gx[4] = 0.0; gy[4] = 0.0; gz[4] = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double n2 = gx[i]*gx[i] + gy[i]*gy[i] + gz[i]*gz[i];
    const double s = n2 > 0.0 ? 1.0/std::sqrt(n2) : 0.0;
    d[3*i] = gx[i]*s; d[3*i + 1] = gy[i]*s; d[3*i + 2] = gz[i]*s;
  }
}

}  // namespace armrt::generated::pendulum2
