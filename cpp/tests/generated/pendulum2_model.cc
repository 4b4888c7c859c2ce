// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model tests/data/pendulum2.json --out cpp/tests/generated`
// from the model file pendulum2.json (sha256 2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96).
// Change the model file or the generator and regenerate instead.

#include "pendulum2.h"

namespace armrt::generated::pendulum2 {

namespace {

const DofParams kDofs[2] = {
    {"ELx", "EL_x", -1.5, 2.0, 0.0},
    {"PSy", "PS_y", -1.2, 1.2, 0.0},
};

const ElementParams kElements[5] = {
    {"flexor1", "flexor", 300.0, 0.10000000000000001, 0.14999999999999999, 0.0, 10.0, 0.02, 0.059999999999999998, 1.0, 0.02, 0, 1, 1.0},
    {"flexor2", "flexor", 200.0, 0.089999999999999997, 0.14999999999999999, 0.10000000000000001, 10.0, 0.02, 0.059999999999999998, 1.0, 0.02, 0, 1, 1.0},
    {"extensor1", "extensor", 400.0, 0.10000000000000001, 0.13, 0.0, 10.0, 0.02, 0.059999999999999998, 1.0, 0.02, 0, 1, 1.0},
    {"pronator1", "pronator", 100.0, 0.040000000000000001, 0.035000000000000003, 0.0, 10.0, 0.02, 0.059999999999999998, 1.0, 0.02, 0, 2, 1.0},
    {"supinator1", "supinator", 100.0, 0.040000000000000001, 0.035000000000000003, 0.0, 10.0, 0.02, 0.059999999999999998, 1.0, 0.02, 0, 2, 1.0},
};

const int kMuscle0[2] = {0, 1};
const int kMuscle1[1] = {2};
const int kMuscle2[1] = {3};
const int kMuscle3[1] = {4};

const GroupDef kMuscles[4] = {
    {"flexor", 2, kMuscle0},
    {"extensor", 1, kMuscle1},
    {"pronator", 1, kMuscle2},
    {"supinator", 1, kMuscle3},
};

const int kGroup0[3] = {0, 1, 2};
const int kGroup1[2] = {3, 4};

const GroupDef kGroups[2] = {
    {"elbow", 3, kGroup0},
    {"forearm", 2, kGroup1},
};

const ModelDef kModel = {
    "pendulum2",
    "2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96",
    2,
    5,
    kDofs,
    kElements,
    4,
    kMuscles,
    2,
    kGroups,
    {0.0, -9.8066499999999994, 0.0},
    {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0},
    {0.0, 0.0, 0.0},
    {0.0, 0.0, 0.0},
    {-1.0, 0.0, 0.0},
    {0.0, 1.0, 0.0},
    {0.0, 0.0, -1.0},
    0.77439999999999998,
    0.67279999999999995,
    3.8999999999999999,
    1.0,
    5000.0,
    0.0,
    &mass_matrix,
    &bias_force,
    &dynamics,
    &hand_position,
    &hand_jacobian,
    &arm_momentum_rate,
    &body_poses,
    &muscle_lengths,
    &muscle_paths,
    &gh_directions,
};

}  // namespace

const armrt::ModelDef& model_def() { return kModel; }

}  // namespace armrt::generated::pendulum2
