// Stepper: how one arm is advanced in time (integrator, control step, substeps) and that integrator's own
// workspace and memory. step(model, data, stepper, n) is the one entry point that advances a Data; like
// MuJoCo's mj_step it reads the Model, changes the Data, and keeps nothing of its own but the integrator's.
#pragma once

#include <memory>
#include <string>

#include "armrt/data.h"
#include "armrt/model.h"
#include "armrt/path_history.h"
#include "armrt/step_jacobian.h"

namespace armrt {

class CvodeIntegrator;

// Integrator choices: the paper's explicit Euler and RK4, CVODE (BDF) as the accuracy reference, and the
// linearly implicit ROS2 (ros2.cc), fixed-step or with one level of step halving (offline only).
enum class Integrator { kEuler = 0, kRk4 = 1, kCvode = 2, kRos2 = 3, kRos2Adaptive = 4 };

// ROS2's gamma (Verwer et al. 1999): 1 + 1/sqrt(2), L-stable.
inline constexpr double kRos2Gamma = 1.7071067811865475;
// Error tolerances of the ROS2 step-halving mode (ros2.cc): joint angles (rad) and CE lengths (x lceopt) of
// the embedded error estimate.
inline constexpr double kRos2AdaptiveTolQ = 1e-5;
inline constexpr double kRos2AdaptiveTolLce = 1e-3;
// The longest control step (s) a Stepper takes: inputs are held for a control step, and nothing the arm
// does is slower than a second (activation time constants are 10-40 ms).
inline constexpr double kMaxControlStep = 1.0;
// The most substeps of one control step: 1e5 (10 us steps in the longest control step, 10 ns in a 1 ms one)
// is far below any integrator's accurate step and keeps a control step's cost bounded (armrt.integrators
// MAX_SUBSTEPS refuses the same).
inline constexpr int kMaxSubsteps = 100000;

Integrator parse_integrator(const std::string& name);  // "ros2", "ros2_adaptive", "euler", "rk4", "cvode"; throws std::invalid_argument
const char* integrator_name(Integrator integrator);
// Largest integration step (s) the integrator takes by default inside a control step: ROS2 1 ms (one
// step per 1 ms control step), its step-halving mode 2 ms, RK4 0.17 ms (6 per 1 ms), Euler 0.1 ms, inside
// what the solver studies found accurate on the paper's tasks (docs/engine.md); CVODE picks its own (inf).
double default_max_step(Integrator integrator);
// Substeps of at most default_max_step(integrator) that make up a control step dt.
int default_substeps(Integrator integrator, double dt);
// Whether the integrator's cost per step is fixed (usable for hard real time): not CVODE, not ros2_adaptive.
bool is_fixed_cost(Integrator integrator);
// Real stability interval [-limit, 0] of an explicit integrator (Euler 2, RK4 2.785; infinity otherwise).
double explicit_stability_limit(Integrator integrator);

// Euler's and RK4's stages.
struct ExplicitWorkspace {
  StateVec k1{}, k2{}, k3{}, k4{};  // state derivatives at the stages
  StateVec x_stage{};               // the state a stage is evaluated at
};

// ROS2's workspace and memory (ros2.cc).
struct Ros2Workspace {
  StateVec f{};        // f(x_n)
  StateVec k1{};       // first stage: (I - h gamma J) k1 = f(x_n)
  StateVec x2{};       // x_n + h k1
  StateVec f2{};       // f(x2) - 2 k1
  StateVec k2{};       // second stage: (I - h gamma J) k2 = f(x2) - 2 k1
  StepJacobian jac;    // the structured Jacobian at x_n, and its factorisation
  PathHistory path_history;  // memory: what the next step's paths are extrapolated from
};

struct Stepper {
  Integrator integrator = Integrator::kRos2;
  double dt = 1e-3;   // s, the control step: inputs are held and outputs reported once per dt
  int substeps = 1;   // integration steps of dt / substeps per control step (CVODE: its own)
  ExplicitWorkspace explicit_ws;
  Ros2Workspace ros2;
  std::unique_ptr<CvodeIntegrator> cvode;  // bound to one Data (stepper_init)
  StateVec scratch{};  // derivative that evaluate_outputs() discards

  Stepper();
  ~Stepper();
  Stepper(Stepper&&) noexcept;
  Stepper& operator=(Stepper&&) noexcept;
};

// Sets s up for integrator, control step dt (s) and substeps integration steps per control step, to step d
// (CVODE is bound to d). Throws std::invalid_argument for dt outside (0, kMaxControlStep] or substeps outside
// [1, kMaxSubsteps].
void stepper_init(const Model& m, Data& d, Stepper& s, Integrator integrator, double dt, int substeps = 1);
// Forgets the integrator's memory (ROS2's path history, CVODE's): after d's state was set from outside.
void stepper_restart(const Model& m, Data& d, Stepper& s);

// Advances d by n control steps of s.dt (each s.substeps integration steps); stops at the first step that
// diverges (d.status says why, false returned). With record, each control step's outputs describe the state
// it started from (forward() at its first stage); without, the outputs are left as they were. d.tet holds the
// wall time of whole control steps: the task execution time that must stay below dt in real time. Never
// allocates except with CVODE.
bool step(const Model& m, Data& d, Stepper& s, long n = 1, bool record = true);
// The outputs (forces, GH stability, ...) at d's current state, without advancing.
void evaluate_outputs(const Model& m, Data& d, Stepper& s);
// One integration step of h (s) by s.integrator (not CVODE), then the state check; no TET.
bool integrate(const Model& m, Data& d, Stepper& s, double h, bool record = true);

// Describes d.status for an error message: which state, when, and for an unstable explicit step what to use.
std::string step_error_message(const Model& m, const Data& d, const Stepper& s);

}  // namespace armrt
