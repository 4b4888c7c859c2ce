// The linearly implicit step (rosenbrock.cc): the muscle kernel's derivatives against finite
// differences (kinks included), the structured Jacobian's exact blocks against finite differences of
// forward(), and the Schur-complement solve against a dense LU of the same 214 x 214 matrix.
#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "armrt/arm.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::kDas2Dofs, armrt_test::kQ, armrt_test::kQd, armrt_test::kLce;
using armrt_test::das2;

namespace {

struct KernelOut {
  double force, velocity;
  MuscleDerivatives der;
};

KernelOut kernel(const ElementConstants& e, double b0, double L, double lce, double a) {
  KernelOut o;
  const MuscleOut out = muscle_element_derivatives(e, b0, L, lce, a, &o.der);
  o.force = out.force;
  o.velocity = out.fibre_velocity;
  return o;
}

// Checks an analytic derivative against finite differences of f with step h. Away from kinks the
// central difference must match. Within h of a kink the analytic value must match the one-sided
// difference of the side it belongs to: forward or backward (at the C1 slack points of tendon and
// PEE both sides agree to first order but the second derivative jumps, so only one side is accurate).
// Returns true if the central difference did not match (a kink within h).
template <class F>
bool check_derivative(F f, double x, double h, double analytic, double scale, const char* what) {
  const double f0 = f(x), fp = f(x + h), fm = f(x - h);
  const double fwd = (fp - f0) / h, bwd = (f0 - fm) / h, central = (fp - fm) / (2 * h);
  const double tol = 1e-5 * scale + 1e-6 * std::fabs(analytic);
  const std::string name = what;
  CAPTURE(name);
  CAPTURE(x);
  CAPTURE(analytic);
  CAPTURE(central);
  CAPTURE(fwd);
  CAPTURE(bwd);
  if (std::fabs(analytic - central) <= tol + 2e-3 * std::fabs(central)) return false;
  const double side_tol = tol + 2e-3 * std::fabs(analytic);
  CHECK((std::fabs(analytic - fwd) <= side_tol || std::fabs(analytic - bwd) <= side_tol));
  return true;
}

// All five derivatives of one element at (L, lce, a).
int check_element(const ElementConstants& e, double b0, double L, double lce, double a) {
  const KernelOut o = kernel(e, b0, L, lce, a);
  const double hL = 1e-8 * e.lslack + 1e-10, hl = 1e-8 * e.lceopt;
  const double fscale = e.fmax / e.lceopt, vscale = e.vmax / e.lceopt;
  int kinks = 0;
  kinks += check_derivative([&](double x) { return kernel(e, b0, x, lce, a).force; }, L, hL, o.der.dforce_dL, fscale, "dforce_dL");
  kinks += check_derivative([&](double x) { return kernel(e, b0, L, x, a).force; }, lce, hl, o.der.dforce_dlce, fscale, "dforce_dlce");
  kinks += check_derivative([&](double x) { return kernel(e, b0, x, lce, a).velocity; }, L, hL, o.der.dvel_dL, vscale, "dvel_dL");
  kinks += check_derivative([&](double x) { return kernel(e, b0, L, x, a).velocity; }, lce, hl, o.der.dvel_dlce, vscale, "dvel_dlce");
  if (a > 1e-6)
    kinks += check_derivative([&](double x) { return kernel(e, b0, L, lce, x).velocity; }, a, 1e-7, o.der.dvel_da, e.vmax, "dvel_da");
  return kinks;
}

}  // namespace

