// static_optimization.cc against computations of its own: moments by the element-major path function and the
// rigid-tendon force law, optimality by the KKT conditions with multipliers fitted to the free elements, the GH
// bound by gh_stability, the polygon by random directions, infeasibility reported with residuals.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "armrt/arm.h"
#include "armrt/engine.h"
#include "armrt/static_optimization.h"
#include "static_optimization_solver.h"
#include "test_util.h"

using namespace armrt;

namespace {

// A random pose inside das2's ranges (the middle 60 %), a random velocity and acceleration.
void random_state(const ModelDef& def, std::mt19937& rng, double* q, double* qd, double* qdd) {
  std::uniform_real_distribution<double> unit(0.2, 0.8), sym(-1.0, 1.0);
  for (int j = 0; j < def.num_dofs; ++j) {
    q[j] = def.dofs[j].range_min + unit(rng) * (def.dofs[j].range_max - def.dofs[j].range_min);
    qd[j] = 0.5 * sym(rng);
    qdd[j] = 2.0 * sym(rng);
  }
}

// Moments of activations a by the element-major paths and the force law, minus the inverse dynamics'.
double moment_residual(const Arm& arm, const double* q, const double* qd, const double* qdd, const double* f,
                       const double* a) {
  const Model& m = arm.model;
  const int n = m.num_elements, nq = m.num_dofs;
  std::vector<double> L(n), R(n * nq);
  muscle_paths_by_element(*m.def, q, L.data(), R.data());
  InverseDynamics id;
  const double zero[3] = {};
  inverse_dynamics(m, arm.data.settings.gravity.data(), q, qd, qdd, f, zero, &id);
  double worst = 0;
  for (int j = 0; j < nq; ++j) {
    double tau = 0;
    for (int i = 0; i < n; ++i) {
      double v = 0;
      for (int k = 0; k < nq; ++k) v -= R[i * nq + k] * qd[k];
      const RigidTendonForce F = muscle_rigid_tendon_force(data_element(m, arm.data, i), m.fibre_damping, L[i], v);
      tau += R[i * nq + j] * (F.force_per_activation * a[i] + F.passive_force);
    }
    worst = std::max(worst, std::abs(tau - id.tau_muscle[j]));
  }
  return worst;
}

// KKT of min sum a^2, A a = b, 0 <= a <= amax (no GH rows): 2 a_i = (A^T lambda)_i on free elements, <= 0 at
// 0, >= 2 amax at the cap. lambda fitted by least squares to the free elements; the largest violation (per unit
// of the largest 2 a_i) returned.
double kkt_violation(const Arm& arm, const double* q, const double* qd, const double* a) {
  const Model& m = arm.model;
  const int n = m.num_elements, nq = m.num_dofs;
  std::vector<double> L(n), R(n * nq);
  muscle_paths_by_element(*m.def, q, L.data(), R.data());
  Eigen::MatrixXd At(n, nq);  // A^T: row i = R_i Fa_i
  for (int i = 0; i < n; ++i) {
    double v = 0;
    for (int k = 0; k < nq; ++k) v -= R[i * nq + k] * qd[k];
    const double Fa = muscle_rigid_tendon_force(data_element(m, arm.data, i), m.fibre_damping, L[i], v).force_per_activation;
    for (int j = 0; j < nq; ++j) At(i, j) = R[i * nq + j] * Fa;
  }
  const double* amax = arm.data.settings.max_activation.data();
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (a[i] > 1e-6 && a[i] < amax[i] - 1e-6) free.push_back(i);
  Eigen::MatrixXd Af(free.size(), nq);
  Eigen::VectorXd rhs(free.size());
  for (std::size_t k = 0; k < free.size(); ++k) {
    Af.row(k) = At.row(free[k]);
    rhs(k) = 2.0 * a[free[k]];
  }
  const Eigen::VectorXd lambda = Af.colPivHouseholderQr().solve(rhs);
  const Eigen::VectorXd g = At * lambda;
  double scale = 1e-12, worst = 0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, 2.0 * a[i]);
  for (int i = 0; i < n; ++i) {
    double viol;
    if (a[i] <= 1e-6) viol = std::max(0.0, g(i));
    else if (a[i] >= amax[i] - 1e-6) viol = std::max(0.0, 2.0 * amax[i] - g(i));
    else viol = std::abs(g(i) - 2.0 * a[i]);
    worst = std::max(worst, viol);
  }
  return worst / scale;
}

}  // namespace

