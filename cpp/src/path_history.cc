// path_history.cc: exact path evaluations (anchors) -> ROS2's extrapolated paths in between. Along a run of
// equal steps ROS2 evaluates the path polynomials at one step in kRos2PathPeriod and extrapolates them from the
// last two evaluations at every other evaluation of f, which keeps its order (evaluated at both stages of every
// step, the polynomials were 30 % of a das3 step).
#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "armrt/path_history.h"
#include "dof_dispatch.h"
#include "lanes.h"

namespace armrt {

namespace {

// Paths extrapolated from the last two exact evaluations (PathHistory's anchors, at q_old and q_new) instead
// of the polynomials (evaluated at both stages of every step, they were 30 % of a das3 step):
//   R_out = R_new + c (R_new - R_old)                   (linear in time: c = steps past q_new / anchor spacing)
//   L_out = L_from - (R_from + R_out)/2 . (q_to - q_from)   (trapezoid along the step, R = -dL/dq)
// The anchors are at most kRos2PathPeriod steps apart and the extrapolation reaches at most that far past the
// newest, each step h qd + O(h^2), so the moment arms' error is O(h^2) and the lengths' O(h^3): ROS2 stays second
// order (tests/test_rosenbrock.cc checks 4x per halving of h), as with any O(h^2) error in an evaluation of f.
// Moment arms by DOF (data.h), so each line below runs across eight elements at a time; each block of eight
// only over the DOFs its run crosses (Model::element_runs): the other rows of R_out are left as they are (zero
// in every buffer this writes), and their terms of L_out's sum are zero. The last block's ghost lanes are
// zero in R and L_from and written as zeros (L_out has room for them).
template <int nq>
void extrapolate_paths_n(const Model& m, const double* R_old, const double* R_new, double c, const double* L_from,
                         const double* R_from, const double* q_from, const double* q_to, double* L_out,
                         double* R_out) {
  using detail::v8d;
  double dq[nq];
  for (int a = 0; a < nq; ++a) dq[a] = q_to[a] - q_from[a];
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    for (int i = run.begin; i < run.end; i += 8) {
      v8d s = {};
      for (int a = run.dof_lo; a <= run.dof_hi; ++a) {
        const int o = a * kMaxElements + i;
        v8d rn, ro, rf;
        std::memcpy(&rn, R_new + o, sizeof(v8d));
        std::memcpy(&ro, R_old + o, sizeof(v8d));
        std::memcpy(&rf, R_from + o, sizeof(v8d));
        const v8d e = rn + c * (rn - ro);
        std::memcpy(R_out + o, &e, sizeof(v8d));
        s += (rf + e) * dq[a];
      }
      v8d lf;
      std::memcpy(&lf, L_from + i, sizeof(v8d));
      const v8d lo = lf - 0.5 * s;
      std::memcpy(L_out + i, &lo, sizeof(v8d));
    }
  }
}

}  // namespace

void extrapolate_paths(const Model& m, const PathHistory& ph, double c, const double* L_from, const double* R_from,
                       const double* q_from, const double* q_to, double* L_out, double* R_out) {
  const double* R_new = ph.anchor_moment_arm[ph.newest].data();
  const double* R_old = ph.anchor_moment_arm[1 - ph.newest].data();
  detail::dispatch_dofs(m.num_dofs, [&](auto N) {
    extrapolate_paths_n<N>(m, R_old, R_new, c, L_from, R_from, q_from, q_to, L_out, R_out);
  });
}

