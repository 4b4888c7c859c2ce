// linearize.cc: (model, data at x with its excitation u and loads, h) -> df/dx, df/du of forward() at x and
// A = dx+/dx, B = dx+/du of one ROS2 step of h from x (exact paths at both stages, as a step from a state set
// from outside takes), differentiated with its matrix W = I - h gamma J moving too (J's own derivatives by
// differences per element, all elements at once, and through them by the chain rule per joint).
// df/dx is the structured Jacobian's exact per-element blocks plus the mechanical terms the step leaves out
// (gravity, Coriolis, dM/dq, moment-arm derivatives, the hand load's J^T F), taken by central differences of the
// skeleton and path stages with the tendon forces held; docs/control.md "Linearised dynamics" derives A, B and states the kinks.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>

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
// lceopt (of each element): the CE-length, muscle-tendon-length and lengthening-rate (per second) steps of J_W's
// element derivatives. J_W's entries are analytic, so their differences lose only 1e-16 |J| / step to round-off; a
// step of 1e-6 lceopt (about 1e-7 m) straddled kinks a few 1e-8 m away (the concentric/eccentric switch: A 5.6 % off,
// tests/test_linearize.py). The activation and excitation steps stay 1e-6: at 1e-8 the rest states' (q, activation)
// block lost digits to round-off (5.7e-4 relative against 5.6e-5).
constexpr double kElementLengthStep = 1e-8;

// The generalised forces (N m) at q that do not move with qd, the tendon forces F (N) held, paths R at q given (by
// DOF): R^T F, the hand load, the girdle and the applied moments, as forward() sums them.
void held_joint_torque(const Model& m, const Data& d, const double* q, const double* R, const double* force,
                       double* tau) {
  const int nq = m.num_dofs, n = m.num_elements;
  double tau_muscle[kMaxDofs], tau_ext[kMaxDofs], tau_girdle[kMaxDofs];
  double f_ext[3], t_ext[3];
  generalised_force(R, force, n, nq, tau_muscle, m.dof_elements_begin.data(), m.dof_elements_end.data());
  external_load(m, q, d.hand_force.data(), d.hand_moment.data(), f_ext, t_ext, tau_ext);
  if (m.def->girdle) girdle_forces(m, q, tau_girdle, nullptr, nullptr);
  else std::fill(tau_girdle, tau_girdle + nq, 0.0);
  for (int j = 0; j < nq; ++j) tau[j] = tau_muscle[j] + tau_ext[j] + tau_girdle[j] + d.applied_moment[j];
}

// qdd (rad/s^2) at (q, qd) from held_joint_torque's tau_held at q plus the passive joints at (q, qd): the skeleton
// stage with every generalised force as forward() has it, the tendon forces held. M(q) into mass_matrix if given.
void held_force_acceleration(const Model& m, const Data& d, const double* q, const double* qd, const double* tau_held,
                             double* qdd, double* mass_matrix = nullptr) {
  const int nq = m.num_dofs;
  double tau_passive[kMaxDofs], tau[kMaxDofs], M[kMaxDofs * kMaxDofs];
  passive_joint_torque(*m.def, q, qd, tau_passive);
  for (int j = 0; j < nq; ++j) tau[j] = tau_held[j] + tau_passive[j];
  skeleton_dynamics(m, d.settings.gravity.data(), q, qd, tau, mass_matrix ? mass_matrix : M, qdd);
}

