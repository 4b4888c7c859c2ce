// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das2.json --out cpp/generated`
// from the model file das2.json (sha256 effb6ef66ec79560b06b1541ad3764787289ecb15b03c0a146d0090edd57a0b0).
// Change the model file or the generator and regenerate instead.
#pragma once

#include "armrt/model_def.h"

namespace armrt::generated::das2 {

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

}  // namespace armrt::generated::das2
