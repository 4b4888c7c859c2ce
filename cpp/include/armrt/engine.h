// The simulation stages, one per file under cpp/src/ (each file opens with its in -> out contract):
//   muscle.cc          Hill-type muscle element: tendon force and contractile-element velocity
//   forward.cc         the state derivative: the stages below in order
//     muscles.cc         excitation, paths, CE state -> activation/CE rates, forces, tau_muscle
//     passive_joints.cc  q, qd -> tau_passive
//     external_loads.cc  q, hand load -> tau_ext
//     girdle.cc          q -> tau_girdle (scapulothoracic contact, conoid ligament; das3)
//     skeleton.cc        q, qd, tau -> M(q), qdd
//     gh_reaction.cc     q, qd, qdd, forces, hand load -> GH force and stability
//   integrate.cc     fixed-step Euler, RK4 and ROS2 (TET: Simulator::step, simulator.cc)
//   rosenbrock.cc    the linearly implicit ROS2 step: structured Jacobian, Schur-complement solve
//   cvode.cc         SUNDIALS CVODE (BDF), the accurate reference
//   kinematics.cc    outputs derived from q: thorax-humerus angles
#pragma once

#include <string>

#include "armrt/data.h"
#include "armrt/model.h"
#include "armrt/muscle_kernel.h"