TEST_SUITE("rosenbrock") {

TEST_CASE("muscle kernel derivatives match finite differences at random states (every element)") {
  Model m;
  model_init(m, das2());
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int samples = 0, kinks = 0;
  for (int i = 0; i < m.num_elements; ++i) {
    const ElementConstants& e = m.element[i];
    const std::string element = m.def->elements[i].name;
    CAPTURE(element);
    for (int k = 0; k < 40; ++k) {
      const double lce = e.lceopt * (0.55 + 1.0 * U(rng));
      const double cos_pen = std::sqrt(1.0 - std::pow(e.thickness / lce, 2));
      // Tendon from 2% slack to 6% strain (beyond Fmax); activation 0..1 (a quarter of them 0).
      const double strain = -0.02 + 0.08 * U(rng);
      const double L = lce * cos_pen + e.lslack * (1.0 + strain);
      const double a = k % 4 == 0 ? 0.0 : U(rng);
      kinks += check_element(e, m.fibre_damping, L, lce, a);
      ++samples;
    }
  }
  MESSAGE(samples << " random states, " << kinks << " derivatives within a finite-difference step of a kink");
  CHECK(samples == 40 * m.num_elements);
  CHECK(kinks < samples / 20);  // kinks are rare at random states: the central check covers the bulk
}

TEST_CASE("muscle kernel derivatives at the kinks: slack tendon, concentric/eccentric switch, compressive onset, damping floor, lce floor") {
  Model m;
  model_init(m, das2());
  const double b0 = m.fibre_damping;
  for (const char* name : {"termaj1", "bicl", "supinator2", "deltscap5", "pronquad3"}) {
    const int i = armrt_test::element_index(das2(), name);
    REQUIRE(i >= 0);
    const ElementConstants& e = m.element[i];
    const std::string element = name;
    CAPTURE(element);
    const double lce = e.lceopt;
    const double cos_pen = std::sqrt(1.0 - std::pow(e.thickness / lce, 2));
    const double L_slack = lce * cos_pen + e.lslack;  // tendon exactly at its slack length
    // Tendon slack point (C1: the quadratic term starts with zero slope): at it (one-sided) and on
    // both sides, 100 finite-difference steps away (central).
    for (double d : {-1e-6, 0.0, 1e-6}) check_element(e, b0, L_slack + d * e.lslack, lce, 0.3);
    // The concentric/eccentric switch is at v = 0: the equilibrium CE length (both sides of it).
    for (double a : {0.0, 0.01, 0.2, 1.0}) {
      const double L = L_slack + 0.02 * e.lslack;
      const double lce_eq = muscle_equilibrium_lce(e, b0, L, a);
      CHECK(std::fabs(kernel(e, b0, L, lce_eq, a).velocity) < 1e-6 * e.vmax);
      for (double d : {-1e-6, 0.0, 1e-6}) check_element(e, b0, L, lce_eq + d * e.lceopt, a);
    }
    // Onset of the fibre compressive element (C1), tendon slack and taut, relaxed and active.
    for (double a : {0.0, 0.5})
      for (double strain : {-0.01, 0.02})
        for (double d : {-1e-6, 0.0, 1e-6})
          check_element(e, b0, e.compress_length + e.lslack * (1.0 + strain), e.compress_length + d * e.lceopt, a);
    // Inside the compressive range (a smooth quadratic there).
    check_element(e, b0, e.lslack, 0.5 * (e.min_lce + e.compress_length), 1.0);
    // Damping floor fading out at F0 = 0.02 fmax: a = 0.02 / f(lce) at lce = lceopt.
    check_element(e, b0, L_slack + 0.01 * e.lslack, lce, kLowActivation);
    // At the lce floor: derivatives with respect to lce are those of the clamped side (zero).
    const KernelOut o = kernel(e, b0, L_slack, 0.5 * e.min_lce, 0.3);
    CHECK(o.der.dforce_dlce == 0.0);
    CHECK(o.der.dvel_dlce == 0.0);
  }
}

namespace {

// A stimulated, moving state: 300 ms of ROS2 at 1 ms with flexors, cuff and deltoid on, a hand load.
std::unique_ptr<Arm> moving_state() {
  auto sim = std::make_unique<Arm>(das2(), Integrator::kRos2, 1e-3);
  armrt_test::set_group_excitation(*sim, "elbow_flexors", 0.4);
  armrt_test::set_group_excitation(*sim, "rotator_cuff", 0.1);
  armrt_test::set_group_excitation(*sim, "deltoid", 0.2);
  sim->data.hand_force = {0.0, -10.0, 0.0};
  for (int k = 0; k < 300; ++k) REQUIRE(sim->step());
  return sim;
}

}  // namespace

TEST_CASE("the structured Jacobian's exact blocks match finite differences of forward()") {
  auto sim = moving_state();
  const Model& m = sim->model;
  Data& d = sim->data;
  Ros2Workspace& ws = sim->stepper.ros2;
  const int n = m.num_elements, ia = act_offset(m);
  StateVec x = d.x, f0{}, fp{}, fm{};
  forward(m, d, x.data(), f0.data(), false, &ws.jac);
  const StepJacobian& J = ws.jac;
  Eigen::Matrix<double, kDas2Dofs, kDas2Dofs, Eigen::RowMajor> M;
  for (int k = 0; k < kDas2Dofs * kDas2Dofs; ++k) M.data()[k] = J.mass_matrix[k];
  const auto Minv = M.inverse().eval();
  auto fd = [&](int col, double h, int row) {
    StateVec xp = x, xm = x;
    xp[col] += h;
    xm[col] -= h;
    StepJacobian scratch;
    forward(m, d, xp.data(), fp.data(), false);
    forward(m, d, xm.data(), fm.data(), false);
    return (fp[row] - fm[row]) / (2 * h);
  };
  int checked = 0;
  for (int i = 0; i < n; i += 7) {
    const std::string element = m.def->elements[i].name;
    CAPTURE(element);
    const double h = 1e-8 * m.element[i].lceopt;
    // d lce'/d lce (the stiff diagonal), d lce'/d a, d a'/d a: exact in J.
    CHECK(fd(kLce + i, h, kLce + i) == doctest::Approx(J.dvel_dlce[i]).epsilon(1e-4).scale(1.0));
    CHECK(fd(ia + i, 1e-7, kLce + i) == doctest::Approx(J.dvel_da[i]).epsilon(1e-4).scale(1e-3));
    CHECK(fd(ia + i, 1e-7, ia + i) == doctest::Approx(-J.act_rate[i]).epsilon(1e-6));
    // d lce_i'/d q_j = -dvel_dL R_ij: exact (lce' depends on q only through L).
    for (int j = 0; j < kDas2Dofs; ++j)
      CHECK(fd(kQ + j, 1e-7, kLce + i) ==
            doctest::Approx(-J.dvel_dL[i] * J.moment_arm[j * kMaxElements + i]).epsilon(1e-4).scale(1e-2));
    // d qdd/d lce_i = M^-1 R^T e_i dforce_dlce: exact.
    for (int j = 0; j < kDas2Dofs; ++j) {
      double expected = 0;
      for (int b = 0; b < kDas2Dofs; ++b) expected += Minv(j, b) * J.moment_arm[b * kMaxElements + i] * J.dforce_dlce[i];
      CHECK(fd(kLce + i, h, kQd + j) == doctest::Approx(expected).epsilon(1e-4).scale(1e-2));
    }
    ++checked;
  }
  CHECK(checked >= 14);
  // The mechanical block is approximate (no dR/dq, gravity, Coriolis, dM/dq): its muscle and passive
  // stiffness must still carry the bulk of d qdd/d q at this stimulated state.
  Eigen::Matrix<double, kDas2Dofs, kDas2Dofs> Kfd, Kj;
  for (int c = 0; c < kDas2Dofs; ++c)
    for (int r = 0; r < kDas2Dofs; ++r) Kfd(r, c) = fd(kQ + c, 1e-7, kQd + r);
  Eigen::Matrix<double, kDas2Dofs, kDas2Dofs> K = Eigen::Matrix<double, kDas2Dofs, kDas2Dofs>::Zero();
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < kDas2Dofs; ++a)
      for (int b = 0; b < kDas2Dofs; ++b)
        K(a, b) -= J.dforce_dL[i] * J.moment_arm[a * kMaxElements + i] * J.moment_arm[b * kMaxElements + i];
  for (int a = 0; a < kDas2Dofs; ++a) K(a, a) += J.dtau_passive_dq[a];
  Kj = Minv * K;
  const double rel = (Kj - Kfd).norm() / Kfd.norm();
  MESSAGE("d qdd/dq: relative difference of the approximate block from finite differences " << rel);
  CHECK(rel < 0.05);
}

