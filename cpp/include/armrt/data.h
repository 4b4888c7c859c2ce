// Data: everything that changes during a simulation (like mjData / pinocchio::Data): the state, the
// inputs, the outputs of the last forward() and the integrators' workspace. Fixed-size: creating one
// allocates nothing afterwards, and stepping never touches the heap.
#pragma once

#include <array>
#include <cstdint>

#include "armrt/model.h"

namespace armrt {

// State vector layout: [q (num_dofs) | qdot (num_dofs) | lce (num_elements) | activation (num_elements)].
// These offsets are the one definition of the layout (the Python API reads them from armrt._core).
inline int q_offset(const Model&) { return 0; }
inline int qd_offset(const Model& m) { return m.num_dofs; }
inline int lce_offset(const Model& m) { return 2 * m.num_dofs; }
inline int act_offset(const Model& m) { return 2 * m.num_dofs + m.num_elements; }
inline int state_size(const Model& m) { return 2 * m.num_dofs + 2 * m.num_elements; }

using StateVec = std::array<double, kMaxState>;

// Running statistics of the task execution time, in nanoseconds.
struct TetStats {
  std::int64_t count = 0;
  double last_ns = 0, min_ns = 0, max_ns = 0, mean_ns = 0;
  void add(double ns) {
    if (count == 0 || ns < min_ns) min_ns = ns;
    if (count == 0 || ns > max_ns) max_ns = ns;
    ++count;
    mean_ns += (ns - mean_ns) / static_cast<double>(count);
    last_ns = ns;
  }
};

// The structured ("arrow") Jacobian of forward() at one state, filled by forward(..., jac) and
// factored by rosenbrock.cc (docs/engine.md): per-element derivatives of the muscle kernel, the moment
// arms and mass matrix at that state, and the passive joint stiffness and damping. Moment-arm
// derivatives, gravity, Coriolis and dM/dq are left out (docs/engine.md says why).
struct StepJacobian {
  // Filled by forward() with a non-null jac.
  std::array<double, kMaxElements> dforce_dL{};    // N/m, tendon force vs muscle-tendon length
  std::array<double, kMaxElements> dforce_dlce{};  // N/m, tendon force vs CE length
  std::array<double, kMaxElements> dvel_dL{};      // 1/s, CE velocity vs muscle-tendon length
  std::array<double, kMaxElements> dvel_dlce{};    // 1/s, CE velocity vs CE length
  std::array<double, kMaxElements> dvel_da{};      // m/s, CE velocity vs activation
  std::array<double, kMaxElements> act_rate{};     // 1/s, -d(activation rate)/d(activation) = c1 u + c2
  // The kernel's lce-only terms at this state (MuscleDerivatives), for limit_fibre_overshoot.
  std::array<double, kMaxElements> force_length{};    // f(lce)
  std::array<double, kMaxElements> lce_along{};       // m, lce cos(pennation)
  std::array<double, kMaxElements> cos_pennation{};   // lce_along / lce
  std::array<double, kMaxElements> inv_cos_pennation{};  // lce / lce_along
  std::array<double, kMaxElements> pee_force{};       // N
  std::array<double, kMaxElements> compress_force{};  // N
  std::array<double, kMaxElements> muscle_length{};          // m
  std::array<double, kMaxDofs * kMaxElements> moment_arm{};  // m, by DOF: [dof][element], row stride kMaxElements (model_def.h)
  std::array<double, kMaxDofs * kMaxDofs> mass_matrix{};     // kg m^2, num_dofs x num_dofs row-major
  std::array<double, kMaxDofs> dtau_passive_dq{};   // N m/rad, diagonal
  std::array<double, kMaxDofs> dtau_passive_dqd{};  // N m s/rad, diagonal
  std::array<double, kMaxDofs * kMaxDofs> dtau_girdle_dq{};  // N m/rad, girdle contact and conoid (girdle.cc)

