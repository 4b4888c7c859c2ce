// Data: everything that changes during a simulation (like mjData / pinocchio::Data): the state, the
// inputs, the outputs of the last forward() and the integrators' workspace. Fixed-size: creating one
// allocates nothing afterwards, and stepping never touches the heap.
#pragma once

#include <array>
#include <cstdint>

#include "armrt/model.h"

namespace armrt {

// State vector layout: [q (5) | qdot (5) | lce (n) | activation (n)].
inline constexpr int kQ = 0;
inline constexpr int kQd = kNumDofs;
inline constexpr int kLce = 2 * kNumDofs;
inline int act_offset(const Model& m) { return kLce + m.num_elements; }
inline int state_size(const Model& m) { return 2 * kNumDofs + 2 * m.num_elements; }

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

enum class Status { kOk = 0, kNonFinite = 1, kTooFast = 2, kCvodeFailed = 3 };

struct Data {
  double time = 0;   // s
  StateVec x{};      // state, see layout above

  // Inputs.
  std::array<double, kMaxElements> excitation{};  // neural excitation u in [0, 1]
  std::array<double, 3> hand_force{};   // N, applied at the hand point, thorax frame
  std::array<double, 3> hand_moment{};  // N m, applied to the hand, thorax frame

  // Outputs of the last forward() (at the state it was evaluated at).
  std::array<double, kNumDofs> qdd{};             // rad/s^2
  std::array<double, kMaxElements> muscle_length{};  // m, muscle-tendon length
  std::array<double, kMaxElements * kNumDofs> moment_arm{};  // m, [element][dof]
  std::array<double, kMaxElements> muscle_force{};   // N, tendon (SEE) force
  std::array<double, kMaxElements> fibre_velocity{}; // m/s, d lce/dt (lengthening positive)
  std::array<double, kNumDofs> muscle_torque{};   // N m, generalised muscle forces
  std::array<double, kNumDofs> passive_torque{};  // N m, passive joint moments
  std::array<double, kNumDofs> external_torque{}; // N m, from the hand force and moment
  std::array<double, 3> hand_position{};  // m, thorax frame
  std::array<double, 3> gh_force{};       // N, humeral head on glenoid, scapula frame
  double gh_theta = 0, gh_phi = 0;        // rad, from the glenoid normal along the major / minor axis
  double gh_stab = 0;                     // (theta/theta_a)^2 + (phi/phi_a)^2; > 1: dislocating

  // Errors: set by step(), never thrown in the hot path.
  Status status = Status::kOk;
  int bad_index = -1;  // state index that went bad
  double bad_time = 0;

  TetStats tet;

  // Integrator workspace.
  StateVec k1{}, k2{}, k3{}, k4{}, xtmp{};
};

void data_reset(const Model& m, Data& d, const double* q /* 5 or nullptr: rest posture */);

}  // namespace armrt