// The Schur-complement solve of jacobian_solve against a dense LU of the same state-sized matrix
// I - h gamma J, written out from the StepJacobian (test only: the engine never forms it).
static void check_schur_solve(Arm& sim) {
  const Model& m = sim.model;
  Data& d = sim.data;
  Ros2Workspace& ws = sim.stepper.ros2;
  const int n = m.num_elements, nq = m.num_dofs, ns = state_size(m);
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  StateVec f{};
  forward(m, d, d.x.data(), f.data(), false, &ws.jac);
  const double hg = 1.7071067811865475e-3;
  jacobian_factor(m, ws.jac, hg);
  const StepJacobian& J = ws.jac;
  Eigen::MatrixXd Jd = Eigen::MatrixXd::Zero(ns, ns), M(nq, nq), R(n, nq), G(nq, nq);
  for (int a = 0; a < nq; ++a)
    for (int b = 0; b < nq; ++b) {
      M(a, b) = J.mass_matrix[a * nq + b];
      G(a, b) = m.def->girdle ? J.dtau_girdle_dq[a * nq + b] : 0.0;
    }
  const Eigen::MatrixXd Minv = M.inverse();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < nq; ++j) R(i, j) = J.moment_arm[j * kMaxElements + i];  // by DOF
  Eigen::MatrixXd Kq = -R.transpose() * Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(J.dforce_dL.data(), n)).asDiagonal() * R + G;
  for (int j = 0; j < nq; ++j) Kq(j, j) += J.dtau_passive_dq[j];
  for (int j = 0; j < nq; ++j) Jd(iq + j, iqd + j) = 1.0;
  Jd.block(iqd, iq, nq, nq) = Minv * Kq;
  Jd.block(iqd, iqd, nq, nq) = Minv * Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(J.dtau_passive_dqd.data(), nq)).asDiagonal();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < nq; ++j) {
      Jd(iqd + j, il + i) = (Minv.row(j) * R.row(i).transpose())(0) * J.dforce_dlce[i];
      Jd(il + i, iq + j) = -J.dvel_dL[i] * R(i, j);
    }
    Jd(il + i, il + i) = J.dvel_dlce[i];
    Jd(il + i, ia + i) = J.dvel_da[i];
    Jd(ia + i, ia + i) = -J.act_rate[i];
  }
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(ns, ns) - hg * Jd;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd r(ns);
    for (int k = 0; k < ns; ++k) r[k] = trial == 0 ? f[k] : N(rng);
    StateVec k_schur{};
    jacobian_solve(m, ws.jac, r.data(), k_schur.data());
    const Eigen::VectorXd k_dense = A.partialPivLu().solve(r);
    const Eigen::VectorXd ks = Eigen::Map<const Eigen::VectorXd>(k_schur.data(), ns);
    CAPTURE(trial);
    CHECK((ks - k_dense).norm() <= 1e-9 * k_dense.norm());
    CHECK((A * ks - r).norm() <= 1e-9 * r.norm());
  }
}

