// RtConfig (the runner's options as given) -> the same options checked and completed, and the
// Schedule they imply; std::invalid_argument naming the option for anything the loop could not run.
// Model-dependent checks (--q0, names) are the loop's, which has the model (rt_loop.cc).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace armrt::rt {

struct RtConfig {
  // Model and integrator.
  std::string model = "das2";
  // The participant profile the strength / max_activation came from (its name, recorded in the statistics);
  // empty: none. RealtimeSession(profile=...) resolves the profile in Python (armrt.profile) and sets it.
  std::string profile;
  std::string integrator = "ros2";
  double rate_hz = 1000.0;     // loop rate; the control step is 1/rate_hz s (one cycle)
  // Largest integration step (s): each control step takes ceil(period / integration_step) substeps;
  // 0: default_max_step() (ros2 1 ms, rk4 0.17 ms, euler 0.1 ms). armrt-rt --integration-step (--dt before).
  double integration_step = 0;
  std::vector<double> q0;      // initial joint angles (one per DOF of the model, rad); empty: rest posture
  double duration = 0;         // s; 0: until stop() / a signal
  // s of relaxation before the loop starts (Arm.settle: zero excitation, then the clock back to 0); 0: none.
  double settle_s = 0;
  // > 0: the joints are held where the loop started (q and qdot written back after every cycle's step; activations,
  // fibre lengths and the stimulation chain evolve as usual) from the start until support_s s after the first
  // command the runner applies (excitation, stimulation or target; without --listen, the first support_s s): the
  // arm supported while a controller's stimulation builds up, as fes_control.run_offline(hold_s=...) starts a
  // trial, however long the controller takes to come; 0: none.
  double support_s = 0;
  // A constant load at the hand from the start (--settle included), as Arm.set_hand_load: force (N) at the hand
  // point and moment (N m) on the hand, thorax frame (x lateral, y up, z posterior); a 1 kg weight is 0,-9.81,0.
  // Empty: none. The static optimisation's solves account for it.
  std::vector<double> hand_force, hand_moment;
  // Real-time set-up.
  bool realtime = true;        // try SCHED_FIFO; false: normal scheduling on purpose
  int priority = 80;           // SCHED_FIFO priority (1..99)
  bool lock_memory = true;     // mlockall(MCL_CURRENT | MCL_FUTURE)
  bool require_rt = false;     // fail (instead of falling back) without SCHED_FIFO / mlockall
  int cpu = -1;                // pin the loop thread to this CPU; -1: no affinity
  double busy_wait_us = 0;     // sleep until deadline - busy_wait_us, then spin on the clock
  double max_lag = 0;          // s; stop (fail safe) once simulated time lags the schedule by more; 0: never
  // UDP I/O. Empty listen: no excitation input.
  std::string listen;          // "host:port" (port 0: ephemeral, see RtLoop::bound_port())
  std::vector<std::string> state_to;  // "host:port" subscribers that always get state; the owner gets it too
  std::vector<std::string> allow;     // "host[:port]": only these may own a session; empty: anyone
  std::string key;             // shared key (>= 16 bytes): HMAC-SHA256 on every packet; empty: none
  double state_rate_hz = 100;  // state packets per second (0: none); must divide rate_hz
  bool send_forces = false;    // append the muscle forces to state packets
  bool send_excitation = false;  // append the applied element excitations to state packets
  double input_timeout = 0.1;  // s of silence from the owner after which its session ends (excitation 0)
  // s after the hold that follows a timeout during which only the timed-out owner may claim the session again
  // (rt_session.h; docs/realtime.md "Sessions"): 0 .. 60.
  double resume_grace = 1.0;
  std::vector<std::string> channels;  // names (element, muscle or group) of the kExcitationChannels mapping
  // Paralysis / weakness: "NAME=VALUE" (element, muscle or group; VALUE in [0, 1]) caps the
  // activation every excitation source can produce; later entries override earlier ones.
  std::vector<std::string> max_activation;
  // Weakness: "NAME=VALUE" (element, muscle or group; VALUE finite, >= 0) scales the elements' DAS3 fmax, as
  // Arm.strength does (1 = intact); the same names and overlap rule as max_activation.
  std::vector<std::string> strength;
  // Stimulation map (docs/fes.md): a .json / .toml file or "per_muscle"; empty: none. With one, kStimulation
  // packets drive the channels (a packet beyond a channel's limits is refused whole and counted, the previous
  // command held) and state packets
  // carry the applied stimulation and each channel's fatigue.
  std::string stimulation;
  // Feedforward by static optimisation (cpp/src/static_optimization.cc, docs/realtime.md): the owner sends
  // kTarget packets (desired q, qdot, qddot) instead of excitations, and every cycle the runner solves the
  // rigid-tendon static optimisation for qddot_cmd = qddot_d + so_kp (q_d - q) + so_kd (qdot_d - qdot) at the
  // arm's state (so_kp = so_kd = 0: at the desired state, pure feedforward) and applies the activations as
  // excitations; zero excitation without a target, when infeasible, or once the session ends.
  bool static_optimization = false;
  std::optional<double> so_gh_stab_max;  // GHstab <= this (> 0) in the solve (the GH polygon); none: no bound
  // Given only with static_optimization (a gain of 0 included: a gain for a loop that does not run is a mistaken
  // command line); none: 0.
  std::optional<double> so_kp;  // 1/s^2, the computed-torque loop's stiffness on the joint angles
  std::optional<double> so_kd;  // 1/s, its damping on the joint velocities
  double rx_budget_us = 0;     // receive work per cycle: drain the socket until empty or this long; 0: min(150 us, period / 4)
};

// The timing the options imply.
struct Schedule {
  double period_s = 0;          // control step, 1/rate
  int substeps = 1;             // integration steps per period (integration_step = period_s / substeps)
  std::int64_t max_cycles = 0;  // from duration; 0: unbounded
  int state_every = 0;          // cycles between state packets; 0: none
};

// Checks every model-independent option (so the executable and RealtimeSession refuse the same
// things) and completes cfg: integration_step becomes period / substeps, rx_budget_us its default.
Schedule check_config(RtConfig& cfg);

// "NAME=VALUE" items of --max-activation -> (name, value) pairs, VALUE a number in [0, 1].
std::vector<std::pair<std::string, double>> parse_max_activation(const std::vector<std::string>& items);
// "NAME=VALUE" items of --strength -> (name, value) pairs, VALUE a finite number >= 0 (no upper bound: the
// engine's own check, model.cc, as Arm.strength).
std::vector<std::pair<std::string, double>> parse_strength(const std::vector<std::string>& items);

// Loads a model library given with --model-library (registry.h load_model_library) after checking it against the
// SHA-256 written beside it when `armrt model build` made it (PATH.sha256: "HEX  NAME", armrt/model_build.py): a
// truncated or damaged library would kill the runner inside dlopen with SIGBUS or SIGSEGV and no message.
// Throws std::invalid_argument naming the file when the checksum is missing, unreadable or does not match.
void load_checked_model_library(const std::string& path);

std::string fmt(double v);  // "%g"

}  // namespace armrt::rt
