// Data: everything of one arm that is not the shared Model (like mjData / pinocchio::Data): its settings
// (strength, maximum activation, gravity) with the muscle constants they scale, the state, the inputs, the
// outputs of the last forward(), errors and statistics. The integrator and its workspace are the arm's
// Stepper (stepper.h). Fixed-size: creating one allocates nothing afterwards, and stepping never touches
// the heap.
#pragma once

#include <array>
#include <cstdint>

#include "armrt/layouts.h"
#include "armrt/model.h"
#include "armrt/stimulation.h"

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
// Per-arm settings: set between runs (data_apply_settings derives Data::muscles from them), never by a step.
struct ArmSettings {
  std::array<double, kMaxElements> strength_scale{};  // multiplies DAS3 fmax (1 = intact; weakness < 1)
  std::array<double, kMaxElements> max_activation{};  // [0, 1], the cap on excitation and activation (paralysis)
  std::array<double, 3> gravity{};                    // m/s^2, base frame (e.g. a lying posture)
  double max_joint_speed = kDefaultMaxJointSpeed;     // rad/s; faster means the simulation diverged
};

struct Data {
  // Settings, and what they derive (data_apply_settings).
  ArmSettings settings;
  MuscleArrays muscles{};   // the elements' constants at settings' strength and maximum activation
  // The stiffest CE mode at the rest posture with zero activation: its eigenvalue dvel/dlce (1/s, negative)
  // and element. An explicit step h with h |rate| beyond the method's stability interval cannot hold the
  // resting arm (integrate.cc refuses it).
  double rest_fibre_rate = 0;
  int rest_fibre_element = 0;
  bool settings_applied = false;  // set by data_apply_settings: a Data without it has no muscles (all zero)
  std::uint64_t settings_version = 0;  // counts data_apply_settings calls (outputs_current)

  // State.
  double time = 0;   // s
  StateVec x{};      // [q | qdot | lce | activation], offsets above

  // Inputs.
  std::array<double, kMaxElements> excitation{};  // neural excitation u in [0, 1]
  std::array<double, 3> hand_force{};   // N, applied at the hand point, thorax frame
  std::array<double, 3> hand_moment{};  // N m, applied to the hand, thorax frame
  // N m per DOF, added to the generalised forces as they are (MuJoCo's qfrc_applied): joint friction, an
  // exoskeleton's or a perturbation's moments; held over the steps like the hand load.
  std::array<double, kMaxDofs> applied_moment{};

  // Stimulation (stimulation.h): the map (a setting: which channels reach which elements), each channel's
  // command held over the steps [pulse width (s), amplitude (A), frequency (Hz)] x num_channels, and the chain's
  // memory (StimState x num_channels; part of the snapshot). Without a map (num_channels 0) excitation drives
  // every element; with one, the elements it reaches follow the stimulation and ignore their excitation.
  StimulationMap stimulation_map;
  std::array<double, kMaxChannels * kStimInputs> stimulation{};
  std::array<double, kMaxChannels * kStimStateSize> stimulation_state{};
  // At the start of the last control step (recorded with its start state): each channel's recruitment (the
  // fraction its last pulse recruited) and fatigue (1 - A/A_rest).
  std::array<double, kMaxChannels> recruitment{};
  std::array<double, kMaxChannels> fatigue{};
  // The driven elements' activation ODE over the current control step (stimulation_advance): target, rate (1/s).
  std::array<double, kMaxElements> drive_target{};
  std::array<double, kMaxElements> drive_rate{};

  // Outputs of forward() with record = true: one field per ARMRT_OUTPUTS row (layouts.h gives each its size,
  // unit and the stage that fills it), all describing the state at output_q. The moment arms there are
  // muscle_paths(output_q): not copied at every recorded step (1.5 k doubles for das3, 3 % of its step).
#define ARMRT_X(name, size, ...) ARMRT_STORAGE(size) name{};
  ARMRT_OUTPUTS(ARMRT_X)
#undef ARMRT_X
  // What the outputs were computed from (forward() with record): the whole state, the hand load, gravity and
  // the settings' version. outputs_current() compares them with now, so that outputs are read, not recomputed,
  // while they still describe the arm (and recomputed once when anything they depend on changed).
  StateVec output_state{};
  // hand force (N), hand moment (N m), gravity (m/s^2), applied moments (N m, kMaxDofs)
  std::array<double, 9 + kMaxDofs> output_loads{};
  std::uint64_t output_settings_version = 0;
  bool outputs_computed = false;

  // Errors: set by step(), never thrown in the hot path.
  Status status = Status::kOk;
  int bad_index = -1;  // state index that went bad
  int bad_contact = -1;  // kOutOfDomain by a girdle contact point (index) too deep in the thorax, else -1
  double bad_contact_distance = 0;  // m, its signed distance
  double bad_time = 0;

  // Statistics.
  TetStats tet;                          // wall time of whole control steps (step(), stepper.h)
  std::int64_t halved_steps = 0;         // ROS2 steps redone as two halves (Integrator::kRos2Adaptive)
  std::int64_t limited_fibre_steps = 0;  // ROS2: element-steps whose CE mode was stiffened (fibre_limiter.cc)
};

// The excitation the dynamics use for a command u: clipped to [0, max_activation] (the arm's cap, paralysis or
// weakness, Data::settings). The one rule: the muscle stage applies it, and every path that stores or records an
// excitation (the bindings, the real-time runner) stores what it gives.
inline double capped_excitation(double u, double max_activation) {
  return u < 0.0 ? 0.0 : (u > max_activation ? max_activation : u);
}

// Holds the excitation u (num_elements) over the next steps as the dynamics use it: capped_excitation with d's
// maximum activation. Every writer of d.excitation (the bindings, snapshots, the recorder's excitation rows, the
// real-time runner) goes through it, so that d.excitation reads back what the dynamics use.
void data_set_excitation(const Model& m, Data& d, const double* u);

// A Data for m at its rest posture, with the model's own settings (intact strength, the model file's
// maximum activation and gravity).
void data_init(const Model& m, Data& d);
// Derives d.muscles and the rest fibre rate from d.settings (after a change of strength or maximum activation;
// gravity and the speed bound need nothing), and caps the held excitation at the new maximum activation. Throws std::invalid_argument for a setting out of range.
void data_apply_settings(const Model& m, Data& d);
// Whether d's outputs describe its current state, hand load, applied moments, gravity and settings (computed by forward() with
// record at exactly these).
bool outputs_current(const Model& m, const Data& d);
// What the outputs depend on besides the state and settings, in output_loads' order (9 + kMaxDofs values; the
// applied moments beyond the model's DOFs are 0).
inline void output_loads_of(const Data& d, double* out) {
  for (int k = 0; k < 3; ++k) out[k] = d.hand_force[k], out[3 + k] = d.hand_moment[k], out[6 + k] = d.settings.gravity[k];
  for (int j = 0; j < kMaxDofs; ++j) out[9 + j] = d.applied_moment[j];
}
// One element's constants under d.settings (what d.muscles holds, as a struct): for scalar uses.
ElementConstants data_element(const Model& m, const Data& d, int i);
// Back to time 0 at q (num_dofs or nullptr: rest posture), at rest, zero activation, CE lengths in static
// equilibrium; settings, inputs and statistics are kept, errors and outputs cleared.
void data_reset(const Model& m, Data& d, const double* q);

}  // namespace armrt