TEST_CASE("the Schur-complement solve equals a dense LU of I - h gamma J") {
  auto sim = moving_state();
  check_schur_solve(*sim);
}

TEST_CASE("das3: the Schur-complement solve (stiffness and solves by DOF, girdle stiffness) equals a dense LU") {
  const ModelDef* def = find_model("das3");
  REQUIRE(def);
  auto sim = std::make_unique<Arm>(*def, Integrator::kRos2, 1e-3);
  for (const char* g : {"deltoid", "serratus_anterior", "elbow_flexors"}) armrt_test::set_group_excitation(*sim, g, 0.3);
  sim->data.hand_force = {0.0, -10.0, 0.0};
  for (int k = 0; k < 300; ++k) REQUIRE(sim->step());
  check_schur_solve(*sim);
}

TEST_CASE("forward() with a Jacobian leaves the kernel's lce-only terms for the overshoot limiter") {
  auto sim = moving_state();
  const Model& m = sim->model;
  Data& d = sim->data;
  Ros2Workspace& ws = sim->stepper.ros2;
  StateVec f{};
  forward(m, d, d.x.data(), f.data(), false, &ws.jac);
  const MuscleArrays& mc = d.muscles;
  for (int i = 0; i < m.num_elements; ++i) {
    const double lce_x = d.x[kLce + i];
    const double lce = lce_x > mc.min_lce[i] ? lce_x : mc.min_lce[i];
    const double xfl = (lce * mc.inv_lceopt[i] - 1.0) / kForceLengthWidth;
    CAPTURE(i);
    CHECK(ws.jac.force_length[i] == doctest::Approx(std::exp(-xfl * xfl)).epsilon(1e-14));
    const double lce_along = std::sqrt(lce * lce - mc.thickness[i] * mc.thickness[i]);
    CHECK(ws.jac.lce_along[i] == doctest::Approx(lce_along).epsilon(1e-14));
    CHECK(ws.jac.cos_pennation[i] == doctest::Approx(lce_along / lce).epsilon(1e-14));
    CHECK(ws.jac.inv_cos_pennation[i] == doctest::Approx(lce / lce_along).epsilon(1e-14));
    // PEE quadratic beyond its slack length, compressive element quadratic below compress_length (muscle.cc)
    const double stretch = std::max(lce - mc.pee_slack[i], 0.0), compression = std::max(mc.compress_length[i] - lce, 0.0);
    CHECK(ws.jac.pee_force[i] == doctest::Approx(mc.k_pee[i] * stretch * stretch).epsilon(1e-14).scale(1e-9));
    CHECK(ws.jac.compress_force[i] == doctest::Approx(mc.k_compress[i] * compression * compression).epsilon(1e-14).scale(1e-9));
  }
}