TEST_CASE("static optimisation (rigid tendon): das2 at random states, moments balanced and the KKT conditions held") {
  Arm arm(armrt_test::das2(), Integrator::kRos2, 1e-3);
  StaticOptimizationWorkspace w;
  static_optimization_setup(arm.model, StaticOptimizationOptions{}, w);
  std::mt19937 rng(3);
  const double hand[3] = {0, -9.81, 0}, zero[3] = {};
  double q[kMaxDofs], qd[kMaxDofs], qdd[kMaxDofs], a[kMaxElements];
  StaticOptimizationReport rep;
  int solved = 0;
  // The runner's options (no ProxQP fallback): a request the default path solves is never certified infeasible.
  StaticOptimizationOptions no_fallback;
  no_fallback.proxqp_fallback = false;
  StaticOptimizationWorkspace wn;
  static_optimization_setup(arm.model, no_fallback, wn);
  double an[kMaxElements];
  StaticOptimizationReport rep_n;
  for (int trial = 0; trial < 12; ++trial) {
    random_state(*arm.model.def, rng, q, qd, qdd);
    static_optimization_rigid(arm.model, arm.data, w, q, qd, qdd, hand, zero, a, &rep);
    static_optimization_rigid(arm.model, arm.data, wn, q, qd, qdd, hand, zero, an, &rep_n);
    if (!rep.feasible) continue;
    CHECK(rep_n.status != StaticOptimizationStatus::kInfeasible);
    ++solved;
    CHECK(rep.residual_max < 1e-6);
    CHECK(moment_residual(arm, q, qd, qdd, hand, a) < 1e-6);
    CHECK(kkt_violation(arm, q, qd, a) < 1e-5);
    for (int i = 0; i < arm.model.num_elements; ++i) {
      CHECK(a[i] >= 0.0);
      CHECK(a[i] <= arm.data.settings.max_activation[i]);
    }
  }
  CHECK(solved >= 10);  // a random state may need more than the muscles have; most do not
}

TEST_CASE("static optimisation (rigid tendon): GHstab <= the bound, the bound binding where the free optimum exceeds it") {
  Arm arm(armrt_test::das2(), Integrator::kRos2, 1e-3);
  StaticOptimizationWorkspace free_w, bound_w;
  static_optimization_setup(arm.model, StaticOptimizationOptions{}, free_w);
  StaticOptimizationOptions o;
  o.gh_stab_max = 0.05;
  static_optimization_setup(arm.model, o, bound_w);
  std::mt19937 rng(5);
  const double hand[3] = {0, -20.0, 0}, zero[3] = {};
  double q[kMaxDofs], qd[kMaxDofs], qdd[kMaxDofs], a[kMaxElements], af[kMaxElements];
  StaticOptimizationReport rep, rep_free;
  int binding = 0;
  for (int trial = 0; trial < 10; ++trial) {
    random_state(*arm.model.def, rng, q, qd, qdd);
    static_optimization_rigid(arm.model, arm.data, free_w, q, qd, qdd, hand, zero, af, &rep_free);
    static_optimization_rigid(arm.model, arm.data, bound_w, q, qd, qdd, hand, zero, a, &rep);
    if (!rep.feasible) {
      CHECK(rep.residual_max > 1e-6);  // reported with its residuals
      continue;
    }
    CHECK(rep.gh_stab <= 0.05 + 1e-6);
    CHECK(moment_residual(arm, q, qd, qdd, hand, a) < 1e-6);
    if (rep_free.feasible && rep_free.gh_stab > 0.05) {
      ++binding;
      CHECK(rep.gh_bound_active);
      CHECK(rep.gh_stab > 0.05 * 0.9);
    }
  }
  CHECK(binding >= 1);
}

