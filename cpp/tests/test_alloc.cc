// No heap allocation while stepping with the fixed-step integrators: this executable replaces the
// global operator new / new[] with counting versions.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <new>
#include <utility>
#include <vector>

#include "armrt/registry.h"
#include "armrt/arm.h"
#include "armrt/engine.h"
#include "armrt/static_optimization.h"
#include "pendulum2.h"
#include "test_util.h"

namespace {
std::atomic<long> g_allocations{0};

void* counted_alloc(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (size == 0) size = 1;
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted_alloc(size); }
void* operator new[](std::size_t size) { return counted_alloc(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size ? size : 1);
}
// malloc itself, counted while g_count_mallocs is set: Eigen (the static optimisation's ProxQP fallback) and the
// OpenMP runtime (test_batch.cc) allocate with std::malloc, not new. glibc's own entry point does the work; every
// malloc of the process, the engine library's included, comes here.
extern "C" void* __libc_malloc(std::size_t size);
std::atomic<bool> g_count_mallocs{false};
std::atomic<long> g_mallocs{0};
extern "C" void* malloc(std::size_t size) {
  if (g_count_mallocs.load(std::memory_order_relaxed)) g_mallocs.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

using namespace armrt;

TEST_SUITE("realtime") {

TEST_CASE("the counting operator new is in effect") {
  const long before = g_allocations.load();
  int* p = new int(3);
  const long after = g_allocations.load();
  delete p;
  CHECK(after == before + 1);
}

// Steps `sim` 1000 times under a hand load and stimulation and counts the heap allocations, which must be none.
void check_1000_steps_allocate_nothing(Arm& sim, std::initializer_list<std::pair<const char*, double>> groups) {
  for (const auto& [group, u] : groups) armrt_test::set_group_excitation(sim, group, u);
  sim.data.hand_force = {0.0, -9.81, 0.0};  // exercises the hand Jacobian branch too
  bool ok = true;
  const long before = g_allocations.load();
  for (int k = 0; k < 1000; ++k) ok &= sim.step();
  sim.evaluate_outputs();
  const long after = g_allocations.load();
  CHECK(ok);
  CHECK(after - before == 0);
}

TEST_CASE("no heap allocation during 1000 steps (euler, rk4, ros2, ros2_adaptive)") {
  for (Integrator integ : {Integrator::kEuler, Integrator::kRk4, Integrator::kRos2, Integrator::kRos2Adaptive}) {
    CAPTURE(integrator_name(integ));
    // (RK4 at 2.5e-4 s: stable for this stimulation; the cost per step does not depend on dt.)
    const double dt = integ == Integrator::kEuler ? 1e-4 : integ == Integrator::kRk4 ? 2.5e-4 : default_max_step(integ);
    auto sim = std::make_unique<Arm>(armrt_test::das2(), integ, dt);
    check_1000_steps_allocate_nothing(*sim, {{"elbow_flexors", 0.3}, {"rotator_cuff", 0.05}});
  }
}

TEST_CASE("no heap allocation in linearize() after its workspace exists (das2, A and B of one ROS2 step)") {
  auto sim = std::make_unique<Arm>(armrt_test::das2(), Integrator::kRos2, 1e-3);
  armrt_test::set_group_excitation(*sim, "elbow_flexors", 0.3);
  for (int k = 0; k < 20; ++k) REQUIRE(sim->step(false));
  const int ns = state_size(sim->model), n = sim->model.num_elements;
  std::vector<double> dfdx(ns * ns), dfdu(ns * n), A(ns * ns), B(ns * n);
  auto w = std::make_unique<LinearizeWorkspace>();
  const long before = g_allocations.load();
  for (int k = 0; k < 3; ++k) linearize(sim->model, sim->data, *w, 1e-3, dfdx.data(), dfdu.data(), A.data(), B.data());
  CHECK(g_allocations.load() - before == 0);
}

// The dual Newton path only: ProxQP, its fallback (a solve it does not finish, an infeasible request), allocates
// inside proxsuite when its active set changes (linesearch::active_set_change copies a strided block into an
// Eigen::Ref; counted with this test's interposer: about 2 mallocs per such solve), docs/control.md.
TEST_CASE("no heap allocation in static_optimization_rigid after set-up (dual Newton, GH bound binding)") {
  const Arm sim(armrt_test::das2(), Integrator::kRos2, 1e-3);
  const int nq = sim.model.num_dofs;
  const double hand[3] = {0, -9.81, 0}, zero[3] = {};
  double a[kMaxElements];
  StaticOptimizationReport rep;
  {
    const long m0 = g_mallocs.load();
    g_count_mallocs = true;
    void* volatile p = std::malloc(16);
    g_count_mallocs = false;
    std::free(p);
    REQUIRE(g_mallocs.load() == m0 + 1);  // the counting malloc is in effect
  }
  StaticOptimizationOptions o;
  o.gh_stab_max = 0.1;
  StaticOptimizationWorkspace w;
  static_optimization_setup(sim.model, o, w);
  double q[kMaxDofs], qd[kMaxDofs] = {}, qdd[kMaxDofs] = {};
  for (int j = 0; j < nq; ++j) q[j] = sim.model.def->dofs[j].rest;
  static_optimization_rigid(sim.model, sim.data, w, q, qd, qdd, hand, zero, a, &rep);
  const long m0 = g_mallocs.load(), n0 = g_allocations.load();
  g_count_mallocs = true;
  int newton = 0, bound_active = 0;
  for (int k = 0; k < 200; ++k) {
    for (int j = 0; j < nq; ++j) {
      q[j] = sim.model.def->dofs[j].rest + 0.2 * std::sin(0.05 * k + j);
      qd[j] = 0.3 * std::cos(0.05 * k + j);
    }
    static_optimization_rigid(sim.model, sim.data, w, q, qd, qdd, hand, zero, a, &rep);
    newton += rep.feasible && rep.solver == StaticOptimizationSolverUsed::kDualNewton;
    bound_active += rep.gh_bound_active;
  }
  g_count_mallocs = false;
  CHECK(newton == 200);
  CHECK(bound_active > 0);  // the GH rows took part
  CHECK(g_mallocs.load() - m0 == 0);
  CHECK(g_allocations.load() - n0 == 0);
}

TEST_CASE("no heap allocation during 1000 steps driven by stimulation (22 channels pulsing, fatigue on)") {
  for (Integrator integ : {Integrator::kRk4, Integrator::kRos2}) {
    CAPTURE(integrator_name(integ));
    const double dt = integ == Integrator::kRk4 ? 2.5e-4 : default_max_step(integ);
    auto sim = std::make_unique<Arm>(armrt_test::das2(), integ, dt);
    data_set_stimulation_map(sim->model, sim->data, stimulation_map_per_muscle(*sim->model.def));
    for (int k = 0; k < sim->data.stimulation_map.num_channels; ++k) {
      double* c = sim->data.stimulation.data() + k * kStimInputs;
      c[kStimPulseWidth] = 150e-6, c[kStimAmplitude] = 0.012, c[kStimFrequency] = 20.0 + k;
    }
    const double pulses[3] = {0.0105, 0.0207, 0.0309};
    stimulation_queue_pulses(sim->model, sim->data, 3, pulses, 3);
    check_1000_steps_allocate_nothing(*sim, {});
    CHECK(sim->data.stimulation_state[stim_state_index(kStimForce, 0, sim->data.stimulation_map.num_channels)] > 0.0);  // the first channel's fibres pull
  }
}

TEST_CASE("no heap allocation during 1000 steps of a second model (the 2-DOF pendulum)") {
  for (Integrator integ : {Integrator::kEuler, Integrator::kRk4, Integrator::kRos2, Integrator::kRos2Adaptive}) {
    CAPTURE(integrator_name(integ));
    const double dt = integ == Integrator::kEuler ? 2e-5 : integ == Integrator::kRk4 ? 1e-4 : default_max_step(integ);
    auto sim = std::make_unique<Arm>(generated::pendulum2::model_def(), integ, dt);
    check_1000_steps_allocate_nothing(*sim, {{"elbow", 0.3}, {"pronator", 0.2}});
  }
}

TEST_CASE("no heap allocation during 1000 steps of the moving-girdle model (das3: girdle stage, 11 DOFs)") {
  const ModelDef* def = find_model("das3");
  REQUIRE(def != nullptr);
  for (Integrator integ : {Integrator::kRos2, Integrator::kRos2Adaptive}) {
    CAPTURE(integrator_name(integ));
    auto sim = std::make_unique<Arm>(*def, integ, default_max_step(integ));
    check_1000_steps_allocate_nothing(*sim, {{"serratus_anterior", 0.3}, {"deltoid", 0.2}});
  }
}

}  // TEST_SUITE
