// linearize.cc: A = dx+/dx and B = dx+/du of one ROS2 step against central differences of step_ros2 itself (a fresh
// path history each time, as linearize() assumes), df/dx against central differences of forward(), and the arm left
// as it was. The full column sweep at random das2/das3 states is tests/test_linearize.py.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "armrt/arm.h"
#include "armrt/engine.h"
#include "test_util.h"

using namespace armrt;

namespace {

// x+ of one ROS2 step of h from x with excitation u, from a fresh path history (exact paths at both stages).
std::vector<double> ros2_step(Arm& sim, const std::vector<double>& x, const std::vector<double>& u, double h) {
  const Model& m = sim.model;
  const int ns = state_size(m);
  Data d = sim.data;
  std::copy(x.begin(), x.end(), d.x.begin());
  std::copy(u.begin(), u.end(), d.excitation.begin());
  Ros2Workspace w;
  step_ros2(m, d, w, h, false);
  return std::vector<double>(d.x.begin(), d.x.begin() + ns);
}

std::vector<double> state_derivative(Arm& sim, const std::vector<double>& x) {
  std::vector<double> xdot(kMaxState);
  Data d = sim.data;
  forward(sim.model, d, x.data(), xdot.data(), false);
  xdot.resize(state_size(sim.model));
  return xdot;
}

}  // namespace

TEST_CASE("linearize: A, B and df/dx of das2 against central differences of the ROS2 step and of forward()") {
  auto sim = std::make_unique<Arm>(armrt_test::das2(), Integrator::kRos2, 1e-3);
  armrt_test::set_group_excitation(*sim, "elbow_flexors", 0.3);
  armrt_test::set_group_excitation(*sim, "rotator_cuff", 0.1);
  armrt_test::set_group_excitation(*sim, "deltoid", 0.15);
  sim->data.hand_force = {3.0, -9.81, 1.0};
  for (int k = 0; k < 40; ++k) REQUIRE(sim->step(false));
  const Model& m = sim->model;
  const int ns = state_size(m), n = m.num_elements, nq = m.num_dofs;
  const double h = 1e-3;
  std::vector<double> dfdx(ns * ns), dfdu(ns * n), A(ns * ns), B(ns * n);
  auto w = std::make_unique<LinearizeWorkspace>();
  MESSAGE("sizeof(LinearizeWorkspace) = " << sizeof(LinearizeWorkspace) << " bytes");
  const std::vector<double> x(sim->data.x.begin(), sim->data.x.begin() + ns);
  const std::vector<double> u(sim->data.excitation.begin(), sim->data.excitation.begin() + n);
  const auto limited = sim->data.limited_fibre_steps;
  linearize(m, sim->data, *w, h, dfdx.data(), dfdu.data(), A.data(), B.data());
  // The arm as it was.
  CHECK(std::equal(x.begin(), x.end(), sim->data.x.begin()));
  CHECK(sim->data.limited_fibre_steps == limited);
  // Where the step lands: step_ros2's own x+ from a set state, to the bit (Arm.linearize returns it as x0_next).
  {
    const std::vector<double> x_plus = ros2_step(*sim, x, u, h);
    int differ = 0;
    for (int k = 0; k < ns; ++k) differ += w->x_next[k] != x_plus[k];
    CHECK(differ == 0);
  }

  // Columns: every joint angle and velocity, and every seventh CE length, activation and excitation.
  std::vector<int> cols;
  for (int c = 0; c < 2 * nq; ++c) cols.push_back(c);
  for (int i = 0; i < n; i += 7) {
    cols.push_back(lce_offset(m) + i);
    cols.push_back(act_offset(m) + i);
  }
  double worst_A = 0, worst_J = 0;
  for (int c : cols) {
    const double eps = c < nq ? 1e-6 : (c < 2 * nq ? 1e-5 : (c < act_offset(m) ? 1e-7 : 1e-6));
    std::vector<double> xp = x, xm = x;
    xp[c] += eps;
    xm[c] -= eps;
    const std::vector<double> sp = ros2_step(*sim, xp, u, h), sm = ros2_step(*sim, xm, u, h);
    const std::vector<double> fp = state_derivative(*sim, xp), fm = state_derivative(*sim, xm);
    double scale_A = 0, scale_J = 0, err_A = 0, err_J = 0;
    for (int r = 0; r < ns; ++r) {
      const double a = (sp[r] - sm[r]) / (2 * eps), j = (fp[r] - fm[r]) / (2 * eps);
      scale_A = std::max(scale_A, std::fabs(a));
      scale_J = std::max(scale_J, std::fabs(j));
      err_A = std::max(err_A, std::fabs(A[r * ns + c] - a));
      err_J = std::max(err_J, std::fabs(dfdx[r * ns + c] - j));
    }
    CAPTURE(c);
    CHECK(err_A <= 1e-3 * scale_A);
    CHECK(err_J <= 1e-3 * scale_J);
    worst_A = std::max(worst_A, err_A / scale_A);
    worst_J = std::max(worst_J, err_J / scale_J);
  }
  MESSAGE("worst column-relative residual: A " << worst_A << ", df/dx " << worst_J);
  // B: central differences inside the excitation's range; at u = 0 (the elements outside the three groups) the
  // forward difference, the side linearize() takes at the cap's ends.
  const std::vector<double> s0 = ros2_step(*sim, x, u, h);
  int at_zero = 0;
  for (int i = 0; i < n; i += 7) {
    std::vector<double> up = u, um = u;
    up[i] += 1e-6;
    um[i] -= 1e-6;
    const bool one_sided = u[i] == 0.0;
    at_zero += one_sided;
    const std::vector<double> sp = ros2_step(*sim, x, up, h), sm = one_sided ? s0 : ros2_step(*sim, x, um, h);
    double scale = 0, err = 0;
    for (int r = 0; r < ns; ++r) {
      const double b = (sp[r] - sm[r]) / (one_sided ? 1e-6 : 2e-6);
      scale = std::max(scale, std::fabs(b));
      err = std::max(err, std::fabs(B[r * n + i] - b));
    }
    CAPTURE(i);
    CHECK(err <= 1e-3 * scale);
  }
  CHECK(at_zero > 0);
  // The continuous call alone gives the same df/dx, df/du.
  std::vector<double> dfdx2(ns * ns), dfdu2(ns * n);
  linearize(m, sim->data, *w, h, dfdx2.data(), dfdu2.data(), nullptr, nullptr);
  CHECK(dfdx2 == dfdx);
  CHECK(dfdu2 == dfdu);
}
