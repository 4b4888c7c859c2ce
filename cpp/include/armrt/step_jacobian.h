// The structured ("arrow") Jacobian of the state derivative that ROS2 steps with: what forward() fills,
// and its factorisation and solve (step_jacobian.cc).
#pragma once

#include <array>

#include "armrt/model.h"

namespace armrt {

// The structured ("arrow") Jacobian of forward() at one state, filled by forward(..., jac) and
// factored by step_jacobian.cc (docs/engine.md): per-element derivatives of the muscle kernel, the moment
// arms and mass matrix at that state, and the passive joint stiffness and damping. Moment-arm
// derivatives, gravity, Coriolis and dM/dq are left out (docs/engine.md says why).
struct StepJacobian {
  // Filled by forward() with a non-null jac.
  std::array<double, kMaxElements> dforce_dL{};    // N/m, tendon force vs muscle-tendon length
  std::array<double, kMaxElements> dforce_dlce{};  // N/m, tendon force vs CE length
  std::array<double, kMaxElements> dvel_dL{};      // 1/s, CE velocity vs muscle-tendon length
  std::array<double, kMaxElements> dvel_dlce{};    // 1/s, CE velocity vs CE length
  std::array<double, kMaxElements> dvel_da{};      // m/s, CE velocity vs activation
  std::array<double, kMaxElements> act_rate{};     // 1/s, -d(activation rate)/d(activation) = c1 u + c2
  // The kernel's lce-only terms at this state (MuscleDerivatives), for limit_fibre_overshoot.
  std::array<double, kMaxElements> force_length{};    // f(lce)
  std::array<double, kMaxElements> lce_along{};       // m, lce cos(pennation)
  std::array<double, kMaxElements> cos_pennation{};   // lce_along / lce
  std::array<double, kMaxElements> inv_cos_pennation{};  // lce / lce_along
  std::array<double, kMaxElements> pee_force{};       // N
  std::array<double, kMaxElements> compress_force{};  // N
  std::array<double, kMaxElements> muscle_length{};          // m
  std::array<double, kMaxDofs * kMaxElements> moment_arm{};  // m, by DOF: [dof][element], row stride kMaxElements (model_def.h)
  std::array<double, kMaxDofs * kMaxDofs> mass_matrix{};     // kg m^2, num_dofs x num_dofs row-major
  std::array<double, kMaxDofs> dtau_passive_dq{};   // N m/rad, diagonal
  std::array<double, kMaxDofs> dtau_passive_dqd{};  // N m s/rad, diagonal
  std::array<double, kMaxDofs * kMaxDofs> dtau_girdle_dq{};  // N m/rad, girdle contact and conoid (girdle.cc)

  // Factorisation of I - h gamma J for one h gamma (jacobian_factor).
  double hg = 0;                                    // s, h * gamma it was built for
  std::array<double, kMaxElements> inv_act{};       // 1 / (1 + hg act_rate)
  std::array<double, kMaxElements> inv_lce{};       // 1 / (1 - hg dvel_dlce)
  std::array<double, kMaxElements> lce_from_q{};    // hg dvel_dL / (1 - hg dvel_dlce), m/m
  std::array<double, kMaxElements> series_stiffness{};  // N/m, dforce_dL + dforce_dlce * lce_from_q
  std::array<double, kMaxDofs * kMaxDofs> schur_lu{};   // LU of the num_dofs x num_dofs Schur complement
  std::array<int, kMaxDofs> schur_perm{};               // its row permutation
  std::array<double, kMaxDofs> schur_inv_diag{};        // 1 / U's diagonal
  std::array<double, kMaxDofs * kMaxDofs> stiffness{};  // N m/rad, K_eff = diag(dtau_passive_dq) + dtau_girdle_dq - R^T diag(series_stiffness) R
  std::array<double, kMaxElements> tmp{};               // scratch of one solve
};

// Factors I - hg J for the structured Jacobian in jac (filled by forward(..., &jac)); hg = h gamma (s).
void jacobian_factor(const Model& m, StepJacobian& jac, double hg);
// Solves (I - hg J) k = r for state-sized vectors r and k (distinct arrays).
void jacobian_solve(const Model& m, StepJacobian& jac, const double* r, double* k);

}  // namespace armrt
