// Divergence reporting (integrate.cc: check_state, state_name; Arm::error_message).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "armrt/engine.h"
#include "armrt/arm.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::kDas2Dofs, armrt_test::kQ, armrt_test::kQd, armrt_test::kLce;

TEST_SUITE("divergence") {

TEST_CASE("NaN in the state: kNonFinite with the index, message names the state and the time") {
  Arm sim(armrt_test::das2(), Integrator::kEuler, 1e-4);
  for (int k = 0; k < 10; ++k) REQUIRE(sim.step());
  // NaN elbow angle: with Euler only q[ELx] itself is non-finite after one step (the other angles
  // advance with the old, finite velocities), so the first bad index is that of q[ELx].
  sim.data.x[kQ + 3] = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(sim.step());
  CHECK(sim.data.status == Status::kNonFinite);
  CHECK(sim.data.bad_index == kQ + 3);
  CHECK(sim.data.bad_time == doctest::Approx(11e-4));
  const std::string msg = sim.error_message();
  INFO(msg);
  CHECK(msg.find("q[ELx]") != std::string::npos);
  CHECK(msg.find("non-finite") != std::string::npos);
  CHECK(msg.find("0.0011") != std::string::npos);
  // The status is sticky: further steps refuse to run.
  CHECK_FALSE(sim.step());
  CHECK(sim.data.time == doctest::Approx(11e-4));
  // reset() clears it.
  sim.reset(nullptr, nullptr, nullptr);
  CHECK(sim.data.status == Status::kOk);
  CHECK(sim.step());
}

TEST_CASE("NaN activation: the bad index names the element") {
  Arm sim(armrt_test::das2(), Integrator::kEuler, 1e-4);
  const int i = armrt_test::element_index(*sim.model.def, "bicl");
  REQUIRE(i >= 0);
  sim.data.x[act_offset(sim.model) + i] = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(sim.step());
  CHECK(sim.data.status == Status::kNonFinite);
  // The NaN activation makes the CE velocity NaN; lce comes before activation in the state.
  CHECK(sim.data.bad_index == kLce + i);
  CHECK(sim.error_message().find("lce[bicl]") != std::string::npos);
}

TEST_CASE("huge joint velocity: kTooFast naming qdot[...] and the time") {
  for (Integrator integ : {Integrator::kEuler, Integrator::kRk4}) {
    CAPTURE(integrator_name(integ));
    Arm sim(armrt_test::das2(), integ, 1e-4);
    sim.data.x[kQd + 3] = 5.0 * sim.data.settings.max_joint_speed;
    CHECK_FALSE(sim.step());
    CHECK(sim.data.status == Status::kTooFast);
    REQUIRE(sim.data.bad_index >= kQd);
    REQUIRE(sim.data.bad_index < kQd + kDas2Dofs);
    CHECK(std::fabs(sim.data.x[sim.data.bad_index]) > sim.data.settings.max_joint_speed);
    const std::string msg = sim.error_message();
    INFO(msg);
    CHECK(msg.find("qdot[" + std::string(sim.model.def->dofs[sim.data.bad_index - kQd].name) + "]") !=
          std::string::npos);
    CHECK(msg.find("t = 0.0001") != std::string::npos);
    CHECK(msg.find("rad/s") != std::string::npos);
  }
}

TEST_CASE("elbow velocity beyond the bound: qdot[ELx]") {
  Arm sim(armrt_test::das2(), Integrator::kEuler, 1e-5);
  sim.data.x[kQd + 3] = 1.5 * sim.data.settings.max_joint_speed;
  CHECK_FALSE(sim.step());
  CHECK(sim.data.status == Status::kTooFast);
  CHECK(sim.data.bad_index == kQd + 3);
  CHECK(sim.error_message().find("qdot[ELx]") != std::string::npos);
}

TEST_CASE("domain check: a CE length, activation or joint angle out of its physical range stops the step") {
  struct Case {
    const char* what;
    int index;
    double value;
    const char* expect;
  };
  Model m;
  model_init(m, armrt_test::das2());
  const int i = armrt_test::element_index(*m.def, "supinator2");
  REQUIRE(i >= 0);
  const ElementConstants& e = m.element[i];
  const DofParams& psy = m.def->dofs[4];
  const Case cases[] = {
      {"lce below its geometric minimum", kLce + i, 0.5 * e.min_lce, "fibre length lce[supinator2]"},
      {"lce above its maximum", kLce + i, 1.01 * e.max_lce, "fibre length lce[supinator2]"},
      {"activation above 1", act_offset(m) + i, 1.2, "activation[supinator2] = 1.2 is outside [0, 1]"},
      {"activation below 0", act_offset(m) + i, -0.1, "activation[supinator2] = -0.1 is outside [0, 1]"},
      {"joint far beyond its range", kQ + 4, psy.range_max + kJointRangeMargin + 0.2, "q[PSy]"},
  };
  for (const Case& c : cases) {
    const std::string what = c.what;
    CAPTURE(what);
    Arm sim(armrt_test::das2(), Integrator::kRos2, 1e-3);
    for (int k = 0; k < 6; ++k) REQUIRE(sim.step());
    // The state a step would have produced (check_state runs after every step).
    sim.data.x[c.index] = c.value;
    CHECK_FALSE(check_state(sim.model, sim.data));
    CHECK_FALSE(sim.step());  // sticky
    CHECK(sim.data.status == Status::kOutOfDomain);
    CHECK(sim.data.bad_index == c.index);
    const std::string msg = sim.error_message();
    INFO(msg);
    CHECK(msg.find("left the physical domain") != std::string::npos);
    CHECK(msg.find(c.expect) != std::string::npos);
    CHECK(msg.find("t = 0.006") != std::string::npos);
  }
}

TEST_CASE("explicit steps beyond the model's stability limit at rest are refused before any data") {
  Model m;
  model_init(m, armrt_test::das2());
  Data d0;
  data_init(m, d0);
  // The stiffest fibre at rest, cross-checked by a finite difference of its CE velocity.
  const int i = d0.rest_fibre_element;
  const ElementConstants& e = m.element[i];
  double q[kDas2Dofs], L[kMaxElements];
  for (int j = 0; j < kDas2Dofs; ++j) q[j] = m.def->dofs[j].rest;
  m.def->muscle_lengths(q, L);
  const double lce = muscle_equilibrium_lce(e, m.fibre_damping, L[i], 0.0), h = 1e-9;
  const double fd = (muscle_element(e, m.fibre_damping, L[i], lce + h, 0.0).fibre_velocity -
                     muscle_element(e, m.fibre_damping, L[i], lce - h, 0.0).fibre_velocity) / (2 * h);
  MESSAGE("stiffest fibre at rest: " << std::string(m.def->elements[i].name) << ", " << d0.rest_fibre_rate << " 1/s");
  CHECK(d0.rest_fibre_rate == doctest::Approx(fd).epsilon(1e-4));
  CHECK(d0.rest_fibre_rate < -2.785e3);  // beyond RK4 at 1 ms
  for (Integrator integ : {Integrator::kRk4, Integrator::kEuler}) {
    CAPTURE(integrator_name(integ));
    Arm one(armrt_test::das2(), integ, 1e-3);  // substeps = 1
    CHECK_FALSE(one.step());
    CHECK(one.data.status == Status::kUnstableStep);
    CHECK(one.data.time == 0.0);
    const std::string msg = one.error_message();
    INFO(msg);
    CHECK(msg.find("step too large") != std::string::npos);
    CHECK(msg.find(m.def->elements[i].name) != std::string::npos);
    // The default substeps (the validated step) run.
    Arm ok(armrt_test::das2(), integ, 1e-3, default_substeps(integ, 1e-3));
    for (int k = 0; k < 20; ++k) CHECK(ok.step());
  }
  Arm ros2(armrt_test::das2(), Integrator::kRos2, 1e-3);
  CHECK(ros2.step());  // L-stable: no such limit
}

TEST_CASE("state_name covers every part of the state") {
  Model m;
  model_init(m, armrt_test::das2());
  char buf[96];
  CHECK(std::string(state_name(m, 0, buf, sizeof buf)) == "q[GHy]");
  CHECK(std::string(state_name(m, kQd + 4, buf, sizeof buf)) == "qdot[PSy]");
  CHECK(std::string(state_name(m, kLce, buf, sizeof buf)) == "lce[deltscap1]");
  CHECK(std::string(state_name(m, act_offset(m) + m.num_elements - 1, buf, sizeof buf)) == "activation[anconeus5]");
}

}  // TEST_SUITE