TEST_CASE("solve_spd: Cholesky (1-7 DOFs) and L D L^T (8-16) solves equal Eigen's LLT on mass-matrix-like systems") {
  // Well and badly scaled SPD matrices (das3's mass matrix spans ~1e-4 to ~1 kg m^2 on its diagonal).
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0.0, 1.0);
  for (int n = 1; n <= kMaxDofs; ++n)
    for (double spread : {1.0, 1e4}) {
      Eigen::MatrixXd B(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) B(i, j) = N(rng);
      Eigen::VectorXd scale(n), b(n);
      for (int i = 0; i < n; ++i) scale[i] = std::pow(spread, -double(i) / std::max(n - 1, 1)), b[i] = N(rng);
      const Eigen::MatrixXd A = scale.asDiagonal() * (B * B.transpose() + n * Eigen::MatrixXd::Identity(n, n)) * scale.asDiagonal();
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Ar = A;
      std::vector<double> x(n);
      solve_spd(Ar.data(), b.data(), n, x.data());
      const Eigen::VectorXd expected = A.llt().solve(b);
      CAPTURE(n);
      CAPTURE(spread);
      CHECK((Eigen::Map<const Eigen::VectorXd>(x.data(), n) - expected).norm() <= 1e-10 * expected.norm());
    }
}

TEST_CASE("generalised_force: R^T F for 1-16 DOFs, any number of elements and DOF spans equals the plain sum") {
  // Eight elements per vector and the rest in scalars; each row's entries past n hold NaN here, so a read
  // past them would show as a wrong sum.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-0.05, 0.05);
  for (int ndof = 1; ndof <= kMaxDofs; ++ndof)
    for (int n : {1, 2, 3, 5, 8, 13, 138}) {
      std::vector<double> R(ndof * kMaxElements, std::nan("")), F(n), tau(ndof);
      for (int j = 0; j < ndof; ++j)
        for (int i = 0; i < n; ++i) R[j * kMaxElements + i] = U(rng);
      for (double& v : F) v = 1e4 * U(rng);
      generalised_force(R.data(), F.data(), n, ndof, tau.data());
      for (int j = 0; j < ndof; ++j) {
        double expected = 0;
        for (int i = 0; i < n; ++i) expected += R[j * kMaxElements + i] * F[i];  // by DOF
        CAPTURE(ndof);
        CAPTURE(n);
        CHECK(tau[j] == doctest::Approx(expected).epsilon(1e-12).scale(1e-9));
      }
      // With each DOF's span of crossing elements (Model::dof_elements_begin, _end): zero arms outside it.
      std::vector<int> begin(ndof), end(ndof);
      for (int j = 0; j < ndof; ++j) {
        std::uniform_int_distribution<int> pick(0, n);
        begin[j] = pick(rng), end[j] = pick(rng);
        if (begin[j] > end[j]) std::swap(begin[j], end[j]);
        for (int i = 0; i < n; ++i)
          if (i < begin[j] || i >= end[j]) R[j * kMaxElements + i] = 0.0;
      }
      generalised_force(R.data(), F.data(), n, ndof, tau.data(), begin.data(), end.data());
      for (int j = 0; j < ndof; ++j) {
        double expected = 0;
        for (int i = begin[j]; i < end[j]; ++i) expected += R[j * kMaxElements + i] * F[i];
        CAPTURE(ndof);
        CAPTURE(n);
        CAPTURE(begin[j]);
        CAPTURE(end[j]);
        CHECK(tau[j] == doctest::Approx(expected).epsilon(1e-12).scale(1e-9));
      }
    }
}

