// One table per layout (as MuJoCo's mjxmacro.h): the state vector's blocks, the outputs of forward() and the
// channels a recording keeps. Data's output fields, forward()'s record step, the recorder, the bindings'
// outputs and recordings, ArmBatch's views, armrt.Result's arrays and its row size all come from these
// tables: a new output is one ARMRT_OUTPUTS row and the line of its stage that fills it. (The real-time
// state packet has its own table: cpp/rt/packet.h ARMRT_STATE_PACKET_FIELDS.)
#pragma once

#include <array>

#include "armrt/model.h"
#include "armrt/stimulation.h"

namespace armrt {

// How many values a row has: one, two, three (x, y, z), the model's DOFs, its elements, its girdle contact
// points (0 without girdle forces), or ROS2's packed path history (snapshot.h: 4 + 2 x DOFs).
// kChannels, kChannelInputs and kChannelState are sized by the arm's stimulation map (num_channels; 0 without).
enum class SizeRule { kOne, kTwo, kThree, kDofs, kElements, kContactPoints, kPathHistory, kChannels, kChannelInputs, kChannelState };

inline int layout_size(SizeRule rule, const ModelDef& def, int num_channels = 0) {
  switch (rule) {
    case SizeRule::kOne: return 1;
    case SizeRule::kTwo: return 2;
    case SizeRule::kThree: return 3;
    case SizeRule::kDofs: return def.num_dofs;
    case SizeRule::kElements: return def.num_elements;
    case SizeRule::kContactPoints: return def.girdle ? def.girdle->num_contact_points : 0;
    case SizeRule::kPathHistory: return 4 + 2 * def.num_dofs;
    case SizeRule::kChannels: return num_channels;
    case SizeRule::kChannelInputs: return 3 * num_channels;
    case SizeRule::kChannelState: return kStimStateSize * num_channels;
  }
  return 0;
}

// The storage of a row in Data (its capacity).
#define ARMRT_STORAGE_kOne double
#define ARMRT_STORAGE_kTwo std::array<double, 2>
#define ARMRT_STORAGE_kThree std::array<double, 3>
#define ARMRT_STORAGE_kDofs std::array<double, kMaxDofs>
#define ARMRT_STORAGE_kElements std::array<double, kMaxElements>
#define ARMRT_STORAGE_kContactPoints std::array<double, kMaxContactPoints>
#define ARMRT_STORAGE_kChannels std::array<double, kMaxChannels>
#define ARMRT_STORAGE(size) ARMRT_STORAGE_##size

// State blocks, in the order of x = [q | qdot | lce | activation] (offsets: data.h).
//   X(name, size, unit, description)
#define ARMRT_STATE_BLOCKS(X)                                         \
  X(q, kDofs, "rad", "joint angles")                                  \
  X(qdot, kDofs, "rad/s", "joint angular velocities")                 \
  X(lce, kElements, "m", "contractile-element (fibre) lengths")       \
  X(activation, kElements, "1", "muscle activations in [0, 1]")

// Outputs of forward() with record (data.h Data): what each stage computes about the state forward() was
// evaluated at (output_q). In stage order (forward.cc).
//   X(name, size, unit, stage, girdle_only, recorded, description)
//   girdle_only: 1 for models with girdle forces only (das3's scapulothoracic contact and conoid)
//   recorded: 1 if a recording (armrt.Result) keeps it, one row per recorded step
// A build may append rows of its own: cpp/tests/test_layout_extension.cc adds a made-up output this way (with
// ARMRT_EXTRA_OUTPUT_STAGES, forward.cc, as its stage) and checks that nothing else needs to change.
#ifndef ARMRT_EXTRA_OUTPUTS
#define ARMRT_EXTRA_OUTPUTS(X)
#endif
#define ARMRT_OUTPUTS(X)                                                                                             \
  X(output_q, kDofs, "rad", "paths", 0, 0, "the joint angles the outputs describe")                                  \
  X(muscle_length, kElements, "m", "paths", 0, 1, "muscle-tendon lengths")                                           \
  X(muscle_force, kElements, "N", "muscles", 0, 1, "tendon (SEE) forces")                                            \
  X(fibre_velocity, kElements, "m/s", "muscles", 0, 0, "d lce / dt (lengthening positive)")                          \
  X(muscle_torque, kDofs, "N m", "muscles", 0, 0, "generalised muscle forces R^T F")                                 \
  X(passive_torque, kDofs, "N m", "passive_joints", 0, 0, "passive joint moments")                                   \
  X(external_torque, kDofs, "N m", "external_loads", 0, 0, "generalised forces of the hand force and moment")        \
  X(hand_position, kThree, "m", "external_loads", 0, 1, "hand point, thorax frame")                                  \
  X(girdle_torque, kDofs, "N m", "girdle", 1, 0, "generalised forces of the scapulothoracic contact and conoid")     \
  X(contact_distance, kContactPoints, "m", "girdle", 1, 1,                                                           \
    "signed distance of each contact point (TS, AI) from the thorax surface (negative: inside)")                     \
  X(contact_force, kContactPoints, "N", "girdle", 1, 0, "magnitude of each contact force")                           \
  X(conoid_length, kOne, "m", "girdle", 1, 0, "conoid ligament length")                                              \
  X(conoid_tension, kOne, "N", "girdle", 1, 1, "conoid ligament tension")                                            \
  X(qddot, kDofs, "rad/s^2", "skeleton", 0, 0, "joint angular accelerations")                                        \
  X(gh_force, kThree, "N", "gh_reaction", 0, 1, "force of the humeral head on the glenoid, scapula frame")           \
  X(gh_angles, kTwo, "rad", "gh_reaction", 0, 1,                                                                     \
    "(theta, phi): the GH force from the glenoid normal along the major (+ superior) and minor axis")                \
  X(gh_stab, kOne, "1", "gh_reaction", 0, 1, "(theta/theta_a)^2 + (phi/phi_a)^2 (the paper's eq. 5); > 1 beyond the rim") \
  X(gh_rim_margin, kOne, "rad", "gh_reaction", 0, 1, "how far the GH force can still turn to the rim; < 0 beyond")  \
  X(gh_rim_direction, kOne, "rad", "gh_reaction", 0, 1, "atan2(phi, theta): 0 superior, pi/2 anterior")              \
  X(thorax_humerus, kThree, "rad", "kinematics", 0, 1,                                                               \
    "thorax-humerus angles: plane of elevation, elevation, axial rotation")                                          \
  ARMRT_EXTRA_OUTPUTS(X)

// What a recording keeps per row (recorder.h), in this order: the row's time, the state blocks, the excitation
// held over the step, the recorded outputs, and the step's task execution time.
//   X(name, size, unit, girdle_only, description)
#define ARMRT_RECORDED_EXTRA_FIRST(X) X(time, kOne, "s", 0, "time of the row's state")
#define ARMRT_RECORDED_INPUTS(X)                                                                      \
  X(excitation, kElements, "1", 0, "neural excitation held over the step")                            \
  X(stimulation, kChannelInputs, "s, A, Hz", 0,                                                       \
    "per channel: pulse width (s), amplitude (A), frequency (Hz) held over the step")                  \
  X(recruitment, kChannels, "1", 0, "per channel: fraction its last pulse recruited, at the step's start") \
  X(fatigue, kChannels, "1", 0, "per channel: 1 - A/A_rest (Ding 2003's force-scaling factor lost), at the step's start")
#define ARMRT_RECORDED_EXTRA_LAST(X) X(tet_ns, kOne, "ns", 0, "task execution time of the step (0: the final state)")

// Indices of the recorded channels (Recording::channel).
enum class Channel {
#define ARMRT_X_CH(name, ...) name,
#define ARMRT_X_CH_STATE(name, size, unit, description) name,
#define ARMRT_X_CH_OUT(name, size, unit, stage, girdle_only, recorded, description) ARMRT_X_CH_OUT_##recorded(name)
#define ARMRT_X_CH_OUT_0(name)
#define ARMRT_X_CH_OUT_1(name) name,
  ARMRT_RECORDED_EXTRA_FIRST(ARMRT_X_CH) ARMRT_STATE_BLOCKS(ARMRT_X_CH_STATE) ARMRT_RECORDED_INPUTS(ARMRT_X_CH)
      ARMRT_OUTPUTS(ARMRT_X_CH_OUT) ARMRT_RECORDED_EXTRA_LAST(ARMRT_X_CH) kCount
#undef ARMRT_X_CH
#undef ARMRT_X_CH_STATE
#undef ARMRT_X_CH_OUT
#undef ARMRT_X_CH_OUT_0
#undef ARMRT_X_CH_OUT_1
};
inline constexpr int kNumChannels = static_cast<int>(Channel::kCount);

// The snapshot (snapshot.h; as MuJoCo's mjtState): what get_snapshot copies and set_snapshot restores, in this
// order. Each row is one bit of a signature (1 << its SnapshotPart): time, the state blocks, the inputs held
// over a step, the integrator's memory. Time and input rows are Data fields of the same name.
//   X(name, size, unit, description)
#define ARMRT_SNAPSHOT_TIME(X) X(time, kOne, "s", "simulation time")
#define ARMRT_SNAPSHOT_INPUTS(X)                                                               \
  X(excitation, kElements, "1", "neural excitation held over the steps (capped at max_activation)") \
  X(hand_force, kThree, "N", "force at the hand point, thorax frame")                          \
  X(hand_moment, kThree, "N m", "moment on the hand, thorax frame")                             \
  X(applied_moment, kDofs, "N m",                                                              \
    "generalised forces applied at the joints (as MuJoCo's qfrc_applied): friction, a device, a push") \
  X(stimulation, kChannelInputs, "s, A, Hz",                                                   \
    "per channel: pulse width (s), amplitude (A), frequency (Hz) held over the steps")
// The stimulation chain's memory per channel (stimulation.h StimState): calcium sum, CN, force level, fatigue
// (A, tau1, Km over their rested values), last pulse time, last recruitment, queued pulse count and times.
#define ARMRT_SNAPSHOT_STIMULATION(X) \
  X(stimulation_state, kChannelState, "", "per channel: the stimulation chain's memory (stimulation.h StimState; Data stores it by column)")
#define ARMRT_SNAPSHOT_INTEGRATOR(X)                                                                  \
  X(ros2_path_history, kPathHistory, "",                                                              \
    "ROS2's memory: step size h (s), anchors (0-2), anchor spacing and steps since the newest anchor " \
    "(steps), the anchors' q (2 x DOFs, rad, oldest first, unused rows 0); all 0 when there is none")
#define ARMRT_SNAPSHOT(X)                                                                                     \
  ARMRT_SNAPSHOT_TIME(X) ARMRT_STATE_BLOCKS(X) ARMRT_SNAPSHOT_INPUTS(X) ARMRT_SNAPSHOT_STIMULATION(X) \
      ARMRT_SNAPSHOT_INTEGRATOR(X)

enum class SnapshotPart {
#define ARMRT_X_SNAP(name, ...) name,
  ARMRT_SNAPSHOT(ARMRT_X_SNAP) kCount
#undef ARMRT_X_SNAP
};
inline constexpr int kNumSnapshotParts = static_cast<int>(SnapshotPart::kCount);
inline constexpr unsigned snapshot_bit(SnapshotPart p) { return 1u << static_cast<int>(p); }
// Signatures (as mjSTATE_PHYSICS, ...): any OR of snapshot_bit()s.
#define ARMRT_X_SNAP_BIT(name, ...) | snapshot_bit(SnapshotPart::name)
inline constexpr unsigned kSnapshotTime = 0u ARMRT_SNAPSHOT_TIME(ARMRT_X_SNAP_BIT);
inline constexpr unsigned kSnapshotPhysics = 0u ARMRT_STATE_BLOCKS(ARMRT_X_SNAP_BIT);
inline constexpr unsigned kSnapshotInputs = 0u ARMRT_SNAPSHOT_INPUTS(ARMRT_X_SNAP_BIT);
inline constexpr unsigned kSnapshotStimulation = 0u ARMRT_SNAPSHOT_STIMULATION(ARMRT_X_SNAP_BIT);
inline constexpr unsigned kSnapshotIntegrator = 0u ARMRT_SNAPSHOT_INTEGRATOR(ARMRT_X_SNAP_BIT);
inline constexpr unsigned kSnapshotFull = (1u << kNumSnapshotParts) - 1;
#undef ARMRT_X_SNAP_BIT

// A row's values in Data, whatever its storage (for code generated from the tables).
inline const double* row_values(const double& v) { return &v; }
template <std::size_t N>
const double* row_values(const std::array<double, N>& a) { return a.data(); }
inline double* row_values(double& v) { return &v; }
template <std::size_t N>
double* row_values(std::array<double, N>& a) { return a.data(); }

// A row of a table, for code that walks it (bindings, the recorder's reservations).
struct LayoutRow {
  const char* name;
  SizeRule size;
  const char* unit;
  const char* stage;  // the stage that fills it ("state", "input", "recording" for the recording's own)
  bool girdle_only;
  const char* description;
};

// The recorded channels in Channel order, the outputs in ARMRT_OUTPUTS order, the snapshot's parts in
// SnapshotPart order (kNumSnapshotParts rows; stage "time", "state", "input" or "integrator").
const LayoutRow* recorded_channels();  // kNumChannels rows
const LayoutRow* output_rows(int* count);
const LayoutRow* snapshot_rows();

}  // namespace armrt
