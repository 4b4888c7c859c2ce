// One test per engine stage (engine.h lists them), each calling the stage function directly on the tiny
// two-DOF pendulum (tests/data/pendulum2.json, compiled into the tests: generated/pendulum2*.cc) and checking
// it against an answer it does not compute itself: the closed form from the model file's parameters, a hand
// calculation, or a finite difference of another stage (as Pinocchio checks ABA against RNEA). Then forward()
// as the composition of the stages, the outputs' currency, and per-arm settings on one shared Model.
//
// The pendulum (see also test_pendulum.cc): humerus welded to the scapula (= base = thorax frame, identity),
// ulna about the elbow pin ELx (base z) at (0, -0.3, 0), radius and hand about PSy (the forearm's long axis,
// the ulna's y), both symmetric about it. Masses: humerus 2, ulna 1, radius 0.5, hand 0.4 kg; COMs below the
// elbow: ulna 0.12, radius 0.12, hand 0.25 + 0.06 m; hand point 0.25 + 0.08 m below the elbow.
// Five elements with linear length polynomials L_i = c0_i + c1_i q_dof(i) (constant moment arms -c1_i).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "armrt/arm.h"
#include "armrt/engine.h"
#include "armrt/layouts.h"
#include "armrt/registry.h"
#include "pendulum2.h"
#include "test_util.h"

using namespace armrt;

