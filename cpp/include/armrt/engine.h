// The simulation stages, one per file under cpp/src/ (each file opens with its in -> out contract):
//   muscle.cc          Hill-type muscle element: tendon force and contractile-element velocity
//   forward.cc         the state derivative: the stages below in order
//     muscles.cc         excitation, paths, CE state -> activation/CE rates, forces, tau_muscle
//     passive_joints.cc  q, qd -> tau_passive
//     external_loads.cc  q, hand load -> tau_ext
//     girdle.cc          q -> tau_girdle (scapulothoracic contact, conoid ligament; das3)
//     skeleton.cc        q, qd, tau -> M(q), qdd
//     gh_reaction.cc     q, qd, qdd, forces, hand load -> GH force and stability
//   inverse_dynamics.cc q, qd, qdd, hand load -> tau_muscle the muscles must supply (forward's equation solved for it)
//   stepper.cc       step(model, data, stepper, n): control steps, substeps, TET; error messages
//   integrate.cc     one integration step: explicit Euler and RK4, ROS2 (ros2.cc); the state check
//   ros2.cc          the linearly implicit ROS2 step: its two stages, the step-halving mode
//   step_jacobian.cc the structured Jacobian's factorisation and Schur-complement solve
//   fibre_limiter.cc ROS2's limit on a CE running through its operating point within a step
//   path_history.cc  ROS2's path anchors and extrapolation
//   cvode.cc         SUNDIALS CVODE (BDF), the accurate reference
//   stimulation.cc   FES channels -> recruitment, Ding calcium/force/fatigue -> element activation targets
//   stimulation_map.cc a lab's stimulation map (JSON/TOML) -> StimulationMap, the electrode kinds' defaults
//   kinematics.cc    outputs derived from q: thorax-humerus angles
//   linearize.cc     df/dx, df/du of forward() and A = dx+/dx, B = dx+/du of one ROS2 step
#pragma once

#include <cstdint>
#include <string>

#include "armrt/data.h"
#include "armrt/model.h"
#include "armrt/muscle_kernel.h"
#include "armrt/stepper.h"

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
// CE length (m) at which the element's fibre velocity is fibre_velocity (m/s) at muscle-tendon length L (m) and
// activation a: the control side's model of a muscle's force as a function of its activation (static
// optimisation, docs/control.md). Safeguarded Newton from lce_guess (m; outside the bracket or NaN: its middle).
// Unlike muscle_equilibrium_lce, a relaxed slack unit's fibre may end anywhere in its force-free range.
double muscle_lce_at_velocity(const ElementConstants& e, double fibre_damping, double L, double a, double fibre_velocity,
                              double lce_guess);
// The tendon force (N) at that CE length and its derivative with respect to a along that family of states.
struct SteadyForce {
  double lce = 0;        // m
  double force = 0;      // N
  double dforce_da = 0;  // N per unit activation
};
SteadyForce muscle_steady_force(const ElementConstants& e, double fibre_damping, double L, double a, double fibre_velocity,
                                double lce_guess);
// The rigid-tendon approximation of the same element (tendon at its slack length, lce from L and the
// thickness, the fibre velocity from dL/dt): tendon force = a force_per_activation + passive_force (N), linear
// in a. The damper's low-activation floor (muscle.cc) is left out (it multiplies the fibre velocity).
struct RigidTendonForce {
  double lce = 0;                   // m
  double force_per_activation = 0;  // N: fmax f(lce) g(v) cos(pennation)
  double passive_force = 0;         // N: (PEE - compressive element + damper) cos(pennation)
};
RigidTendonForce muscle_rigid_tendon_force(const ElementConstants& e, double fibre_damping, double L, double dL_dt);

// ---- forward.cc (the pipeline) and its stage files
// Evaluates dx/dt at state x into xdot. With record = true also fills the outputs of d (the q they
// describe, path lengths, forces, qdd, hand position, GH force and stability); with a non-null jac also the parts of the
// structured Jacobian at x (data.h StepJacobian), in the same pass over the elements.
void forward(const Model& m, Data& d, const double* x, double* xdot, bool record, StepJacobian* jac = nullptr);
// forward() after its paths stage, with the muscle-tendon lengths L (m, num_elements) and moment arms R (m, by
// DOF as ModelDef::muscle_paths writes them) at x's q given: for ROS2's second stage, whose paths are
// extrapolated (ros2.cc).
void forward_from_paths(const Model& m, Data& d, const double* x, const double* L, const double* R, double* xdot,
                        bool record, StepJacobian* jac = nullptr);
