// Stage: muscles. (excitation u, path lengths L, moment arms R, CE lengths lce, activations a) ->
// (da/dt, dlce/dt, tendon forces F (N), generalised muscle forces tau = R^T F (N m)), and with a
// Jacobian the kernel's derivatives in the same pass. The element itself: muscle_kernel.h, muscle.cc.
#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "dof_dispatch.h"
#include "lanes.h"

namespace armrt {

namespace {

template <int ndof>
void generalised_force_n(const double* moment_arm, const double* force, int n, double* tau) {
  // Four independent partial sums per DOF: one running sum would chain n multiply-adds back to back.
  if constexpr (ndof < 8) {
    double acc[4][ndof] = {};
    int i = 0;
    for (; i + 4 <= n; i += 4)
      for (int k = 0; k < 4; ++k)
        for (int j = 0; j < ndof; ++j) acc[k][j] += moment_arm[(i + k) * ndof + j] * force[i + k];
    for (; i < n; ++i)
      for (int j = 0; j < ndof; ++j) acc[0][j] += moment_arm[i * ndof + j] * force[i];
    for (int j = 0; j < ndof; ++j) tau[j] = (acc[0][j] + acc[1][j]) + (acc[2][j] + acc[3][j]);
  } else {
    // 8-16 DOFs (das3): the same sums in the same order, each row as a lane pair held in registers
    // (a scalar loop over 11 DOFs kept the sums in memory, load-add-store per term).
    using detail::v8d;
    v8d lo0 = {}, lo1 = {}, lo2 = {}, lo3 = {}, hi0 = {}, hi1 = {}, hi2 = {}, hi3 = {};
    // Rows whose 16-value window ends inside the n x ndof array are loaded whole; the last one or two
    // through a padded copy (callers' arrays need not extend past n rows).
    const int n_whole = n * ndof >= 16 ? (n * ndof - 16) / ndof + 1 : 0;
    int i = 0;
    for (; i + 4 <= n_whole; i += 4) {
      v8d l, h;
      detail::load_row16(moment_arm + i * ndof, l, h);
      lo0 += l * force[i], hi0 += h * force[i];
      detail::load_row16(moment_arm + (i + 1) * ndof, l, h);
      lo1 += l * force[i + 1], hi1 += h * force[i + 1];
      detail::load_row16(moment_arm + (i + 2) * ndof, l, h);
      lo2 += l * force[i + 2], hi2 += h * force[i + 2];
      detail::load_row16(moment_arm + (i + 3) * ndof, l, h);
      lo3 += l * force[i + 3], hi3 += h * force[i + 3];
    }
    // The rest in the scalar loop's order: whole groups of four into sums 0-3, single rows into sum 0.
    v8d* lo[4] = {&lo0, &lo1, &lo2, &lo3};
    v8d* hi[4] = {&hi0, &hi1, &hi2, &hi3};
    const int n_fours = n / 4 * 4;
    for (; i < n; ++i) {
      v8d l, h;
      detail::load_row(moment_arm + i * ndof, ndof, l, h);
      const int k = i < n_fours ? i % 4 : 0;
      *lo[k] += l * force[i], *hi[k] += h * force[i];
    }
    for (int j = 0; j < ndof; ++j)
      tau[j] = j < 8 ? (lo0[j] + lo1[j]) + (lo2[j] + lo3[j]) : (hi0[j - 8] + hi1[j - 8]) + (hi2[j - 8] + hi3[j - 8]);
  }
}

// tau[a] = sum_i RT[a][i] F[i]: eight elements per multiply-add, one accumulator per DOF (nq chains side by
// side), the tail past the last whole eight in scalars (F and RT past n are not read).
template <int nq>
void generalised_force_by_dof_n(const double* RT, const double* force, int n, double* tau) {
  using detail::v8d;
  v8d acc[nq];
  for (int a = 0; a < nq; ++a) acc[a] = v8d{};
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    v8d f;
    std::memcpy(&f, force + i, sizeof(v8d));
    for (int a = 0; a < nq; ++a) {
      v8d r;
      std::memcpy(&r, RT + a * kMaxElements + i, sizeof(v8d));
      acc[a] += r * f;
    }
  }
  for (int a = 0; a < nq; ++a) {
    double s = detail::lane_sum(acc[a]);
    for (int k = i; k < n; ++k) s += RT[a * kMaxElements + k] * force[k];
    tau[a] = s;
  }
}

template <int nq>
void moment_arms_by_dof_n(const double* R, int n, double* RT) {
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < nq; ++a) RT[a * kMaxElements + i] = R[i * nq + a];
}

}  // namespace

void muscle_dynamics(const Model& m, const double* excitation, const double* muscle_length,
                     const double* moment_arm, const double* act, const double* lce, double* act_dot,
                     double* lce_dot, double* force, double* tau, StepJacobian* jac, MomentArmLayout layout) {
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
  if (layout == MomentArmLayout::kByDof) generalised_force_by_dof(moment_arm, force, n, m.num_dofs, tau);
  else generalised_force(moment_arm, force, n, m.num_dofs, tau);
}

void generalised_force(const double* moment_arm, const double* force, int n, int ndof, double* tau) {
  detail::dispatch_dofs(ndof, [&](auto N) { generalised_force_n<N>(moment_arm, force, n, tau); });
}

void generalised_force_by_dof(const double* moment_arm_by_dof, const double* force, int n, int ndof, double* tau) {
  detail::dispatch_dofs(ndof, [&](auto N) { generalised_force_by_dof_n<N>(moment_arm_by_dof, force, n, tau); });
}

void moment_arms_by_dof(const double* moment_arm, int n, int ndof, double* moment_arm_by_dof) {
  detail::dispatch_dofs(ndof, [&](auto N) { moment_arms_by_dof_n<N>(moment_arm, n, moment_arm_by_dof); });
}

}  // namespace armrt
