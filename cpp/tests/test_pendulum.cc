// The engine on a second, tiny generated model (tests/data/pendulum2.json): a two-DOF pendulum whose
// answers are known in closed form. The forearm (ulna, radius, hand) hangs from the elbow pin ELx; the
// radius and hand turn about the forearm's long axis (PSy) and are symmetric about it, so
//   M = diag(I_el, I_ps),  I_el = sum_b (Izz_b + m_b d_b^2),  I_ps = sum (Iyy of radius and hand),
//   gravity torque on ELx = -g sum_b m_b d_b sin(q_el),  none on PSy,
// and every muscle element has a constant moment arm (linear length polynomial).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include "armrt/engine.h"
#include "armrt/arm.h"
#include "pendulum2.h"

using namespace armrt;

namespace {

const ModelDef& pendulum() { return generated::pendulum2::model_def(); }

constexpr double kG = 9.80665;
// From the model file: distances of the ulna, radius and hand COMs below the elbow (m), masses (kg).
constexpr double kMassMoment = 1.0 * 0.12 + 0.5 * 0.12 + 0.4 * (0.25 + 0.06);              // sum m d, kg m
constexpr double kInertiaEl = (0.006 + 1.0 * 0.12 * 0.12) + (0.003 + 0.5 * 0.12 * 0.12) +
                              (0.001 + 0.4 * 0.31 * 0.31);                                 // kg m^2
constexpr double kInertiaPs = 0.0002 + 0.0003;                                              // kg m^2
constexpr double kSpring = 1.0;        // passive_joint.stiffness_inside, N m/rad (rest 0)
constexpr double kHandDistance = 0.25 + 0.08;  // elbow to hand point, m
const double kMomentArm[5] = {0.03, 0.02, -0.025, 0.01, -0.01};  // m: -dL/dq of each element's polynomial

// The same model with the muscles detached (lengths held at their rest values, zero moment arms): a
// pure pendulum.
void detached_paths(const double* q, double* L, double* R) {
  (void)q;
  const double rest_length[5] = {0.26, 0.25, 0.24, 0.08, 0.08};  // the polynomials' constant terms, m
  for (int i = 0; i < 5; ++i) {
    L[i] = rest_length[i];
    R[i] = R[kMaxElements + i] = 0.0;  // by DOF
  }
}
void detached_lengths(const double* q, double* L) {
  double R[2 * kMaxElements];
  detached_paths(q, L, R);
}
const ModelDef& detached() {
  static const ModelDef def = [] {
    ModelDef d = pendulum();
    d.muscle_paths = &detached_paths;
    d.muscle_lengths = &detached_lengths;
    return d;
  }();
  return def;
}

double energy(const Arm& s) {
  const double* x = s.data.x.data();
  const double q0 = x[0], q1 = x[1], w0 = x[2], w1 = x[3];
  return 0.5 * kInertiaEl * w0 * w0 + 0.5 * kInertiaPs * w1 * w1 + kG * kMassMoment * (1.0 - std::cos(q0)) +
         0.5 * kSpring * (q0 * q0 + q1 * q1);
}

}  // namespace

