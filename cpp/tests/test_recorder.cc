// Recording (recorder.h) and TET (Arm::step, the one place it is measured), on the pendulum.
#include <doctest/doctest.h>

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
