// Divergence reporting (integrate.cc: check_state, state_name; Simulator::error_message).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "armrt/simulator.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::kDas2Dofs, armrt_test::kQ, armrt_test::kQd, armrt_test::kLce;

TEST_SUITE("divergence") {

TEST_CASE("NaN in the state: kNonFinite with the index, message names the state and the time") {
  Simulator sim(armrt_test::das2(), Integrator::kEuler, 1e-4);
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
  Simulator sim(armrt_test::das2(), Integrator::kEuler, 1e-4);
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
    Simulator sim(armrt_test::das2(), integ, 1e-4);
    sim.data.x[kQd + 3] = 5.0 * sim.model.max_joint_speed;
    CHECK_FALSE(sim.step());
    CHECK(sim.data.status == Status::kTooFast);
    REQUIRE(sim.data.bad_index >= kQd);
    REQUIRE(sim.data.bad_index < kQd + kDas2Dofs);
    CHECK(std::fabs(sim.data.x[sim.data.bad_index]) > sim.model.max_joint_speed);
    const std::string msg = sim.error_message();
    INFO(msg);
    CHECK(msg.find("qdot[" + std::string(sim.model.def->dofs[sim.data.bad_index - kQd].name) + "]") !=
          std::string::npos);
    CHECK(msg.find("t = 0.0001") != std::string::npos);
    CHECK(msg.find("rad/s") != std::string::npos);
  }
}

TEST_CASE("elbow velocity beyond the bound: qdot[ELx]") {
  Simulator sim(armrt_test::das2(), Integrator::kEuler, 1e-5);
  sim.data.x[kQd + 3] = 1.5 * sim.model.max_joint_speed;
  CHECK_FALSE(sim.step());
  CHECK(sim.data.status == Status::kTooFast);
  CHECK(sim.data.bad_index == kQd + 3);
  CHECK(sim.error_message().find("qdot[ELx]") != std::string::npos);
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