TEST_SUITE("pendulum model") {

TEST_CASE("sizes and state layout come from the model") {
  const ModelDef& def = pendulum();
  CHECK(def.num_dofs == 2);
  CHECK(def.num_elements == 5);
  Model m;
  model_init(m, def);
  CHECK(m.num_dofs == 2);
  CHECK(qd_offset(m) == 2);
  CHECK(lce_offset(m) == 4);
  CHECK(act_offset(m) == 9);
  CHECK(state_size(m) == 14);
  char buf[64];
  CHECK(std::string(state_name(m, qd_offset(m) + 1, buf, sizeof buf)) == "qdot[PSy]");
  CHECK(std::string(state_name(m, lce_offset(m) + 2, buf, sizeof buf)) == "lce[extensor1]");
  CHECK(std::string(state_name(m, act_offset(m) + 4, buf, sizeof buf)) == "activation[supinator1]");
}

TEST_CASE("mass matrix, gravity and moment arms match the closed form") {
  const ModelDef& def = pendulum();
  for (double q0 : {-1.0, 0.0, 0.4, 1.7})
    for (double q1 : {-1.0, 0.3}) {
      const double q[2] = {q0, q1}, qd[2] = {0.7, -2.0};
      double M[4], b[2];
      def.dynamics(q, qd, def.gravity_base, M, b);
      CHECK(M[0] == doctest::Approx(kInertiaEl).epsilon(1e-12));
      CHECK(M[3] == doctest::Approx(kInertiaPs).epsilon(1e-12));
      CHECK(std::fabs(M[1]) < 1e-14);
      CHECK(std::fabs(M[2]) < 1e-14);
      CHECK(std::fabs(b[0] + kG * kMassMoment * std::sin(q0)) < 1e-12);
      CHECK(std::fabs(b[1]) < 1e-12);
      double L[5], R[2 * kMaxElements];
      def.muscle_paths(q, L, R);
      for (int i = 0; i < 5; ++i) {
        const int j = i < 3 ? 0 : 1;
        CHECK(R[j * kMaxElements + i] == doctest::Approx(kMomentArm[i]).epsilon(1e-14));  // by DOF
        CHECK(R[(1 - j) * kMaxElements + i] == 0.0);
      }
    }
}

TEST_CASE("small-oscillation period: 2 pi sqrt(I / (g sum m d + k))") {
  const double period = 2 * M_PI * std::sqrt(kInertiaEl / (kG * kMassMoment + kSpring));
  for (Integrator integ : {Integrator::kRk4, Integrator::kRos2}) {
    CAPTURE(integrator_name(integ));
    const double dt = integ == Integrator::kRk4 ? 1e-4 : 1e-3;
    Arm s(detached(), integ, dt);
    const double q0[2] = {0.01, 0.0};
    s.reset(q0, nullptr, nullptr);
    // Times of downward zero crossings of q_el, linearly interpolated; the mean spacing is the period.
    double prev = s.data.x[0], first = -1, last = -1;
    int crossings = 0;
    while (s.data.time < 10 * period) {
      const double t0 = s.data.time;
      REQUIRE(s.step());
      const double now = s.data.x[0];
      if (prev > 0 && now <= 0) {
        const double tc = t0 + dt * prev / (prev - now);
        if (first < 0) first = tc;
        last = tc;
        ++crossings;
      }
      prev = now;
    }
    REQUIRE(crossings >= 9);
    const double measured = (last - first) / (crossings - 1);
    CHECK(measured == doctest::Approx(period).epsilon(integ == Integrator::kRk4 ? 1e-5 : 1e-3));
  }
}

TEST_CASE("energy is conserved without damping or muscles (large swing, both DOFs)") {
  Arm s(detached(), Integrator::kRk4, 1e-4);
  const double q0[2] = {1.0, 0.0}, qd0[2] = {0.0, 1.0};
  s.reset(q0, qd0, nullptr);
  const double e0 = energy(s);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    REQUIRE(s.step());
    worst = std::max(worst, std::fabs(energy(s) - e0));
  }
  CHECK(worst / e0 < 1e-9);
  // And the forces it reports are the closed-form ones at the end state.
  s.evaluate_outputs();
  CHECK(s.data.passive_torque[0] == doctest::Approx(-kSpring * s.data.x[0]).epsilon(1e-12));
}

TEST_CASE("static equilibrium: moment arm x force balances gravity and the joint spring") {
  Arm s(pendulum(), Integrator::kRos2, 1e-3);
  const Model& m = s.model;
  double act[5] = {0.3, 0.3, 0.02, 0.05, 0.05};
  s.reset(nullptr, nullptr, act);
  for (int i = 0; i < 5; ++i) s.data.excitation[i] = act[i];
  for (int k = 0; k < 5000; ++k) REQUIRE(s.step());
  s.evaluate_outputs();
  const Data& d = s.data;
  CHECK(std::fabs(d.x[qd_offset(m)]) < 1e-6);
  CHECK(std::fabs(d.x[qd_offset(m) + 1]) < 1e-6);
  const double q_el = d.x[0];
  CHECK(q_el > 0.1);  // the flexors lifted the forearm
  double tau_el = 0, tau_ps = 0;
  for (int i = 0; i < 3; ++i) tau_el += kMomentArm[i] * d.muscle_force[i];
  for (int i = 3; i < 5; ++i) tau_ps += kMomentArm[i] * d.muscle_force[i];
  CHECK(d.muscle_torque[0] == doctest::Approx(tau_el).epsilon(1e-12));
  CHECK(std::fabs(d.muscle_torque[1] - tau_ps) < 1e-12);
  // sum r F = g sum m d sin q + k q at rest.
  CHECK(tau_el == doctest::Approx(kG * kMassMoment * std::sin(q_el) + kSpring * q_el).epsilon(1e-6));
  CHECK(tau_ps == doctest::Approx(kSpring * d.x[1]).epsilon(1e-6).scale(1e-6));
  // At rest the GH reaction is the arm's weight (no muscle crosses GH).
  double mass = 2.0 + 1.0 + 0.5 + 0.4;
  CHECK(d.gh_force[1] == doctest::Approx(-mass * kG).epsilon(1e-6));
}

