// ros2.cc: (model, data, ROS2 workspace, h) -> data advanced by one ROS2 step, the workspace's path history
// updated.
// Linearly implicit (Rosenbrock) steps: ROS2 (Verwer, Spee, Blom & Hundsdorfer 1999, SIAM J. Sci.
// Comput. 20(4), eq. 2.5, gamma = 1 + 1/sqrt(2)), L-stable, second order with any approximate Jacobian
// (W-method), one Jacobian and two derivative evaluations per step:
//   (I - h gamma J) k1 = f(x_n)
//   (I - h gamma J) k2 = f(x_n + h k1) - 2 k1
//   x_{n+1} = x_n + h (3/2 k1 + 1/2 k2)
// Along a run of equal steps the muscle paths are evaluated at one step in kRos2PathPeriod and extrapolated
// from the last two evaluations at all other evaluations of f (path_history.cc), which keeps the order.
// J is the structured Jacobian (step_jacobian.h), stiffened where a tangent cannot see the step
// (fibre_limiter.cc); its linear systems are solved by step_jacobian.cc.
#include <algorithm>
#include <cmath>

#include "armrt/engine.h"
#include "armrt/path_history.h"
#include "armrt/step_jacobian.h"

namespace armrt {

namespace {

// One ROS2 step of h from d.x; leaves the two stage vectors in w.k1 and w.k2, x untouched.
// Paths: a step that continues the history extrapolates its second stage's from the anchors, and so do the
// kRos2PathPeriod - 1 steps after an exact one their first stage's; the rest evaluate the polynomials.
void ros2_stages(const Model& m, Data& d, Ros2Workspace& w, double h, bool record) {
  const int ns = state_size(m);
  const double* x = d.x.data();
  const double* q = x + q_offset(m);
  PathHistory& ph = w.path_history;
  StepJacobian& jac = w.jac;
  if (!path_history_continues(m, ph, q, x + qd_offset(m), h)) ph.num_anchors = 0;
  if (ph.num_anchors == 2 && ph.steps_since_anchor < kRos2PathPeriod) {
    extrapolate_paths(m, ph, static_cast<double>(ph.steps_since_anchor) / ph.anchor_spacing,
                      ph.anchor_muscle_length.data(),
                      ph.anchor_moment_arm[ph.newest].data(), ph.anchor_q_new.data(), q, jac.muscle_length.data(),
                      jac.moment_arm.data());
    forward_from_paths(m, d, x, jac.muscle_length.data(), jac.moment_arm.data(), w.f.data(), record, &jac);
  } else {
    forward(m, d, x, w.f.data(), record, &jac);
    add_anchor(m, ph, q, jac);
  }
  limit_fibre_overshoot(m, d, jac, x, w.f.data(), h);
  jacobian_factor(m, jac, kRos2Gamma * h);
  jacobian_solve(m, jac, w.f.data(), w.k1.data());
  double* xt = w.x2.data();
  for (int k = 0; k < ns; ++k) xt[k] = x[k] + h * w.k1[k];
  if (ph.num_anchors == 2) {
    // The second stage is one step past the first (q2 = q_n + h k1_q).
    double L2[kMaxElements];
    double* R2 = ph.stage2_moment_arm.data();
    extrapolate_paths(m, ph, static_cast<double>(ph.steps_since_anchor + 1) / ph.anchor_spacing,
                      jac.muscle_length.data(), jac.moment_arm.data(), q, xt + q_offset(m), L2, R2);
    forward_from_paths(m, d, xt, L2, R2, w.f2.data(), false);
  } else {
    forward(m, d, xt, w.f2.data(), false);
  }
  ph.h = 0;  // until ros2_update takes the step
  for (int k = 0; k < ns; ++k) w.f2[k] -= 2.0 * w.k1[k];
  jacobian_solve(m, jac, w.f2.data(), w.k2.data());
}

// The embedded first-order solution is x_n + h k1 (linearly implicit Euler); their difference
// h/2 (k1 + k2) estimates the local error. Scaled by kRos2AdaptiveTolQ (rad) on the joint angles and
// kRos2AdaptiveTolLce (x lceopt) on the CE lengths, where the stiff slack-to-taut events show first.
double ros2_error_estimate(const Model& m, const Data& d, const Ros2Workspace& w, double h) {
  double err = 0;
  const int iq = q_offset(m), il = lce_offset(m);
  for (int j = 0; j < m.num_dofs; ++j)
    err = std::max(err, std::fabs(0.5 * h * (w.k1[iq + j] + w.k2[iq + j])) / kRos2AdaptiveTolQ);
  const MuscleArrays& mc = d.muscles;
  for (int i = 0; i < m.num_elements; ++i)
    err = std::max(err, std::fabs(0.5 * h * (w.k1[il + i] + w.k2[il + i])) * mc.inv_lceopt[i] /
                            kRos2AdaptiveTolLce);
  return err;
}

void ros2_update(const Model& m, Data& d, Ros2Workspace& w, double h) {
  const int ns = state_size(m);
  for (int k = 0; k < ns; ++k) d.x[k] += h * (1.5 * w.k1[k] + 0.5 * w.k2[k]);
  path_history_step_taken(m, w.path_history, d.x.data() + q_offset(m), d.x.data() + qd_offset(m), h);
}

}  // namespace

void step_ros2(const Model& m, Data& d, Ros2Workspace& w, double h, bool record) {
  ros2_stages(m, d, w, h, record);
  ros2_update(m, d, w, h);
}

int step_ros2_adaptive(const Model& m, Data& d, Ros2Workspace& w, double h, bool record) {
  ros2_stages(m, d, w, h, record);
  if (ros2_error_estimate(m, d, w, h) <= 1.0) {
    ros2_update(m, d, w, h);
    return 1;
  }
  // Rejected: redo as two halves, accepted without a further check (fixed worst case, ~3 steps' work).
  step_ros2(m, d, w, 0.5 * h, false);
  step_ros2(m, d, w, 0.5 * h, false);
  ++d.halved_steps;
  return 2;
}

}  // namespace armrt
