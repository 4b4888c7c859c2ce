// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model tests/data/pendulum2.json --out cpp/tests/generated`
// from the model file pendulum2.json (sha256 2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96).
// Change the model file or the generator and regenerate instead.

#include "pendulum2.h"

namespace armrt::generated::pendulum2 {

namespace {

const DofParams kDofs[2] = {
    {.name = "ELx", .osim_name = "EL_x", .range_min = -1.5, .range_max = 2.0, .rest = 0.0},
    {.name = "PSy", .osim_name = "PS_y", .range_min = -1.2, .range_max = 1.2, .rest = 0.0},
};

const ElementParams kElements[5] = {
    {.name = "flexor1", .muscle = "flexor", .osim_name = "flexor1", .fmax = 300.0, .lceopt = 0.10000000000000001, .lslack = 0.14999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02, .tdeact = 0.059999999999999998, .peeslack = 1.0, .mass = 0.02, .crosses_gh = 0, .dof_mask = 1, .max_activation = 1.0},
    {.name = "flexor2", .muscle = "flexor", .osim_name = "flexor2", .fmax = 200.0, .lceopt = 0.089999999999999997, .lslack = 0.14999999999999999, .pennopt = 0.10000000000000001, .vmax = 10.0, .tact = 0.02, .tdeact = 0.059999999999999998, .peeslack = 1.0, .mass = 0.02, .crosses_gh = 0, .dof_mask = 1, .max_activation = 1.0},
    {.name = "extensor1", .muscle = "extensor", .osim_name = "extensor1", .fmax = 400.0, .lceopt = 0.10000000000000001, .lslack = 0.13, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02, .tdeact = 0.059999999999999998, .peeslack = 1.0, .mass = 0.02, .crosses_gh = 0, .dof_mask = 1, .max_activation = 1.0},
    {.name = "pronator1", .muscle = "pronator", .osim_name = "pronator1", .fmax = 100.0, .lceopt = 0.040000000000000001, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02, .tdeact = 0.059999999999999998, .peeslack = 1.0, .mass = 0.02, .crosses_gh = 0, .dof_mask = 2, .max_activation = 1.0},
    {.name = "supinator1", .muscle = "supinator", .osim_name = "supinator1", .fmax = 100.0, .lceopt = 0.040000000000000001, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02, .tdeact = 0.059999999999999998, .peeslack = 1.0, .mass = 0.02, .crosses_gh = 0, .dof_mask = 2, .max_activation = 1.0},
};

const int kMuscle0[2] = {0, 1};
const int kMuscle1[1] = {2};
const int kMuscle2[1] = {3};
const int kMuscle3[1] = {4};

const GroupDef kMuscles[4] = {
    {.name = "flexor", .num_elements = 2, .elements = kMuscle0},
    {.name = "extensor", .num_elements = 1, .elements = kMuscle1},
    {.name = "pronator", .num_elements = 1, .elements = kMuscle2},
    {.name = "supinator", .num_elements = 1, .elements = kMuscle3},
};

const int kGroup0[3] = {0, 1, 2};
const int kGroup1[2] = {3, 4};

const GroupDef kGroups[2] = {
    {.name = "elbow", .num_elements = 3, .elements = kGroup0},
    {.name = "forearm", .num_elements = 2, .elements = kGroup1},
};

const char* const kBodyNames[4] = {"humerus", "ulna", "radius", "hand"};

const ModelDef kModel = {
    .name = "pendulum2",
    .source_hash = "2718c0e45e068edd42892f9941382c2ce55fbc1c7f7eee6ca80b24523a8d3c96",
    .num_dofs = 2,
    .num_elements = 5,
    .dofs = kDofs,
    .elements = kElements,
    .num_muscles = 4,
    .muscles = kMuscles,
    .num_groups = 2,
    .groups = kGroups,
    .base_body = "scapula",
    .gravity_base = {0.0, -9.8066499999999994, 0.0},
    .base_rotation_in_thorax = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0},
    .base_origin_in_thorax = {0.0, 0.0, 0.0},
    .num_bodies = 4,
    .body_names = kBodyNames,
    .scapula_body = -1,
    .humerus_body = 0,
    .girdle = nullptr,
    .gh_centre = {0.0, 0.0, 0.0},
    .glenoid_normal = {-1.0, 0.0, 0.0},
    .glenoid_major_axis = {0.0, 1.0, 0.0},
    .glenoid_minor_axis = {0.0, 0.0, -1.0},
    .rim_half_angle_major = 0.77439999999999998,
    .rim_half_angle_minor = 0.67279999999999995,
    .arm_mass = 3.8999999999999999,
    .passive_stiffness_inside = 1.0,
    .passive_stiffness_outside = 5000.0,
    .passive_damping = 0.0,
    .mass_matrix = &mass_matrix,
    .bias_force = &bias_force,
    .dynamics = &dynamics,
    .hand_position = &hand_position,
    .hand_jacobian = &hand_jacobian,
    .arm_momentum_rate = &arm_momentum_rate,
    .body_poses = &body_poses,
    .muscle_lengths = &muscle_lengths,
    .muscle_paths = &muscle_paths,
    .gh_directions = &gh_directions,
};

}  // namespace

const armrt::ModelDef& model_def() { return kModel; }

}  // namespace armrt::generated::pendulum2