namespace armrt {

// ---- muscle.cc
struct MuscleOut {
  double force;          // N, SEE (tendon) force
  double fibre_velocity; // m/s, d lce / dt
};
// One element: muscle-tendon length L (m), contractile-element length lce (m), activation a.
MuscleOut muscle_element(const ElementConstants& e, double fibre_damping, double L, double lce, double a);
// The same with the kernel's derivatives (muscle_kernel.h), for scalar uses outside the vectorised loop.
MuscleOut muscle_element_derivatives(const ElementConstants& e, double fibre_damping, double L, double lce, double a,
                                     MuscleDerivatives* der);
// Contractile-element length at which the element is in static equilibrium (zero fibre velocity)
// at muscle-tendon length L and activation a; used to start simulations without transients.
double muscle_equilibrium_lce(const ElementConstants& e, double fibre_damping, double L, double a);

// ---- forward.cc (the pipeline) and its stage files
// Evaluates dx/dt at state x into xdot. With record = true also fills the outputs of d (the q they
// describe, path lengths, forces, qdd, hand position, GH force and stability); with a non-null jac also the parts of the
// structured Jacobian at x (data.h StepJacobian), in the same pass over the elements.
void forward(const Model& m, Data& d, const double* x, double* xdot, bool record, StepJacobian* jac = nullptr);
// forward() after its paths stage, with the muscle-tendon lengths L (m, num_elements) and moment arms R (m, by
// DOF as ModelDef::muscle_paths writes them) at x's q given: for ROS2's second stage, whose paths are
// extrapolated (rosenbrock.cc).
void forward_from_paths(const Model& m, Data& d, const double* x, const double* L, const double* R, double* xdot,
                        bool record, StepJacobian* jac = nullptr);
// muscles.cc. The muscle stage of forward(): activation dynamics and CE velocity of every element (a vectorised
// loop), their tendon forces (N) and the generalised muscle forces tau = R^T F (N m).
void muscle_dynamics(const Model& m, const double* excitation, const double* muscle_length,
                     const double* moment_arm, const double* act, const double* lce, double* act_dot,
                     double* lce_dot, double* force, double* tau, StepJacobian* jac = nullptr);
// Generalised forces tau = R^T F (N m) of n element forces F (N) with moment arms R (m) by DOF, as
// ModelDef::muscle_paths writes them (R[j * kMaxElements + i]). With dof_begin and dof_end (Model's
// dof_elements_begin, _end) row j is summed over the elements [dof_begin[j], dof_end[j]) only, the moment
// arms being zero outside; without them over all n.
void generalised_force(const double* moment_arm, const double* force, int n, int ndof, double* tau,
                       const int* dof_begin = nullptr, const int* dof_end = nullptr);
// The model's path polynomials at q (rad, num_dofs): lengths L (m, num_elements) and moment arms (m) as
// (num_elements, num_dofs) by element, row-major, the layout the Python API returns (the generated function
// writes them by DOF, model_def.h).
void muscle_paths_by_element(const ModelDef& def, const double* q, double* L, double* moment_arm);
// passive_joints.cc. Passive joint moments (N m) at q, qd.
void passive_joint_torque(const ModelDef& def, const double* q, const double* qd, double* tau);
// Their derivatives (diagonal): d tau / dq (N m/rad) and d tau / dqd (N m s/rad).
void passive_joint_stiffness(const ModelDef& def, const double* q, double* dtau_dq, double* dtau_dqd);
// external_loads.cc. The hand force (N) and moment (N m), thorax frame, in the base frame (f_ext,
// t_ext) and as generalised forces tau_ext (N m); false (tau_ext zero) when there is no load.
bool external_load(const Model& m, const double* q, const double* hand_force, const double* hand_moment,
                   double* f_ext, double* t_ext, double* tau_ext);
// The hand point (m) in the thorax frame at q.
void hand_position_in_thorax(const Model& m, const double* q, double* p_thorax);
// girdle.cc. Generalised forces tau (N m) of the girdle's contact and conoid forces at q (zero for a model
// with a fixed girdle); with a non-null stiffness also d tau/dq (n x n row-major, N m/rad), with a
// non-null state the contact distances and forces and the conoid's length and tension.
void girdle_forces(const Model& m, const double* q, double* tau, double* stiffness, GirdleState* state);
// skeleton.cc. M(q) (n x n, row-major, kg m^2) and qdd (rad/s^2) from M qdd = tau + b(q, qd, g).
void skeleton_dynamics(const Model& m, const double* q, const double* qd, const double* tau, double* M, double* qdd);
// Solves A x = b for a symmetric positive definite n x n A (row-major, n <= kMaxDofs), e.g. M(q) qdd = tau:
// Cholesky below 8 DOFs, L D L^T (no square roots) from 8.
void solve_spd(const double* A, const double* b, int n, double* x);
// gh_reaction.cc. Where a force of the humeral head on the glenoid points, relative to the glenoid's
// elliptical rim (docs/conventions.md). theta, phi: angles of the force from the normal in the
// (normal, major) and (normal, minor) planes; the rim is (theta/theta_a)^2 + (phi/phi_a)^2 = 1 in the
// (theta, phi) plane, and direction and margin are polar coordinates in that plane.
struct GHStability {
  double theta = 0;          // rad, atan2(F.e_major, F.n): + superior
  double phi = 0;            // rad, atan2(F.e_minor, F.n): + along e_minor (anterior for a right scapula)
  double stab = 0;           // 1, (theta/theta_a)^2 + (phi/phi_a)^2 (the paper's eq. (5)); > 1: beyond the rim
  double rim_direction = 0;  // rad, psi = atan2(phi, theta) in (-pi, pi]: 0 superior, pi/2 anterior; 0 at rho = 0
  double rim_margin = 0;     // rad, r(psi) - rho: how far (theta, phi) can still move along psi before the rim,
                             // rho = |(theta, phi)|, r(psi) the rim's radius along psi; < 0 beyond the rim
};
// gh_reaction.cc. Force of the humeral head on the glenoid (N, scapula frame, which moves with q when the
// girdle does) from the tendon forces F, the hand load f_ext (base frame) and the arm's weight and
// acceleration; its angles, GHstab and margin to the rim.
void gh_reaction(const Model& m, const double* q, const double* qd, const double* qdd, const double* force,
                 const double* f_ext_base, double* gh_force, GHStability* stab);
// GH stability of a force of the humeral head on the glenoid (scapula frame): the one definition of
// theta, phi, GHstab (the paper's eq. (5)), the rim direction and the margin (docs/conventions.md).
GHStability gh_stability(const ModelDef& def, const double* force);
// Rim direction psi and margin (rad) of the angles theta, phi (rad) on a rim of half-angles theta_a, phi_a:
// the part of gh_stability that needs no glenoid basis (a recorded result's angles are enough).
void gh_rim(double theta, double phi, double theta_a, double phi_a, double* direction, double* margin);

// ---- integrate.cc
// Advances d by one step of dt with the fixed-step integrator; with record, the outputs of d describe
// the state at the start of the step. Returns false (and sets d.status) if the state became
// non-finite or a joint moved faster than m.max_joint_speed. (TET is measured by Simulator::step.)
bool step(const Model& m, Data& d, Integrator integrator, double dt, bool record = true);
bool check_state(const Model& m, Data& d);
// Real stability interval [-limit, 0] of an explicit integrator (Euler 2, RK4 2.785; infinity otherwise).
double explicit_stability_limit(Integrator integrator);
const char* state_name(const Model& m, int index, char* buf, int buflen);

// ---- rosenbrock.cc
// Factors I - hg J for the structured Jacobian in jac (filled by forward(..., &jac)); hg = h gamma (s).
void jacobian_factor(const Model& m, StepJacobian& jac, double hg);
// Solves (I - hg J) k = r for state-sized vectors r and k (distinct arrays).
void jacobian_solve(const Model& m, StepJacobian& jac, const double* r, double* k);
// For every element whose CE would run through its operating point within a ROS2 step of h (s) (a
// slack tendon engaging), stiffens d.jac's CE mode so that the step stops there (rosenbrock.cc). Call it
// after forward(m, d, x, xdot, ..., &d.jac) at the same x: it reads what that evaluation left in d.jac.
void limit_fibre_overshoot(const Model& m, Data& d, const double* x, const double* xdot, double h);
// One ROS2 step of h (s) from d.x (no TET, no state check: step() adds both). When the step continues
// d.path_history (data.h PathHistory) its second stage extrapolates the paths, and so do all but one step in
// kRos2PathPeriod their first stage's; the others evaluate the polynomials.
void step_ros2(const Model& m, Data& d, double h, bool record);
// Whether the next ROS2 step of h from d.x continues d.path_history (the last step was of h and ended at d.x's
// q and qdot).
bool ros2_continues_history(const Model& m, const Data& d, double h);
// Rebuilds d.path_history as the ROS2 steps of h (s) that reached d.x would have left it: num_anchors (0, 1 or 2)
// exact path evaluations at anchor_q (num_anchors x num_dofs, rad, oldest first), anchor_spacing steps apart (1
// or 2; 0 with one anchor), the newest steps_since_anchor steps (1 or 2) before d.x (PathHistory). The paths
// at the anchors are evaluated again, the same function of the same q, so that a restored state continues
// bit for bit; h <= 0 or num_anchors = 0 clears it. Throws std::invalid_argument for counts out of range.
// Why (num_anchors, anchor_spacing, steps_since_anchor) is not a ROS2 history a run of steps leaves (the
// counts ros2_restore_history accepts), or "" if it is one.
std::string ros2_history_error(int num_anchors, int anchor_spacing, int steps_since_anchor);
void ros2_restore_history(const Model& m, Data& d, const double* anchor_q, int num_anchors, int anchor_spacing,
                          int steps_since_anchor, double h);
// One ROS2 step of h, redone as two steps of h/2 when the embedded error estimate exceeds the
// tolerances (kRos2AdaptiveTol*). Returns the number of steps taken (1 or 2). Not for hard real time:
// a halved step costs about three normal ones.
int step_ros2_adaptive(const Model& m, Data& d, double h, bool record);

// ---- kinematics.cc
// Thorax-humerus angles (rad): plane of elevation, elevation, axial rotation (Y-Z-Y sequence in the
// DSEM thorax axes: plane 0 = abduction in the frontal plane, 90 deg = forward flexion).
void thorax_humerus_angles(const Model& m, const double* q, double* angles);

}  // namespace armrt