void add_anchor(const Model& m, PathHistory& ph, const double* q, const StepJacobian& jac) {
  const int nq = m.num_dofs, n = m.num_elements;
  if (ph.num_anchors >= 1) {
    ph.anchor_spacing = ph.steps_since_anchor;
    std::copy(ph.anchor_q_new.begin(), ph.anchor_q_new.begin() + nq, ph.anchor_q_old.begin());
    ph.newest ^= 1;
    ph.num_anchors = 2;
  } else {
    ph.anchor_spacing = 0;
    ph.num_anchors = 1;
  }
  // The rows the runs cross (the other rows are zero in both), eight at a time (a library copy per row and run
  // cost more in calls than in bytes).
  double* R = ph.anchor_moment_arm[ph.newest].data();
  const double* src = jac.moment_arm.data();
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    for (int a = run.dof_lo; a <= run.dof_hi; ++a)
      for (int i = run.begin; i < run.end; i += 8) {
        detail::v8d v;
        std::memcpy(&v, src + a * kMaxElements + i, sizeof v);
        std::memcpy(R + a * kMaxElements + i, &v, sizeof v);
      }
  }
  std::copy(jac.muscle_length.begin(), jac.muscle_length.begin() + n, ph.anchor_muscle_length.begin());
  std::copy(q, q + nq, ph.anchor_q_new.begin());
  ph.steps_since_anchor = 0;
}

bool path_history_continues(const Model& m, const PathHistory& ph, const double* q, const double* qdot, double h) {
  if (ph.h != h || h <= 0) return false;
  bool same = true;
  for (int j = 0; j < m.num_dofs; ++j) same &= q[j] == ph.q_end[j] && qdot[j] == ph.qd_end[j];
  return same;
}

void path_history_step_taken(const Model& m, PathHistory& ph, const double* q, const double* qdot, double h) {
  ph.h = h;
  ++ph.steps_since_anchor;
  for (int j = 0; j < m.num_dofs; ++j) {
    ph.q_end[j] = q[j];
    ph.qd_end[j] = qdot[j];
  }
}

std::string path_history_error(int num_anchors, int anchor_spacing, int steps_since_anchor) {
  if (num_anchors < 0 || num_anchors > 2) return "0, 1 or 2 path anchors, got " + std::to_string(num_anchors);
  if (num_anchors == 0) return "";
  // Only what a run of steps leaves: one anchor after its first step; then anchors 1 step apart (its first two
  // evaluations) or kRos2PathPeriod apart, the newest 1 to kRos2PathPeriod steps back.
  const std::string period = std::to_string(kRos2PathPeriod);
  if (num_anchors == 2 ? (anchor_spacing != 1 && anchor_spacing != kRos2PathPeriod) : anchor_spacing != 0)
    return "anchor spacing " + std::to_string(anchor_spacing) + " with " + std::to_string(num_anchors) +
           " anchors (a run leaves 1 or " + period + " steps with two, 0 with one)";
  if (steps_since_anchor < 1 || steps_since_anchor > (num_anchors == 2 ? kRos2PathPeriod : 1))
    return "steps since the newest anchor must be 1 to " + std::string(num_anchors == 2 ? period : "1") + " with " +
           std::to_string(num_anchors) + " anchor(s), got " + std::to_string(steps_since_anchor);
  return "";
}

void path_history_restore(const Model& m, PathHistory& ph, const double* q, const double* qdot, const double* anchor_q,
                          int num_anchors, int anchor_spacing, int steps_since_anchor, double h) {
  ph.h = 0;
  ph.num_anchors = 0;
  if (!(h > 0) || num_anchors == 0) return;
  const std::string error = path_history_error(num_anchors, anchor_spacing, steps_since_anchor);
  if (!error.empty()) throw std::invalid_argument("ROS2 history: " + error);
  const int nq = m.num_dofs;
  const double* q_new = anchor_q + (num_anchors - 1) * nq;
  // The polynomials again at the anchors' q: the same function of the same q, so the same bits.
  double L_old[kMaxElements];
  ph.newest = 0;
  m.def->muscle_paths(q_new, ph.anchor_muscle_length.data(), ph.anchor_moment_arm[0].data());
  std::copy(q_new, q_new + nq, ph.anchor_q_new.begin());
  if (num_anchors == 2) {
    m.def->muscle_paths(anchor_q, L_old, ph.anchor_moment_arm[1].data());
    std::copy(anchor_q, anchor_q + nq, ph.anchor_q_old.begin());
  }
  ph.num_anchors = num_anchors;
  ph.anchor_spacing = anchor_spacing;
  ph.steps_since_anchor = steps_since_anchor;
  for (int j = 0; j < nq; ++j) {
    ph.q_end[j] = q[j];
    ph.qd_end[j] = qdot[j];
  }
  ph.h = h;
}

}  // namespace armrt