// muscles.cc. The muscle stage of forward(): activation dynamics and CE velocity of every element (a vectorised
// loop) with the arm's constants mc (Data::muscles), their tendon forces (N) and the generalised muscle forces
// tau = R^T F (N m). The excitation is capped at mc.max_activation here, the one place the cap is applied.
// Elements a stimulation map drives (drive != nullptr and drive->driven[i]) follow drive's target and rate instead
// (stimulation.cc): da/dt = rate (target - a).
struct ActivationDrive {
  const double* driven;        // num_elements: 1.0 where the map drives the element, else 0.0
  const double* target;        // [0, max_activation]
  const double* rate;          // 1/s
};
void muscle_dynamics(const Model& m, const MuscleArrays& mc, const double* excitation, const double* muscle_length,
                     const double* moment_arm, const double* act, const double* lce, double* act_dot,
                     double* lce_dot, double* force, double* tau, StepJacobian* jac = nullptr,
                     const ActivationDrive* drive = nullptr);
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
// The largest hand load any input takes (N, N m; |.| of the three components): 1e5 N is ten tonnes in the hand.
// A load that large is a wrong unit, not a load: 1e5 N already throws das2 past the joint-speed bound in its first
// step, 1e7 N and more did so at once, and ProxQP's closest-solution QPs ran for minutes at 1e16 N.
inline constexpr double kMaxHandForce = 1e5;   // N
inline constexpr double kMaxHandMoment = 1e4;  // N m
// "" or why a hand force (moment false: N, against kMaxHandForce) or moment (N m, kMaxHandMoment), three finite values,
// is refused: "<what> of <|v|> N is beyond 1e+05 N, more than any arm bears (check the units)", |v| by std::hypot
// (no overflow) in the shortest form that round-trips, so a value one ulp beyond shows it. The one rule of
// Arm.set_hand_load, the snapshots, inverse dynamics, static optimisation and armrt-rt (checks.hand_load calls it).
std::string hand_load_error(const char* what, const double* v, bool moment);
// girdle.cc. Generalised forces tau (N m) of the girdle's contact and conoid forces at q (zero for a model
// with a fixed girdle); with a non-null stiffness also d tau/dq (n x n row-major, N m/rad), with a
// non-null state the contact distances and forces and the conoid's length and tension.
void girdle_forces(const Model& m, const double* q, double* tau, double* stiffness, GirdleState* state);
// skeleton.cc. M(q) (n x n, row-major, kg m^2) and qdd (rad/s^2) from M qdd = tau + b(q, qd, g), gravity g
// (m/s^2, base frame).
void skeleton_dynamics(const Model& m, const double* gravity, const double* q, const double* qd, const double* tau,
                       double* M, double* qdd);
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
// acceleration under gravity (m/s^2, base frame); its angles, GHstab and margin to the rim.
void gh_reaction(const Model& m, const double* gravity, const double* q, const double* qd, const double* qdd, const double* force,
                 const double* f_ext_base, double* gh_force, GHStability* stab);
// GH stability of a force of the humeral head on the glenoid (scapula frame): the one definition of
// theta, phi, GHstab (the paper's eq. (5)), the rim direction and the margin (docs/conventions.md).
GHStability gh_stability(const ModelDef& def, const double* force);
// Rim direction psi and margin (rad) of the angles theta, phi (rad) on a rim of half-angles theta_a, phi_a:
// the part of gh_stability that needs no glenoid basis (a recorded result's angles are enough).
void gh_rim(double theta, double phi, double theta_a, double phi_a, double* direction, double* margin);

// inverse_dynamics.cc. (q, qd, qdd, hand load, gravity) -> the generalised forces the muscles must supply,
// tau_muscle = M(q) qdd - b(q, qd, g) - tau_passive - tau_ext - tau_girdle (N m), forward()'s equation solved
// for tau_muscle; with its parts and the GH force (N, scapula frame) of everything but the muscles (hand load,
// weight, minus the arm's momentum rate): the GH force is that plus sum_i F_i dir_i.
struct InverseDynamics {
  double tau_muscle[kMaxDofs];
  double mass_times_qdd[kMaxDofs];
  double bias[kMaxDofs];     // b(q, qd, g): gravity and velocity products, on the right-hand side
  double passive[kMaxDofs];
  double external[kMaxDofs];
  double girdle[kMaxDofs];
  double gh_force_without_muscles[3];
};
void inverse_dynamics(const Model& m, const double* gravity, const double* q, const double* qd, const double* qdd,
                      const double* hand_force, const double* hand_moment, InverseDynamics* out);

