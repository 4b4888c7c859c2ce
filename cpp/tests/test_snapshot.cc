// Snapshots by signature (snapshot.h) on the tiny pendulum (tests/data/pendulum2.json): the layout follows the
// table, a full snapshot continues a ROS2 run bit for bit, a partial one sets only its parts, and the engine's
// check refuses what a step would refuse, naming the value, without writing anything.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "armrt/arm.h"
#include "armrt/layouts.h"
#include "armrt/snapshot.h"
#include "pendulum2.h"

using namespace armrt;

namespace {

const ModelDef& pendulum() { return generated::pendulum2::model_def(); }

std::vector<double> snapshot(const Arm& a, unsigned signature) {
  std::vector<double> x(snapshot_size(*a.model.def, signature));
  get_snapshot(a.model, a.data, a.stepper, signature, x.data());
  return x;
}

// An arm a few ROS2 steps into a run: a path history with two anchors.
Arm running_arm() {
  Arm a(pendulum(), Integrator::kRos2, 1e-3);
  const double q[2] = {0.3, 0.2}, act[5] = {0.5, 0.4, 0.3, 0.6, 0.2}, u[5] = {0.9, 0.1, 0.5, 0.7, 0.0};
  a.reset(q, nullptr, act);
  data_set_excitation(a.model, a.data, u);
  a.data.hand_force = {0.0, -2.0, 0.0};
  REQUIRE(step(a.model, a.data, a.stepper, 5));
  return a;
}

bool contains(const std::string& s, const char* part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("snapshot (pendulum)") {

TEST_CASE("snapshot layout: sizes and offsets follow the table's rows") {
  const ModelDef& def = pendulum();
  const int nq = 2, n = 5;
  CHECK(snapshot_size(def, kSnapshotTime) == 1);
  CHECK(snapshot_size(def, kSnapshotPhysics) == 2 * nq + 2 * n);
  CHECK(snapshot_size(def, kSnapshotInputs) == n + 3 + 3 + nq);
  CHECK(snapshot_size(def, kSnapshotIntegrator) == 4 + 2 * nq);
  CHECK(snapshot_size(def, kSnapshotFull) == 1 + (2 * nq + 2 * n) + (n + 6 + nq) + (4 + 2 * nq));
  CHECK(snapshot_offset(def, kSnapshotFull, SnapshotPart::q) == 1);
  CHECK(snapshot_offset(def, kSnapshotFull, SnapshotPart::excitation) == 1 + 2 * nq + 2 * n);
  CHECK(snapshot_offset(def, kSnapshotPhysics, SnapshotPart::time) == -1);
  CHECK(snapshot_offset(def, snapshot_bit(SnapshotPart::qdot) | snapshot_bit(SnapshotPart::hand_moment),
                        SnapshotPart::hand_moment) == nq);
  CHECK_THROWS_AS(snapshot_size(def, kSnapshotFull + 1), std::invalid_argument);
  CHECK(std::string(snapshot_rows()[static_cast<int>(SnapshotPart::ros2_path_history)].stage) == "integrator");
}

TEST_CASE("snapshot round trip: a full snapshot continues a ROS2 run bit for bit, also in another arm") {
  Arm a = running_arm();
  const std::vector<double> s = snapshot(a, kSnapshotFull);
  // The memory is there: h, two anchors.
  const int ih = snapshot_offset(*a.model.def, kSnapshotFull, SnapshotPart::ros2_path_history);
  CHECK(s[ih] == 1e-3);
  CHECK(s[ih + 1] == 2);
  REQUIRE(step(a.model, a.data, a.stepper, 20));
  const StateVec ahead = a.data.x;

  Arm b(pendulum(), Integrator::kRos2, 1e-3);
  CHECK(snapshot_error(b.model, b.data, kSnapshotFull, s.data()) == "");
  set_snapshot(b.model, b.data, b.stepper, kSnapshotFull, s.data());
  CHECK(snapshot(b, kSnapshotFull) == s);
  REQUIRE(step(b.model, b.data, b.stepper, 20));
  for (int k = 0; k < state_size(b.model); ++k) CHECK(b.data.x[k] == ahead[k]);
  CHECK(b.data.time == a.data.time);
}

TEST_CASE("snapshot parts: a partial signature sets its parts only and keeps the others") {
  Arm a = running_arm();
  const std::vector<double> before = snapshot(a, kSnapshotFull);
  std::vector<double> inputs = snapshot(a, kSnapshotInputs);
  inputs[0] = 0.25;          // excitation of the first element
  inputs[5 + 1] = -7.0;      // hand force y
  set_snapshot(a.model, a.data, a.stepper, kSnapshotInputs, inputs.data());
  CHECK(a.data.excitation[0] == 0.25);
  CHECK(a.data.hand_force[1] == -7.0);
  // Physics, time and ROS2's memory are as they were: the run continues from the same history.
  const std::vector<double> after = snapshot(a, kSnapshotTime | kSnapshotPhysics | kSnapshotIntegrator);
  const std::vector<double> kept(before.begin(), before.begin() + 1 + snapshot_size(*a.model.def, kSnapshotPhysics));
  CHECK(std::vector<double>(after.begin(), after.begin() + kept.size()) == kept);
  CHECK(after.back() == before.back());
  // Physics without the memory: the next step evaluates the paths afresh (no memory reported).
  const std::vector<double> x = snapshot(a, kSnapshotPhysics);
  set_snapshot(a.model, a.data, a.stepper, kSnapshotPhysics, x.data());
  const std::vector<double> memory = snapshot(a, kSnapshotIntegrator);
  for (double v : memory) CHECK(v == 0.0);
}

TEST_CASE("snapshot excitation: stored capped at max_activation, and capped again when the cap drops") {
  Arm a(pendulum(), Integrator::kRos2, 1e-3);
  a.data.settings.max_activation[2] = 0.3;
  a.apply_settings();
  std::vector<double> u = snapshot(a, snapshot_bit(SnapshotPart::excitation));
  for (double& v : u) v = 0.8;
  set_snapshot(a.model, a.data, a.stepper, snapshot_bit(SnapshotPart::excitation), u.data());
  CHECK(a.data.excitation[2] == 0.3);
  CHECK(a.data.excitation[1] == 0.8);
  a.data.settings.max_activation[1] = 0.5;
  a.apply_settings();  // the held excitation follows the new cap
  CHECK(a.data.excitation[1] == 0.5);
}

TEST_CASE("snapshot check: refuses what a step refuses, naming the value, and writes nothing") {
  Arm a = running_arm();
  const std::vector<double> good = snapshot(a, kSnapshotFull);
  const ModelDef& def = *a.model.def;
  const int iq = snapshot_offset(def, kSnapshotFull, SnapshotPart::q);
  const int iqd = snapshot_offset(def, kSnapshotFull, SnapshotPart::qdot);
  const int il = snapshot_offset(def, kSnapshotFull, SnapshotPart::lce);
  const int ia = snapshot_offset(def, kSnapshotFull, SnapshotPart::activation);
  const int iu = snapshot_offset(def, kSnapshotFull, SnapshotPart::excitation);
  const int ih = snapshot_offset(def, kSnapshotFull, SnapshotPart::ros2_path_history);
  // Without ROS2's memory for the state checks (a changed q no longer fits its anchors: checked below).
  std::vector<double> no_memory = good;
  std::fill(no_memory.begin() + ih, no_memory.end(), 0.0);
  auto error_with = [&](int index, double value) {
    std::vector<double> bad = index >= ih ? good : no_memory;
    bad[index] = value;
    return snapshot_error(a.model, a.data, kSnapshotFull, bad.data());
  };
  // ELx's range is [-1.5, 2] rad: 2.3 is within kJointRangeMargin (a passive limit is a spring), 2.5 beyond.
  CHECK(error_with(iq, 2.3) == "");
  CHECK(contains(error_with(iq, 2.5), "q[ELx] = 2.5 rad is more than 0.35 rad beyond its range [-1.5, 2] rad"));
  // A radian value just beyond the margin is not called degrees: read as degrees almost any pose is in range, so
  // the hint needs a value beyond a full turn (it fired for 2.5 rad before).
  CHECK(!contains(error_with(iq, 2.5), "degrees"));
  // Both joints in degrees: 17.2 and 11.5 deg read as rad are far out, as rad they are in range.
  {
    std::vector<double> bad = no_memory;
    bad[iq] = 17.2, bad[iq + 1] = 11.5;
    CHECK(contains(snapshot_error(a.model, a.data, kSnapshotFull, bad.data()), "look like degrees"));
  }
  CHECK(contains(error_with(iqd + 1, 1e3), "qdot[PSy] = 1000 rad/s is beyond max_joint_speed"));
  CHECK(contains(error_with(il + 2, 10.0), "fibre length lce["));
  CHECK(contains(error_with(ia, 1.5), "is outside [0, 1]"));
  CHECK(contains(error_with(iu + 4, -0.1), "excitation["));
  CHECK(contains(error_with(0, NAN), "time is not finite"));
  CHECK(contains(error_with(ih + 1, 3), "0, 1 or 2 path anchors, got 3"));
  CHECK(contains(error_with(ih + 3, 7), "steps since the newest anchor must be 1 to 3"));
  CHECK(contains(error_with(ih + 2, 1.5), "whole numbers"));
  CHECK(contains(error_with(ih, 0.0), "h must be > 0 s with anchors"));
  // An anchor that q could not have left in its steps.
  CHECK(contains(error_with(ih + 4 + 2, good[ih + 4 + 2] + 5.0), "the newest anchor is not"));
  // Nothing was written by any check.
  CHECK(snapshot(a, kSnapshotFull) == good);
  // A physics part alone is checked against the rest of the arm's state.
  const std::vector<double> q_only = {2.5, 0.0};
  CHECK(contains(snapshot_error(a.model, a.data, snapshot_bit(SnapshotPart::q), q_only.data()), "q[ELx]"));
}

}  // TEST_SUITE