TEST_CASE("gh_polygon: every force satisfying its rows has GHstab <= the bound, within and beyond convexity") {
  const ModelDef& def = armrt_test::das2();
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0.0, 1.0);
  for (double bound : {0.3, 1.0, 3.0}) {
    double rows[(kGhPolygonSides + 1) * 3];
    gh_polygon(def.rim_half_angle_major, def.rim_half_angle_minor, bound, kGhPolygonSides, rows);
    int inside = 0;
    for (int k = 0; k < 20000; ++k) {
      const double local[3] = {std::abs(nd(rng)), nd(rng), nd(rng)};
      bool ok = true;
      for (int r = 0; r < kGhPolygonSides && ok; ++r)
        ok = rows[3 * r] * local[0] + rows[3 * r + 1] * local[1] + rows[3 * r + 2] * local[2] <= 0;
      if (!ok) continue;
      ++inside;
      double f[3];
      for (int c = 0; c < 3; ++c)
        f[c] = def.glenoid_normal[c] * local[0] + def.glenoid_major_axis[c] * local[1] + def.glenoid_minor_axis[c] * local[2];
      CHECK(gh_stability(def, f).stab <= bound * (1 + 1e-9));
    }
    CHECK(inside > 100);
  }
  double rows[75];
  CHECK_THROWS_AS(gh_polygon(def.rim_half_angle_major, def.rim_half_angle_minor, 0.0, 24, rows), std::invalid_argument);
  // Below kMinGhStabMax (1e-6): refused; at it, rows.
  CHECK_THROWS_AS(gh_polygon(def.rim_half_angle_major, def.rim_half_angle_minor, 9.9e-7, 24, rows), std::invalid_argument);
  CHECK_NOTHROW(gh_polygon(def.rim_half_angle_major, def.rim_half_angle_minor, kMinGhStabMax, 24, rows));
  CHECK_THROWS_AS(gh_polygon(def.rim_half_angle_major, def.rim_half_angle_minor, 10.0, 24, rows), std::invalid_argument);
}