// ---- integrate.cc
// Where a state vector x leaves the physical domain (model.h) of an arm with d's settings: kOk, or the status
// a step ending there would get and what went bad.
struct DomainCheck {
  Status status = Status::kOk;
  int bad_index = -1;    // state index, or -1
  int bad_contact = -1;  // girdle contact point too deep in the thorax, or -1
  double bad_contact_distance = 0;  // m, its signed distance
};
DomainCheck check_domain(const Model& m, const Data& d, const double* x);
// Whether d.x lies in the physical domain; sets d.status (and what went bad) and returns false otherwise.
bool check_state(const Model& m, Data& d);
// What is outside the domain for a kOutOfDomain check of x, e.g. "q[GHy] = 4 rad is more than 0.35 rad beyond
// its range [-1.2, 1.5] rad" (stepper.cc; step_error_message and the snapshot checks say it).
std::string domain_problem(const Model& m, const Data& d, const double* x, const DomainCheck& c);
const char* state_name(const Model& m, int index, char* buf, int buflen);

// ---- ros2.cc
// One ROS2 step of h (s) from d.x in s's workspace (no TET, no state check: integrate() adds it). When the step
// continues s.ros2.path_history its second stage extrapolates the paths, and so do all but one step in
// kRos2PathPeriod their first stage's; the others evaluate the polynomials.
void step_ros2(const Model& m, Data& d, Ros2Workspace& w, double h, bool record);
// One ROS2 step of h, redone as two steps of h/2 when the embedded error estimate exceeds the tolerances
// (kRos2AdaptiveTol*). Returns the number of steps taken (1 or 2). Not for hard real time: a halved step
// costs about three normal ones.
int step_ros2_adaptive(const Model& m, Data& d, Ros2Workspace& w, double h, bool record);

// ---- fibre_limiter.cc
// For every element whose CE would run through its operating point within a ROS2 step of h (s) (a slack
// tendon engaging), stiffens jac's CE mode so that the step stops there. Call it after
// forward(m, d, x, xdot, ..., &jac) at the same x: it reads what that evaluation left in jac. Adds the
// element-steps it changed to d.limited_fibre_steps.
void limit_fibre_overshoot(const Model& m, Data& d, StepJacobian& jac, const double* x, const double* xdot, double h);
// The same with the muscle-tendon lengthening rates dL/dt (m/s, per element) given instead of -R qd from x's qd
// and jac's moment arms: the limiter's only dependence on qd, which linearize() differentiates through it.
void limit_fibre_overshoot_at_rates(const Model& m, Data& d, StepJacobian& jac, const double* x, const double* xdot,
                                    double h, const double* L_rate);

