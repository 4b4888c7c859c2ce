// Stage: muscles. (excitation u or the stimulation stage's drive, path lengths L, moment arms R, CE lengths lce, activations a) ->
// (da/dt, dlce/dt, tendon forces F (N), generalised muscle forces tau = R^T F (N m)), and with a
// Jacobian the kernel's derivatives in the same pass. The element itself: muscle_kernel.h, muscle.cc.
#include <algorithm>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "dof_dispatch.h"
#include "lanes.h"

namespace armrt {

namespace {

// tau[j] = sum_i R[j][i] F[i] with R by DOF (row stride kMaxElements): eight elements per multiply-add over
// the elements [begin[j], end[j]) that cross DOF j (all n without ranges), two running sums per DOF; the
// elements past the last whole eight in scalars.
template <int ndof>
void generalised_force_n(const double* moment_arm, const double* force, int n, double* tau, const int* begin,
                         const int* end) {
  using detail::v8d;
  const int n8 = n / 8 * 8;
  for (int j = 0; j < ndof; ++j) {
    const double* r = moment_arm + j * kMaxElements;
    const int i0 = begin ? begin[j] / 8 * 8 : 0;
    const int i1 = end ? std::min(n8, end[j]) : n8;
    v8d acc0 = {}, acc1 = {};
    int i = i0;
    for (; i + 8 < i1; i += 16) {  // chunks i and i + 8 both start before i1 (and end by n8)
      v8d r0, r1, f0, f1;
      std::memcpy(&r0, r + i, sizeof(v8d));
      std::memcpy(&f0, force + i, sizeof(v8d));
      std::memcpy(&r1, r + i + 8, sizeof(v8d));
      std::memcpy(&f1, force + i + 8, sizeof(v8d));
      acc0 += r0 * f0;
      acc1 += r1 * f1;
    }
    for (; i < i1; i += 8) {
      v8d r0, f0;
      std::memcpy(&r0, r + i, sizeof(v8d));
      std::memcpy(&f0, force + i, sizeof(v8d));
      acc0 += r0 * f0;
    }
    double s = detail::lane_sum(acc0 + acc1);
    for (int k = n8; k < n; ++k) s += r[k] * force[k];
    tau[j] = s;
  }
}

}  // namespace

void muscle_dynamics(const Model& m, const MuscleArrays& mc, const double* excitation, const double* muscle_length,
                     const double* moment_arm, const double* act, const double* lce, double* act_dot,
                     double* lce_dot, double* force, double* tau, StepJacobian* jac, const ActivationDrive* drive) {
  const int n = m.num_elements;
  const double b = m.fibre_damping;
  // Elements a stimulation map drives follow the stimulation stage's target and rate, da/dt = rate (target - a);
  // the others their excitation, da/dt = (c1 u + c2)(u - a). Selected per element inside the one pass, so that a
  // map costs no pass of its own (without a map no element is driven).
  static const double kNoneDriven[kMaxElements] = {};
  const double* driven = drive ? drive->driven : kNoneDriven;
  const double* drive_target = drive ? drive->target : kNoneDriven;
  const double* drive_rate = drive ? drive->rate : kNoneDriven;
  if (!jac) {
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      const double u_exc = capped_excitation(excitation[i], mc.max_activation[i]);
      const bool by_drive = driven[i] != 0.0;
      const double u = by_drive ? drive_target[i] : u_exc;
      const double rate = by_drive ? drive_rate[i] : mc.c1[i] * u_exc + mc.c2[i];
      act_dot[i] = rate * (u - act[i]);
      muscle_kernel(mc.fmax[i], mc.inv_lceopt[i], mc.lslack[i], mc.thickness[i], mc.min_lce[i], mc.vmax[i],
                    mc.k_see[i], mc.k_pee[i], mc.pee_slack[i], mc.compress_length[i], mc.k_compress[i], mc.ecc_c[i], mc.damping_slope[i], b,
                    muscle_length[i], lce[i], act[i], &force[i], &lce_dot[i]);
    }
  } else {
    // The same loop with the kernel's derivatives (one pass: the Jacobian costs no second sweep).
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      const double u_exc = capped_excitation(excitation[i], mc.max_activation[i]);
      const bool by_drive = driven[i] != 0.0;
      const double u = by_drive ? drive_target[i] : u_exc;
      const double rate = by_drive ? drive_rate[i] : mc.c1[i] * u_exc + mc.c2[i];
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
  generalised_force(moment_arm, force, n, m.num_dofs, tau, m.dof_elements_begin.data(), m.dof_elements_end.data());
}

void generalised_force(const double* moment_arm, const double* force, int n, int ndof, double* tau,
                       const int* dof_begin, const int* dof_end) {
  detail::dispatch_dofs(ndof, [&](auto N) { generalised_force_n<N>(moment_arm, force, n, tau, dof_begin, dof_end); });
}

void muscle_paths_by_element(const ModelDef& def, const double* q, double* L, double* moment_arm) {
  double by_dof[kMaxDofs * kMaxElements];
  def.muscle_paths(q, L, by_dof);
  const int n = def.num_elements, ndof = def.num_dofs;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < ndof; ++j) moment_arm[i * ndof + j] = by_dof[j * kMaxElements + i];
}

}  // namespace armrt