TEST_CASE("a slack tendon engaging within a 1 ms step: the CE stops near where it takes up the load") {
  // teres major from rest: its tendon is slack, excitation 0.65 makes the CE shorten at about 1 m/s
  // until the 6 mm tendon engages ~20 ms later, stiffly (4 % strain at fmax).
  Arm ros2(das2(), Integrator::kRos2, 1e-3);
  Arm fine(das2(), Integrator::kRk4, 1e-3, 100);
  for (Arm* s : {&ros2, &fine}) armrt_test::set_group_excitation(*s, "termaj", 0.65);
  const int i = armrt_test::element_index(das2(), "termaj1");
  double worst_lce = 0, worst_q = 0;
  for (int k = 0; k < 80; ++k) {
    REQUIRE(ros2.step());
    REQUIRE(fine.step());
    worst_lce = std::max(worst_lce, std::fabs(ros2.data.x[kLce + i] - fine.data.x[kLce + i]));
    for (int j = 0; j < kDas2Dofs; ++j) worst_q = std::max(worst_q, std::fabs(ros2.data.x[kQ + j] - fine.data.x[kQ + j]));
  }
  MESSAGE("termaj1: max |lce - reference| " << worst_lce * 1e3 << " mm, joints " << worst_q * 180 / M_PI
          << " deg; element-steps limited " << ros2.data.limited_fibre_steps);
  CHECK(ros2.data.limited_fibre_steps > 0);
  CHECK(worst_lce < 1e-3);  // the unlimited step overshot by ~25 mm here
  CHECK(worst_q * 180 / M_PI < 0.05);
  // The tendon did engage: termaj1 carries force at the end.
  ros2.evaluate_outputs();
  CHECK(ros2.data.muscle_force[i] > 20.0);
}

TEST_CASE("ros2_adaptive: a rejected 2 ms step is redone from its start as two ROS2 steps of 1 ms") {
  Arm a(das2(), Integrator::kRos2Adaptive, 2e-3);
  armrt_test::set_group_excitation(a, "elbow_flexors", 1.0);
  armrt_test::set_group_excitation(a, "deltoid", 1.0);
  int halved_at = -1;
  for (int k = 0; k < 1000 && halved_at < 0; ++k) {
    auto before = std::make_unique<Data>(a.data);
    auto before_ws = std::make_unique<Ros2Workspace>(a.stepper.ros2);
    const std::int64_t h0 = a.data.halved_steps;
    REQUIRE_MESSAGE(a.step(), a.error_message());
    if (a.data.halved_steps == h0) continue;
    halved_at = k;
    // The same start state, two plain half steps: identical to the rejected-and-redone step.
    step_ros2(a.model, *before, *before_ws, 1e-3, false);
    step_ros2(a.model, *before, *before_ws, 1e-3, false);
    for (int s = 0; s < state_size(a.model); ++s) CHECK(before->x[s] == a.data.x[s]);
  }
  MESSAGE("first halved step at step " << halved_at << "; total halved " << a.data.halved_steps);
  CHECK(halved_at >= 0);
}