// ---- linearize.cc
// The full tangent of forward() at one state: the structured Jacobian (jac, as forward() fills it: no fibre
// limiter) and the mechanical terms it leaves out.
struct ForwardTangent {
  StepJacobian jac;
  std::array<double, kMaxElements> force{};                     // N, tendon forces at the state
  std::array<double, kMaxDofs * kMaxDofs> dqdd_dq{};            // 1/s^2, full d qdd/dq, nq x nq row-major
  std::array<double, kMaxDofs * kMaxDofs> dqdd_dqd{};           // 1/s, full d qdd/d qd
  std::array<double, kMaxDofs * kMaxDofs> inv_mass_matrix{};    // 1/(kg m^2), M^-1
  std::array<double, kMaxDofs * kMaxElements> accel_per_force{};  // rad/s^2/N, M^-1 R^T by DOF (stride kMaxElements)
  std::array<double, kMaxElements> act_rate_du{};               // 1/s, d(da/dt)/du
  std::array<double, kMaxElements> act_rate_dlag{};             // 1/s, d(c1 u + c2)/du
  std::array<double, kMaxDofs * kMaxElements> scratch_moment_arm{};  // m, paths at the difference points
};
// What linearize() works in: fixed size (about 1.6 MB: hold it on the heap), so no call allocates.
struct LinearizeWorkspace {
  ForwardTangent at_x, at_x2;  // the tangent at x and at the second stage x2 = x + h k1
  StepJacobian step_jacobian;  // the step's own J (fibre limiter applied) and its factorisation
  StateVec f{}, k1{}, x2{}, f2{}, k2{};  // the step's stages, as ros2.cc forms them
  StateVec x_next{};  // x + h (3/2 k1 + 1/2 k2): where the step lands (written with A and B), as step_ros2 from x
  StateVec r{}, dk1{}, dk2{}, y{};       // one column's right-hand side and stage derivatives
  // How the step's J moves with x and u (W is not frozen: A and B differentiate the real step). Per element, the
  // derivatives of (dvel_dL, dvel_dlce, dvel_da, dforce_dL, dforce_dlce) with the element's own lce, activation and
  // excitation (each depends on its element's alone, so all elements are perturbed at once); per joint angle and
  // velocity, dJ/dx_c k1 and dJ/dx_c k2 (forward differences of J, by the chain rule through the entries below).
  // ... and with the element's muscle-tendon length L and lengthening rate dL/dt (through the fibre limiter), which
  // is how they move with the joint angles and velocities.
  std::array<std::array<double, kMaxElements>, 5> dJ_dlce{}, dJ_da{}, dJ_du{}, dJ_dL{}, dJ_dLrate{};
  std::array<StateVec, 2 * kMaxDofs> dJ_k1{}, dJ_k2{};
  // The paths L (m), R (m, by DOF, stride kMaxElements) and M(q) (kg m^2) at q + 1e-6 rad e_k for each joint k: the
  // tangent's difference points, where J moves with q_k too.
  std::array<std::array<double, kMaxElements>, kMaxDofs> length_plus{};
  std::array<std::array<double, kMaxDofs * kMaxElements>, kMaxDofs> moment_arm_plus{};
  std::array<std::array<double, kMaxDofs * kMaxDofs>, kMaxDofs> mass_matrix_plus{};
  std::array<double, kMaxElements> R_k1{}, R_k2{};  // m/s, R k_q of the two stages per element
  StepJacobian jac_plus, jac_minus;                 // J at the difference points
  StateVec x_shift{}, f_shift{};
  // The columns of A and B are formed kLinearizeTile at a time, each tile a (state, column) array with the columns
  // side by side, so that every operation runs over the tile's columns in SIMD lanes.
  static constexpr int kTile = 16;
  std::array<double, kMaxState * kTile> tile_r{}, tile_dk1{}, tile_y{}, tile_dk2{};
  // The 3 n element columns (each element's lce, activation, excitation; column c = type * n + element) in block form
  // (linearize.cc "Element columns"): DOF rows [dof][column] of the stage derivatives and of one right-hand side,
  // each column's own entries (its element's lce and activation rows), and the joint-space matrices of the low-rank
  // CE-length rows.
  static constexpr int kElementColumns = 3 * kMaxElements;
  std::array<double, kMaxDofs * kElementColumns> ec_q1{}, ec_qd1{}, ec_q2{}, ec_qd2{}, ec_rq{}, ec_rqd{}, ec_rhs{};
  std::array<double, kElementColumns> ec_lce1{}, ec_act1{}, ec_lce2{}, ec_act2{}, ec_rl{}, ec_ra{};
  std::array<double, kMaxElements> ec_d1{}, ec_d2{}, ec_d3{}, ec_d4{};  // per-element diagonals of the low-rank terms
  std::array<double, kMaxDofs * kMaxDofs> ec_P{};
};
// At d.x with d's excitation u (num_elements, as the dynamics use it) and loads: df/dx (ns x ns, row-major,
// ns = state_size) and df/du (ns x num_elements) of forward(); with A non-null also A = dx+/dx (ns x ns) and
// B = dx+/du (ns x num_elements) of one ROS2 step of h (s) taken with exact paths at both stages (a step from a
// state set from outside), W = I - h gamma J differentiated too (J's own derivatives by central differences, the
// fibre limiter's stiffening included), and w.x_next: where that step lands, the same arithmetic as step_ros2's
// from a state set from outside (its domain is not checked: check_domain(m, d, w.x_next) as integrate() does).
// d's state, inputs and statistics are unchanged. Throws std::invalid_argument when d has a stimulation map (the
// driven elements follow the stimulation stage's memory, not part of x) or for h <= 0.
void linearize(const Model& m, Data& d, LinearizeWorkspace& w, double h, double* dfdx, double* dfdu, double* A,
               double* B);

// ---- kinematics.cc
// Thorax-humerus angles (rad): plane of elevation, elevation, axial rotation (Y-Z-Y sequence in the
// DSEM thorax axes: plane 0 = abduction in the frontal plane, 90 deg = forward flexion).
void thorax_humerus_angles(const Model& m, const double* q, double* angles);

// ---- stimulation.cc
// Installs a map (num_channels 0: none, excitation drives every element): zero commands, rested channels.
void data_set_stimulation_map(const Model& m, Data& d, const StimulationMap& map);
// Rested channels (no pulse yet, no fatigue), commands kept.
void stimulation_reset(Data& d);
// The stage: advances the channels over [d.time, d.time + h] and sets the driven elements' targets and rates.
void stimulation_advance(const Model& m, Data& d, double h);
// Queues explicit pulse times (s, increasing, not before d.time) on a channel; throws std::invalid_argument
// beyond kMaxQueuedPulses or for times out of order.
void stimulation_queue_pulses(const Model& m, Data& d, int channel, const double* times, int count);
// 1 - A/A_rest of channel k now.
double channel_fatigue(const Data& d, int k);
// The chain's memory one row of kStimStateSize per channel (the snapshot's and the Python API's order), out of
// Data's by-column storage (stimulation.h stim_state_index), and back in.
void stimulation_state_by_channel(const Data& d, double* out);
void set_stimulation_state_by_channel(Data& d, const double* in);

}  // namespace armrt
