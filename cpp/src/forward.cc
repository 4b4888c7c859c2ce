// The state derivative (paper eq. 1): M(q) qdd = Q_muscle + Q_passive + Q_external + b(q, qd, g),
// plus activation and contractile-element dynamics of every element, and the GH stability value.
#include <algorithm>
#include <cmath>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "dof_dispatch.h"

namespace armrt {

namespace {

// Signed excursion beyond the range of motion (rad): q - range_max above it, q - range_min below,
// 0 inside. The torque and its derivative below are written in terms of it.
double range_excursion(const DofParams& dof, double q) {
  return q > dof.range_max ? q - dof.range_max : (q < dof.range_min ? q - dof.range_min : 0.0);
}

}  // namespace

void passive_joint_torque(const ModelDef& def, const double* q, const double* qd, double* tau) {
  for (int j = 0; j < def.num_dofs; ++j) {
    const DofParams& dof = def.dofs[j];
    const double e = range_excursion(dof, q[j]);
    tau[j] = -def.passive_stiffness_inside * (q[j] - dof.rest) - def.passive_damping * qd[j] -
             def.passive_stiffness_outside * e * std::fabs(e);
  }
}

namespace {

template <int n>
void solve_spd_n(const double* A, const double* b, double* x) {
  // Cholesky A = L L^T, row-major, fixed size: no pivoting needed for a mass matrix.
  double Lc[n * n];
  double inv_diag[n];
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) {
      double sum = A[i * n + j];
      for (int k = 0; k < j; ++k) sum -= Lc[i * n + k] * Lc[j * n + k];
      if (i == j) {
        Lc[i * n + i] = std::sqrt(sum);
        inv_diag[i] = 1.0 / Lc[i * n + i];
      } else {
        Lc[i * n + j] = sum * inv_diag[j];
      }
    }
  }
  double y[n];
  for (int i = 0; i < n; ++i) {
    double sum = b[i];
    for (int k = 0; k < i; ++k) sum -= Lc[i * n + k] * y[k];
    y[i] = sum * inv_diag[i];
  }
  for (int i = n - 1; i >= 0; --i) {
    double sum = y[i];
    for (int k = i + 1; k < n; ++k) sum -= Lc[k * n + i] * x[k];
    x[i] = sum * inv_diag[i];
  }
}

template <int ndof>
void generalised_force_n(const double* moment_arm, const double* force, int n, double* tau) {
  // Four independent partial sums per DOF: one running sum would chain n multiply-adds back to back.
  double acc[4][ndof] = {};
  int i = 0;
  for (; i + 4 <= n; i += 4)
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < ndof; ++j) acc[k][j] += moment_arm[(i + k) * ndof + j] * force[i + k];
  for (; i < n; ++i)
    for (int j = 0; j < ndof; ++j) acc[0][j] += moment_arm[i * ndof + j] * force[i];
  for (int j = 0; j < ndof; ++j) tau[j] = (acc[0][j] + acc[1][j]) + (acc[2][j] + acc[3][j]);
}

}  // namespace

void solve_spd(const double* A, const double* b, int n, double* x) {
  detail::dispatch_dofs(n, [&](auto N) { solve_spd_n<N>(A, b, x); });
}

void passive_joint_stiffness(const ModelDef& def, const double* q, double* dtau_dq, double* dtau_dqd) {
  for (int j = 0; j < def.num_dofs; ++j) {
    const double e = range_excursion(def.dofs[j], q[j]);
    dtau_dq[j] = -def.passive_stiffness_inside - 2.0 * def.passive_stiffness_outside * std::fabs(e);
    dtau_dqd[j] = -def.passive_damping;
  }
}

void gh_stability(const ModelDef& def, const double* f, double* theta, double* phi, double* stab) {
  double fn = 0, fmaj = 0, fmin = 0;
  for (int k = 0; k < 3; ++k) {
    fn += f[k] * def.glenoid_normal[k];
    fmaj += f[k] * def.glenoid_major_axis[k];
    fmin += f[k] * def.glenoid_minor_axis[k];
  }
  *theta = std::atan2(fmaj, fn);
  *phi = std::atan2(fmin, fn);
  const double rt = *theta / def.rim_half_angle_major, rp = *phi / def.rim_half_angle_minor;
  *stab = rt * rt + rp * rp;
}

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
                    mc.k_see[i], mc.k_pee[i], mc.pee_slack[i], mc.ecc_c[i], mc.damping_slope[i], b,
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
                                mc.vmax[i], mc.k_see[i], mc.k_pee[i], mc.pee_slack[i], mc.ecc_c[i],
                                mc.damping_slope[i], b, muscle_length[i], lce[i], act[i], &force[i], &lce_dot[i],
                                &der);
      jac->dforce_dL[i] = der.dforce_dL;
      jac->dforce_dlce[i] = der.dforce_dlce;
      jac->dvel_dL[i] = der.dvel_dL;
      jac->dvel_dlce[i] = der.dvel_dlce;
      jac->dvel_da[i] = der.dvel_da;
    }
  }
  generalised_force(moment_arm, force, n, m.num_dofs, tau);
}

void generalised_force(const double* moment_arm, const double* force, int n, int ndof, double* tau) {
  detail::dispatch_dofs(ndof, [&](auto N) { generalised_force_n<N>(moment_arm, force, n, tau); });
}

