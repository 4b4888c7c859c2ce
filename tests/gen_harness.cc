// C entry points to the generated model code, for the codegen/dynamics tests (loaded with ctypes).
// The model namespace is chosen at compile time with -DARMRT_MODEL_NS=<name>.
#include <cstring>

#include "armrt/model_def.h"

#ifndef ARMRT_MODEL_NS
#error "compile with -DARMRT_MODEL_NS=<model name> and the generated <name>*.cc"
#endif
#define ARMRT_STR2(x) #x
#define ARMRT_STR(x) ARMRT_STR2(x)
#include ARMRT_STR(ARMRT_MODEL_HEADER)

namespace {
const armrt::ModelDef& md() { return armrt::generated::ARMRT_MODEL_NS::model_def(); }
}  // namespace

extern "C" {

const char* h_name() { return md().name; }
const char* h_source_hash() { return md().source_hash; }
int h_num_dofs() { return md().num_dofs; }
int h_num_elements() { return md().num_elements; }
int h_num_muscles() { return md().num_muscles; }
int h_num_groups() { return md().num_groups; }
const char* h_element_name(int i) { return md().elements[i].name; }
int h_element_dof_mask(int i) { return md().elements[i].dof_mask; }
int h_element_crosses_gh(int i) { return md().elements[i].crosses_gh; }
double h_element_fmax(int i) { return md().elements[i].fmax; }
const char* h_muscle_name(int i) { return md().muscles[i].name; }
int h_muscle_size(int i) { return md().muscles[i].num_elements; }
int h_muscle_element(int i, int k) { return md().muscles[i].elements[k]; }
const char* h_group_name(int i) { return md().groups[i].name; }
int h_group_size(int i) { return md().groups[i].num_elements; }
int h_group_element(int i, int k) { return md().groups[i].elements[k]; }
double h_arm_mass() { return md().arm_mass; }
void h_gravity_base(double* g) { std::memcpy(g, md().gravity_base, sizeof(double) * 3); }
void h_scapula_rotation(double* R) { std::memcpy(R, md().base_rotation_in_thorax, sizeof(double) * 9); }

void h_mass_matrix(const double* q, double* M) { md().mass_matrix(q, M); }
void h_bias_force(const double* q, const double* qd, const double* g, double* b) { md().bias_force(q, qd, g, b); }
void h_hand_position(const double* q, double* p) { md().hand_position(q, p); }
void h_hand_jacobian(const double* q, double* Jv, double* Jw) { md().hand_jacobian(q, Jv, Jw); }
void h_arm_momentum_rate(const double* q, const double* qd, double* A, double* c) {
  md().arm_momentum_rate(q, qd, A, c);
}
void h_body_poses(const double* q, double* R, double* p) { md().body_poses(q, R, p); }
void h_muscle_lengths(const double* q, double* L) { md().muscle_lengths(q, L); }
void h_muscle_paths(const double* q, double* L, double* r) { md().muscle_paths(q, L, r); }
void h_gh_directions(const double* q, double* d) { md().gh_directions(q, d); }

}  // extern "C"