// The full tangent of forward() at x into t (xdot: forward()'s derivative there). The mechanical block by central
// differences, or with one_sided by forward ones (half the path and skeleton evaluations; O(eps) = 1e-6 relative, for
// the tangent at the second stage, which enters A and B only multiplied by h). With plus, the paths and M at each
// q + kJointAngleStep e_k are kept there (plus->length_plus, moment_arm_plus, mass_matrix_plus) for how J moves with q.
void tangent_at(const Model& m, Data& d, const double* x, ForwardTangent& t, double* xdot, bool one_sided = false,
                LinearizeWorkspace* plus = nullptr) {
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
  // The velocity columns move only the passive joints and the skeleton: the rest of the torque is taken once.
  double tau_held[kMaxDofs], tau_held_x[kMaxDofs];
  held_joint_torque(m, d, q, R, t.force.data(), tau_held_x);
  double a0[kMaxDofs];
  if (one_sided) held_force_acceleration(m, d, q, qd, tau_held_x, a0);
  const double span = one_sided ? 1.0 : 2.0;  // the differences' width in steps
  for (int k = 0; k < nq; ++k) {
    std::copy(q, q + nq, qp);
    qp[k] = q[k] + kJointAngleStep;
    double* L_plus = plus ? plus->length_plus[k].data() : Lp;
    double* R_plus = plus ? plus->moment_arm_plus[k].data() : Rp;
    m.def->muscle_paths(qp, L_plus, R_plus);
    held_joint_torque(m, d, qp, R_plus, t.force.data(), tau_held);
    held_force_acceleration(m, d, qp, qd, tau_held, ap, plus ? plus->mass_matrix_plus[k].data() : nullptr);
    if (one_sided) {
      std::copy(a0, a0 + nq, am);
    } else {
      qp[k] = q[k] - kJointAngleStep;
      m.def->muscle_paths(qp, Lp, Rp);
      held_joint_torque(m, d, qp, Rp, t.force.data(), tau_held);
      held_force_acceleration(m, d, qp, qd, tau_held, am);
    }
    for (int j = 0; j < nq; ++j) t.dqdd_dq[j * nq + k] = (ap[j] - am[j]) / (span * kJointAngleStep);
    std::copy(qd, qd + nq, qdp);
    qdp[k] = qd[k] + kJointVelocityStep;
    held_force_acceleration(m, d, q, qdp, tau_held_x, ap);
    if (one_sided) {
      std::copy(a0, a0 + nq, am);
    } else {
      qdp[k] = qd[k] - kJointVelocityStep;
      held_force_acceleration(m, d, q, qdp, tau_held_x, am);
    }
    for (int j = 0; j < nq; ++j) t.dqdd_dqd[j * nq + k] = (ap[j] - am[j]) / (span * kJointVelocityStep);
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
  for (int j = 0; j < nq; ++j) std::fill(G + j * kMaxElements, G + j * kMaxElements + n, 0.0);
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

// Zeroes p[0, count) in pieces of at most 1 kB: glibc's memset switches to `rep stosb` above 2 kB, which is as fast
// but which callgrind counts once per byte (the instruction counts of bench.linearize would mostly measure it).
inline void zero_fill(double* p, long count) {
  constexpr long kPiece = 128;
  for (long k = 0; k < count; k += kPiece) std::fill(p + k, p + std::min(count, k + kPiece), 0.0);
}

// dst = src for a StepJacobian (47 kB) in pieces of 1 kB, for the same reason (glibc's memcpy is a `rep movsb` there).
void copy_jacobian(const StepJacobian& src, StepJacobian& dst) {
  static_assert(std::is_trivially_copyable_v<StepJacobian>);
  constexpr std::size_t kPiece = 1024;
  const auto* from = reinterpret_cast<const unsigned char*>(&src);
  auto* to = reinterpret_cast<unsigned char*>(&dst);
  for (std::size_t k = 0; k < sizeof(StepJacobian); k += kPiece)
    std::memcpy(to + k, from + k, std::min(kPiece, sizeof(StepJacobian) - k));
}

// df/dx (ns x ns) and df/du (ns x num_elements), row-major, from the tangent t: each row zeroed (zero_fill) and its
// few entries set.
void write_dense(const Model& m, const ForwardTangent& t, double* dfdx, double* dfdu) {
  const int nq = m.num_dofs, n = m.num_elements, ns = state_size(m);
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const StepJacobian& jac = t.jac;
  zero_fill(dfdu, static_cast<long>(ns) * n);
  for (int j = 0; j < nq; ++j) {
    double* row = dfdx + static_cast<long>(iq + j) * ns;
    zero_fill(row, ns);
    row[iqd + j] = 1.0;
  }
  for (int j = 0; j < nq; ++j) {
    double* row = dfdx + static_cast<long>(iqd + j) * ns;
    for (int k = 0; k < nq; ++k) {
      row[iq + k] = t.dqdd_dq[j * nq + k];
      row[iqd + k] = t.dqdd_dqd[j * nq + k];
    }
    for (int i = 0; i < n; ++i) row[il + i] = t.accel_per_force[j * kMaxElements + i] * jac.dforce_dlce[i];
    zero_fill(row + ia, n);
  }
  for (int i = 0; i < n; ++i) {
    double* row = dfdx + static_cast<long>(il + i) * ns;
    zero_fill(row + iqd, ns - iqd);
    for (int k = 0; k < nq; ++k) row[iq + k] = -jac.dvel_dL[i] * jac.moment_arm[k * kMaxElements + i];
    row[il + i] = jac.dvel_dlce[i];
    row[ia + i] = jac.dvel_da[i];
  }
  for (int i = 0; i < n; ++i) {
    double* row = dfdx + static_cast<long>(ia + i) * ns;
    zero_fill(row, ns);
    row[ia + i] = -jac.act_rate[i];
    dfdu[static_cast<long>(ia + i) * n + i] = t.act_rate_du[i];
  }
}

// The step's own J (forward()'s Jacobian stiffened by the fibre limiter as ros2.cc does, d's count of limited steps
// kept; xdot = f(x)) for an x whose joint angles are those the paths in `paths` were evaluated at (x differs there in
// velocities, CE lengths or activations, or u does): the paths are copied, not evaluated again (the limiter reads them
// from jac; whole blocks of eight, so moment_arm_dot's ghost lanes come along).
// With length_shift, jac's muscle-tendon lengths are the paths' plus it (m, per element; the moment arms kept).
void step_jacobian_with_paths(const Model& m, Data& d, const double* x, const StepJacobian& paths, double h,
                              StepJacobian& jac, double* xdot, const double* length_shift = nullptr) {
  const int n8 = (m.num_elements + 7) / 8 * 8;
  std::copy(paths.muscle_length.begin(), paths.muscle_length.begin() + n8, jac.muscle_length.begin());
  if (length_shift)
    for (int i = 0; i < m.num_elements; ++i) jac.muscle_length[i] += length_shift[i];
  for (int j = 0; j < m.num_dofs; ++j)
    std::copy(paths.moment_arm.begin() + j * kMaxElements, paths.moment_arm.begin() + j * kMaxElements + n8,
              jac.moment_arm.begin() + j * kMaxElements);
  forward_from_paths(m, d, x, jac.muscle_length.data(), jac.moment_arm.data(), xdot, false, &jac);
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

// d(entries)/dz_i for z = lce (block 0), activation (1), excitation (2) or muscle-tendon length L (3, the moment arms
// held) of every element at once: element i's entries depend on its own L, dL/dt, lce, a, u (and on nothing else), so
// one perturbation of all elements gives every diagonal. Central differences for lce, a and L; one-sided into the
// range for u (capped at [0, max_activation]).
void element_derivatives(const Model& m, Data& d, LinearizeWorkspace& w, double h, int block,
                         std::array<std::array<double, kMaxElements>, kElementEntries>& out) {
  const int n = m.num_elements, ns = state_size(m);
  const int off = block == 0 ? lce_offset(m) : act_offset(m);
  const MuscleArrays& mc = d.muscles;
  double eps[kMaxElements];
  for (int i = 0; i < n; ++i)
    eps[i] = block == 0 || block == 3
                 ? kElementLengthStep / mc.inv_lceopt[i]
                 : (block == 1 ? 1e-6 : (d.excitation[i] < 0.5 * mc.max_activation[i] ? 1e-6 : -1e-6));
  const double* x = d.x.data();
  if (block == 3) {
    double shift[kMaxElements];
    for (int sgn = 0; sgn < 2; ++sgn) {
      for (int i = 0; i < n; ++i) shift[i] = sgn == 0 ? eps[i] : -eps[i];
      step_jacobian_with_paths(m, d, x, w.at_x.jac, h, sgn == 0 ? w.jac_plus : w.jac_minus, w.f_shift.data(), shift);
    }
  } else if (block < 2) {
    for (int sgn = 0; sgn < 2; ++sgn) {
      std::copy(x, x + ns, w.x_shift.begin());
      for (int i = 0; i < n; ++i) w.x_shift[off + i] += sgn == 0 ? eps[i] : -eps[i];
      step_jacobian_with_paths(m, d, w.x_shift.data(), w.at_x.jac, h, sgn == 0 ? w.jac_plus : w.jac_minus,
                               w.f_shift.data());
    }
  } else {
    double u_held[kMaxElements];
    std::copy(d.excitation.begin(), d.excitation.begin() + n, u_held);
    for (int i = 0; i < n; ++i) d.excitation[i] = u_held[i] + eps[i];
    step_jacobian_with_paths(m, d, x, w.at_x.jac, h, w.jac_plus, w.f_shift.data());
    std::copy(u_held, u_held + n, d.excitation.begin());
  }
  const bool central = block != 2;
  for (int i = 0; i < n; ++i) {
    double ep[kElementEntries], em[kElementEntries];
    element_entries(w.jac_plus, i, ep);
    element_entries(central ? w.jac_minus : w.step_jacobian, i, em);
    const double step = central ? 2 * eps[i] : eps[i];
    for (int k = 0; k < kElementEntries; ++k) out[k][i] = (ep[k] - em[k]) / step;
  }
}

// d(entries)/d(dL/dt) of every element at once: the lengthening rate enters J only through the fibre limiter
// (the muscle stage does not see it), so the limiter alone runs again from x's unlimited J, with every element's
// dL/dt = -R qd moved by +-kElementLengthStep lceopt per second. Central differences.
void element_rate_derivatives(const Model& m, Data& d, LinearizeWorkspace& w, double h,
                              std::array<std::array<double, kMaxElements>, kElementEntries>& out) {
  const int n = m.num_elements, nq = m.num_dofs, iqd = qd_offset(m);
  const MuscleArrays& mc = d.muscles;
  const StepJacobian& unlimited = w.at_x.jac;
  double L_rate[kMaxElements], shifted[kMaxElements], minus_qd[kMaxDofs];
  for (int j = 0; j < nq; ++j) minus_qd[j] = -d.x[iqd + j];
  detail::dispatch_dofs(nq, [&](auto N) { moment_arm_dot<N>(m, unlimited.moment_arm.data(), minus_qd, L_rate); });
  const auto limited = d.limited_fibre_steps;
  for (int sgn = 0; sgn < 2; ++sgn) {
    StepJacobian& jac = sgn == 0 ? w.jac_plus : w.jac_minus;
    copy_jacobian(unlimited, jac);
    for (int i = 0; i < n; ++i)
      shifted[i] = L_rate[i] + (sgn == 0 ? kElementLengthStep : -kElementLengthStep) / mc.inv_lceopt[i];
    limit_fibre_overshoot_at_rates(m, d, jac, d.x.data(), w.f.data(), h, shifted);
  }
  d.limited_fibre_steps = limited;
  for (int i = 0; i < n; ++i) {
    double ep[kElementEntries], em[kElementEntries];
    element_entries(w.jac_plus, i, ep);
    element_entries(w.jac_minus, i, em);
    const double step = 2 * kElementLengthStep / mc.inv_lceopt[i];
    for (int k = 0; k < kElementEntries; ++k) out[k][i] = (ep[k] - em[k]) / step;
  }
}

// J at x + eps e_c for joint angle c (< n_dofs) or velocity c - n_dofs into P, from W (J at x, limiter applied) by
// the chain rule through what J depends on: each element's entries move with its L and dL/dt (w.dJ_dL, dJ_dLrate:
// L by the paths at q + eps e_k, dL/dt = -R qd by the moment arms there or by -R_k eps), and R, M and the passive and
// girdle stiffness are those at q + eps e_k (tangent_at's points). First order in eps, as the forward difference of
// J it replaces (that evaluated the muscle stage and the limiter once per column). P's other fields are W's.
template <int nq>
void shifted_jacobian(const Model& m, LinearizeWorkspace& w, int c, double eps, StepJacobian& P) {
  const int n = m.num_elements, n8 = (n + 7) / 8 * 8, iqd = qd_offset(m);
  const StepJacobian& W = w.step_jacobian;
  const double* qd = w.x_shift.data() + iqd;  // x itself: the caller's copy
  double dL[kMaxElements], dL_rate[kMaxElements];
  if (c < nq) {
    const double* Lp = w.length_plus[c].data();
    const double* Rp = w.moment_arm_plus[c].data();
    double minus_qd[nq], rate_plus[kMaxElements], rate[kMaxElements];
    for (int j = 0; j < nq; ++j) minus_qd[j] = -qd[j];
    moment_arm_dot<nq>(m, Rp, minus_qd, rate_plus);
    moment_arm_dot<nq>(m, W.moment_arm.data(), minus_qd, rate);
    for (int i = 0; i < n; ++i) {
      dL[i] = Lp[i] - W.muscle_length[i];
      dL_rate[i] = rate_plus[i] - rate[i];
    }
    for (int j = 0; j < nq; ++j)
      std::copy(Rp + j * kMaxElements, Rp + j * kMaxElements + n8, P.moment_arm.begin() + j * kMaxElements);
    std::copy(w.mass_matrix_plus[c].begin(), w.mass_matrix_plus[c].begin() + nq * nq, P.mass_matrix.begin());
    double q_plus[nq];
    std::copy(w.x_shift.begin() + q_offset(m), w.x_shift.begin() + q_offset(m) + nq, q_plus);
    q_plus[c] += eps;
    passive_joint_stiffness(*m.def, q_plus, P.dtau_passive_dq.data(), P.dtau_passive_dqd.data());
    if (m.def->girdle) {
      double tau[kMaxDofs];
      girdle_forces(m, q_plus, tau, P.dtau_girdle_dq.data(), nullptr);
    }
  } else {
    const int k = c - nq;
    for (int i = 0; i < n; ++i) {
      dL[i] = 0.0;
      dL_rate[i] = -W.moment_arm[k * kMaxElements + i] * eps;
    }
  }
  const auto& gL = w.dJ_dL;
  const auto& gr = w.dJ_dLrate;
  for (int i = 0; i < n; ++i) {
    P.dvel_dL[i] = W.dvel_dL[i] + gL[0][i] * dL[i] + gr[0][i] * dL_rate[i];
    P.dvel_dlce[i] = W.dvel_dlce[i] + gL[1][i] * dL[i] + gr[1][i] * dL_rate[i];
    P.dvel_da[i] = W.dvel_da[i] + gL[2][i] * dL[i] + gr[2][i] * dL_rate[i];
    P.dforce_dL[i] = W.dforce_dL[i] + gL[3][i] * dL[i] + gr[3][i] * dL_rate[i];
    P.dforce_dlce[i] = W.dforce_dlce[i] + gL[4][i] * dL[i] + gr[4][i] * dL_rate[i];
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

// Mechanical column c (< 2 n_dofs: joint angle c, or velocity c - n_dofs) of df/dx (write_dense's entries, from the
// tangent's structure rather than the dense matrix, whose columns are strided in memory) added into tile column t of r.
void add_tangent_column(const Model& m, const ForwardTangent& tg, int c, double* r, int t) {
  const int nq = m.num_dofs, n = m.num_elements, iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m);
  const StepJacobian& jac = tg.jac;
  if (c < iqd) {
    const int k = c - iq;
    for (int j = 0; j < nq; ++j) r[(iqd + j) * kT + t] += tg.dqdd_dq[j * nq + k];
    for (int i = 0; i < n; ++i) r[(il + i) * kT + t] -= jac.dvel_dL[i] * jac.moment_arm[k * kMaxElements + i];
  } else {
    const int k = c - iqd;
    r[(iq + k) * kT + t] += 1.0;
    for (int j = 0; j < nq; ++j) r[(iqd + j) * kT + t] += tg.dqdd_dqd[j * nq + k];
  }
}

// The 2 n_dofs mechanical columns of A (joint angles and velocities), kT at a time as full state-long vectors: their
// dJ_W terms (w.dJ_k1, dJ_k2) are dense (see linearize_step_n for the algebra).
template <int nq>
void mechanical_columns(const Model& m, LinearizeWorkspace& w, double h, double* A) {
  const int ns = state_size(m);
  const double hg = kRos2Gamma * h;
  const StepJacobian& W = w.step_jacobian;
  double* r = w.tile_r.data();
  double* dk1 = w.tile_dk1.data();
  double* y = w.tile_y.data();
  double* dk2 = w.tile_dk2.data();
  const int total = 2 * nq;
  for (int c0 = 0; c0 < total; c0 += kT) {
    const int width = std::min(kT, total - c0);
    // r = hg dJ_c k1 + J(x) e_c, assigned lane by lane (no zeroing pass over the tile), unused lanes zero.
    for (int s = 0; s < ns; ++s) {
      double* rs = r + s * kT;
      for (int t = 0; t < width; ++t) rs[t] = hg * w.dJ_k1[c0 + t][s];
      for (int t = width; t < kT; ++t) rs[t] = 0.0;
    }
    for (int t = 0; t < width; ++t) add_tangent_column(m, w.at_x, c0 + t, r, t);
    solve_tile<nq>(m, W, r, dk1);
    for (int s = 0; s < ns * kT; ++s) y[s] = h * dk1[s];
    for (int t = 0; t < width; ++t) y[(c0 + t) * kT + t] += 1.0;
    apply_tile<nq>(m, w.at_x2, y, r);
    for (int s = 0; s < ns; ++s) {
      double* rs = r + s * kT;
      const double* ds = dk1 + s * kT;
      for (int t = 0; t < width; ++t) rs[t] += hg * w.dJ_k2[c0 + t][s] - 2.0 * ds[t];
      for (int t = width; t < kT; ++t) rs[t] -= 2.0 * ds[t];
    }
    solve_tile<nq>(m, W, r, dk2);
    // h (3/2 dk1 + 1/2 dk2), row by row into A's first 2 n_dofs columns.
    for (int s = 0; s < ns; ++s) {
      const double* a = dk1 + s * kT;
      const double* b = dk2 + s * kT;
      double* out = A + static_cast<long>(s) * ns + c0;
      for (int t = 0; t < width; ++t) out[t] = h * (1.5 * a[t] + 0.5 * b[t]);
    }
    for (int t = 0; t < width; ++t) A[static_cast<long>(c0 + t) * ns + c0 + t] += 1.0;
  }
}

// ---- Element columns: the 3 n columns of [A | B] that perturb one element's CE length (type 0), activation (1) or
// excitation (2), column c = type * n + i, in block form rather than as state-long vectors. W and J couple an element
// to the others only through the joints, so W^-1 and J applied to such a column keep
//   the DOF rows (q, qd)     dense, n_dofs per column;
//   the activation rows      the column's own element only (W's and J's activation rows are diagonal);
//   the CE-length rows       the own element's entry plus terms d (.) (R V): a per-element diagonal d times the moment
//                            arms R (at x or at x2) times a DOF-row vector V of the column (a stage's k_q),
// and a solve costs n_dofs^2 per column (the Schur complement's LU, with R^T diag(.) R formed once per term) instead
// of solve_tile's sweep over every element; only writing A and B is state-long per column.
constexpr int kEC = LinearizeWorkspace::kElementColumns;

// A CE-length-row term d (.) (R V) of the element columns: d per element, R by DOF (stride kMaxElements), V by DOF
// (stride kEC).
struct LowRankTerm {
  const double* d;
  const double* R;
  const double* V;
};

// W k = r for the element columns: r's DOF rows rq (nullptr: zero), rqd, own entries rl (CE length), ra
// (activation) and CE-length terms; out: k's DOF rows kq, kqd and own entries kl, ka. k's CE-length rows are
// kl + sum_t (inv_lce d_t) (.) (R_t V_t) - lce_from_q (.) (R kq): solve_tile's algebra, the terms reaching the joints
// through R^T diag(hg dF/dlce inv_lce d_t) R_t (P, n_dofs^2 scratch). rhs: n_dofs x kEC scratch.
template <int nq>
void solve_element_columns(const Model& m, const StepJacobian& W, const double* rq, const double* rqd,
                           const double* rl, const double* ra, const LowRankTerm* terms, int num_terms, double* P,
                           double* rhs, double* kq, double* kqd, double* kl, double* ka) {
  const int n = m.num_elements, C = 3 * n;
  const double hg = W.hg;
  const double* R = W.moment_arm.data();
  for (int t = 0; t < 3; ++t)
    for (int i = 0; i < n; ++i) {
      const int c = t * n + i;
      ka[c] = ra[c] * W.inv_act[i];
      kl[c] = W.inv_lce[i] * (rl[c] + hg * W.dvel_da[i] * ka[c]);
    }
  // rhs = M r_qd + hg K r_q (row by row over the columns).
  for (int a = 0; a < nq; ++a) {
    double* out = rhs + a * kEC;
    {
      const double mab = W.mass_matrix[a * nq], kab = hg * W.stiffness[a * nq];
      for (int c = 0; c < C; ++c) out[c] = mab * rqd[c] + (rq ? kab * rq[c] : 0.0);
    }
    for (int b = 1; b < nq; ++b) {
      const double mab = W.mass_matrix[a * nq + b], kab = hg * W.stiffness[a * nq + b];
      const double* vqd = rqd + b * kEC;
      if (rq) {
        const double* vq = rq + b * kEC;
        for (int c = 0; c < C; ++c) out[c] += mab * vqd[c] + kab * vq[c];
      } else {
        for (int c = 0; c < C; ++c) out[c] += mab * vqd[c];
      }
    }
  }
  // + R^T hg dF/dlce p for the own entries (each column's element, over its run's DOFs).
  for (int run = 0; run < m.num_element_runs; ++run) {
    const Model::ElementRun& er = m.element_runs[run];
    for (int i = er.begin; i < std::min(er.end, n); ++i) {
      const double fs = hg * W.dforce_dlce[i];
      for (int a = er.dof_lo; a <= er.dof_hi; ++a) {
        const double coef = R[a * kMaxElements + i] * fs;
        for (int t = 0; t < 3; ++t) rhs[a * kEC + t * n + i] += coef * kl[t * n + i];
      }
    }
  }
  // + (R^T diag(hg dF/dlce inv_lce d) R_t) V_t for the low-rank terms.
  for (int k = 0; k < num_terms; ++k) {
    const LowRankTerm& lr = terms[k];
    std::fill(P, P + nq * nq, 0.0);
    for (int run = 0; run < m.num_element_runs; ++run) {
      const Model::ElementRun& er = m.element_runs[run];
      for (int e = er.begin; e < std::min(er.end, n); ++e) {
        const double we = hg * W.dforce_dlce[e] * W.inv_lce[e] * lr.d[e];
        for (int a = er.dof_lo; a <= er.dof_hi; ++a) {
          const double ra_e = R[a * kMaxElements + e] * we;
          for (int b = er.dof_lo; b <= er.dof_hi; ++b) P[a * nq + b] += ra_e * lr.R[b * kMaxElements + e];
        }
      }
    }
    for (int a = 0; a < nq; ++a) {
      double* out = rhs + a * kEC;
      for (int b = 0; b < nq; ++b) {
        const double p = P[a * nq + b];
        if (p == 0.0) continue;
        const double* v = lr.V + b * kEC;
        for (int c = 0; c < C; ++c) out[c] += p * v[c];
      }
    }
  }
  // The Schur complement's LU (jacobian_factor), column-parallel as in solve_tile, in place in kqd.
  for (int a = 0; a < nq; ++a) std::copy(rhs + W.schur_perm[a] * kEC, rhs + W.schur_perm[a] * kEC + C, kqd + a * kEC);
  const double* lu = W.schur_lu.data();
  for (int c = 0; c < nq; ++c)
    for (int a = c + 1; a < nq; ++a) {
      const double l = lu[a * nq + c];
      const double* yc = kqd + c * kEC;
      double* ya = kqd + a * kEC;
      for (int j = 0; j < C; ++j) ya[j] -= l * yc[j];
    }
  for (int c = nq - 1; c >= 0; --c) {
    const double inv = W.schur_inv_diag[c];
    double* kc = kqd + c * kEC;
    for (int j = 0; j < C; ++j) kc[j] *= inv;
    for (int a = 0; a < c; ++a) {
      const double u = lu[a * nq + c];
      double* ya = kqd + a * kEC;
      for (int j = 0; j < C; ++j) ya[j] -= u * kc[j];
    }
  }
  for (int a = 0; a < nq; ++a) {
    const double* vqd = kqd + a * kEC;
    double* out = kq + a * kEC;
    if (rq) {
      const double* vq = rq + a * kEC;
      for (int c = 0; c < C; ++c) out[c] = vq[c] + hg * vqd[c];
    } else {
      for (int c = 0; c < C; ++c) out[c] = hg * vqd[c];
    }
  }
}

// The element columns of A (its last 2 n columns) and B (all of it), the algebra of linearize_step_n in block form:
//   dk1 = W^-1 (J(x) e + hg dJ_e k1)                    DOF rows q1, qd1; own lce1, act1; CE-length term -lq (R q1)
//   y = e + h dk1;  r2 = J(x2) y - 2 dk1 + hg dJ_e k2 (+ df/du(x2) - dW/du k2 for excitations)
//                                                       CE-length terms lq (2 - h dvc2) (R q1) and -h dvl2 (R2 q1)
//   dk2 = W^-1 r2                                       q2, qd2; lce2, act2; terms il d (R q1), il d (R2 q1), -lq (R q2)
//   column = e + h (3/2 dk1 + 1/2 dk2)
// (lq = lce_from_q, il = inv_lce of W; dvc2, dvl2 the CE velocity's derivatives at x2; R the moment arms at x, R2 at x2).
template <int nq>
void element_columns(const Model& m, LinearizeWorkspace& w, double h, double* A, double* B) {
  const int n = m.num_elements, C = 3 * n, ns = state_size(m), off = 2 * nq;
  const int il = lce_offset(m), ia = act_offset(m);
  const double hg = kRos2Gamma * h;
  const StepJacobian& W = w.step_jacobian;
  const ForwardTangent& tx = w.at_x;
  const ForwardTangent& t2 = w.at_x2;
  const double* Rw = W.moment_arm.data();
  const double* R2 = t2.jac.moment_arm.data();
  const double* Gx = tx.accel_per_force.data();
  const double* G2 = t2.accel_per_force.data();
  const double* lq = W.lce_from_q.data();
  const double* k1 = w.k1.data();
  const double* k2 = w.k2.data();
  double* rq = w.ec_rq.data();
  double* rqd = w.ec_rqd.data();
  double* rl = w.ec_rl.data();
  double* ra = w.ec_ra.data();
  double *q1 = w.ec_q1.data(), *qd1 = w.ec_qd1.data(), *q2 = w.ec_q2.data(), *qd2 = w.ec_qd2.data();
  double *lce1 = w.ec_lce1.data(), *act1 = w.ec_act1.data(), *lce2 = w.ec_lce2.data(), *act2 = w.ec_act2.data();
  double *dA = w.ec_d1.data(), *dB = w.ec_d2.data();
  double* P = w.ec_P.data();
  double s[kEC];  // each column's tendon-force change (N) reaching qdd through M^-1 R^T
  auto dJ_of = [&](int t) -> const std::array<std::array<double, kMaxElements>, kElementEntries>& {
    return t == 0 ? w.dJ_dlce : (t == 1 ? w.dJ_da : w.dJ_du);
  };
  // Stage 1: r1 = J(x) e_c + hg dJ_c k1 (+ df/du - dW/du k1 for excitations); its DOF rows: q none, qd M^-1 R^T s.
  for (int t = 0; t < 3; ++t) {
    const auto& dJ = dJ_of(t);
    for (int i = 0; i < n; ++i) {
      const int c = t * n + i;
      rl[c] = (t == 0 ? tx.jac.dvel_dlce[i] : (t == 1 ? tx.jac.dvel_da[i] : 0.0)) +
              hg * (-dJ[0][i] * w.R_k1[i] + dJ[1][i] * k1[il + i] + dJ[2][i] * k1[ia + i]);
      ra[c] = t == 1 ? -tx.jac.act_rate[i]
                     : (t == 2 ? tx.act_rate_du[i] - hg * tx.act_rate_dlag[i] * k1[ia + i] : 0.0);
      s[c] = (t == 0 ? tx.jac.dforce_dlce[i] : 0.0) + hg * (-dJ[3][i] * w.R_k1[i] + dJ[4][i] * k1[il + i]);
    }
  }
  for (int j = 0; j < nq; ++j)
    for (int t = 0; t < 3; ++t) {
      const double* g = Gx + j * kMaxElements;
      double* out = rqd + j * kEC + t * n;
      const double* st = s + t * n;
      for (int i = 0; i < n; ++i) out[i] = g[i] * st[i];
    }
  solve_element_columns<nq>(m, W, nullptr, rqd, rl, ra, nullptr, 0, P, w.ec_rhs.data(), q1, qd1, lce1, act1);

  // Stage 2. y = e + h dk1: DOF rows h q1, h qd1; own h lce1 (+1), h act1 (+1); CE-length term -h lq (R q1).
  // J(x2) y's qd rows: M2^-1 R2^T dvc... = G2 dF/dlce2 y_own + Q q1 + h (D_q q1 + D_qd qd1), with
  // Q = G2 diag(dF/dlce2 (-h lq)) R (the CE-length term through the tendons).
  const StepJacobian& j2 = t2.jac;
  std::fill(P, P + nq * nq, 0.0);
  for (int run = 0; run < m.num_element_runs; ++run) {
    const Model::ElementRun& er = m.element_runs[run];
    for (int e = er.begin; e < std::min(er.end, n); ++e) {
      const double we = -h * j2.dforce_dlce[e] * lq[e];
      for (int a = 0; a < nq; ++a) {
        const double ge = G2[a * kMaxElements + e] * we;
        for (int b = er.dof_lo; b <= er.dof_hi; ++b) P[a * nq + b] += ge * Rw[b * kMaxElements + e];
      }
    }
  }
  for (int a = 0; a < nq * nq; ++a) P[a] += h * t2.dqdd_dq[a];
  for (int t = 0; t < 3; ++t) {
    const auto& dJ = dJ_of(t);
    for (int i = 0; i < n; ++i) {
      const int c = t * n + i;
      const double yl = h * lce1[c] + (t == 0 ? 1.0 : 0.0), ya = h * act1[c] + (t == 1 ? 1.0 : 0.0);
      rl[c] = j2.dvel_dlce[i] * yl + j2.dvel_da[i] * ya - 2.0 * lce1[c] +
              hg * (-dJ[0][i] * w.R_k2[i] + dJ[1][i] * k2[il + i] + dJ[2][i] * k2[ia + i]);
      ra[c] = -j2.act_rate[i] * ya - 2.0 * act1[c] +
              (t == 2 ? t2.act_rate_du[i] - hg * t2.act_rate_dlag[i] * k2[ia + i] : 0.0);
      s[c] = hg * (-dJ[3][i] * w.R_k2[i] + dJ[4][i] * k2[il + i]);
      lce2[c] = j2.dforce_dlce[i] * yl;  // scratch: the own tendon-force change at x2
    }
  }
  for (int a = 0; a < nq; ++a) {
    double* outq = rq + a * kEC;
    double* out = rqd + a * kEC;
    const double* vq = q1 + a * kEC;
    const double* vqd = qd1 + a * kEC;
    for (int c = 0; c < C; ++c) {
      outq[c] = h * vqd[c] - 2.0 * vq[c];
      out[c] = -2.0 * vqd[c];
    }
    for (int t = 0; t < 3; ++t) {
      const double* gx = Gx + a * kMaxElements;
      const double* g2 = G2 + a * kMaxElements;
      double* o = out + t * n;
      const double* st = s + t * n;
      const double* f2 = lce2 + t * n;
      for (int i = 0; i < n; ++i) o[i] += gx[i] * st[i] + g2[i] * f2[i];
    }
    for (int b = 0; b < nq; ++b) {
      const double p = P[a * nq + b], dqd = h * t2.dqdd_dqd[a * nq + b];
      const double* v1 = q1 + b * kEC;
      const double* v2 = qd1 + b * kEC;
      for (int c = 0; c < C; ++c) out[c] += p * v1[c] + dqd * v2[c];
    }
  }
  for (int i = 0; i < n; ++i) {
    dA[i] = lq[i] * (2.0 - h * j2.dvel_dlce[i]);
    dB[i] = -h * j2.dvel_dL[i];
  }
  const LowRankTerm terms2[2] = {{dA, Rw, q1}, {dB, R2, q1}};
  solve_element_columns<nq>(m, W, rq, rqd, rl, ra, terms2, 2, P, w.ec_rhs.data(), q2, qd2, lce2, act2);

  // column = e + h (3/2 dk1 + 1/2 dk2), row by row: A's columns off.. (lce, activation), B's (excitation).
  for (int a = 0; a < nq; ++a)
    for (int blk = 0; blk < 2; ++blk) {
      const double* v1 = (blk == 0 ? q1 : qd1) + a * kEC;
      const double* v2 = (blk == 0 ? q2 : qd2) + a * kEC;
      const int row = (blk == 0 ? q_offset(m) : qd_offset(m)) + a;
      double* outA = A + static_cast<long>(row) * ns + off;
      double* outB = B + static_cast<long>(row) * n - 2 * n;
      for (int c = 0; c < 2 * n; ++c) outA[c] = h * (1.5 * v1[c] + 0.5 * v2[c]);
      for (int c = 2 * n; c < C; ++c) outB[c] = h * (1.5 * v1[c] + 0.5 * v2[c]);
    }
  for (int run = 0; run < m.num_element_runs; ++run) {
    const Model::ElementRun& er = m.element_runs[run];
    for (int r = er.begin; r < std::min(er.end, n); ++r) {
      // CE-length row r: sum_j (cW1 Rw_jr + c21 R2_jr) q1_j + cW2 Rw_jr q2_j over the run's DOFs.
      const double cW1 = h * (-1.5 * lq[r] + 0.5 * W.inv_lce[r] * dA[r]);
      const double c21 = 0.5 * h * W.inv_lce[r] * dB[r];
      const double cW2 = -0.5 * h * lq[r];
      double al[kMaxDofs], be[kMaxDofs];
      const int j0 = er.dof_lo, nj = er.dof_hi - er.dof_lo + 1;
      for (int j = 0; j < nj; ++j) {
        al[j] = cW1 * Rw[(j0 + j) * kMaxElements + r] + c21 * R2[(j0 + j) * kMaxElements + r];
        be[j] = cW2 * Rw[(j0 + j) * kMaxElements + r];
      }
      double* outA = A + static_cast<long>(il + r) * ns + off;
      double* outB = B + static_cast<long>(il + r) * n - 2 * n;
      auto lce_row = [&](double* out, int cb, int ce) {
        {
          const double* v1 = q1 + j0 * kEC;
          const double* v2 = q2 + j0 * kEC;
          for (int c = cb; c < ce; ++c) out[c] = al[0] * v1[c] + be[0] * v2[c];
        }
        for (int j = 1; j < nj; ++j) {
          const double* v1 = q1 + (j0 + j) * kEC;
          const double* v2 = q2 + (j0 + j) * kEC;
          for (int c = cb; c < ce; ++c) out[c] += al[j] * v1[c] + be[j] * v2[c];
        }
      };
      lce_row(outA, 0, 2 * n);
      lce_row(outB, 2 * n, C);
      for (int t = 0; t < 3; ++t) {
        const int c = t * n + r;
        const double own = h * (1.5 * lce1[c] + 0.5 * lce2[c]) + (t == 0 ? 1.0 : 0.0);
        (t < 2 ? outA : outB)[c] += own;
      }
      // Activation row r: its own entries only.
      double own_a[3];
      for (int t = 0; t < 3; ++t) {
        const int c = t * n + r;
        own_a[t] = h * (1.5 * act1[c] + 0.5 * act2[c]) + (t == 1 ? 1.0 : 0.0);
      }
      double* actA = A + static_cast<long>(ia + r) * ns + off;
      double* actB = B + static_cast<long>(ia + r) * n;
      zero_fill(actA, 2 * n);
      zero_fill(actB, n);
      actA[r] = own_a[0];
      actA[n + r] = own_a[1];
      actB[r] = own_a[2];
    }
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
  copy_jacobian(w.at_x.jac, W);
  const auto limited = d.limited_fibre_steps;
  limit_fibre_overshoot(m, d, W, x, w.f.data(), h);
  d.limited_fibre_steps = limited;
  jacobian_factor(m, W, hg);
  jacobian_solve(m, W, w.f.data(), w.k1.data());
  for (int k = 0; k < ns; ++k) w.x2[k] = x[k] + h * w.k1[k];
  tangent_at(m, d, w.x2.data(), w.at_x2, w.f2.data(), true);
  for (int k = 0; k < ns; ++k) w.f2[k] -= 2.0 * w.k1[k];
  jacobian_solve(m, W, w.f2.data(), w.k2.data());
  // ros2_update's arithmetic, so that a caller needs no second step for where this one lands.
  for (int k = 0; k < ns; ++k) w.x_next[k] = x[k] + h * (1.5 * w.k1[k] + 0.5 * w.k2[k]);
  // How J moves: per element with its lce, a and u; with each joint angle and velocity, applied to k1 and k2.
  element_derivatives(m, d, w, h, 0, w.dJ_dlce);
  element_derivatives(m, d, w, h, 1, w.dJ_da);
  element_derivatives(m, d, w, h, 2, w.dJ_du);
  moment_arm_dot<nq>(m, W.moment_arm.data(), w.k1.data() + q_offset(m), w.R_k1.data());
  moment_arm_dot<nq>(m, W.moment_arm.data(), w.k2.data() + q_offset(m), w.R_k2.data());
  // Per joint angle and velocity by forward differences of J (J at x is W before its factorisation), J at x + eps e_c
  // by the chain rule (shifted_jacobian): a term that is itself O(h) in A, so their O(eps) error is far below the
  // central differences' of the tests. Velocity columns first: they leave P's paths, M and stiffness W's.
  element_derivatives(m, d, w, h, 3, w.dJ_dL);
  element_rate_derivatives(m, d, w, h, w.dJ_dLrate);
  double p1[kMaxState], p2[kMaxState], m1[kMaxState], m2[kMaxState];
  structured_apply<nq>(m, W, w.k1.data(), m1);
  structured_apply<nq>(m, W, w.k2.data(), m2);
  std::copy(x, x + ns, w.x_shift.begin());
  copy_jacobian(W, w.jac_plus);
  for (int step = 0; step < 2 * nq; ++step) {
    const int c = step < nq ? nq + step : step - nq;
    const double eps = c < nq ? kJointAngleStep : kJointVelocityStep;
    shifted_jacobian<nq>(m, w, c, eps, w.jac_plus);
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
  mechanical_columns<nq>(m, w, h, A);
  element_columns<nq>(m, w, h, A, B);
}

}  // namespace

void linearize(const Model& m, Data& d, LinearizeWorkspace& w, double h, double* dfdx, double* dfdu, double* A,
               double* B) {
  if (d.stimulation_map.num_channels > 0)
    throw std::invalid_argument(
        "linearize: the arm has a stimulation map; the elements it drives follow the stimulation stage's memory, "
        "which is not part of the state x, so dx+/dx over x alone would leave it out");
  tangent_at(m, d, d.x.data(), w.at_x, w.f.data(), false, A ? &w : nullptr);
  write_dense(m, w.at_x, dfdx, dfdu);
  if (!A) return;
  if (!(h > 0.0)) throw std::invalid_argument("linearize: the step h must be > 0 s");
  detail::dispatch_dofs(m.num_dofs, [&](auto N) { linearize_step_n<N>(m, d, w, h, A, B); });
}

}  // namespace armrt
