// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model tests/data/pendulum2.json --out cpp/tests/generated`
// from the model file pendulum2.json (sha256 2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96).
// Change the model file or the generator and regenerate instead.

#include <cmath>

#include "armrt/fast_math.h"
#include "pendulum2.h"

namespace armrt::generated::pendulum2 {

void mass_matrix(const double* q, double* M) {
  const double q0 = q[0];
  const double q1 = q[1];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  double s_q1, c_q1;
  armrt::sin_cos(q1, &s_q1, &c_q1);
  const double x0 = c_q0*c_q0;
  const double x1 = s_q0*s_q0;
  const double x2 = x0 + x1;
  M[0] = 0.0040000000000000001*c_q1*c_q1 + 0.0040000000000000001*s_q1*s_q1 + 0.060040000000000003*x0 + 0.060040000000000003*x1 + 0.0060000000000000001;
  M[1] = 0.0;
  M[2] = 0.0;
  M[3] = x2*(0.00020000000000000001*x0 + 0.00020000000000000001*x1) + x2*(0.00029999999999999997*x0 + 0.00029999999999999997*x1);
}

void bias_force(const double* q, const double* qd, const double* g_base, double* b) {
  const double q0 = q[0];
  const double q1 = q[1];
  const double qd0 = qd[0];
  const double qd1 = qd[1];
  const double g0 = g_base[0];
  const double g1 = g_base[1];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  double s_q1, c_q1;
  armrt::sin_cos(q1, &s_q1, &c_q1);
  const double x0 = c_q0*c_q0*qd1;
  const double x1 = qd1*s_q0*s_q0;
  const double x2 = 0.00029999999999999997*x0 + 0.00029999999999999997*x1;
  const double x3 = c_q1*qd0;
  const double x4 = x0 + x1;
  const double x5 = 0.001*x3;
  const double x6 = 0.00020000000000000001*x0 + 0.00020000000000000001*x1;
  const double x7 = 0.0030000000000000001*x3;
  const double x8 = qd0*s_q1;
  const double x9 = 0.001*x8;
  const double x10 = 0.0030000000000000001*x8;
  const double x11 = qd0*qd0;
  const double x12 = s_q0*x11;
  const double x13 = 0.12*c_q0;
  const double x14 = c_q0*x11;
  const double x15 = 0.12*s_q0;
  b[0] = 0.31*c_q0*(0.40000000000000002*g0 + 0.124*x12) - c_q1*(0.001*qd0*s_q1*x4 - x0*x9 - x1*x9 - x2*x8) - c_q1*(0.0030000000000000001*qd0*s_q1*x4 - x0*x10 - x1*x10 - x6*x8) + 0.31*s_q0*(0.40000000000000002*g1 - 0.124*x14) + s_q1*(0.001*c_q1*qd0*x4 - x0*x5 - x1*x5 - x2*x3) + s_q1*(0.0030000000000000001*c_q1*qd0*x4 - x0*x7 - x1*x7 - x3*x6) + x13*(0.5*g0 + 0.059999999999999998*x12) + x13*(1.0*g0 + 0.12*x12) + x15*(0.5*g1 - 0.059999999999999998*x14) + x15*(1.0*g1 - x11*x13);
  b[1] = 0.0;
}

void dynamics(const double* q, const double* qd, const double* g_base, double* M, double* b) {
  const double q0 = q[0];
  const double q1 = q[1];
  const double qd0 = qd[0];
  const double qd1 = qd[1];
  const double g0 = g_base[0];
  const double g1 = g_base[1];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  double s_q1, c_q1;
  armrt::sin_cos(q1, &s_q1, &c_q1);
  const double x0 = c_q0*c_q0;
  const double x1 = s_q0*s_q0;
  const double x2 = x0 + x1;
  const double x3 = 0.00029999999999999997*x0;
  const double x4 = 0.00029999999999999997*x1;
  const double x5 = 0.00020000000000000001*x0;
  const double x6 = 0.00020000000000000001*x1;
  const double x7 = qd1*x3 + qd1*x4;
  const double x8 = c_q1*qd0;
  const double x9 = qd1*x0;
  const double x10 = qd1*x1;
  const double x11 = x10 + x9;
  const double x12 = 0.001*x8;
  const double x13 = qd1*x5 + qd1*x6;
  const double x14 = 0.0030000000000000001*x8;
  const double x15 = qd0*s_q1;
  const double x16 = 0.001*x15;
  const double x17 = 0.0030000000000000001*x15;
  const double x18 = qd0*qd0;
  const double x19 = s_q0*x18;
  const double x20 = 0.12*c_q0;
  const double x21 = c_q0*x18;
  const double x22 = 0.12*s_q0;
  M[0] = 0.0040000000000000001*c_q1*c_q1 + 0.0040000000000000001*s_q1*s_q1 + 0.060040000000000003*x0 + 0.060040000000000003*x1 + 0.0060000000000000001;
  M[1] = 0.0;
  M[2] = 0.0;
  M[3] = x2*(x3 + x4) + x2*(x5 + x6);
  b[0] = 0.31*c_q0*(0.40000000000000002*g0 + 0.124*x19) - c_q1*(0.001*qd0*s_q1*x11 - x10*x16 - x15*x7 - x16*x9) - c_q1*(0.0030000000000000001*qd0*s_q1*x11 - x10*x17 - x13*x15 - x17*x9) + 0.31*s_q0*(0.40000000000000002*g1 - 0.124*x21) + s_q1*(0.001*c_q1*qd0*x11 - x10*x12 - x12*x9 - x7*x8) + s_q1*(0.0030000000000000001*c_q1*qd0*x11 - x10*x14 - x13*x8 - x14*x9) + x20*(0.5*g0 + 0.059999999999999998*x19) + x20*(1.0*g0 + 0.12*x19) + x22*(0.5*g1 - 0.059999999999999998*x21) + x22*(1.0*g1 - x18*x20);
  b[1] = 0.0;
}

void hand_position(const double* q, double* p) {
  const double q0 = q[0];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  p[0] = 0.33000000000000002*s_q0;
  p[1] = -0.33000000000000002*c_q0 - 0.29999999999999999;
  p[2] = 0.0;
}

void hand_jacobian(const double* q, double* Jv, double* Jw) {
  const double q0 = q[0];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  Jv[0] = 0.33000000000000002*c_q0;
  Jv[1] = 0.0;
  Jv[2] = 0.33000000000000002*s_q0;
  Jv[3] = 0.0;
  Jv[4] = 0.0;
  Jv[5] = 0.0;
  Jw[0] = 0.0;
  Jw[1] = -s_q0;
  Jw[2] = 0.0;
  Jw[3] = c_q0;
  Jw[4] = 1.0;
  Jw[5] = 0.0;
}

void arm_momentum_rate(const double* q, const double* qd, double* A, double* c) {
  const double q0 = q[0];
  const double qd0 = qd[0];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  const double x0 = 0.30399999999999999*c_q0;
  const double x1 = 0.30399999999999999*s_q0;
  const double x2 = qd0*qd0;
  A[0] = x0;
  A[1] = 0.0;
  A[2] = x1;
  A[3] = 0.0;
  A[4] = 0.0;
  A[5] = 0.0;
  c[0] = -x1*x2;
  c[1] = x0*x2;
  c[2] = 0.0;
}

void body_poses(const double* q, double* R, double* p) {
  const double q0 = q[0];
  const double q1 = q[1];
  double s_q0, c_q0;
  armrt::sin_cos(q0, &s_q0, &c_q0);
  double s_q1, c_q1;
  armrt::sin_cos(q1, &s_q1, &c_q1);
  const double x0 = -s_q0;
  const double x1 = c_q0*c_q1;
  const double x2 = c_q0*s_q1;
  const double x3 = c_q1*s_q0;
  const double x4 = s_q0*s_q1;
  const double x5 = -s_q1;
  R[0] = 1.0;
  R[1] = 0.0;
  R[2] = 0.0;
  R[3] = 0.0;
  R[4] = 1.0;
  R[5] = 0.0;
  R[6] = 0.0;
  R[7] = 0.0;
  R[8] = 1.0;
  R[9] = c_q0;
  R[10] = x0;
  R[11] = 0.0;
  R[12] = s_q0;
  R[13] = c_q0;
  R[14] = 0.0;
  R[15] = 0.0;
  R[16] = 0.0;
  R[17] = 1.0;
  R[18] = x1;
  R[19] = x0;
  R[20] = x2;
  R[21] = x3;
  R[22] = c_q0;
  R[23] = x4;
  R[24] = x5;
  R[25] = 0.0;
  R[26] = c_q1;
  R[27] = x1;
  R[28] = x0;
  R[29] = x2;
  R[30] = x3;
  R[31] = c_q0;
  R[32] = x4;
  R[33] = x5;
  R[34] = 0.0;
  R[35] = c_q1;
  p[0] = 0.0;
  p[1] = 0.0;
  p[2] = 0.0;
  p[3] = 0.0;
  p[4] = -0.29999999999999999;
  p[5] = 0.0;
  p[6] = 0.0;
  p[7] = -0.29999999999999999;
  p[8] = 0.0;
  p[9] = 0.25*s_q0;
  p[10] = -0.25*c_q0 - 0.29999999999999999;
  p[11] = 0.0;
}

}  // namespace armrt::generated::pendulum2
