// ROS2's memory of the muscle paths (path_history.cc): the last exact evaluations of the path polynomials,
// from which the steps in between extrapolate them.
#pragma once

#include <array>
#include <string>

#include "armrt/model.h"
#include "armrt/step_jacobian.h"

namespace armrt {

// ROS2 evaluates the muscle-path polynomials at one step in kRos2PathPeriod of a run of equal steps and
// extrapolates them in between and at every second stage.
inline constexpr int kRos2PathPeriod = 3;

// What ROS2 extrapolates the muscle paths from (path_history.cc): the last two exact evaluations of the path
// polynomials ("anchors", one step in kRos2PathPeriod once a run is under way) and the state the last step
// ended at.
// A step continues that history only if it starts from exactly that state with the same h; anything else
// (a reset, a state set from outside, another step size) starts afresh: exact paths in both stages.
struct PathHistory {
  // m, moment arms at the anchors by DOF (as StepJacobian's): anchor_moment_arm[newest] at anchor_q_new, the
  // other at anchor_q_old (two slots, so that a new anchor replaces the oldest without a copy). Rows an
  // element run does not cross (Model::element_runs) stay zero.
  std::array<double, kMaxDofs * kMaxElements> anchor_moment_arm[2]{};
  int newest = 0;
  std::array<double, kMaxElements> anchor_muscle_length{};  // m, at anchor_q_new
  std::array<double, kMaxDofs> anchor_q_old{}, anchor_q_new{};  // rad
  int num_anchors = 0;         // 0, 1 (anchor_q_new only) or 2
  int anchor_spacing = 0;      // steps of h from anchor_q_old to anchor_q_new (1 or kRos2PathPeriod; 0 with one)
  int steps_since_anchor = 0;  // steps of h from anchor_q_new to where the last step ended (1 to kRos2PathPeriod)
  // m, the second stage's extrapolated moment arms, by DOF; written only where Model::element_runs cross (and
  // the elements past them), so zero wherever the polynomials' are.
  std::array<double, kMaxDofs * kMaxElements> stage2_moment_arm{};
  std::array<double, kMaxDofs> q_end{};   // rad, q the last step ended at
  std::array<double, kMaxDofs> qd_end{};  // rad/s, and qdot
  double h = 0;                           // s, that step's size; 0: no history
};

// Paths extrapolated from the history's anchors, c anchor spacings past the newest: moment arms R_out (by
// DOF) and lengths L_out from the trapezoid along q_from -> q_to starting at L_from, R_from.
void extrapolate_paths(const Model& m, const PathHistory& ph, double c, const double* L_from, const double* R_from,
                       const double* q_from, const double* q_to, double* L_out, double* R_out);
// The exact paths just evaluated at q (in jac) become the newest anchor; the newest becomes the old one.
void add_anchor(const Model& m, PathHistory& ph, const double* q, const StepJacobian& jac);
// Whether a step of h from (q, qdot) continues ph (the last step was of h and ended there).
bool path_history_continues(const Model& m, const PathHistory& ph, const double* q, const double* qdot, double h);
// The history a step of h leaves when it ends at (q, qdot).
void path_history_step_taken(const Model& m, PathHistory& ph, const double* q, const double* qdot, double h);
// Why (num_anchors, anchor_spacing, steps_since_anchor) is not a history a run of steps leaves, or "" if it is one.
std::string path_history_error(int num_anchors, int anchor_spacing, int steps_since_anchor);
// Rebuilds ph as the ROS2 steps of h (s) that reached (q, qdot) would have left it: num_anchors (0, 1 or 2)
// exact path evaluations at anchor_q (num_anchors x num_dofs, rad, oldest first), anchor_spacing steps apart
// (1 or kRos2PathPeriod; 0 with one anchor), the newest steps_since_anchor steps before. The paths at the anchors
// are evaluated again, the same function of the same q, so that a restored state continues bit for bit; h <= 0
// or num_anchors = 0 clears it. Throws std::invalid_argument for counts path_history_error refuses.
void path_history_restore(const Model& m, PathHistory& ph, const double* q, const double* qdot, const double* anchor_q,
                          int num_anchors, int anchor_spacing, int steps_since_anchor, double h);

}  // namespace armrt