namespace {

template <int nq>
void forward_n(const Model& m, Data& d, const double* x, double* xdot, bool record, StepJacobian* jac) {
  const ModelDef& def = *m.def;
  const int n = m.num_elements;
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const double* q = x + iq;
  const double* qd = x + iqd;

  double L_local[kMaxElements];
  double R_local[kMaxElements * kMaxDofs];
  double* L = jac ? jac->muscle_length.data() : L_local;  // the Jacobian keeps the path geometry
  double* R = jac ? jac->moment_arm.data() : R_local;
  def.muscle_paths(q, L, R);

  double force[kMaxElements];
  double tau[kMaxDofs];
  const double* lce_dot = xdot + il;
  muscle_dynamics(m, d.excitation.data(), L, R, x + ia, x + il, xdot + ia, xdot + il, force, tau, jac);
  if (record) {
    std::copy(force, force + n, d.muscle_force.begin());
    std::copy(lce_dot, lce_dot + n, d.fibre_velocity.begin());
  }

  double tau_passive[kMaxDofs];
  passive_joint_torque(def, q, qd, tau_passive);
  if (jac) passive_joint_stiffness(def, q, jac->dtau_passive_dq.data(), jac->dtau_passive_dqd.data());

  // External hand load, given in the thorax frame; the Jacobians are in the scapula frame.
  const double* Rs = def.scapula_rotation_in_thorax;  // columns = scapula axes in thorax
  double f_ext[3], t_ext[3];
  for (int k = 0; k < 3; ++k) {
    f_ext[k] = Rs[0 * 3 + k] * d.hand_force[0] + Rs[1 * 3 + k] * d.hand_force[1] + Rs[2 * 3 + k] * d.hand_force[2];
    t_ext[k] = Rs[0 * 3 + k] * d.hand_moment[0] + Rs[1 * 3 + k] * d.hand_moment[1] + Rs[2 * 3 + k] * d.hand_moment[2];
  }
  double tau_ext[kMaxDofs];
  for (int j = 0; j < nq; ++j) tau_ext[j] = 0.0;
  const bool loaded = f_ext[0] != 0 || f_ext[1] != 0 || f_ext[2] != 0 || t_ext[0] != 0 || t_ext[1] != 0 || t_ext[2] != 0;
  if (loaded) {
    double Jv[3 * kMaxDofs], Jw[3 * kMaxDofs];
    def.hand_jacobian(q, Jv, Jw);
    for (int j = 0; j < nq; ++j)
      for (int k = 0; k < 3; ++k) tau_ext[j] += Jv[k * nq + j] * f_ext[k] + Jw[k * nq + j] * t_ext[k];
  }

  double M[kMaxDofs * kMaxDofs];
  double rhs[kMaxDofs];
  def.dynamics(q, qd, m.gravity_scapula.data(), M, rhs);
  if (jac) std::copy(M, M + nq * nq, jac->mass_matrix.begin());
  for (int j = 0; j < nq; ++j) rhs[j] += tau[j] + tau_passive[j] + tau_ext[j];
  double qdd[kMaxDofs];
  solve_spd_n<nq>(M, rhs, qdd);
  for (int j = 0; j < nq; ++j) {
    xdot[iq + j] = qd[j];
    xdot[iqd + j] = qdd[j];
  }

  if (!record) return;
  for (int j = 0; j < nq; ++j) {
    d.qdd[j] = qdd[j];
    d.muscle_torque[j] = tau[j];
    d.passive_torque[j] = tau_passive[j];
    d.external_torque[j] = tau_ext[j];
  }
  std::copy(L, L + n, d.muscle_length.begin());
  std::copy(R, R + n * nq, d.moment_arm.begin());

  double p[3];
  def.hand_position(q, p);
  for (int k = 0; k < 3; ++k)
    d.hand_position[k] = def.scapula_origin_in_thorax[k] + Rs[k * 3 + 0] * p[0] + Rs[k * 3 + 1] * p[1] + Rs[k * 3 + 2] * p[2];

  // GH reaction (conventions.md): muscle forces along their lines of action, the hand load, and the
  // arm's weight minus its mass times acceleration.
  double dir[kMaxElements * 3];
  def.gh_directions(q, dir);
  double A[3 * kMaxDofs], c[3];
  def.arm_momentum_rate(q, qd, A, c);
  for (int k = 0; k < 3; ++k) {
    double Aqdd = 0.0;
    for (int j = 0; j < nq; ++j) Aqdd += A[k * nq + j] * qdd[j];
    const double inertial = Aqdd + c[k];
    double fk = f_ext[k] + def.arm_mass * m.gravity_scapula[k] - inertial;
    for (int i = 0; i < n; ++i) fk += force[i] * dir[i * 3 + k];
    d.gh_force[k] = fk;
  }
  gh_stability(def, d.gh_force.data(), &d.gh_theta, &d.gh_phi, &d.gh_stab);
}

}  // namespace

void forward(const Model& m, Data& d, const double* x, double* xdot, bool record, StepJacobian* jac) {
  detail::dispatch_dofs(m.num_dofs, [&](auto N) { forward_n<N>(m, d, x, xdot, record, jac); });
}

}  // namespace armrt
