// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das2.json --out cpp/generated`
// from the model file das2.json (sha256 ec92251b8a91a713a4ad540cee2e3b5a770c526c2d74919f8394002d2da5939c).
// Change the model file or the generator and regenerate instead.
#pragma once

#include "armrt/model_def.h"

namespace armrt::generated::das2 {

const armrt::ModelDef& model_def();

void mass_matrix(const double* q, double* M);
void bias_force(const double* q, const double* qd, const double* g_scapula, double* b);
void dynamics(const double* q, const double* qd, const double* g_scapula, double* M, double* b);
void hand_position(const double* q, double* p);
void hand_jacobian(const double* q, double* Jv, double* Jw);
void arm_momentum_rate(const double* q, const double* qd, double* A, double* c);
void body_poses(const double* q, double* R, double* p);
void muscle_lengths(const double* q, double* L);
void muscle_paths(const double* q, double* L, double* moment_arm);
void gh_directions(const double* q, double* d);

}  // namespace armrt::generated::das2