TEST_CASE("static optimisation (rigid tendon): infeasible requests reported with residuals, never a silent answer") {
  Arm arm(armrt_test::das2(), Integrator::kRos2, 1e-3);
  StaticOptimizationWorkspace w;
  static_optimization_setup(arm.model, StaticOptimizationOptions{}, w);
  double q[kMaxDofs], qd[kMaxDofs] = {}, qdd[kMaxDofs] = {}, a[kMaxElements];
  for (int j = 0; j < arm.model.num_dofs; ++j) q[j] = arm.model.def->dofs[j].rest;
  const double heavy[3] = {0, -5000.0, 0}, zero[3] = {}, light[3] = {0, -9.81, 0};
  StaticOptimizationReport rep;
  static_optimization_rigid(arm.model, arm.data, w, q, qd, qdd, heavy, zero, a, &rep);
  CHECK_FALSE(rep.feasible);
  CHECK(rep.status == StaticOptimizationStatus::kInfeasible);
  CHECK(rep.residual_max > 1.0);
  CHECK(rep.at_upper_bound > 0);
  // The residuals are those of the activations returned (the closest solution's), not of some other iterate.
  CHECK(std::abs(moment_residual(arm, q, qd, qdd, heavy, a) - rep.residual_max) < 1e-6 * std::max(1.0, rep.residual_max));
  // The next, feasible, request is solved (the failed iterate is not used as a warm start).
  static_optimization_rigid(arm.model, arm.data, w, q, qd, qdd, light, zero, a, &rep);
  CHECK(rep.feasible);
  CHECK(moment_residual(arm, q, qd, qdd, light, a) < 1e-6);
  // Without the ProxQP fallback (the runner's choice): reported at once, never as a solution; infeasible, by the
  // Newton method's weak-duality certificate, within a few of its 50 iterations (all 50 before 2026-12-07).
  StaticOptimizationOptions no_fallback;
  no_fallback.proxqp_fallback = false;
  StaticOptimizationWorkspace wn;
  static_optimization_setup(arm.model, no_fallback, wn);
  static_optimization_rigid(arm.model, arm.data, wn, q, qd, qdd, heavy, zero, a, &rep);
  CHECK_FALSE(rep.feasible);
  CHECK(rep.status == StaticOptimizationStatus::kInfeasible);
  MESSAGE("Newton iterations to the infeasibility certificate: " << rep.newton_iterations);
  CHECK(rep.newton_iterations < 10);
  CHECK(rep.qps == 0);
  static_optimization_rigid(arm.model, arm.data, wn, q, qd, qdd, light, zero, a, &rep);
  CHECK(rep.feasible);
  CHECK(moment_residual(arm, q, qd, qdd, light, a) < 1e-6);
  // Bad options are refused.
  StaticOptimizationOptions bad;
  bad.weights.assign(3, 1.0);
  CHECK_THROWS_AS(static_optimization_setup(arm.model, bad, w), std::invalid_argument);
  bad.weights.assign(arm.model.num_elements, 1.0);
  bad.weights[4] = 0.0;
  CHECK_THROWS_AS(static_optimization_setup(arm.model, bad, w), std::invalid_argument);
  bad.weights.clear();
  bad.gh_stab_max = -1;
  CHECK_THROWS_AS(static_optimization_setup(arm.model, bad, w), std::invalid_argument);
}

TEST_CASE("static optimisation (elastic tendon): the engine's element at the returned CE lengths supplies the moments") {
  // Independent of the optimiser's linearisation: muscle_element (forward()'s element) at (L, lce, a) must give the
  // forces whose R^T F is the inverse dynamics' moments and fibre velocities equal to the path's dL/dt.
  Arm arm(armrt_test::das2(), Integrator::kRos2, 1e-3);
  const Model& m = arm.model;
  const int n = m.num_elements, nq = m.num_dofs;
  for (double gh : {0.0, 0.3}) {
    CAPTURE(gh);
    StaticOptimizationOptions o;
    o.gh_stab_max = gh;
    StaticOptimizationWorkspace w;
    static_optimization_setup(m, o, w);
    std::mt19937 rng(9);
    const double hand[3] = {0, -9.81, 0}, zero[3] = {};
    double q[kMaxDofs], qd[kMaxDofs], qdd[kMaxDofs], a[kMaxElements];
    StaticOptimizationReport rep;
    int solved = 0;
    for (int trial = 0; trial < 6; ++trial) {
      random_state(*m.def, rng, q, qd, qdd);
      if (trial < 2) std::fill(qd, qd + nq, 0.0);  // static equilibrium: no approximation in the velocity
      static_optimization_elastic(m, arm.data, w, q, qd, qdd, hand, zero, a, &rep);
      if (!rep.feasible) {
        CHECK(rep.status == StaticOptimizationStatus::kNotConverged);
        continue;
      }
      ++solved;
      std::vector<double> L(n), R(n * nq);
      muscle_paths_by_element(*m.def, q, L.data(), R.data());
      InverseDynamics id;
      inverse_dynamics(m, arm.data.settings.gravity.data(), q, qd, qdd, hand, zero, &id);
      std::vector<double> tau(nq, 0.0);
      double worst_v = 0;
      for (int i = 0; i < n; ++i) {
        CHECK(a[i] >= 0.0);
        CHECK(a[i] <= arm.data.settings.max_activation[i]);
        const MuscleOut out = muscle_element(data_element(m, arm.data, i), m.fibre_damping, L[i], rep.lce[i], a[i]);
        double v = 0;
        for (int j = 0; j < nq; ++j) v -= R[i * nq + j] * qd[j];
        worst_v = std::max(worst_v, std::abs(out.fibre_velocity - v));
        for (int j = 0; j < nq; ++j) tau[j] += R[i * nq + j] * out.force;
      }
      CHECK(worst_v < 1e-8);
      for (int j = 0; j < nq; ++j) CHECK(std::abs(tau[j] - id.tau_muscle[j]) < 1e-6);
      if (gh > 0) CHECK(rep.gh_stab <= gh + 1e-6);
    }
    CHECK(solved >= 4);
  }
}