// A das3 arm moving its girdle and arm: n_steps ROS2 steps of h, the second stage's paths extrapolated
// (the default) or, with fresh_paths, evaluated at every step (the history cleared before each one).
std::unique_ptr<Arm> das3_run(double h, double duration, bool fresh_paths) {
  const ModelDef* def = find_model("das3");
  REQUIRE(def);
  auto sim = std::make_unique<Arm>(*def, Integrator::kRos2, h);
  for (const char* g : {"deltoid", "serratus_anterior", "elbow_flexors"}) armrt_test::set_group_excitation(*sim, g, 0.3);
  const int n = static_cast<int>(std::lround(duration / h));
  for (int k = 0; k < n; ++k) {
    if (fresh_paths) sim->stepper.ros2.path_history.h = 0;
    REQUIRE_MESSAGE(sim->step(), sim->error_message());
  }
  return sim;
}

// Whether the next ROS2 step of h continues the arm's path history.
bool continues_history(const Arm& a, double h) {
  return path_history_continues(a.model, a.stepper.ros2.path_history, a.data.x.data() + q_offset(a.model),
                                a.data.x.data() + qd_offset(a.model), h);
}

void restore_history(Arm& a, const double* anchor_q, int num_anchors, int anchor_spacing, int steps_since_anchor,
                     double h) {
  path_history_restore(a.model, a.stepper.ros2.path_history, a.data.x.data() + q_offset(a.model),
                       a.data.x.data() + qd_offset(a.model), anchor_q, num_anchors, anchor_spacing, steps_since_anchor,
                       h);
}

double max_q_difference(const Arm& a, const Arm& b) {
  double e = 0;
  for (int j = 0; j < a.model.num_dofs; ++j) e = std::max(e, std::fabs(a.data.x[j] - b.data.x[j]));
  return e;
}

TEST_CASE("das3: ROS2's extrapolated paths differ from evaluated ones by O(h^2) (4x per halving)") {
  // The extrapolation's errors in R and L are O(h^2) and O(h^3) (rosenbrock.cc), so over a fixed time the
  // trajectories with and without it part by O(h^2): ROS2 stays second order.
  const double hs[3] = {2e-3, 1e-3, 5e-4};
  double diff[3];
  for (int k = 0; k < 3; ++k) diff[k] = max_q_difference(*das3_run(hs[k], 0.1, false), *das3_run(hs[k], 0.1, true));
  MESSAGE("max |q| difference (rad) at h = 2, 1, 0.5 ms: " << diff[0] << " " << diff[1] << " " << diff[2]);
  CHECK(diff[0] > 1e-12);
  CHECK(diff[0] / diff[1] > 3.0);
  CHECK(diff[1] / diff[2] > 3.0);
  CHECK(diff[1] < 1e-4);  // 0.006 deg after 0.1 s of girdle and arm motion; ROS2's own error is ~1e-4 rad
}

TEST_CASE("ROS2 keeps the last block's ghost lanes zero (Model::element_runs reads them)") {
  // das2's 102 and das3's 138 elements leave 2 ghost lanes in their last block of eight.
  for (const char* name : {"das2", "das3"}) {
    CAPTURE(name);
    const ModelDef* def = find_model(name);
    REQUIRE(def);
    auto sim = std::make_unique<Arm>(*def, Integrator::kRos2, 1e-3);
    for (int g = 0; g < def->num_groups; ++g) armrt_test::set_group_excitation(*sim, def->groups[g].name, 0.3);
    const Model& m = sim->model;
    const Data& d = sim->data;
    const Ros2Workspace& ws = sim->stepper.ros2;
    const int n = m.num_elements, end = (n + 7) / 8 * 8;
    REQUIRE(end > n);
    for (int k = 0; k < 7; ++k) {  // both kinds of step, and a step after a reset
      REQUIRE(sim->step());
      if (k == 3) sim->reset(nullptr, nullptr, nullptr);
      for (int i = n; i < end; ++i) {
        CAPTURE(i);
        CHECK(ws.jac.series_stiffness[i] == 0.0);
        CHECK(ws.jac.muscle_length[i] == 0.0);
        CHECK(ws.path_history.anchor_muscle_length[i] == 0.0);
        for (int j = 0; j < m.num_dofs; ++j) {
          const int o = j * kMaxElements + i;
          CHECK(ws.jac.moment_arm[o] == 0.0);
          CHECK(ws.path_history.anchor_moment_arm[0][o] == 0.0);
          CHECK(ws.path_history.anchor_moment_arm[1][o] == 0.0);
          CHECK(ws.path_history.stage2_moment_arm[o] == 0.0);
        }
      }
    }
  }
}

