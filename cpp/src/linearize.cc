// linearize.cc: (model, data at x with its excitation u and loads, h) -> df/dx, df/du of forward() at x and
// A = dx+/dx, B = dx+/du of one ROS2 step of h from x (exact paths at both stages, as a step from a state set
// from outside takes), differentiated with its matrix W = I - h gamma J moving too (J's own derivatives by central
// differences: per element all at once, per joint one by one).
// df/dx is the structured Jacobian's exact per-element blocks plus the mechanical terms the step leaves out
// (gravity, Coriolis, dM/dq, moment-arm derivatives, the hand load's J^T F), taken by central differences of the
// skeleton and path stages with the tendon forces held; docs/control.md "Linearised dynamics" derives A, B and states the kinks.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "armrt/engine.h"
#include "armrt/step_jacobian.h"
#include "dof_dispatch.h"
#include "moment_arm_dot.h"

namespace armrt {

using detail::moment_arm_dot;

namespace {

// Central-difference steps of the mechanical block: small enough that the truncation error (eps^2 times the
// third derivative) is below round-off, large enough that round-off (1e-16 qdd / eps) stays near 1e-10 relative.
constexpr double kJointAngleStep = 1e-6;     // rad
constexpr double kJointVelocityStep = 1e-6;  // rad/s

// qdd (rad/s^2) at (q, qd) with the tendon forces F (N) held, paths L, R at q given (R by DOF): the skeleton stage
// with every q-dependent generalised force (R^T F, passive joints, hand load, girdle) as forward() sums them.
void held_force_acceleration(const Model& m, const Data& d, const double* q, const double* qd, const double* R,
                             const double* force, double* qdd) {
  const int nq = m.num_dofs, n = m.num_elements;
  double tau_muscle[kMaxDofs], tau_passive[kMaxDofs], tau_ext[kMaxDofs], tau_girdle[kMaxDofs];
  double f_ext[3], t_ext[3];
  generalised_force(R, force, n, nq, tau_muscle, m.dof_elements_begin.data(), m.dof_elements_end.data());
  passive_joint_torque(*m.def, q, qd, tau_passive);
  external_load(m, q, d.hand_force.data(), d.hand_moment.data(), f_ext, t_ext, tau_ext);
  if (m.def->girdle) girdle_forces(m, q, tau_girdle, nullptr, nullptr);
  else std::fill(tau_girdle, tau_girdle + nq, 0.0);
  double tau[kMaxDofs], M[kMaxDofs * kMaxDofs];
  for (int j = 0; j < nq; ++j) tau[j] = tau_muscle[j] + tau_passive[j] + tau_ext[j] + tau_girdle[j];
  skeleton_dynamics(m, d.settings.gravity.data(), q, qd, tau, M, qdd);
}

// The full tangent of forward() at x into t (xdot: forward()'s derivative there).
void tangent_at(const Model& m, Data& d, const double* x, ForwardTangent& t, double* xdot) {
  const int nq = m.num_dofs, n = m.num_elements;
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  StepJacobian& jac = t.jac;
  forward(m, d, x, xdot, false, &jac);
  // The tendon forces at x: the muscle stage again, without its derivatives (forward() keeps them local).
  double act_dot[kMaxElements], lce_dot[kMaxElements], tau_muscle[kMaxDofs];
  muscle_dynamics(m, d.muscles, d.excitation.data(), jac.muscle_length.data(), jac.moment_arm.data(), x + ia, x + il,
                  act_dot, lce_dot, t.force.data(), tau_muscle, nullptr, nullptr);
  const double* q = x + iq;
  const double* qd = x + iqd;
  const double* R = jac.moment_arm.data();
  // d qdd/dq with the forces held (gravity, Coriolis, dM/dq, dR/dq^T F, passive, hand load, girdle) and
  // d qdd/dqd (passive damping, Coriolis), by central differences; column k at [j * nq + k].
  double qp[kMaxDofs], qdp[kMaxDofs], ap[kMaxDofs], am[kMaxDofs];
  double Lp[kMaxElements];
  double* Rp = t.scratch_moment_arm.data();
  for (int k = 0; k < nq; ++k) {
    std::copy(q, q + nq, qp);
    qp[k] = q[k] + kJointAngleStep;
    m.def->muscle_paths(qp, Lp, Rp);
    held_force_acceleration(m, d, qp, qd, Rp, t.force.data(), ap);
    qp[k] = q[k] - kJointAngleStep;
    m.def->muscle_paths(qp, Lp, Rp);
    held_force_acceleration(m, d, qp, qd, Rp, t.force.data(), am);
    for (int j = 0; j < nq; ++j) t.dqdd_dq[j * nq + k] = (ap[j] - am[j]) / (2 * kJointAngleStep);
    std::copy(qd, qd + nq, qdp);
    qdp[k] = qd[k] + kJointVelocityStep;
    held_force_acceleration(m, d, q, qdp, R, t.force.data(), ap);
    qdp[k] = qd[k] - kJointVelocityStep;
    held_force_acceleration(m, d, q, qdp, R, t.force.data(), am);
    for (int j = 0; j < nq; ++j) t.dqdd_dqd[j * nq + k] = (ap[j] - am[j]) / (2 * kJointVelocityStep);
  }
  // G = M^-1 R^T (by DOF, stride kMaxElements): how a tendon force moves qdd. M^-1 column by column.
  double Minv[kMaxDofs * kMaxDofs], e[kMaxDofs], col[kMaxDofs];
  for (int k = 0; k < nq; ++k) {
    std::fill(e, e + nq, 0.0);
    e[k] = 1.0;
    solve_spd(jac.mass_matrix.data(), e, nq, col);
    for (int j = 0; j < nq; ++j) Minv[j * nq + k] = col[j];
  }
  std::copy(Minv, Minv + nq * nq, t.inv_mass_matrix.begin());
  double* G = t.accel_per_force.data();
  std::fill(t.accel_per_force.begin(), t.accel_per_force.end(), 0.0);
  for (int j = 0; j < nq; ++j)
    for (int k = 0; k < nq; ++k) {
      const double c = Minv[j * nq + k];
      const double* rk = R + k * kMaxElements;
      double* gj = G + j * kMaxElements;
      for (int i = 0; i < n; ++i) gj[i] += c * rk[i];
    }
  // The tendon forces' own dependence on q through L (dL/dq = -R): - G diag(dF/dL) R^T.
  for (int j = 0; j < nq; ++j)
    for (int k = 0; k < nq; ++k) {
      const double* gj = G + j * kMaxElements;
      const double* rk = R + k * kMaxElements;
      double s = 0;
      for (int i = 0; i < n; ++i) s += gj[i] * jac.dforce_dL[i] * rk[i];
      t.dqdd_dq[j * nq + k] -= s;
    }
  // d(activation rate)/du = d/du [(c1 u + c2)(u - a)] = c1 (u - a) + c1 u + c2, u capped at [0, max_activation]:
  // zero where the cap holds u, and the derivative from inside the range at its ends (u = 0 included).
  const MuscleArrays& mc = d.muscles;
  for (int i = 0; i < n; ++i) {
    const double u_raw = d.excitation[i];
    const double u = capped_excitation(u_raw, mc.max_activation[i]);
    const bool held = u_raw < 0.0 || u_raw > mc.max_activation[i] ||
                      (u_raw == mc.max_activation[i] && mc.max_activation[i] <= 0.0);
    t.act_rate_du[i] = held ? 0.0 : mc.c1[i] * (u - x[ia + i]) + mc.c1[i] * u + mc.c2[i];
    t.act_rate_dlag[i] = held ? 0.0 : mc.c1[i];  // d(c1 u + c2)/du: how W's activation rows move with u
  }
}

// df/dx (ns x ns) and df/du (ns x num_elements), row-major, from the tangent t.
void write_dense(const Model& m, const ForwardTangent& t, double* dfdx, double* dfdu) {
  const int nq = m.num_dofs, n = m.num_elements, ns = state_size(m);
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const StepJacobian& jac = t.jac;
  std::fill(dfdx, dfdx + static_cast<long>(ns) * ns, 0.0);
  std::fill(dfdu, dfdu + static_cast<long>(ns) * n, 0.0);
  for (int j = 0; j < nq; ++j) {
    dfdx[(iq + j) * ns + iqd + j] = 1.0;
    double* row = dfdx + static_cast<long>(iqd + j) * ns;
    for (int k = 0; k < nq; ++k) {
      row[iq + k] = t.dqdd_dq[j * nq + k];
      row[iqd + k] = t.dqdd_dqd[j * nq + k];
    }
    for (int i = 0; i < n; ++i) row[il + i] = t.accel_per_force[j * kMaxElements + i] * jac.dforce_dlce[i];
  }
  for (int i = 0; i < n; ++i) {
    double* row = dfdx + static_cast<long>(il + i) * ns;
    for (int k = 0; k < nq; ++k) row[iq + k] = -jac.dvel_dL[i] * jac.moment_arm[k * kMaxElements + i];
    row[il + i] = jac.dvel_dlce[i];
    row[ia + i] = jac.dvel_da[i];
    dfdx[static_cast<long>(ia + i) * ns + ia + i] = -jac.act_rate[i];
    dfdu[static_cast<long>(ia + i) * n + i] = t.act_rate_du[i];
  }
}

// The step's own J at x: forward()'s Jacobian stiffened by the fibre limiter as ros2.cc does (d's count of limited
// steps kept); xdot = f(x).
void step_jacobian_at(const Model& m, Data& d, const double* x, double h, StepJacobian& jac, double* xdot) {
  forward(m, d, x, xdot, false, &jac);
  const auto limited = d.limited_fibre_steps;
  limit_fibre_overshoot(m, d, jac, x, xdot, h);
  d.limited_fibre_steps = limited;
}

// out = J v for a step's structured J (the matrix ros2.cc solves with: moment-arm derivatives, gravity, Coriolis and
// dM/dq left out).
template <int nq>
void structured_apply(const Model& m, const StepJacobian& jac, const double* v, double* out) {
  const int n = m.num_elements;
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  double Rv[kMaxElements], fl[kMaxElements];
  moment_arm_dot<nq>(m, jac.moment_arm.data(), v + iq, Rv);
  for (int i = 0; i < n; ++i) {
    out[il + i] = -jac.dvel_dL[i] * Rv[i] + jac.dvel_dlce[i] * v[il + i] + jac.dvel_da[i] * v[ia + i];
    out[ia + i] = -jac.act_rate[i] * v[ia + i];
    fl[i] = jac.dforce_dlce[i] * v[il + i] - jac.dforce_dL[i] * Rv[i];
  }
  double tau[nq];
  generalised_force(jac.moment_arm.data(), fl, n, nq, tau, m.dof_elements_begin.data(), m.dof_elements_end.data());
  for (int j = 0; j < nq; ++j) tau[j] += jac.dtau_passive_dq[j] * v[iq + j] + jac.dtau_passive_dqd[j] * v[iqd + j];
  if (m.def->girdle)
    for (int j = 0; j < nq; ++j)
      for (int k = 0; k < nq; ++k) tau[j] += jac.dtau_girdle_dq[j * nq + k] * v[iq + k];
  solve_spd(jac.mass_matrix.data(), tau, nq, out + iqd);
  for (int j = 0; j < nq; ++j) out[iq + j] = v[iqd + j];
}

// The five per-element entries of J that move with the state (and u, through the fibre limiter).
constexpr int kElementEntries = 5;
void element_entries(const StepJacobian& jac, int i, double* e) {
  e[0] = jac.dvel_dL[i];
  e[1] = jac.dvel_dlce[i];
  e[2] = jac.dvel_da[i];
  e[3] = jac.dforce_dL[i];
  e[4] = jac.dforce_dlce[i];
}

// d(entries)/dz_i for z = lce (block 0), activation (1) or excitation (2) of every element at once: element i's
// entries depend on its own L, lce, a, u (and on q, qd), so one perturbation of all elements gives every diagonal.
// Central differences for lce and a; one-sided into the range for u (capped at [0, max_activation]).
void element_derivatives(const Model& m, Data& d, LinearizeWorkspace& w, double h, int block,
                         std::array<std::array<double, kMaxElements>, kElementEntries>& out) {
  const int n = m.num_elements, ns = state_size(m);
  const int off = block == 0 ? lce_offset(m) : act_offset(m);
  const MuscleArrays& mc = d.muscles;
  double eps[kMaxElements];
  for (int i = 0; i < n; ++i)
    eps[i] = block == 0 ? 1e-6 / mc.inv_lceopt[i]
                        : (block == 1 ? 1e-6 : (d.excitation[i] < 0.5 * mc.max_activation[i] ? 1e-6 : -1e-6));
  const double* x = d.x.data();
  if (block < 2) {
    for (int sgn = 0; sgn < 2; ++sgn) {
      std::copy(x, x + ns, w.x_shift.begin());
      for (int i = 0; i < n; ++i) w.x_shift[off + i] += sgn == 0 ? eps[i] : -eps[i];
      step_jacobian_at(m, d, w.x_shift.data(), h, sgn == 0 ? w.jac_plus : w.jac_minus, w.f_shift.data());
    }
  } else {
    double u_held[kMaxElements];
    std::copy(d.excitation.begin(), d.excitation.begin() + n, u_held);
    for (int i = 0; i < n; ++i) d.excitation[i] = u_held[i] + eps[i];
    step_jacobian_at(m, d, x, h, w.jac_plus, w.f_shift.data());
    std::copy(u_held, u_held + n, d.excitation.begin());
  }
  for (int i = 0; i < n; ++i) {
    double ep[kElementEntries], em[kElementEntries];
    element_entries(w.jac_plus, i, ep);
    element_entries(block < 2 ? w.jac_minus : w.step_jacobian, i, em);
    const double step = block < 2 ? 2 * eps[i] : eps[i];
    for (int k = 0; k < kElementEntries; ++k) out[k][i] = (ep[k] - em[k]) / step;
  }
}

// ---- The column phase in tiles of kT columns: T[k * kT + t] is state entry k of the tile's column t.
constexpr int kT = LinearizeWorkspace::kTile;

// (I - hg J) k = r for a tile of right-hand sides: jacobian_solve's algebra (step_jacobian.cc) column-parallel, the
// moment-arm sums over each element run's DOFs only (R is zero outside them).
template <int nq>
void solve_tile(const Model& m, const StepJacobian& jac, const double* r, double* k) {
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const double hg = jac.hg;
  const double* R = jac.moment_arm.data();
  double rhs[nq][kT] = {};
  for (int a = 0; a < nq; ++a)
    for (int b = 0; b < nq; ++b) {
      const double mab = jac.mass_matrix[a * nq + b], kab = hg * jac.stiffness[a * nq + b];
#pragma omp simd
      for (int t = 0; t < kT; ++t) rhs[a][t] += mab * r[(iqd + b) * kT + t] + kab * r[(iq + b) * kT + t];
    }
  for (int run = 0; run < m.num_element_runs; ++run) {
    const Model::ElementRun& er = m.element_runs[run];
    for (int i = er.begin; i < std::min(er.end, m.num_elements); ++i) {
      const double ia_i = jac.inv_act[i], il_i = jac.inv_lce[i], dvda = hg * jac.dvel_da[i];
      const double fs = hg * jac.dforce_dlce[i];
      double* ka = k + (ia + i) * kT;
      double* p = k + (il + i) * kT;  // p until k_q is known
      const double* ra = r + (ia + i) * kT;
      const double* rl = r + (il + i) * kT;
      double f[kT];
#pragma omp simd
      for (int t = 0; t < kT; ++t) {
        ka[t] = ra[t] * ia_i;
        p[t] = il_i * (rl[t] + dvda * ka[t]);
        f[t] = fs * p[t];
      }
      for (int j = er.dof_lo; j <= er.dof_hi; ++j) {
        const double rji = R[j * kMaxElements + i];
#pragma omp simd
        for (int t = 0; t < kT; ++t) rhs[j][t] += rji * f[t];
      }
    }
  }
  // LU solve of the Schur complement, column-parallel.
  double y[nq][kT];
  for (int a = 0; a < nq; ++a)
    for (int t = 0; t < kT; ++t) y[a][t] = rhs[jac.schur_perm[a]][t];
  const double* lu = jac.schur_lu.data();
  for (int c = 0; c < nq; ++c)
    for (int a = c + 1; a < nq; ++a) {
      const double l = lu[a * nq + c];
#pragma omp simd
      for (int t = 0; t < kT; ++t) y[a][t] -= l * y[c][t];
    }
  double kq[nq][kT];
  for (int c = nq - 1; c >= 0; --c) {
    const double inv = jac.schur_inv_diag[c];
    double* kqd = k + (iqd + c) * kT;
#pragma omp simd
    for (int t = 0; t < kT; ++t) kqd[t] = y[c][t] * inv;
    for (int a = 0; a < c; ++a) {
      const double u = lu[a * nq + c];
#pragma omp simd
      for (int t = 0; t < kT; ++t) y[a][t] -= u * kqd[t];
    }
  }
  for (int a = 0; a < nq; ++a)
#pragma omp simd
    for (int t = 0; t < kT; ++t) {
      kq[a][t] = r[(iq + a) * kT + t] + hg * k[(iqd + a) * kT + t];
      k[(iq + a) * kT + t] = kq[a][t];
    }
  for (int run = 0; run < m.num_element_runs; ++run) {
    const Model::ElementRun& er = m.element_runs[run];
    for (int i = er.begin; i < std::min(er.end, m.num_elements); ++i) {
      double rk[kT];
      {
        const double r0 = R[er.dof_lo * kMaxElements + i];
#pragma omp simd
        for (int t = 0; t < kT; ++t) rk[t] = r0 * kq[er.dof_lo][t];
      }
      for (int j = er.dof_lo + 1; j <= er.dof_hi; ++j) {
        const double rji = R[j * kMaxElements + i];
#pragma omp simd
        for (int t = 0; t < kT; ++t) rk[t] += rji * kq[j][t];
      }
      const double lq = jac.lce_from_q[i];
      double* p = k + (il + i) * kT;
#pragma omp simd
      for (int t = 0; t < kT; ++t) p[t] -= lq * rk[t];
    }
  }
}

// out = J v for the full tangent t, a tile of columns (tangent_apply's algebra, column-parallel).
template <int nq>
void apply_tile(const Model& m, const ForwardTangent& tg, const double* v, double* out) {
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const StepJacobian& jac = tg.jac;
  const double* R = jac.moment_arm.data();
  double tau[nq][kT] = {};
  for (int run = 0; run < m.num_element_runs; ++run) {
    const Model::ElementRun& er = m.element_runs[run];
    for (int i = er.begin; i < std::min(er.end, m.num_elements); ++i) {
      double rv[kT];
      {
        const double r0 = R[er.dof_lo * kMaxElements + i];
#pragma omp simd
        for (int t = 0; t < kT; ++t) rv[t] = r0 * v[(iq + er.dof_lo) * kT + t];
      }
      for (int j = er.dof_lo + 1; j <= er.dof_hi; ++j) {
        const double rji = R[j * kMaxElements + i];
#pragma omp simd
        for (int t = 0; t < kT; ++t) rv[t] += rji * v[(iq + j) * kT + t];
      }
      const double dvl = jac.dvel_dL[i], dvc = jac.dvel_dlce[i], dva = jac.dvel_da[i], ar = jac.act_rate[i];
      const double dfc = jac.dforce_dlce[i];
      const double* vl = v + (il + i) * kT;
      const double* va = v + (ia + i) * kT;
      double* ol = out + (il + i) * kT;
      double* oa = out + (ia + i) * kT;
      double fl[kT];
#pragma omp simd
      for (int t = 0; t < kT; ++t) {
        ol[t] = -dvl * rv[t] + dvc * vl[t] + dva * va[t];
        oa[t] = -ar * va[t];
        fl[t] = dfc * vl[t];
      }
      for (int j = er.dof_lo; j <= er.dof_hi; ++j) {
        const double rji = R[j * kMaxElements + i];
#pragma omp simd
        for (int t = 0; t < kT; ++t) tau[j][t] += rji * fl[t];
      }
    }
  }
  for (int a = 0; a < nq; ++a) {
    double s[kT] = {};
    for (int b = 0; b < nq; ++b) {
      const double mi = tg.inv_mass_matrix[a * nq + b], dq = tg.dqdd_dq[a * nq + b], dqd = tg.dqdd_dqd[a * nq + b];
#pragma omp simd
      for (int t = 0; t < kT; ++t) s[t] += mi * tau[b][t] + dq * v[(iq + b) * kT + t] + dqd * v[(iqd + b) * kT + t];
    }
    std::copy(s, s + kT, out + (iqd + a) * kT);
  }
  for (int a = 0; a < nq; ++a) std::copy(v + (iqd + a) * kT, v + (iqd + a) * kT + kT, out + (iq + a) * kT);
}

// Column c's part of a stage's right-hand side that the column adds: hg dJ_c k (k the stage vector, R_k = R k_q) for
// column c of [A | B] (c < ns: state entry c; else excitation c - ns), written into tile column t of r.
void add_column_term(const Model& m, const LinearizeWorkspace& w, int c, int stage, double hg, double* r, int t) {
  const int nq = m.num_dofs, ns = state_size(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const double* k = stage == 1 ? w.k1.data() : w.k2.data();
  const double* R_k = stage == 1 ? w.R_k1.data() : w.R_k2.data();
  const std::array<std::array<double, kMaxElements>, kElementEntries>* dJ;
  int i;
  if (c < 2 * nq) {
    const StateVec& d = stage == 1 ? w.dJ_k1[c] : w.dJ_k2[c];
    for (int s = 0; s < ns; ++s) r[s * kT + t] += hg * d[s];
    return;
  } else if (c < ia) {
    dJ = &w.dJ_dlce, i = c - il;
  } else if (c < ns) {
    dJ = &w.dJ_da, i = c - ia;
  } else {
    dJ = &w.dJ_du, i = c - ns;
  }
  r[(il + i) * kT + t] += hg * (-(*dJ)[0][i] * R_k[i] + (*dJ)[1][i] * k[il + i] + (*dJ)[2][i] * k[ia + i]);
  const double df = hg * (-(*dJ)[3][i] * R_k[i] + (*dJ)[4][i] * k[il + i]);
  for (int j = 0; j < nq; ++j) r[(iqd + j) * kT + t] += w.at_x.accel_per_force[j * kMaxElements + i] * df;
}

// Column c of df/dx (write_dense's entries, from the tangent's structure rather than the dense matrix, whose columns
// are strided in memory) into tile column t of r (zero there before).
void tangent_column(const Model& m, const ForwardTangent& tg, int c, double* r, int t) {
  const int nq = m.num_dofs, n = m.num_elements, iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m),
            ia = act_offset(m);
  const StepJacobian& jac = tg.jac;
  if (c < iqd) {
    const int k = c - iq;
    for (int j = 0; j < nq; ++j) r[(iqd + j) * kT + t] = tg.dqdd_dq[j * nq + k];
    for (int i = 0; i < n; ++i) r[(il + i) * kT + t] = -jac.dvel_dL[i] * jac.moment_arm[k * kMaxElements + i];
  } else if (c < il) {
    const int k = c - iqd;
    r[(iq + k) * kT + t] = 1.0;
    for (int j = 0; j < nq; ++j) r[(iqd + j) * kT + t] = tg.dqdd_dqd[j * nq + k];
  } else if (c < ia) {
    const int i = c - il;
    for (int j = 0; j < nq; ++j) r[(iqd + j) * kT + t] = tg.accel_per_force[j * kMaxElements + i] * jac.dforce_dlce[i];
    r[(il + i) * kT + t] = jac.dvel_dlce[i];
  } else {
    const int i = c - ia;
    r[(il + i) * kT + t] = jac.dvel_da[i];
    r[(ia + i) * kT + t] = -jac.act_rate[i];
  }
}

// The columns of A and B, kT at a time (see linearize_step_n for the algebra).
template <int nq>
void step_columns(const Model& m, LinearizeWorkspace& w, double h, double* A, double* B) {
  const int n = m.num_elements, ns = state_size(m), ia = act_offset(m);
  const double hg = kRos2Gamma * h;
  const StepJacobian& W = w.step_jacobian;
  double* r = w.tile_r.data();
  double* dk1 = w.tile_dk1.data();
  double* y = w.tile_y.data();
  double* dk2 = w.tile_dk2.data();
  const int total = ns + n;
  for (int c0 = 0; c0 < total; c0 += kT) {
    const int width = std::min(kT, total - c0);
    std::fill(r, r + ns * kT, 0.0);
    for (int t = 0; t < width; ++t) {
      const int c = c0 + t;
      if (c < ns) {
        tangent_column(m, w.at_x, c, r, t);
      } else {
        const int i = c - ns;
        r[(ia + i) * kT + t] = w.at_x.act_rate_du[i] - hg * w.at_x.act_rate_dlag[i] * w.k1[ia + i];
      }
      add_column_term(m, w, c, 1, hg, r, t);
    }
    solve_tile<nq>(m, W, r, dk1);
    for (int s = 0; s < ns * kT; ++s) y[s] = h * dk1[s];
    for (int t = 0; t < width; ++t)
      if (c0 + t < ns) y[(c0 + t) * kT + t] += 1.0;
    apply_tile<nq>(m, w.at_x2, y, r);
    for (int s = 0; s < ns * kT; ++s) r[s] -= 2.0 * dk1[s];
    for (int t = 0; t < width; ++t) {
      const int c = c0 + t;
      if (c >= ns) {
        const int i = c - ns;
        r[(ia + i) * kT + t] += w.at_x2.act_rate_du[i] - hg * w.at_x2.act_rate_dlag[i] * w.k2[ia + i];
      }
      add_column_term(m, w, c, 2, hg, r, t);
    }
    solve_tile<nq>(m, W, r, dk2);
    // dk1 <- h (3/2 dk1 + 1/2 dk2), then row by row into A (columns < ns) and B (the rest), contiguous runs.
#pragma omp simd
    for (int s = 0; s < ns * kT; ++s) dk1[s] = h * (1.5 * dk1[s] + 0.5 * dk2[s]);
    const int in_A = std::max(0, std::min(width, ns - c0));
    for (int s = 0; s < ns; ++s) {
      const double* v = dk1 + s * kT;
      if (in_A > 0) std::copy(v, v + in_A, A + static_cast<long>(s) * ns + c0);
      if (in_A < width) std::copy(v + in_A, v + width, B + static_cast<long>(s) * n + (c0 + in_A - ns));
    }
    for (int t = 0; t < in_A; ++t) A[static_cast<long>(c0 + t) * ns + c0 + t] += 1.0;
  }
}

template <int nq>
void linearize_step_n(const Model& m, Data& d, LinearizeWorkspace& w, double h, double* A,
                      double* B) {
  const int ns = state_size(m);
  const double hg = kRos2Gamma * h;
  const double* x = d.x.data();
  // The step itself: W from the tangent at x, stiffened as the step stiffens it (its count of limited steps kept),
  // k1, x2 = x + h k1, the tangent at x2, k2.
  StepJacobian& W = w.step_jacobian;
  W = w.at_x.jac;
  const auto limited = d.limited_fibre_steps;
  limit_fibre_overshoot(m, d, W, x, w.f.data(), h);
  d.limited_fibre_steps = limited;
  jacobian_factor(m, W, hg);
  jacobian_solve(m, W, w.f.data(), w.k1.data());
  for (int k = 0; k < ns; ++k) w.x2[k] = x[k] + h * w.k1[k];
  tangent_at(m, d, w.x2.data(), w.at_x2, w.f2.data());
  for (int k = 0; k < ns; ++k) w.f2[k] -= 2.0 * w.k1[k];
  jacobian_solve(m, W, w.f2.data(), w.k2.data());
  // How J moves: per element with its lce, a and u; with each joint angle and velocity, applied to k1 and k2.
  element_derivatives(m, d, w, h, 0, w.dJ_dlce);
  element_derivatives(m, d, w, h, 1, w.dJ_da);
  element_derivatives(m, d, w, h, 2, w.dJ_du);
  moment_arm_dot<nq>(m, W.moment_arm.data(), w.k1.data() + q_offset(m), w.R_k1.data());
  moment_arm_dot<nq>(m, W.moment_arm.data(), w.k2.data() + q_offset(m), w.R_k2.data());
  // Per joint angle and velocity by forward differences (J at x is W before its factorisation): a term that is
  // itself O(h) in A, so their O(eps) error is far below the central differences' of the tests.
  double p1[kMaxState], p2[kMaxState], m1[kMaxState], m2[kMaxState];
  structured_apply<nq>(m, W, w.k1.data(), m1);
  structured_apply<nq>(m, W, w.k2.data(), m2);
  for (int c = 0; c < 2 * nq; ++c) {
    const double eps = c < nq ? kJointAngleStep : kJointVelocityStep;
    std::copy(x, x + ns, w.x_shift.begin());
    w.x_shift[c] += eps;
    step_jacobian_at(m, d, w.x_shift.data(), h, w.jac_plus, w.f_shift.data());
    structured_apply<nq>(m, w.jac_plus, w.k1.data(), p1);
    structured_apply<nq>(m, w.jac_plus, w.k2.data(), p2);
    for (int k = 0; k < ns; ++k) {
      w.dJ_k1[c][k] = (p1[k] - m1[k]) / eps;
      w.dJ_k2[c][k] = (p2[k] - m2[k]) / eps;
    }
  }
  // Column by column: W k = f gives dk = W^-1 (df - dW k) with dW = -hg dJ:
  // dk1 = W^-1 (J(x) e + hg dJ_e k1), dk2 = W^-1 (J(x2) (e + h dk1) - 2 dk1 + hg dJ_e k2), A e = e + h (3/2 dk1 + 1/2 dk2).
  // B: u enters f through the activation rows, W through their rate c1 u + c2 (d W_aa/du = hg c1) and through the
  // fibre limiter (dJ_du): dk1 = W^-1 (df/du - dW/du k1), dk2 = W^-1 (J(x2) h dk1 + df/du(x2) - 2 dk1 - dW/du k2),
  // B = h (3/2 dk1 + 1/2 dk2).
  step_columns<nq>(m, w, h, A, B);
}

}  // namespace

void linearize(const Model& m, Data& d, LinearizeWorkspace& w, double h, double* dfdx, double* dfdu, double* A,
               double* B) {
  if (d.stimulation_map.num_channels > 0)
    throw std::invalid_argument(
        "linearize: the arm has a stimulation map; the elements it drives follow the stimulation stage's memory, "
        "which is not part of the state x, so dx+/dx over x alone would leave it out");
  tangent_at(m, d, d.x.data(), w.at_x, w.f.data());
  write_dense(m, w.at_x, dfdx, dfdu);
  if (!A) return;
  if (!(h > 0.0)) throw std::invalid_argument("linearize: the step h must be > 0 s");
  detail::dispatch_dofs(m.num_dofs, [&](auto N) { linearize_step_n<N>(m, d, w, h, A, B); });
}

}  // namespace armrt