namespace {

const ModelDef& pendulum() { return generated::pendulum2::model_def(); }

constexpr double kG = 9.80665;
// sum over the bodies turning about the elbow of m_b d_b (kg m): ulna, radius, hand (pendulum2.json).
constexpr double kMassMoment = 1.0 * 0.12 + 0.5 * 0.12 + 0.4 * (0.25 + 0.06);
constexpr double kInertiaEl = (0.006 + 1.0 * 0.12 * 0.12) + (0.003 + 0.5 * 0.12 * 0.12) + (0.001 + 0.4 * 0.31 * 0.31);
constexpr double kInertiaPs = 0.0002 + 0.0003;  // Iyy of radius and hand, kg m^2
constexpr double kArmMass = 2.0 + 1.0 + 0.5 + 0.4;  // humerus, ulna, radius, hand (kg)
constexpr double kHandDistance = 0.25 + 0.08;    // elbow to hand point, m
constexpr double kElbowY = -0.3;                 // elbow below the GH centre, m
// The length polynomials of pendulum2.json: L_i = kC0[i] + kC1[i] q[kDof[i]].
constexpr double kC0[5] = {0.26, 0.25, 0.24, 0.08, 0.08};
constexpr double kC1[5] = {-0.03, -0.02, 0.025, -0.01, 0.01};
constexpr int kDof[5] = {0, 0, 0, 1, 1};
// Activation dynamics of every element (tact 0.02 s, tdeact 0.06 s): c2 = 1/tdeact, c1 = 1/tact - c2.
constexpr double kC2 = 1.0 / 0.06;
constexpr double kC1act = 1.0 / 0.02 - kC2;

// 3x3 rotations, row-major, columns = rotated axes in the original frame.
void rot_y(double a, double* R) {
  const double c = std::cos(a), s = std::sin(a);
  const double r[9] = {c, 0, s, 0, 1, 0, -s, 0, c};
  std::memcpy(R, r, sizeof r);
}
void rot_z(double a, double* R) {
  const double c = std::cos(a), s = std::sin(a);
  const double r[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
  std::memcpy(R, r, sizeof r);
}
void rot_x(double a, double* R) {
  const double c = std::cos(a), s = std::sin(a);
  const double r[9] = {1, 0, 0, 0, c, -s, 0, s, c};
  std::memcpy(R, r, sizeof r);
}
void matmul3(const double* A, const double* B, double* C) {
  double t[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t[r * 3 + c] = A[r * 3] * B[c] + A[r * 3 + 1] * B[3 + c] + A[r * 3 + 2] * B[6 + c];
  std::memcpy(C, t, sizeof t);
}

// A pendulum whose base is turned and moved in the thorax (base_rotation_in_thorax = Rz(0.4) Rx(-0.7)): the
// thorax-to-base conversion of the hand load and the hand position is then not the identity, so a transposed
// rotation shows.
const ModelDef& rotated_base() {
  static const ModelDef def = [] {
    ModelDef d = pendulum();
    double Rz[9], Rx[9], R[9];
    rot_z(0.4, Rz);
    rot_x(-0.7, Rx);
    matmul3(Rz, Rx, R);
    std::memcpy(d.base_rotation_in_thorax, R, sizeof R);
    d.base_origin_in_thorax[0] = 0.1;
    d.base_origin_in_thorax[1] = -0.2;
    d.base_origin_in_thorax[2] = 0.05;
    return d;
  }();
  return def;
}

// State of an Arm of the pendulum at q, qd with activations act (CE lengths in static equilibrium there, so
// that the tendons are taut and carry force).
void set_state(Arm& a, const double* q, const double* qd, const double* act) {
  a.reset(q, qd, act);
}

}  // namespace

TEST_SUITE("stages (pendulum)") {

// ---------------------------------------------------------------------------------------------------- 1. paths
TEST_CASE("stage paths: lengths are the model's polynomials, moment arms -dL/dq by finite difference") {
  const ModelDef& def = pendulum();
  for (double q0 : {-0.8, 0.0, 1.3})
    for (double q1 : {-0.5, 0.9}) {
      CAPTURE(q0);
      CAPTURE(q1);
      const double q[2] = {q0, q1};
      double L[5], R[kMaxDofs * kMaxElements], Rel[5 * 2];
      def.muscle_paths(q, L, R);
      muscle_paths_by_element(def, q, L, Rel);
      double L_only[5];
      def.muscle_lengths(q, L_only);
      for (int i = 0; i < 5; ++i) {
        CAPTURE(i);
        // Closed form from the model file; the polynomial evaluation is exact to rounding (1e-15 m).
        CHECK(L[i] == doctest::Approx(kC0[i] + kC1[i] * q[kDof[i]]).epsilon(1e-14));
        CHECK(L_only[i] == doctest::Approx(L[i]).epsilon(1e-14));
        for (int j = 0; j < 2; ++j) {
          // -dL_i/dq_j by central difference of muscle_lengths: linear in q, so the difference is exact up to
          // rounding (1e-16 m / 1e-5 rad = 1e-11 m).
          const double h = 1e-5;
          double qp[2] = {q0, q1}, qm[2] = {q0, q1}, Lp[5], Lm[5];
          qp[j] += h;
          qm[j] -= h;
          def.muscle_lengths(qp, Lp);
          def.muscle_lengths(qm, Lm);
          const double fd = -(Lp[i] - Lm[i]) / (2 * h);
          CHECK(R[j * kMaxElements + i] == doctest::Approx(fd).epsilon(1e-9).scale(1e-3));
          // Sign and size against the polynomial: flexors (c1 < 0) have positive moment arms about ELx.
          CHECK(R[j * kMaxElements + i] == doctest::Approx(j == kDof[i] ? -kC1[i] : 0.0).epsilon(1e-14));
          // muscle_paths_by_element is the transpose of the by-DOF layout: (element, DOF) row-major.
          CHECK(Rel[i * 2 + j] == R[j * kMaxElements + i]);
        }
      }
    }

  // The pendulum's polynomials are linear; das2's are not, so its moment arms are checked against a finite
  // difference too (a wrong quadratic or cross term in the derivative would pass on the pendulum).
  const ModelDef& d2 = armrt_test::das2();
  const int n = d2.num_dofs, E = d2.num_elements;
  double q[kMaxDofs];
  for (int j = 0; j < n; ++j) q[j] = d2.dofs[j].rest + 0.1 * (j + 1) * (j % 2 ? -1 : 1);
  std::vector<double> L(kMaxElements), Rel(E * n), Lp(kMaxElements), Lm(kMaxElements);
  muscle_paths_by_element(d2, q, L.data(), Rel.data());
  const double h = 1e-6;
  double worst = 0, largest = 0;
  for (int j = 0; j < n; ++j) {
    double qp[kMaxDofs], qm[kMaxDofs];
    std::copy(q, q + n, qp);
    std::copy(q, q + n, qm);
    qp[j] += h;
    qm[j] -= h;
    d2.muscle_lengths(qp, Lp.data());
    d2.muscle_lengths(qm, Lm.data());
    for (int i = 0; i < E; ++i) {
      const double fd = -(Lp[i] - Lm[i]) / (2 * h);
      worst = std::max(worst, std::fabs(Rel[i * n + j] - fd));
      largest = std::max(largest, std::fabs(fd));
    }
  }
  // Central difference: truncation h^2 L''' / 6 ~ 1e-13 m, rounding 1e-16 m / 1e-6 rad = 1e-10 m; moment arms
  // are centimetres, so 1e-8 m is a failure of the derivative, not of the difference.
  CHECK(largest > 0.01);
  CHECK(worst < 1e-8);
}

// -------------------------------------------------------------------------------------------------- 2. muscles
TEST_CASE("stage muscles: activation rate (c1 u + c2)(u - a), the excitation cap, forces and tau = R^T F") {
  Arm arm(pendulum(), Integrator::kRos2, 1e-3);
  const Model& m = arm.model;
  Data& d = arm.data;
  const double q[2] = {0.5, -0.3}, act[5] = {0.2, 0.6, 0.3, 0.5, 0.05};
  set_state(arm, q, nullptr, act);
  // Inputs chosen so that the rates come out round: (c1 u + c2)(u - a) with c1 = 100/3, c2 = 50/3 (1/s).
  //   u 0.7, a 0.2: (70/3 + 50/3) 0.5 = 20;  u 0.1, a 0.6: (10/3 + 50/3)(-0.5) = -10;
  //   u -0.5 (clamped to 0), a 0.3: (50/3)(-0.3) = -5;  u 1.0, a 0.5: 50 * 0.5 = 25;  u a = 0.05: 0.
  const double u[5] = {0.7, 0.1, -0.5, 1.0, 0.05};
  const double expected_rate[5] = {20.0, -10.0, -5.0, 25.0, 0.0};
  double L[kMaxElements], R[kMaxDofs * kMaxElements];
  pendulum().muscle_paths(q, L, R);
  const double* lce = &d.x[lce_offset(m)];
  const double* a = &d.x[act_offset(m)];
  double act_dot[kMaxElements], lce_dot[kMaxElements], F[kMaxElements], tau[kMaxDofs];
  muscle_dynamics(m, d.muscles, u, L, R, a, lce, act_dot, lce_dot, F, tau);
  for (int i = 0; i < 5; ++i) {
    CAPTURE(i);
    // The hand values are exact in decimal; the engine's c1, c2 are rounded reciprocals (1e-15 relative).
    CHECK(act_dot[i] == doctest::Approx(expected_rate[i]).epsilon(1e-12).scale(1.0));
    CHECK(act_dot[i] == doctest::Approx((kC1act * std::clamp(u[i], 0.0, 1.0) + kC2) * (std::clamp(u[i], 0.0, 1.0) - a[i]))
                            .epsilon(1e-12).scale(1.0));
    // Force and CE velocity: the element function of muscle.cc with this arm's constants (the vectorised loop
    // must compute the same element; both evaluate one formula, so agreement to rounding).
    const MuscleOut e = muscle_element(data_element(m, d, i), m.fibre_damping, L[i], lce[i], a[i]);
    CHECK(F[i] == doctest::Approx(e.force).epsilon(1e-12));
    CHECK(lce_dot[i] == doctest::Approx(e.fibre_velocity).epsilon(1e-10).scale(1e-12));
    CHECK(F[i] > 1.0);  // taut tendons (CE in equilibrium at a > 0): a tau check with zero forces proves nothing
  }
  // Near static equilibrium (set_state) the CE velocity is small: |v| < 1e-6 m/s.
  for (int i = 0; i < 5; ++i) CHECK(std::fabs(lce_dot[i]) < 1e-6);
  // tau = R^T F with the closed-form moment arms: ELx gets 0.03 F0 + 0.02 F1 - 0.025 F2, PSy 0.01 F3 - 0.01 F4.
  CHECK(tau[0] == doctest::Approx(0.03 * F[0] + 0.02 * F[1] - 0.025 * F[2]).epsilon(1e-13));
  CHECK(tau[1] == doctest::Approx(0.01 * F[3] - 0.01 * F[4]).epsilon(1e-12).scale(1e-12));
  CHECK(std::fabs(tau[1]) > 0.01);  // unequal activations: a dropped or swapped row shows

  // The cap: data.settings.max_activation takes effect through data_apply_settings (d.muscles), not before.
  d.settings.max_activation[0] = 0.4;
  d.settings.max_activation[3] = 0.0;  // paralysed
  muscle_dynamics(m, d.muscles, u, L, R, a, lce, act_dot, lce_dot, F, tau);
  CHECK(act_dot[0] == doctest::Approx(20.0).epsilon(1e-12));  // settings not applied yet: no cap
  data_apply_settings(m, d);
  CHECK(d.muscles.max_activation[0] == 0.4);
  muscle_dynamics(m, d.muscles, u, L, R, a, lce, act_dot, lce_dot, F, tau);
  // u 0.7 capped at 0.4, a 0.2: (40/3 + 50/3) 0.2 = 6;  element 3: u capped at 0, a 0.5: (50/3)(-0.5) = -25/3.
  CHECK(act_dot[0] == doctest::Approx(6.0).epsilon(1e-12));
  CHECK(act_dot[3] == doctest::Approx(-25.0 / 3.0).epsilon(1e-12));
  CHECK(act_dot[1] == doctest::Approx(-10.0).epsilon(1e-12));  // the others keep their cap of 1
  CHECK(std::fabs(act_dot[4]) < 1e-12);
}

// ------------------------------------------------------------------------------------------- 3. passive joints
TEST_CASE("stage passive joints: the law by hand inside and outside the range, damping, stiffness = d tau/dq") {
  const ModelDef& def = pendulum();
  // From pendulum2.json: k_inside 1 N m/rad, k_outside 5000 N m/rad^2, damping 0, ranges ELx [-1.5, 2],
  // PSy [-1.2, 1.2], rest 0.
  REQUIRE(def.passive_stiffness_inside == 1.0);
  REQUIRE(def.passive_stiffness_outside == 5000.0);
  REQUIRE(def.passive_damping == 0.0);
  double tau[2], kq[2], kqd[2];
  {  // inside the range: the linear spring only (and no damping: qd does nothing)
    const double q[2] = {0.5, -0.3}, qd[2] = {3.0, -2.0};
    passive_joint_torque(def, q, qd, tau);
    CHECK(tau[0] == doctest::Approx(-0.5).epsilon(1e-15));
    CHECK(tau[1] == doctest::Approx(0.3).epsilon(1e-15));
  }
  {  // outside: ELx 0.1 above its maximum, PSy 0.1 below its minimum: -k q -/+ 5000 * 0.1^2
    const double q[2] = {2.1, -1.3}, qd[2] = {0.0, 0.0};
    passive_joint_torque(def, q, qd, tau);
    // 1e-12: the excursion 2.1 - 2.0 carries the rounding of 2.1 (1e-16 / 0.1 relative, then squared).
    CHECK(tau[0] == doctest::Approx(-2.1 - 50.0).epsilon(1e-12));
    CHECK(tau[1] == doctest::Approx(1.3 + 50.0).epsilon(1e-12));
    passive_joint_stiffness(def, q, kq, kqd);
    CHECK(kq[0] == doctest::Approx(-1.0 - 2 * 5000.0 * 0.1).epsilon(1e-12));
    CHECK(kq[1] == doctest::Approx(-1.0 - 2 * 5000.0 * 0.1).epsilon(1e-12));
    CHECK(kqd[0] == 0.0);
  }
  // Damping and a rest posture away from zero: a copy of the tables with damping 0.5 N m s/rad and rest
  // (0.2, -0.1): tau = -k (q - rest) - c qd - k_out e |e|.
  static const DofParams dofs[2] = {{"ELx", "EL_x", -1.5, 2.0, 0.2}, {"PSy", "PS_y", -1.2, 1.2, -0.1}};
  ModelDef damped = def;
  damped.dofs = dofs;
  damped.passive_damping = 0.5;
  {
    const double q[2] = {0.5, 1.5}, qd[2] = {3.0, -2.0};
    passive_joint_torque(damped, q, qd, tau);
    CHECK(tau[0] == doctest::Approx(-(0.5 - 0.2) - 0.5 * 3.0).epsilon(1e-14));
    CHECK(tau[1] == doctest::Approx(-(1.5 + 0.1) + 0.5 * 2.0 - 5000.0 * 0.3 * 0.3).epsilon(1e-12));
    passive_joint_stiffness(damped, q, kq, kqd);
    CHECK(kqd[0] == -0.5);
    CHECK(kqd[1] == -0.5);
  }
  // The stiffness against a central difference of the torque, inside, outside on both sides and across the
  // range bounds; the torque is piecewise quadratic, so the difference is exact up to rounding
  // (tau ~ 500 N m * 1e-16 / 1e-6 = 5e-8 N m/rad) away from the kinks (|q - bound| > h).
  for (double q0 : {-2.0, -1.6, -0.7, 0.0, 0.4, 1.9, 2.05, 2.3})
    for (double q1 : {-1.5, -1.0, 0.3, 1.25, 1.5}) {
      CAPTURE(q0);
      CAPTURE(q1);
      const double q[2] = {q0, q1}, qd[2] = {0.1, -0.2};
      passive_joint_stiffness(damped, q, kq, kqd);
      const double h = 1e-6;
      for (int j = 0; j < 2; ++j) {
        double qp[2] = {q0, q1}, qm[2] = {q0, q1}, tp[2], tm[2];
        qp[j] += h;
        qm[j] -= h;
        passive_joint_torque(damped, qp, qd, tp);
        passive_joint_torque(damped, qm, qd, tm);
        CHECK(kq[j] == doctest::Approx((tp[j] - tm[j]) / (2 * h)).epsilon(1e-6));
        double qdp[2] = {qd[0], qd[1]}, t0[2], t1[2];
        passive_joint_torque(damped, q, qd, t0);
        qdp[j] += 1.0;
        passive_joint_torque(damped, q, qdp, t1);
        CHECK(kqd[j] == doctest::Approx(t1[j] - t0[j]).epsilon(1e-9));  // linear in qd: a unit step is exact
      }
    }
}

// ------------------------------------------------------------------------------------------- 4. external loads
TEST_CASE("stage external loads: tau_ext = J^T F (J by finite difference of the hand position), a pure moment") {
  // On the turned base, so that the thorax-frame load has to be rotated into the base frame.
  static Model m;
  model_init(m, rotated_base());
  const double* Rb = rotated_base().base_rotation_in_thorax;  // columns = base axes in thorax
  for (double q0 : {-0.9, 0.0, 0.6, 1.8}) {
    const double q1 = 0.4 - 0.3 * q0;
    CAPTURE(q0);
    const double q[2] = {q0, q1};
    // Hand position: origin + R p_base with the closed form p_base = (0.33 sin q0, -0.3 - 0.33 cos q0, 0).
    const double pb[3] = {kHandDistance * std::sin(q0), kElbowY - kHandDistance * std::cos(q0), 0.0};
    double p[3];
    hand_position_in_thorax(m, q, p);
    const double origin[3] = {0.1, -0.2, 0.05};
    for (int k = 0; k < 3; ++k)
      CHECK(p[k] == doctest::Approx(origin[k] + Rb[k * 3] * pb[0] + Rb[k * 3 + 1] * pb[1] + Rb[k * 3 + 2] * pb[2])
                         .epsilon(1e-13).scale(1e-3));
    // J (thorax frame, 3 x 2) = d p / dq by central difference of hand_position_in_thorax: truncation
    // 0.33 h^2 / 6 ~ 5e-12 m/rad, rounding 1e-16 / 1e-5 = 1e-11 m/rad; times |F| ~ 30 N: 1e-9 N m.
    double J[3][2];
    const double h = 1e-5;
    for (int j = 0; j < 2; ++j) {
      double qp[2] = {q0, q1}, qm[2] = {q0, q1}, pp[3], pm[3];
      qp[j] += h;
      qm[j] -= h;
      hand_position_in_thorax(m, qp, pp);
      hand_position_in_thorax(m, qm, pm);
      for (int k = 0; k < 3; ++k) J[k][j] = (pp[k] - pm[k]) / (2 * h);
    }
    const double F[3] = {12.0, -25.0, 7.0}, zero[3] = {0, 0, 0};
    double f_ext[3], t_ext[3], tau[2];
    CHECK(external_load(m, q, F, zero, f_ext, t_ext, tau));
    for (int j = 0; j < 2; ++j) {
      const double expect = J[0][j] * F[0] + J[1][j] * F[1] + J[2][j] * F[2];
      CHECK(tau[j] == doctest::Approx(expect).epsilon(1e-8).scale(1e-8));
    }
    CHECK(std::fabs(tau[0]) > 0.1);  // a real lever (0.33 m x tens of newtons, less where F is nearly along the arm)
    // The load in the base frame is R^T F.
    for (int k = 0; k < 3; ++k) {
      CHECK(f_ext[k] == doctest::Approx(Rb[k] * F[0] + Rb[3 + k] * F[1] + Rb[6 + k] * F[2]).epsilon(1e-14).scale(1e-13));
      CHECK(t_ext[k] == 0.0);
    }
    // A pure moment Mt (thorax frame) on the hand: in the base frame Mb = R^T Mt, and the hand's angular
    // velocity is qd0 z + qd1 (Rz(q0) y) = qd0 (0, 0, 1) + qd1 (-sin q0, cos q0, 0), so
    // tau = (Mb_z, -sin q0 Mb_x + cos q0 Mb_y).
    const double Mt[3] = {2.0, -3.0, 5.0};
    double Mb[3];
    for (int k = 0; k < 3; ++k) Mb[k] = Rb[k] * Mt[0] + Rb[3 + k] * Mt[1] + Rb[6 + k] * Mt[2];
    CHECK(external_load(m, q, zero, Mt, f_ext, t_ext, tau));
    CHECK(tau[0] == doctest::Approx(Mb[2]).epsilon(1e-13));
    CHECK(tau[1] == doctest::Approx(-std::sin(q0) * Mb[0] + std::cos(q0) * Mb[1]).epsilon(1e-13).scale(1e-13));
    for (int k = 0; k < 3; ++k) CHECK(f_ext[k] == 0.0);
    // No load: false, and tau zero even where it held a value before.
    tau[0] = tau[1] = 99.0;
    CHECK_FALSE(external_load(m, q, zero, zero, f_ext, t_ext, tau));
    CHECK(tau[0] == 0.0);
    CHECK(tau[1] == 0.0);
  }
}

// ------------------------------------------------------------------------------------------------- 5. skeleton
TEST_CASE("stage skeleton: M qdd = tau + b against the closed-form pendulum and the generated M, b; gravity is the argument's") {
  const ModelDef& def = pendulum();
  const Model& m = shared_model(def);
  for (double q0 : {-1.1, 0.0, 0.7, 1.9})
    for (double q1 : {-0.6, 0.8}) {
      CAPTURE(q0);
      CAPTURE(q1);
      const double q[2] = {q0, q1}, qd[2] = {1.5, -2.5}, tau[2] = {0.8, -0.05};
      double M[4], qdd[2];
      // Model gravity (0, -g, 0): gravity torque on ELx -g S sin q0; none on PSy, no velocity terms (M constant).
      skeleton_dynamics(m, def.gravity_base, q, qd, tau, M, qdd);
      CHECK(M[0] == doctest::Approx(kInertiaEl).epsilon(1e-12));
      CHECK(M[3] == doctest::Approx(kInertiaPs).epsilon(1e-12));
      CHECK(std::fabs(M[1]) < 1e-14);
      // Closed form to rounding of the solve (1e-14 relative, qdd ~ 10-100 rad/s^2).
      CHECK(qdd[0] == doctest::Approx((tau[0] - kG * kMassMoment * std::sin(q0)) / kInertiaEl).epsilon(1e-12));
      CHECK(qdd[1] == doctest::Approx(tau[1] / kInertiaPs).epsilon(1e-12));
      // Against the generated mass matrix and bias force, solved by hand (2x2 inverse).
      double Mg[4], b[2];
      def.mass_matrix(q, Mg);
      def.bias_force(q, qd, def.gravity_base, b);
      for (int k = 0; k < 4; ++k) CHECK(M[k] == doctest::Approx(Mg[k]).epsilon(1e-14).scale(1e-14));
      const double det = Mg[0] * Mg[3] - Mg[1] * Mg[2];
      const double r0 = tau[0] + b[0], r1 = tau[1] + b[1];
      CHECK(qdd[0] == doctest::Approx((Mg[3] * r0 - Mg[1] * r1) / det).epsilon(1e-12));
      CHECK(qdd[1] == doctest::Approx((Mg[0] * r1 - Mg[2] * r0) / det).epsilon(1e-12));

      // Zero gravity from the argument: no gravity torque, whatever the model file says.
      const double g0[3] = {0, 0, 0};
      skeleton_dynamics(m, g0, q, qd, tau, M, qdd);
      CHECK(qdd[0] == doctest::Approx(tau[0] / kInertiaEl).epsilon(1e-12));
      CHECK(qdd[1] == doctest::Approx(tau[1] / kInertiaPs).epsilon(1e-12));
      // Another direction (a lying arm, partly): the potential -S g . (sin q0, -cos q0, 0) gives the torque
      // S (g_x cos q0 + g_y sin q0) on ELx; g_z is along the elbow axis and does nothing.
      const double g1[3] = {3.0, -4.0, 6.0};
      skeleton_dynamics(m, g1, q, qd, tau, M, qdd);
      CHECK(qdd[0] == doctest::Approx((tau[0] + kMassMoment * (3.0 * std::cos(q0) - 4.0 * std::sin(q0))) / kInertiaEl)
                          .epsilon(1e-12));
      CHECK(qdd[1] == doctest::Approx(tau[1] / kInertiaPs).epsilon(1e-12));
    }
}

// ---------------------------------------------------------------------------------------------- 6. GH reaction
namespace {
// The pendulum's muscles do not cross GH (gh_direction null); this copy gives two of them lines of action at
// GH, so that the muscle term of the balance is exercised.
void two_gh_directions(const double* q, double* d) {
  (void)q;
  std::fill(d, d + 5 * 3, 0.0);
  d[0 * 3 + 0] = 0.6, d[0 * 3 + 1] = 0.8;           // element 0: (0.6, 0.8, 0)
  d[3 * 3 + 0] = -1.0 / std::sqrt(2.0), d[3 * 3 + 2] = 1.0 / std::sqrt(2.0);  // element 3
}
const ModelDef& pendulum_gh_muscles() {
  static const ModelDef def = [] {
    ModelDef d = pendulum();
    d.gh_directions = &two_gh_directions;
    return d;
  }();
  return def;
}
// Newton-Euler of the arm (humerus + forearm) written out: the humerus does not move; the ulna, radius and hand
// COMs are at elbow + Rz(q0) (0, -d_b, 0) (radius and hand on the PSy axis), so
// sum m a = S (qdd cos q0 - qd^2 sin q0, qdd sin q0 + qd^2 cos q0, 0), S = sum m_b d_b; the force of the humeral
// head on the glenoid is what holds the arm: sum F_i d_i + F_hand + m_arm g - sum m a (docs/conventions.md).
void newton_euler_gh(double q0, double qd0, double qdd0, const double* g, const double* f_hand, const double* F,
                     const double* dir, double* out) {
  const double ma[3] = {kMassMoment * (qdd0 * std::cos(q0) - qd0 * qd0 * std::sin(q0)),
                        kMassMoment * (qdd0 * std::sin(q0) + qd0 * qd0 * std::cos(q0)), 0.0};
  for (int k = 0; k < 3; ++k) {
    out[k] = f_hand[k] + kArmMass * g[k] - ma[k];
    for (int i = 0; i < 5; ++i) out[k] += F[i] * dir[i * 3 + k];
  }
}
}  // namespace

TEST_CASE("stage GH reaction: the humerus's force balance (Newton-Euler by hand), gravity from the argument, stability by hand") {
  const ModelDef& def = pendulum();
  REQUIRE(def.arm_mass == doctest::Approx(kArmMass).epsilon(1e-15));
  const Model& m = shared_model(def);
  Model mg;
  model_init(mg, pendulum_gh_muscles());
  const double F[5] = {120.0, 80.0, 40.0, 30.0, 10.0};
  const double g[3] = {0.0, -kG, 0.0};
  double no_dirs[15] = {0}, dirs[15];
  two_gh_directions(nullptr, dirs);
  for (double q0 : {-0.7, 0.0, 1.2})
    for (double qd0 : {0.0, 2.0})
      for (double qdd0 : {0.0, -15.0}) {
        CAPTURE(q0);
        CAPTURE(qd0);
        CAPTURE(qdd0);
        const double q[2] = {q0, 0.3}, qd[2] = {qd0, -1.0}, qdd[2] = {qdd0, 4.0};
        const double f_hand[3] = {-40.0, 15.0, -6.0};  // base frame (= thorax for the pendulum)
        double gh[3], ref[3];
        GHStability st;
        gh_reaction(m, g, q, qd, qdd, F, f_hand, gh, &st);
        newton_euler_gh(q0, qd0, qdd0, g, f_hand, F, no_dirs, ref);
        // Sums of a few terms of ~50 N: rounding 1e-14 N.
        for (int k = 0; k < 3; ++k) CHECK(gh[k] == doctest::Approx(ref[k]).epsilon(1e-12).scale(1e-12));
        // Stability by hand in the pendulum's glenoid basis: n = (-1, 0, 0), e_major = (0, 1, 0),
        // e_minor = (0, 0, -1), half-angles 0.7744 and 0.6728 rad (pendulum2.json).
        const double theta = std::atan2(gh[1], -gh[0]), phi = std::atan2(-gh[2], -gh[0]);
        CHECK(st.theta == doctest::Approx(theta).epsilon(1e-14).scale(1e-14));
        CHECK(st.phi == doctest::Approx(phi).epsilon(1e-14).scale(1e-14));
        const double stab = std::pow(theta / 0.7744, 2) + std::pow(phi / 0.6728, 2);
        CHECK(st.stab == doctest::Approx(stab).epsilon(1e-13));
        // Rim: psi = atan2(phi, theta); r(psi) = 1 / sqrt(cos^2 psi / ta^2 + sin^2 psi / pa^2); margin r - rho.
        const double psi = std::atan2(phi, theta), rho = std::hypot(theta, phi);
        const double r = 1.0 / std::sqrt(std::pow(std::cos(psi) / 0.7744, 2) + std::pow(std::sin(psi) / 0.6728, 2));
        CHECK(st.rim_direction == doctest::Approx(psi).epsilon(1e-14).scale(1e-14));
        CHECK(st.rim_margin == doctest::Approx(r - rho).epsilon(1e-12).scale(1e-12));
        const GHStability again = gh_stability(def, gh);  // the one definition, called on its own
        CHECK(again.stab == st.stab);

        // With muscles crossing GH: their forces along their lines of action are added.
        gh_reaction(mg, g, q, qd, qdd, F, f_hand, gh, &st);
        newton_euler_gh(q0, qd0, qdd0, g, f_hand, F, dirs, ref);
        for (int k = 0; k < 3; ++k) CHECK(gh[k] == doctest::Approx(ref[k]).epsilon(1e-12).scale(1e-12));
      }
  // At rest without load: the weight only, pressing down (-y, the glenoid's inferior rim: theta = -pi/2 for a
  // force with no normal component); and zero gravity from the argument gives no force at all.
  const double q[2] = {0.4, 0.0}, zero[3] = {0, 0, 0}, F0[5] = {0, 0, 0, 0, 0};
  double gh[3];
  GHStability st;
  gh_reaction(m, g, q, zero, zero, F0, zero, gh, &st);
  CHECK(gh[1] == doctest::Approx(-kArmMass * kG).epsilon(1e-14));
  CHECK(gh[0] == 0.0);
  CHECK(gh[2] == 0.0);
  gh_reaction(m, zero, q, zero, zero, F0, zero, gh, &st);
  for (int k = 0; k < 3; ++k) CHECK(gh[k] == 0.0);
  const double g_x[3] = {5.0, 0.0, 0.0};  // gravity along x: the weight follows the argument's direction
  gh_reaction(m, g_x, q, zero, zero, F0, zero, gh, &st);
  CHECK(gh[0] == doctest::Approx(kArmMass * 5.0).epsilon(1e-14));
  CHECK(gh[1] == 0.0);
}

// ----------------------------------------------------------------------------------------------- 7. kinematics
namespace {
double g_humerus_rotation[9];  // what fake_body_poses reports for the humerus (base frame)
void fake_body_poses(const double* q, double* R, double* p) {
  (void)q;
  for (int b = 0; b < 4; ++b) {
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::memcpy(R + 9 * b, b == 0 ? g_humerus_rotation : I, sizeof I);
    for (int k = 0; k < 3; ++k) p[3 * b + k] = 0.0;
  }
}
}  // namespace

TEST_CASE("stage kinematics: thorax-humerus angles at poses with a known answer") {
  // The pendulum's humerus is welded to the scapula with the thorax's axes: elevation 0 at every q.
  {
    const Model& m = shared_model(pendulum());
    for (double q0 : {-1.0, 0.0, 1.5}) {
      const double q[2] = {q0, 0.7};
      double ang[3];
      thorax_humerus_angles(m, q, ang);
      CHECK(std::fabs(ang[1]) < 1e-12);
    }
  }
  // A copy whose humerus pose is set by the test (body_poses replaced) on a base turned by Ry(b0) in the thorax.
  ModelDef def = pendulum();
  def.body_poses = &fake_body_poses;
  Model m;
  double ang[3];
  const double q[2] = {0, 0};
  // Thorax axes: x lateral (right), y superior, z posterior (docs/conventions.md); the humerus's y axis points
  // proximally. Abduction by 90 deg (base = thorax): the humerus turned +90 deg about z, its y axis now -x (the
  // elbow out to the right): plane of elevation 0, elevation 90 deg.
  model_init(m, def);
  rot_z(M_PI / 2, g_humerus_rotation);
  thorax_humerus_angles(m, q, ang);
  CHECK(std::fabs(ang[0]) < 1e-12);
  CHECK(ang[1] == doctest::Approx(M_PI / 2).epsilon(1e-12));
  CHECK(std::fabs(ang[2]) < 1e-12);
  // Forward flexion by 60 deg: the humerus turned +60 deg about x, its y axis to (0, 1/2, sqrt(3)/2), so the
  // elbow goes anterior (-z) and up: plane 90 deg, elevation 60 deg. In the Y-Z-Y sequence a turn about x is
  // Rx(e) = Ry(90 deg) Rz(e) Ry(-90 deg): axial rotation -90 deg.
  rot_x(M_PI / 3, g_humerus_rotation);
  thorax_humerus_angles(m, q, ang);
  CHECK(ang[0] == doctest::Approx(M_PI / 2).epsilon(1e-12));
  CHECK(ang[1] == doctest::Approx(M_PI / 3).epsilon(1e-12));
  CHECK(ang[2] == doctest::Approx(-M_PI / 2).epsilon(1e-12));
  // A generic Y-Z-Y pose split between the base (Ry(plane)) and the humerus in the base (Rz(elev) Ry(axial)):
  // the angles come back, so the base rotation is applied and on the correct side.
  const double plane = 0.7, elev = 1.1, axial = -0.4;
  double Rb[9], Rz_[9], Ry_[9];
  rot_y(plane, Rb);
  std::memcpy(def.base_rotation_in_thorax, Rb, sizeof Rb);
  model_init(m, def);
  rot_z(elev, Rz_);
  rot_y(axial, Ry_);
  matmul3(Rz_, Ry_, g_humerus_rotation);
  thorax_humerus_angles(m, q, ang);
  CHECK(ang[0] == doctest::Approx(plane).epsilon(1e-12));
  CHECK(ang[1] == doctest::Approx(elev).epsilon(1e-12));
  CHECK(ang[2] == doctest::Approx(axial).epsilon(1e-12));
}

// ----------------------------------------------------------------------------------------- 8. forward() composition
TEST_CASE("stage forward(): with record the outputs equal the stages called one by one; outputs_current") {
  Arm arm(pendulum(), Integrator::kRos2, 1e-3);
  const Model& m = arm.model;
  Data& d = arm.data;
  const ModelDef& def = *m.def;
  const double q[2] = {0.9, -0.4}, qd[2] = {1.2, 0.5}, act[5] = {0.3, 0.1, 0.2, 0.4, 0.05};
  set_state(arm, q, qd, act);
  const double u[5] = {0.5, 0.0, 0.9, 0.2, 0.3};
  std::copy(u, u + 5, d.excitation.begin());
  d.hand_force = {3.0, -8.0, 1.5};
  d.hand_moment = {0.2, -0.1, 0.4};
  d.applied_moment[0] = 0.7, d.applied_moment[1] = -0.3;  // N m at ELx, PSy (qfrc_applied)
  d.settings.gravity = {1.0, -9.0, 0.5};  // the arm's own gravity, not the model file's
  StateVec xdot{};
  forward(m, d, d.x.data(), xdot.data(), true);
  CHECK(outputs_current(m, d));
  d.applied_moment[1] = -0.31;  // the outputs depend on the applied moments too
  CHECK_FALSE(outputs_current(m, d));
  d.applied_moment[1] = -0.3;
  CHECK(outputs_current(m, d));

  // The stages one by one on the same state.
  const double* x = d.x.data();
  const double* lce = x + lce_offset(m);
  const double* a = x + act_offset(m);
  double L[kMaxElements], R[kMaxDofs * kMaxElements];
  def.muscle_paths(q, L, R);
  double act_dot[kMaxElements], lce_dot[kMaxElements], F[kMaxElements], tau_m[kMaxDofs];
  muscle_dynamics(m, d.muscles, u, L, R, a, lce, act_dot, lce_dot, F, tau_m);
  double tau_p[kMaxDofs];
  passive_joint_torque(def, q, qd, tau_p);
  double f_ext[3], t_ext[3], tau_e[kMaxDofs];
  external_load(m, q, d.hand_force.data(), d.hand_moment.data(), f_ext, t_ext, tau_e);
  double tau[kMaxDofs], M[4], qdd[2];
  for (int j = 0; j < 2; ++j) tau[j] = tau_m[j] + tau_p[j] + tau_e[j] + d.applied_moment[j];
  skeleton_dynamics(m, d.settings.gravity.data(), q, qd, tau, M, qdd);
  double p_hand[3], gh[3], th[3];
  hand_position_in_thorax(m, q, p_hand);
  GHStability st;
  gh_reaction(m, d.settings.gravity.data(), q, qd, qdd, F, f_ext, gh, &st);
  thorax_humerus_angles(m, q, th);

  // Same functions on the same inputs: equal to rounding (1e-14 relative; scale for the near-zero entries).
#define CHECK_SAME(got, want) CHECK((got) == doctest::Approx(want).epsilon(1e-14).scale(1e-14))
  std::vector<std::string> checked;
  for (int j = 0; j < 2; ++j) {
    CAPTURE(j);
    CHECK(d.output_q[j] == q[j]);
    CHECK_SAME(d.muscle_torque[j], tau_m[j]);
    CHECK_SAME(d.passive_torque[j], tau_p[j]);
    CHECK_SAME(d.external_torque[j], tau_e[j]);
    CHECK(d.girdle_torque[j] == 0.0);  // no girdle
    CHECK_SAME(d.qddot[j], qdd[j]);
    // The derivative itself: dq/dt = qd, dqd/dt = qdd.
    CHECK(xdot[qd_offset(m) + j] == d.qddot[j]);
    CHECK(xdot[q_offset(m) + j] == qd[j]);
  }
  for (int i = 0; i < 5; ++i) {
    CAPTURE(i);
    CHECK_SAME(d.muscle_length[i], L[i]);
    CHECK_SAME(d.muscle_force[i], F[i]);
    CHECK_SAME(d.fibre_velocity[i], lce_dot[i]);
    CHECK_SAME(xdot[lce_offset(m) + i], lce_dot[i]);
    CHECK_SAME(xdot[act_offset(m) + i], act_dot[i]);
  }
  for (int k = 0; k < 3; ++k) {
    CHECK_SAME(d.hand_position[k], p_hand[k]);
    CHECK_SAME(d.gh_force[k], gh[k]);
    CHECK_SAME(d.thorax_humerus[k], th[k]);
  }
  CHECK_SAME(d.gh_angles[0], st.theta);
  CHECK_SAME(d.gh_angles[1], st.phi);
  CHECK_SAME(d.gh_stab, st.stab);
  CHECK_SAME(d.gh_rim_margin, st.rim_margin);
  CHECK_SAME(d.gh_rim_direction, st.rim_direction);
  // The arm's gravity was used, not the model file's: the model's would give another qdd.
  {
    double qdd_model[2];
    skeleton_dynamics(m, def.gravity_base, q, qd, tau, M, qdd_model);
    CHECK(std::fabs(qdd_model[0] - d.qddot[0]) > 1e-3);
  }
  checked = {"output_q", "muscle_length", "muscle_force", "fibre_velocity", "muscle_torque", "passive_torque",
             "external_torque", "hand_position", "girdle_torque", "qddot", "gh_force", "gh_angles", "gh_stab",
             "gh_rim_margin", "gh_rim_direction", "thorax_humerus"};
  // Every output of the table that a model without a girdle has is among those compared above: a new
  // ARMRT_OUTPUTS row makes this test fail until it is checked here too.
  int rows = 0;
  const LayoutRow* row = output_rows(&rows);
  for (int r = 0; r < rows; ++r) {
    if (row[r].girdle_only) continue;
    CAPTURE(row[r].name);
    CHECK(std::find(checked.begin(), checked.end(), std::string(row[r].name)) != checked.end());
  }

  // outputs_current: true at exactly what forward() recorded, false after any change.
  REQUIRE(outputs_current(m, d));
  for (int k = 0; k < state_size(m); ++k) {  // one bit of any state entry (the lowest mantissa bit)
    CAPTURE(k);
    std::uint64_t bits;
    std::memcpy(&bits, &d.x[k], sizeof bits);
    const double saved = d.x[k];
    bits ^= 1u;
    std::memcpy(&d.x[k], &bits, sizeof bits);
    CHECK_FALSE(outputs_current(m, d));
    d.x[k] = saved;
    CHECK(outputs_current(m, d));
  }
  d.hand_force[2] += 1e-9;
  CHECK_FALSE(outputs_current(m, d));
  d.hand_force[2] = 1.5;
  CHECK(outputs_current(m, d));
  d.hand_moment[0] = 0.25;
  CHECK_FALSE(outputs_current(m, d));
  d.hand_moment[0] = 0.2;
  CHECK(outputs_current(m, d));
  d.settings.gravity[1] = -9.80665;
  CHECK_FALSE(outputs_current(m, d));
  d.settings.gravity[1] = -9.0;
  CHECK(outputs_current(m, d));
  data_apply_settings(m, d);  // even with the same settings: the muscles' constants were derived anew
  CHECK_FALSE(outputs_current(m, d));
  forward(m, d, d.x.data(), xdot.data(), true);
  CHECK(outputs_current(m, d));
  // forward() at another x records that x: the outputs no longer describe d.x.
  StateVec other = d.x;
  other[0] += 0.1;
  forward(m, d, other.data(), xdot.data(), true);
  CHECK_FALSE(outputs_current(m, d));
  // Without record nothing is recorded: still not current.
  forward(m, d, d.x.data(), xdot.data(), false);
  CHECK_FALSE(outputs_current(m, d));

  // Arm::evaluate_outputs computes only when stale: a sentinel in an output survives while current.
  arm.evaluate_outputs();
  REQUIRE(outputs_current(m, d));
  const double gh_stab = d.gh_stab, force0 = d.muscle_force[0];
  d.gh_stab = -12345.0;
  d.muscle_force[0] = -777.0;
  arm.evaluate_outputs();
  CHECK(d.gh_stab == -12345.0);
  CHECK(d.muscle_force[0] == -777.0);
  d.hand_force[0] = 3.0 + 1e-12;  // stale now (an input changed by a hair)
  arm.evaluate_outputs();
  CHECK(d.gh_stab == doctest::Approx(gh_stab).epsilon(1e-9));
  CHECK(d.muscle_force[0] == force0);  // the force does not depend on the hand load
  CHECK(outputs_current(m, d));
#undef CHECK_SAME
}

// --------------------------------------------------------------------------------------------- 9. settings per arm
TEST_CASE("stage settings: arms of one model share one Model; one arm's strength changes its forces only") {
  Arm a(pendulum(), Integrator::kRos2, 1e-3);
  Arm b(pendulum(), Integrator::kRk4, 1e-4);
  CHECK(&a.model == &b.model);
  CHECK(&a.model == &shared_model(pendulum()));
  const double q[2] = {0.3, 0.2}, act[5] = {0.5, 0.4, 0.3, 0.6, 0.2};
  a.reset(q, nullptr, act);
  b.reset(q, nullptr, act);
  b.data.x = a.data.x;  // the same state exactly
  a.evaluate_outputs();
  b.evaluate_outputs();
  const auto force_b = b.data.muscle_force;
  REQUIRE(force_b[0] > 1.0);
  for (int i = 0; i < 5; ++i) CHECK(a.data.muscle_force[i] == force_b[i]);

  a.data.settings.strength_scale[0] = 0.5;
  a.apply_settings();
  a.evaluate_outputs();  // stale after apply_settings: recomputed
  b.evaluate_outputs();
  // Every force of the element scales with fmax (SEE, PEE, compression, damping slope; the fixed fibre damper acts
  // on the CE velocity, not on the tendon force at a given state), so at the same lengths the tendon force halves.
  CHECK(a.data.muscle_force[0] == doctest::Approx(0.5 * force_b[0]).epsilon(1e-12));
  CHECK(a.data.muscles.fmax[0] == doctest::Approx(150.0).epsilon(1e-15));
  for (int i = 1; i < 5; ++i) CHECK(a.data.muscle_force[i] == force_b[i]);
  // The other arm and the shared Model are untouched.
  for (int i = 0; i < 5; ++i) CHECK(b.data.muscle_force[i] == force_b[i]);
  CHECK(b.data.muscles.fmax[0] == 300.0);
  CHECK(b.data.settings.strength_scale[0] == 1.0);
  CHECK(a.model.element[0].fmax == 300.0);
  CHECK(a.model.element[0].strength_scale == 1.0);
  // The muscle torque follows: a's ELx torque lost 0.03 * F0 / 2.
  CHECK(a.data.muscle_torque[0] == doctest::Approx(b.data.muscle_torque[0] - 0.03 * 0.5 * force_b[0]).epsilon(1e-12));
}

}  // TEST_SUITE
