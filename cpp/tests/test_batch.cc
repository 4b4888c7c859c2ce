// Batch (batch.cc): each arm bit-identical to a lone Arm for 1 and 2 threads; a diverging arm
// stops alone.
#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>

#include "armrt/batch.h"
#include "test_util.h"

using namespace armrt;
using armrt_test::kDas2Dofs, armrt_test::kQ, armrt_test::kQd, armrt_test::kLce;

// Counts every malloc in the process while enabled, including the OpenMP runtime's (libgomp calls
// malloc directly, not operator new): this executable's malloc (test_alloc.cc) interposes the C library's.
extern std::atomic<bool> g_count_mallocs;
extern std::atomic<long> g_mallocs;

namespace {

// Arm i gets its own excitation pattern and posture, so the arms really differ.
void set_up(Arm& s, int i) {
  double q[kDas2Dofs];
  for (int j = 0; j < kDas2Dofs; ++j) q[j] = s.model.def->dofs[j].rest + 0.05 * i * (j % 2 ? 1 : -1);
  s.reset(q, nullptr, nullptr);
  for (int e = 0; e < s.model.num_elements; ++e) s.data.excitation[e] = 0.02 * ((e * 7 + i * 3) % 11);
}

}  // namespace

TEST_SUITE("batch") {

TEST_CASE("every arm matches a lone Arm bit for bit, on 1, 2 and 3 threads") {
  const int n = 5;
  const long steps = 30;
  for (Integrator integ : {Integrator::kRos2, Integrator::kRk4})
  for (int threads : {1, 2, 3}) {  // 3: more threads than this machine's cores
    CAPTURE(integrator_name(integ));
    CAPTURE(threads);
    const int sub = default_substeps(integ, 1e-3);
    Batch batch(armrt_test::das2(), n, integ, 1e-3, sub);
    for (int i = 0; i < n; ++i) set_up(batch.arm(i), i);
    CHECK(batch.step(steps / 2, threads, true) == 0);
    CHECK(batch.step(steps - steps / 2, threads, true) == 0);
    for (int i = 0; i < n; ++i) {
      Arm lone(armrt_test::das2(), integ, 1e-3, sub);
      set_up(lone, i);
      for (long k = 0; k < steps; ++k) REQUIRE(lone.step());
      lone.evaluate_outputs();
      const int ns = state_size(lone.model);
      CHECK(std::memcmp(lone.data.x.data(), batch.arm(i).data.x.data(), ns * sizeof(double)) == 0);
      CHECK(lone.data.time == batch.arm(i).data.time);
      CHECK(lone.data.gh_stab == batch.arm(i).data.gh_stab);
    }
  }
}

TEST_CASE("a diverging arm stops alone and is flagged; the others go on") {
  Batch batch(armrt_test::das2(), 3, Integrator::kRk4, 1e-3, 6);
  batch.arm(1).data.x[kQd + 3] = 5.0 * batch.arm(1).data.settings.max_joint_speed;
  CHECK(batch.step(10, 2, true) == 1);
  CHECK(batch.newly_failed()[1] == 1);
  CHECK(batch.newly_failed()[0] == 0);
  CHECK(batch.arm(1).data.status == Status::kTooFast);
  CHECK(batch.arm(1).error_message().find("qdot[") != std::string::npos);
  CHECK(batch.arm(0).data.time == doctest::Approx(10e-3));
  CHECK(batch.arm(2).data.time == doctest::Approx(10e-3));
  // Later calls leave the stopped arm alone and do not report it again.
  const double t1 = batch.arm(1).data.time;
  CHECK(batch.step(5, 2, true) == 0);
  CHECK(batch.arm(1).data.time == t1);
  CHECK(batch.arm(0).data.time == doctest::Approx(15e-3));
}

TEST_CASE("no heap allocation while stepping on 2 threads, OpenMP runtime included") {
  for (Integrator integ : {Integrator::kRos2, Integrator::kRk4}) {
  CAPTURE(integrator_name(integ));
  g_mallocs = 0;
  Batch batch(armrt_test::das2(), 4, integ, 1e-3, default_substeps(integ, 1e-3));
  for (int i = 0; i < batch.size(); ++i) set_up(batch.arm(i), i);
  // First call: OpenMP may create its thread pool (run alone, this case counts 2 mallocs there:
  // libgomp's, which shows the interposer sees the runtime's allocations).
  REQUIRE(batch.step(2, 2, true) == 0);
  // The interposer is live: an allocation in this window is counted.
  g_count_mallocs = true;
  void* volatile probe = std::malloc(16);
  g_count_mallocs = false;
  std::free(probe);
  REQUIRE(g_mallocs.load() == 1);
  g_mallocs = 0;
  g_count_mallocs = true;
  int failed = 0;
  for (int call = 0; call < 20; ++call) failed += batch.step(5, 2, true);
  g_count_mallocs = false;
  CHECK(failed == 0);
  CHECK(g_mallocs.load() == 0);
  }
}

TEST_CASE("bad sizes are refused") {
  CHECK_THROWS_AS(Batch(armrt_test::das2(), 0, Integrator::kRk4, 1e-3), std::invalid_argument);
}

}
