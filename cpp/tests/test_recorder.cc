// Recording (recorder.h) and TET (Arm::step, the one place it is measured), on the pendulum.
#include <doctest/doctest.h>

#include <stdexcept>
#include <vector>

#include "armrt/recorder.h"
#include "pendulum2.h"

using namespace armrt;

TEST_SUITE("recorder") {

TEST_CASE("rows are consistent time points; the final state is added when the last step is due") {
  Arm s(generated::pendulum2::model_def(), Integrator::kRos2, 1e-3);
  const int n = s.model.num_elements, nq = s.model.num_dofs;
  const std::vector<double> x_start(s.data.x.begin(), s.data.x.begin() + state_size(s.model));
  std::vector<double> u(n, 0.3);
  Recording r;
  const long done = simulate_recorded(s, u.data(), true, 10, 5, r);
  CHECK(done == 10);
  REQUIRE(r.rows() == 3);  // steps 0 and 5, and the final state
  CHECK(r[Channel::time][0] == 0.0);
  CHECK(r[Channel::time][1] == doctest::Approx(5e-3));
  CHECK(r[Channel::time][2] == doctest::Approx(10e-3));
  for (int j = 0; j < nq; ++j) {
    CHECK(r[Channel::q][j] == x_start[j]);
    CHECK(r[Channel::q][2 * nq + j] == s.data.x[q_offset(s.model) + j]);
  }
  CHECK(r[Channel::q].size() == 3u * nq);
  CHECK(r[Channel::activation].size() == 3u * n);
  CHECK(r[Channel::excitation][n] == 0.3);
  CHECK(r[Channel::tet_ns][0] > 0);
  CHECK(r[Channel::tet_ns][2] == 0.0);  // the final state was not stepped from
  // Forces of a row are those of its state (outputs evaluated at the start of the step).
  Arm t(generated::pendulum2::model_def(), Integrator::kRos2, 1e-3);
  t.evaluate_outputs();
  CHECK(r[Channel::muscle_force][0] == t.data.muscle_force[0]);

  Recording r2;
  Arm s2(generated::pendulum2::model_def(), Integrator::kRos2, 1e-3);
  CHECK(simulate_recorded(s2, u.data(), true, 10, 3, r2) == 10);
  CHECK(r2.rows() == 4);  // steps 0, 3, 6, 9; 10 % 3 != 0: no final row
}

TEST_CASE("rows written into the caller's arrays are the rows the vectors hold, block after block") {
  std::vector<double> u(generated::pendulum2::model_def().num_elements, 0.3);
  Arm a(generated::pendulum2::model_def(), Integrator::kRos2, 1e-3);
  Recording whole;
  REQUIRE(simulate_recorded(a, u.data(), true, 12, 2, whole) == 12);
  REQUIRE(whole.rows() == 7);
  // The same run as two blocks of 6 steps into one set of arrays: block 1's closing row is overwritten by block 2's
  // first row (the same state), as Arm.simulate does it.
  Arm b(generated::pendulum2::model_def(), Integrator::kRos2, 1e-3);
  const auto width = recording_widths(b);
  std::array<std::vector<double>, kNumChannels> store;
  Recording into;
  into.capacity = 7;
  for (int c = 0; c < kNumChannels; ++c) {
    store[c].assign(7 * width[c], -1.0);
    into.into[c] = width[c] ? store[c].data() : nullptr;
  }
  REQUIRE(simulate_recorded(b, u.data(), true, 6, 2, into) == 6);
  CHECK(into.rows() == 4);
  into.num_rows = 3;
  REQUIRE(simulate_recorded(b, u.data(), true, 6, 2, into) == 6);
  CHECK(into.rows() == 7);
  for (int c = 0; c < kNumChannels; ++c) {
    if (c == static_cast<int>(Channel::tet_ns) || width[c] == 0) continue;  // TET: wall time
    CHECK(store[c] == whole.channel[c]);
  }
  // No room for another block: refused before a step is taken.
  const double t = b.data.time;
  CHECK_THROWS_AS(simulate_recorded(b, u.data(), true, 2, 1, into), std::invalid_argument);
  CHECK(b.data.time == t);
  into.into[static_cast<int>(Channel::q)] = nullptr;
  into.num_rows = 0;
  CHECK_THROWS_AS(simulate_recorded(b, u.data(), true, 2, 1, into), std::invalid_argument);
}

TEST_CASE("a stop request ends the loop after the current step") {
  Arm s(generated::pendulum2::model_def(), Integrator::kRos2, 1e-3);
  std::vector<double> u(s.model.num_elements, 0.0);
  int calls = 0;
  auto stop = [](void* c) { return ++*static_cast<int*>(c) >= 4; };
  Recording r;
  CHECK(simulate_recorded(s, u.data(), true, 100, 1, r, stop, &calls) == 4);
  CHECK(r.rows() == 4);
}

TEST_CASE("TET: one entry per control step, whatever the integrator and substeps") {
  for (auto [integ, substeps] : {std::pair{Integrator::kRos2, 1}, {Integrator::kRk4, 10}, {Integrator::kEuler, 50},
                                 {Integrator::kCvode, 1}, {Integrator::kRos2Adaptive, 1}}) {
    Arm s(generated::pendulum2::model_def(), integ, 1e-3, substeps);
    for (int k = 0; k < 7; ++k) REQUIRE(s.step());
    CHECK(s.data.tet.count == 7);
    CHECK(s.data.tet.last_ns > 0);
    CHECK(s.data.time == doctest::Approx(7e-3));
  }
}

}  // TEST_SUITE