TEST_CASE("static optimisation (rigid tendon by ProxQP): proximal parameters a cold restart leaves are not carried on") {
  // tests/test_static_optimization.py's motion (bench.static_optimization's: q0 + 0.3 (1 - cos(pi t / T)) / 2 rad,
  // alternating signs, 400 frames of 1 ms from (20, 40, 0, 60, 60) deg) with GHstab <= 0.1 and ProxQP alone. At frame
  // 150 the QP is put into the state ProxQP's cold restart ends a solve in (mu_eq = mu_in = 1/1.1, what its warm
  // start carries): the next solves must start from the defaults again, as static_optimization.cc's run() makes them.
  Arm arm(armrt_test::das2(), Integrator::kRos2, 1e-3);
  StaticOptimizationOptions o;
  o.gh_stab_max = 0.1;
  o.dual_newton = false;
  StaticOptimizationWorkspace w;
  static_optimization_setup(arm.model, o, w);
  const int nq = arm.model.num_dofs, frames = 400;
  const double q0_deg[5] = {20, 40, 0, 60, 60};
  const double T = frames * 1e-3, omega = M_PI / T, amplitude = 0.3;
  const double hand[3] = {0, -9.81, 0}, zero[3] = {};
  double q[kMaxDofs], qd[kMaxDofs], qdd[kMaxDofs], a[kMaxElements];
  StaticOptimizationReport rep;
  auto solve_frame = [&](int k) {
    const double t = k * 1e-3;
    for (int j = 0; j < nq; ++j) {
      const double sign = j % 2 == 0 ? 1.0 : -1.0;
      q[j] = q0_deg[j] * M_PI / 180.0 + sign * 0.5 * amplitude * (1 - std::cos(omega * t));
      qd[j] = sign * 0.5 * amplitude * omega * std::sin(omega * t);
      qdd[j] = sign * 0.5 * amplitude * omega * omega * std::cos(omega * t);
    }
    static_optimization_rigid(arm.model, arm.data, w, q, qd, qdd, hand, zero, a, &rep);
    return rep.qp_iterations;
  };
  for (int k = 0; k < 150; ++k) solve_frame(k);
  auto& qp = w.solver->qp;
  const double default_mu_eq = qp.settings.default_mu_eq, default_mu_in = qp.settings.default_mu_in;
  // update() with proximal parameters also makes them the defaults: the defaults are put back after.
  qp.update(proxsuite::nullopt, proxsuite::nullopt, proxsuite::nullopt, proxsuite::nullopt, proxsuite::nullopt,
            proxsuite::nullopt, proxsuite::nullopt, proxsuite::nullopt, proxsuite::nullopt, false, proxsuite::nullopt,
            qp.settings.cold_reset_mu_eq, qp.settings.cold_reset_mu_in);
  qp.settings.default_mu_eq = default_mu_eq;
  qp.settings.default_mu_in = default_mu_in;
  REQUIRE(qp.results.info.mu_in == qp.settings.cold_reset_mu_in);
  std::vector<int> iterations;
  for (int k = 150; k < 200; ++k) iterations.push_back(solve_frame(k));
  std::nth_element(iterations.begin(), iterations.begin() + iterations.size() / 2, iterations.end());
  const int median = iterations[iterations.size() / 2];
  MESSAGE("median ProxQP iterations a frame after the cold-restart state: " << median);
  CHECK(median <= 10);
}