TEST_CASE("a hand force enters as J^T F") {
  Arm s(pendulum(), Integrator::kRos2, 1e-3);
  const double q[2] = {0.6, 0.4};
  s.reset(q, nullptr, nullptr);
  s.data.hand_force = {0.0, -10.0, 0.0};
  s.evaluate_outputs();
  CHECK(s.data.external_torque[0] == doctest::Approx(-10.0 * kHandDistance * std::sin(0.6)).epsilon(1e-12));
  CHECK(std::fabs(s.data.external_torque[1]) < 1e-12);
  CHECK(s.data.hand_position[0] == doctest::Approx(kHandDistance * std::sin(0.6)).epsilon(1e-12));
  CHECK(s.data.hand_position[1] == doctest::Approx(-0.3 - kHandDistance * std::cos(0.6)).epsilon(1e-12));
}

TEST_CASE("applied moments: M qdd = tau + a, and the moment that cancels gravity and the spring holds any pose") {
  // Detached muscles: a pure pendulum, M = diag(I_el, I_ps). From rest at q = 0 (no gravity or spring moment),
  // applied moments a give qdd = M^-1 a exactly.
  Arm s(detached(), Integrator::kRos2, 1e-3);
  s.reset(nullptr, nullptr, nullptr);
  s.data.applied_moment[0] = 0.8, s.data.applied_moment[1] = -0.05;
  s.evaluate_outputs();
  CHECK(s.data.qddot[0] == doctest::Approx(0.8 / kInertiaEl).epsilon(1e-12));
  CHECK(s.data.qddot[1] == doctest::Approx(-0.05 / kInertiaPs).epsilon(1e-12));
  CHECK(s.data.external_torque[0] == 0.0);  // not a hand load
  // At q0 = (0.7, -0.4) the moments g sum m d sin q_el + k q_el and k q_ps hold the pendulum still, in every
  // integrator (CVODE restarts at the changed input).
  const double q0[2] = {0.7, -0.4};
  for (Integrator integ : {Integrator::kRos2, Integrator::kRk4, Integrator::kEuler, Integrator::kCvode}) {
    CAPTURE(integrator_name(integ));
    Arm a(detached(), integ, 1e-3);
    a.reset(q0, nullptr, nullptr);
    a.data.applied_moment[0] = kG * kMassMoment * std::sin(q0[0]) + kSpring * q0[0];
    a.data.applied_moment[1] = kSpring * q0[1];
    for (int k = 0; k < 500; ++k) REQUIRE(a.step());
    CHECK(std::fabs(a.data.x[0] - q0[0]) < 1e-9);
    CHECK(std::fabs(a.data.x[1] - q0[1]) < 1e-9);
    // Half the moment: the elbow falls (the moment is held, not used once).
    a.data.applied_moment[0] *= 0.5;
    for (int k = 0; k < 100; ++k) REQUIRE(a.step());
    CHECK(a.data.x[0] < q0[0] - 1e-3);
  }
}

TEST_CASE("every integrator runs the small model (CVODE as the reference for ROS2 and RK4)") {
  double act[5] = {0.2, 0.2, 0.1, 0.3, 0.0};
  auto run = [&](Integrator integ, double dt) {
    auto s = std::make_unique<Arm>(pendulum(), integ, dt);
    for (int i = 0; i < 5; ++i) s->data.excitation[i] = act[i];
    const long steps = std::lround(1.0 / dt);  // 1 s
    for (long k = 0; k < steps; ++k) REQUIRE(s->step());
    return std::make_pair(s->data.x[0], s->data.x[1]);
  };
  const auto ref = run(Integrator::kCvode, 1e-3);
  CHECK(ref.first > 0.1);
  for (auto [integ, dt] : {std::pair{Integrator::kRos2, 1e-3}, {Integrator::kRos2Adaptive, 2e-3},
                           {Integrator::kRk4, 1e-4}, {Integrator::kEuler, 2e-5}}) {
    CAPTURE(integrator_name(integ));
    const auto got = run(integ, dt);
    CHECK(std::fabs(got.first - ref.first) < 2e-3);
    CHECK(std::fabs(got.second - ref.second) < 2e-3);
  }
}

}  // TEST_SUITE
