// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/participant_A_FES.json --out cpp/tests/generated`
// from the model file participant_A_FES.json (sha256 17e8e25d99f33bc075e15c19a20e3aab8e9c0b38092473af66cc730c1c346606).
// Change the model file or the generator and regenerate instead.
#pragma once

#include "armrt/model_def.h"

namespace armrt::generated::participant_A_FES {

const armrt::ModelDef& model_def();

void mass_matrix(const double* q, double* M);
void bias_force(const double* q, const double* qd, const double* g_base, double* b);
void dynamics(const double* q, const double* qd, const double* g_base, double* M, double* b);
void hand_position(const double* q, double* p);
void hand_jacobian(const double* q, double* Jv, double* Jw);
void arm_momentum_rate(const double* q, const double* qd, double* A, double* c);
void body_poses(const double* q, double* R, double* p);
void muscle_lengths(const double* q, double* L);
void muscle_paths(const double* q, double* L, double* moment_arm);
void gh_directions(const double* q, double* d);
void girdle_points(const double* q, double* p, double* J);  // thorax-based models only

}  // namespace armrt::generated::participant_A_FES