  // Factorisation of I - h gamma J for one h gamma (rosenbrock.cc).
  double hg = 0;                                    // s, h * gamma it was built for
  std::array<double, kMaxElements> inv_act{};       // 1 / (1 + hg act_rate)
  std::array<double, kMaxElements> inv_lce{};       // 1 / (1 - hg dvel_dlce)
  std::array<double, kMaxElements> lce_from_q{};    // hg dvel_dL / (1 - hg dvel_dlce), m/m
  std::array<double, kMaxElements> series_stiffness{};  // N/m, dforce_dL + dforce_dlce * lce_from_q
  std::array<double, kMaxDofs * kMaxDofs> schur_lu{};   // LU of the num_dofs x num_dofs Schur complement
  std::array<int, kMaxDofs> schur_perm{};               // its row permutation
  std::array<double, kMaxDofs> schur_inv_diag{};        // 1 / U's diagonal
  std::array<double, kMaxDofs * kMaxDofs> stiffness{};  // N m/rad, K_eff = diag(dtau_passive_dq) + dtau_girdle_dq - R^T diag(series_stiffness) R
  std::array<double, kMaxElements> tmp{};               // scratch of one solve
};

// What ROS2 extrapolates the muscle paths from (rosenbrock.cc): the last two exact evaluations of the path
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

// The girdle stage's outputs (girdle.cc), for models whose scapula moves.
struct GirdleState {
  std::array<double, kMaxContactPoints> contact_distance{};  // m, first-order signed distance of TS, AI from
                                                             // the thorax surface (negative: penetrating)
  std::array<double, kMaxContactPoints> contact_force{};     // N, magnitude of each contact force
  double conoid_length = 0;   // m
  double conoid_tension = 0;  // N
};

// kOutOfDomain: a CE length outside [min_lce, max_lce], an activation outside [0, 1], a joint more than
// kJointRangeMargin beyond its range or a girdle contact point more than kMaxContactPenetration inside the
// thorax (model.h): the step left the model's physical domain.
// kUnstableStep: an explicit step (Euler, RK4) beyond its stability limit for the stiffest CE mode of the
// model at rest (Model::rest_fibre_rate): refused before it is taken (integrate.cc).
enum class Status { kOk = 0, kNonFinite = 1, kTooFast = 2, kCvodeFailed = 3, kOutOfDomain = 4, kUnstableStep = 5 };

// Grouped like mjData and pinocchio::Data: state, inputs, then the outputs of forward() by the stage
// that fills them (forward.cc lists the stages; outputs are filled only with record = true and describe
// the state forward() was evaluated at), then errors, statistics and workspace.
struct Data {
  // State.
  double time = 0;   // s
  StateVec x{};      // [q | qdot | lce | activation], offsets above

  // Inputs.
  std::array<double, kMaxElements> excitation{};  // neural excitation u in [0, 1]
  std::array<double, 3> hand_force{};   // N, applied at the hand point, thorax frame
  std::array<double, 3> hand_moment{};  // N m, applied to the hand, thorax frame

  // The joint angles the outputs describe (rad): the moment arms there are muscle_paths(output_q) (not copied
  // at every recorded step: 1.5 k doubles for das3, 3 % of its step).
  std::array<double, kMaxDofs> output_q{};
  // Paths (generated polynomials).
  std::array<double, kMaxElements> muscle_length{};          // m, muscle-tendon length
  // Muscles (muscles.cc).
  std::array<double, kMaxElements> muscle_force{};   // N, tendon (SEE) force
  std::array<double, kMaxElements> fibre_velocity{}; // m/s, d lce/dt (lengthening positive)
  std::array<double, kMaxDofs> muscle_torque{};      // N m, generalised muscle forces R^T F
  // Passive joints (passive_joints.cc).
  std::array<double, kMaxDofs> passive_torque{};     // N m
  // External loads (external_loads.cc).
  std::array<double, kMaxDofs> external_torque{};    // N m, from the hand force and moment
  std::array<double, 3> hand_position{};             // m, thorax frame
  // Girdle forces (girdle.cc; zero for a fixed girdle).
  std::array<double, kMaxDofs> girdle_torque{};      // N m
  GirdleState girdle{};
  // Skeleton (skeleton.cc).
  std::array<double, kMaxDofs> qdd{};                // rad/s^2
  // GH reaction (gh_reaction.cc).
  std::array<double, 3> gh_force{};       // N, humeral head on glenoid, scapula frame
  double gh_theta = 0, gh_phi = 0;        // rad, from the glenoid normal along the major / minor axis
  double gh_stab = 0;                     // (theta/theta_a)^2 + (phi/phi_a)^2; > 1: dislocating
  double gh_rim_direction = 0;            // rad, psi = atan2(phi, theta): 0 superior, pi/2 anterior (GHStability)
  double gh_rim_margin = 0;               // rad, how far the force can still turn along psi to the rim; < 0 beyond

  // Errors: set by step(), never thrown in the hot path.
  Status status = Status::kOk;
  int bad_index = -1;  // state index that went bad
  int bad_contact = -1;  // kOutOfDomain by a girdle contact point (index) too deep in the thorax, else -1
  double bad_contact_distance = 0;  // m, its signed distance
  double bad_time = 0;

  // Statistics.
  TetStats tet;                          // wall time of whole control steps (Simulator::step)
  std::int64_t halved_steps = 0;         // ROS2 steps redone as two halves (Integrator::kRos2Adaptive)
  std::int64_t limited_fibre_steps = 0;  // ROS2: element-steps whose CE mode was stiffened (rosenbrock.cc)

  // Integrator workspace.
  StateVec k1{}, k2{}, k3{}, k4{}, xtmp{};
  StepJacobian jac;  // linearly implicit steps (rosenbrock.cc)
  PathHistory path_history;  // ROS2's path extrapolation (rosenbrock.cc)
};

void data_reset(const Model& m, Data& d, const double* q /* num_dofs or nullptr: rest posture */);

}  // namespace armrt
