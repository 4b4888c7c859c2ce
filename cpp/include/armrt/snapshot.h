// Snapshots by signature (as MuJoCo's mj_getState / mj_setState with mjtState): the parts of an arm's state that
// a signature selects (layouts.h ARMRT_SNAPSHOT, kSnapshotTime | kSnapshotPhysics | ...), as one flat vector of
// doubles in table order. What armrt.State, Arm copies and pickles, and ArmBatch's state vectors are made of.
#pragma once

#include <string>

#include "armrt/data.h"
#include "armrt/layouts.h"
#include "armrt/model.h"
#include "armrt/stepper.h"

namespace armrt {

// Values in a snapshot of `signature` for an arm with num_channels stimulation channels (Data::stimulation_map);
// throws std::invalid_argument for bits no SnapshotPart has.
int snapshot_size(const ModelDef& def, unsigned signature, int num_channels = 0);
// Offset of `part` in a snapshot of `signature` (-1 if the signature does not hold it).
int snapshot_offset(const ModelDef& def, unsigned signature, SnapshotPart part, int num_channels = 0);
// Copies the parts of `signature` into out (snapshot_size values). ROS2's path history is all zeros unless the
// stepper's memory continues from d's state (a state set from outside, or reached by another integrator, has none).
void get_snapshot(const Model& m, const Data& d, const Stepper& s, unsigned signature, double* out);
// Why `in` (snapshot_size(signature) values) is not a snapshot d may be set to, or "" if it is: a non-finite
// value, a state outside the physical domain a step accepts (engine.h check_domain: joints at most
// kJointRangeMargin beyond their range, with a hint when q looks like degrees; joint speeds within
// max_joint_speed; fibre lengths and activations in range; no girdle contact point deep in the thorax), an
// excitation outside [0, 1], or a path history no run of steps leaves (path_history_error; anchors farther
// from q than max_joint_speed allows over their steps). Parts not in the signature are d's own.
std::string snapshot_error(const Model& m, const Data& d, unsigned signature, const double* in);
// Why q (num_dofs, rad) is no start pose, or "": a joint more than kStartRangeMargin beyond its range, each named
// with its value in rad and deg and its range in deg, with a hint when every joint is in range once read as
// degrees; the words of Python's checks.joint_range (Arm.reset), which tests/test_realtime_parity.py compares.
std::string start_pose_error(const ModelDef& def, const double* q);
// Writes the parts of `signature` from in (check snapshot_error first; an arm's copy writes even a diverged
// state as it was). The excitation is capped at max_activation (data_set_excitation). Any physics or
// integrator part restarts the integrator's memory: ROS2's path history is rebuilt from the snapshot's, if it
// holds one, CVODE starts afresh. Clears a divergence error. Throws std::invalid_argument for a path history
// whose counts path_history_error refuses.
void set_snapshot(const Model& m, Data& d, Stepper& s, unsigned signature, const double* in);

}  // namespace armrt
