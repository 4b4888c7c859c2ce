// Stage: muscles. (excitation u, path lengths L, moment arms R, CE lengths lce, activations a) ->
// (da/dt, dlce/dt, tendon forces F (N), generalised muscle forces tau = R^T F (N m)), and with a
// Jacobian the kernel's derivatives in the same pass. The element itself: muscle_kernel.h, muscle.cc.
#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "dof_dispatch.h"
#include "lanes.h"

namespace armrt {

namespace {

// tau[j] = sum_i R[j][i] F[i] with R by DOF (row stride kMaxElements): eight elements per multiply-add, one running sum
// per DOF (the DOFs' chains side by side), the elements past the last whole eight in scalars.
template <int ndof>
void generalised_force_n(const double* moment_arm, const double* force, int n, double* tau) {
  using detail::v8d;
  const int n8 = n / 8 * 8;
  v8d acc[ndof];
  for (int j = 0; j < ndof; ++j) acc[j] = v8d{};
  for (int i = 0; i < n8; i += 8) {
    v8d f;
    std::memcpy(&f, force + i, sizeof(v8d));
    for (int j = 0; j < ndof; ++j) {
      v8d r;
      std::memcpy(&r, moment_arm + j * kMaxElements + i, sizeof(v8d));
      acc[j] += r * f;
    }
  }
  for (int j = 0; j < ndof; ++j) {
    double s = detail::lane_sum(acc[j]);
    for (int i = n8; i < n; ++i) s += moment_arm[j * kMaxElements + i] * force[i];
    tau[j] = s;
  }
}

}  // namespace

void muscle_dynamics(const Model& m, const double* excitation, const double* muscle_length,
                     const double* moment_arm, const double* act, const double* lce, double* act_dot,
                     double* lce_dot, double* force, double* tau, StepJacobian* jac) {
  const int n = m.num_elements;
  const MuscleArrays& mc = m.muscles;
  const double b = m.fibre_damping;
  if (!jac) {
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      double u = excitation[i];
      u = u < 0.0 ? 0.0 : (u > mc.max_activation[i] ? mc.max_activation[i] : u);
      act_dot[i] = (mc.c1[i] * u + mc.c2[i]) * (u - act[i]);
      muscle_kernel(mc.fmax[i], mc.inv_lceopt[i], mc.lslack[i], mc.thickness[i], mc.min_lce[i], mc.vmax[i],
                    mc.k_see[i], mc.k_pee[i], mc.pee_slack[i], mc.compress_length[i], mc.k_compress[i], mc.ecc_c[i], mc.damping_slope[i], b,
                    muscle_length[i], lce[i], act[i], &force[i], &lce_dot[i]);
    }
  } else {
    // The same loop with the kernel's derivatives (one pass: the Jacobian costs no second sweep).
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      double u = excitation[i];
      u = u < 0.0 ? 0.0 : (u > mc.max_activation[i] ? mc.max_activation[i] : u);
      const double rate = mc.c1[i] * u + mc.c2[i];
      act_dot[i] = rate * (u - act[i]);
      jac->act_rate[i] = rate;
      MuscleDerivatives der;
      muscle_kernel_derivatives(mc.fmax[i], mc.inv_lceopt[i], mc.lslack[i], mc.thickness[i], mc.min_lce[i],
                                mc.vmax[i], mc.k_see[i], mc.k_pee[i], mc.pee_slack[i], mc.compress_length[i], mc.k_compress[i], mc.ecc_c[i],
                                mc.damping_slope[i], b, muscle_length[i], lce[i], act[i], &force[i], &lce_dot[i],
                                &der);
      jac->dforce_dL[i] = der.dforce_dL;
      jac->dforce_dlce[i] = der.dforce_dlce;
      jac->dvel_dL[i] = der.dvel_dL;
      jac->dvel_dlce[i] = der.dvel_dlce;
      jac->dvel_da[i] = der.dvel_da;
      jac->force_length[i] = der.force_length;
      jac->lce_along[i] = der.lce_along;
      jac->cos_pennation[i] = der.cos_pennation;
      jac->inv_cos_pennation[i] = der.inv_cos_pennation;
      jac->pee_force[i] = der.pee_force;
      jac->compress_force[i] = der.compress_force;
    }
  }
  generalised_force(moment_arm, force, n, m.num_dofs, tau);
}

void generalised_force(const double* moment_arm, const double* force, int n, int ndof, double* tau) {
  detail::dispatch_dofs(ndof, [&](auto N) { generalised_force_n<N>(moment_arm, force, n, tau); });
}

void moment_arms_by_element(const double* moment_arm, int n, int ndof, double* out) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < ndof; ++j) out[i * ndof + j] = moment_arm[j * kMaxElements + i];
}

}  // namespace armrt