TEST_CASE("a state restored with its ROS2 history continues bit for bit, one without it by one extrapolation's error") {
  // The paths are evaluated at steps 0, 1, then every kRos2PathPeriod-th: stopping after 1 step leaves one
  // anchor, after 50, 51, 52 each position within the period, so all restorations are covered.
  for (const int steps : {50, 51, 52, 1}) {
    CAPTURE(steps);
    auto a = das3_run(1e-3, steps * 1e-3, false);
    const PathHistory& ph = a->stepper.ros2.path_history;
    const int nq = a->model.num_dofs;
    REQUIRE(continues_history(*a, 1e-3));
    REQUIRE_FALSE(continues_history(*a, 5e-4));  // another step size starts afresh
    CHECK(ph.num_anchors == (steps >= 2 ? 2 : 1));
    CHECK(ph.steps_since_anchor == (steps >= 2 ? (steps - 2) % kRos2PathPeriod + 1 : 1));
    auto with = std::make_unique<Arm>(*a->model.def, Integrator::kRos2, 1e-3);
    auto without = std::make_unique<Arm>(*a->model.def, Integrator::kRos2, 1e-3);
    for (Arm* s : {with.get(), without.get()}) {
      s->data.x = a->data.x;
      s->data.excitation = a->data.excitation;
    }
    double anchors[2 * kMaxDofs];
    const double* newest = ph.anchor_q_new.data();
    if (ph.num_anchors == 2) std::copy(ph.anchor_q_old.begin(), ph.anchor_q_old.begin() + nq, anchors);
    std::copy(newest, newest + nq, anchors + (ph.num_anchors - 1) * nq);
    restore_history(*with, anchors, ph.num_anchors, ph.anchor_spacing, ph.steps_since_anchor,
                         ph.h);
    CHECK(continues_history(*with, 1e-3));
    CHECK_FALSE(continues_history(*without, 1e-3));
    for (int k = 0; k < 20; ++k) {
      REQUIRE(a->step());
      REQUIRE(with->step());
      REQUIRE(without->step());
    }
    for (int s = 0; s < state_size(a->model); ++s) CHECK(with->data.x[s] == a->data.x[s]);
    const double d = max_q_difference(*a, *without);
    MESSAGE("20 steps from a state without its history: max |q| difference " << d << " rad");
    CHECK(d > 0.0);
    CHECK(d < 1e-5);  // 0.0006 deg: the first steps of a fast activation onset are the worst
    // A state changed from outside is not the one the history ended at: the next step evaluates afresh.
    with->data.x[qd_offset(with->model)] += 1e-3;
    CHECK_FALSE(continues_history(*with, 1e-3));
  }
  // Counts that no run of steps leaves are refused by name.
  auto s = das3_run(1e-3, 0.002, false);
  double q2[2 * kMaxDofs] = {};
  CHECK_THROWS_WITH_AS(restore_history(*s, q2, 3, 1, 1, 1e-3), doctest::Contains("anchors"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(restore_history(*s, q2, 2, 0, 1, 1e-3), doctest::Contains("spacing"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(restore_history(*s, q2, 1, 1, 1, 1e-3), doctest::Contains("spacing"),
                       std::invalid_argument);
  if (kRos2PathPeriod > 2)  // anchors are 1 or kRos2PathPeriod steps apart, nothing between
    CHECK_THROWS_WITH_AS(restore_history(*s, q2, 2, 2, 1, 1e-3), doctest::Contains("spacing"),
                         std::invalid_argument);
  CHECK_THROWS_WITH_AS(restore_history(*s, q2, 1, 0, 2, 1e-3), doctest::Contains("since"),
                       std::invalid_argument);  // one anchor: only right after a run's first step
  CHECK_THROWS_WITH_AS(restore_history(*s, q2, 1, 0, kRos2PathPeriod + 1, 1e-3),
                       doctest::Contains("since"), std::invalid_argument);
}

}  // TEST_SUITE
