// Linearly implicit (Rosenbrock) steps: ROS2 (Verwer, Spee, Blom & Hundsdorfer 1999, SIAM J. Sci.
// Comput. 20(4), eq. 2.5, gamma = 1 + 1/sqrt(2)), L-stable, second order with any approximate Jacobian
// (W-method), one Jacobian and two derivative evaluations per step:
//   (I - h gamma J) k1 = f(x_n)
//   (I - h gamma J) k2 = f(x_n + h k1) - 2 k1
//   x_{n+1} = x_n + h (3/2 k1 + 1/2 k2)
// Along a run of equal steps the muscle paths are evaluated at one step in kRos2PathPeriod and extrapolated
// from the last two evaluations at all other evaluations of f (extrapolate_paths_n), which keeps the order.
// J is the structured ("arrow") Jacobian of data.h StepJacobian. The linear systems are never formed
// as a state-sized matrix (214 x 214 for das2): the activation rows are scalar, each CE-length row is
// scalar once the joint part is known, and what remains is an n x n Schur complement (n = num_dofs) in
// the joint-velocity part (docs/engine.md derives it). Cost per step: fixed, two passes over the
// elements, one n x n LU; no iteration, no heap.
//
// J is the tangent at x_n except where a tangent cannot see what happens within the step (ROS2 stays
// second order with any J: it is a W-method): an active element whose slack tendon engages within the
// step, and a taut tendon loading up as activation rises (limit_fibre_overshoot). Measured on seeded
// random protocols: without it a slack-to-taut event could overshoot the CE by centimetres and put
// the joints 6-16 deg off CVODE for a while; with it the error stays ~0.1-0.2 deg (docs/engine.md).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "dof_dispatch.h"
#include "lanes.h"

namespace armrt {

namespace {

// In-place LU with partial pivoting of a row-major n x n matrix (n = the model's DOFs), and the reciprocals
// of U's diagonal. The pivot choice depends on the values, the work does not.
template <int n>
void lu_factor(double* a, int* perm, double* inv_diag) {
  for (int i = 0; i < n; ++i) perm[i] = i;
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(a[i * n + k]) > std::fabs(a[p * n + k])) p = i;
    if (p != k) {
      for (int j = 0; j < n; ++j) std::swap(a[k * n + j], a[p * n + j]);
      std::swap(perm[k], perm[p]);
    }
    const double inv = 1.0 / a[k * n + k];
    inv_diag[k] = inv;
    for (int i = k + 1; i < n; ++i) {
      const double l = a[i * n + k] * inv;
      a[i * n + k] = l;
      for (int j = k + 1; j < n; ++j) a[i * n + j] -= l * a[k * n + j];
    }
  }
}

// Column by column: once y_k (x_k) is known it updates the rest of the right-hand side, so the dependent
// chain is one multiply-add per column; row-by-row dot products chained all of each row's terms and a
// division per row.
template <int n>
void lu_solve(const double* lu, const int* perm, const double* inv_diag, const double* b, double* x) {
  double y[n];
  for (int i = 0; i < n; ++i) y[i] = b[perm[i]];
  for (int k = 0; k < n; ++k)
    for (int i = k + 1; i < n; ++i) y[i] -= lu[i * n + k] * y[k];
  for (int k = n - 1; k >= 0; --k) {
    const double xk = y[k] * inv_diag[k];
    x[k] = xk;
    for (int i = 0; i < k; ++i) y[i] -= lu[i * n + k] * xk;
  }
}

// out[i] = sum_j R[j][i] v[j], the per-element dot products with moment arms by DOF (data.h): eight elements
// per multiply-add, each block of eight over the DOFs its run crosses (Model::element_runs; the other terms
// are zero, so the sums are the same to the bit), in DOF order. out has room for the last block's ghost
// lanes (zeros).
template <int nq>
void moment_arm_dot(const Model& m, const double* R, const double* v, double* out) {
  using detail::v8d;
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    for (int i = run.begin; i < run.end; i += 8) {
      v8d acc = {};
      for (int j = run.dof_lo; j <= run.dof_hi; ++j) {
        v8d rj;
        std::memcpy(&rj, R + j * kMaxElements + i, sizeof(v8d));
        acc += rj * v[j];
      }
      std::memcpy(out + i, &acc, sizeof(v8d));
    }
  }
}

}  // namespace

constexpr double kRos2Gamma = 1.7071067811865475;  // 1 + 1/sqrt(2)
// Isometric force (x fmax) above which a slack element's CE is fast enough to need limiting.
constexpr double kEngagingActiveForce = 0.05;

namespace {

// acc[b] += sum over the elements [begin, end) of c_i R[a][i] R[a + b][i], b < count, eight elements per
// multiply-add (R by DOF, data.h). count is a template parameter so that the sums stay in registers.
template <int count>
[[gnu::always_inline]] inline void stiffness_run(const double* c, const double* ra, int begin, int end,
                                                 detail::v8d* acc) {
  using detail::v8d;
  for (int i = begin; i < end; i += 8) {
    v8d ci, rai;
    std::memcpy(&ci, c + i, sizeof(v8d));
    std::memcpy(&rai, ra + i, sizeof(v8d));
    const v8d cr = ci * rai;
#pragma GCC unroll 16
    for (int b = 0; b < count; ++b) {
      v8d rb;
      std::memcpy(&rb, ra + b * kMaxElements + i, sizeof(v8d));
      acc[b] += cr * rb;
    }
  }
}

// Row a of R^T diag(c) R (entries b >= a, mirrored into column a), negated into K (nq x nq): over the blocks
// of eight elements run by run (Model::element_runs; c and R are zero in the last block's ghost lanes), each
// run only for the DOFs it crosses, the row's sums side by side in registers. (The loop is bound by loading
// moment arms: das3's zero rows were 60 % of them.) Skipping zeros changes no bit of a sum.
template <int nq, int a>
void stiffness_row(const Model& m, const double* R, const double* c, double* K) {
  using detail::v8d;
  constexpr int nb = nq - a;
  const double* ra = R + a * kMaxElements;
  v8d acc[nb];
#pragma GCC unroll 16
  for (int b = 0; b < nb; ++b) acc[b] = v8d{};
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    if (a < run.dof_lo || a > run.dof_hi) continue;
    detail::dispatch_count<nb>(run.dof_hi - a + 1,
                               [&](auto count) { stiffness_run<count>(c, ra, run.begin, run.end, acc); });
  }
  for (int b = 0; b < nb; ++b) {
    const double s = detail::lane_sum(acc[b]);
    K[a * nq + a + b] = K[(a + b) * nq + a] = -s;
  }
}

template <int nq>
void jacobian_factor_n(const Model& m, StepJacobian& jac, double hg) {
  const int n = m.num_elements;
  jac.hg = hg;
  const double* R = jac.moment_arm.data();  // by DOF
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    // Both reciprocals from one division (one costs about nine multiply-adds here).
    const double d_act = 1.0 + hg * jac.act_rate[i], d_lce = 1.0 - hg * jac.dvel_dlce[i];
    const double inv_both = 1.0 / (d_act * d_lce);
    jac.inv_act[i] = d_lce * inv_both;
    jac.inv_lce[i] = d_act * inv_both;
    jac.lce_from_q[i] = hg * jac.dvel_dL[i] * jac.inv_lce[i];
    jac.series_stiffness[i] = jac.dforce_dL[i] + jac.dforce_dlce[i] * jac.lce_from_q[i];
  }
  // K_eff = diag(dtau_passive/dq) + dtau_girdle/dq - R^T diag(series_stiffness) R, R by DOF (data.h), row by row
  // (stiffness_row: over the element runs that cross each row's DOF).
  double K[nq * nq];
  [&]<int... A>(std::integer_sequence<int, A...>) {
    (stiffness_row<nq, A>(m, R, jac.series_stiffness.data(), K), ...);
  }(std::make_integer_sequence<int, nq>{});
  for (int a = 0; a < nq; ++a) K[a * nq + a] += jac.dtau_passive_dq[a];
  if (m.def->girdle)
    for (int k = 0; k < nq * nq; ++k) K[k] += jac.dtau_girdle_dq[k];
  std::copy(K, K + nq * nq, jac.stiffness.begin());
  // Schur complement S = M - hg diag(dtau_passive/dqd) - hg^2 K_eff.
  double* S = jac.schur_lu.data();
  for (int a = 0; a < nq; ++a)
    for (int b = 0; b < nq; ++b)
      S[a * nq + b] = jac.mass_matrix[a * nq + b] - hg * hg * K[a * nq + b] -
                      (a == b ? hg * jac.dtau_passive_dqd[a] : 0.0);
  lu_factor<nq>(S, jac.schur_perm.data(), jac.schur_inv_diag.data());
}

template <int nq>
void jacobian_solve_n(const Model& m, StepJacobian& jac, const double* r, double* k) {
  const int n = m.num_elements;
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const double hg = jac.hg;
  const double* R = jac.moment_arm.data();  // by DOF
  const double* rq = r + iq;
  const double* rqd = r + iqd;
  // Activation rows, then the CE-length rows' part that does not depend on k_q (kept in tmp).
  double* p = jac.tmp.data();
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double ka = r[ia + i] * jac.inv_act[i];
    k[ia + i] = ka;
    p[i] = jac.inv_lce[i] * (r[il + i] + hg * jac.dvel_da[i] * ka);
  }
  // Schur right-hand side: M r_qd + hg R^T (dforce_dlce p) + hg K_eff r_q.
  double rhs[nq];
  for (int a = 0; a < nq; ++a) {
    double s = 0;
    for (int b = 0; b < nq; ++b)
      s += jac.mass_matrix[a * nq + b] * rqd[b] + hg * jac.stiffness[a * nq + b] * rq[b];
    rhs[a] = s;
  }
  double f[kMaxElements];
#pragma omp simd
  for (int i = 0; i < n; ++i) f[i] = hg * jac.dforce_dlce[i] * p[i];
  double tau_p[nq];
  generalised_force(R, f, n, nq, tau_p, m.dof_elements_begin.data(), m.dof_elements_end.data());
  for (int a = 0; a < nq; ++a) rhs[a] += tau_p[a];
  double kqd[nq];
  lu_solve<nq>(jac.schur_lu.data(), jac.schur_perm.data(), jac.schur_inv_diag.data(), rhs, kqd);
  double kq[nq];
  for (int a = 0; a < nq; ++a) {
    kq[a] = rq[a] + hg * kqd[a];
    k[iq + a] = kq[a];
    k[iqd + a] = kqd[a];
  }
  double rk[kMaxElements];
  moment_arm_dot<nq>(m, R, kq, rk);
#pragma omp simd
  for (int i = 0; i < n; ++i) k[il + i] = p[i] - jac.lce_from_q[i] * rk[i];
}

}  // namespace

void jacobian_factor(const Model& m, StepJacobian& jac, double hg) {
  detail::dispatch_dofs(m.num_dofs, [&](auto N) { jacobian_factor_n<N>(m, jac, hg); });
}

void jacobian_solve(const Model& m, StepJacobian& jac, const double* r, double* k) {
  detail::dispatch_dofs(m.num_dofs, [&](auto N) { jacobian_solve_n<N>(m, jac, r, k); });
}

namespace {

// ROS2 on a scalar linear mode x' = lambda x + w moves by h w theta'(2 - theta'), theta' = 1/(1 - hg lambda):
// sets *dvel_dlce to the lambda for which this is theta h w, the fraction theta of the step's drive that
// reaches the operating point, if 0 < theta < 1 and that is stiffer. Returns 1 if it did.
[[gnu::noinline]] int stiffen_to_operating_point(double theta, double hg, double* dvel_dlce) {
  if (!(theta > 0.0 && theta < 1.0)) return 0;
  const double theta_p = 1.0 - std::sqrt(1.0 - theta);
  const double lambda = -(1.0 / theta_p - 1.0) / hg;
  if (!(lambda < *dvel_dlce)) return 0;
  *dvel_dlce = lambda;
  return 1;
}

}  // namespace

void limit_fibre_overshoot(const Model& m, Data& d, const double* x, const double* xdot, double h) {
  StepJacobian& jac = d.jac;
  const MuscleArrays& mc = m.muscles;
  const int n = m.num_elements, nq = m.num_dofs, iqd = qd_offset(m), ia = act_offset(m);
  const double hg = kRos2Gamma * h;
  const double b0 = m.fibre_damping;
  // Muscle-tendon lengthening rates dL/dt = -R qd (m/s), then one branch-free pass per element.
  double L_rate[kMaxElements], minus_qd[kMaxDofs];
  for (int j = 0; j < nq; ++j) minus_qd[j] = -x[iqd + j];
  detail::dispatch_dofs(nq, [&](auto N) { moment_arm_dot<N>(m, jac.moment_arm.data(), minus_qd, L_rate); });
  const double* lce_x = x + lce_offset(m);
  const double* a_x = x + ia;
  const double* lce_rate = xdot + lce_offset(m);
  const double* a_rate = xdot + ia;
  double* dvel_dlce = jac.dvel_dlce.data();
  double* dvel_dL = jac.dvel_dL.data();
  double* dvel_da = jac.dvel_da.data();
  double* dforce_dL = jac.dforce_dL.data();
  double* dforce_dlce = jac.dforce_dlce.data();
  double taut[kMaxElements], L_op[kMaxElements], lce_at_op[kMaxElements], along_at_op[kMaxElements], a_op[kMaxElements];
  // Where the CE may run through its operating point: the distance to it (m, 0 elsewhere) and the drive.
  double op_gap[kMaxElements], op_disp[kMaxElements];
  int limited = 0;
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double L_now = jac.muscle_length[i];
    const double L_next = L_now + h * L_rate[i];
    const double a_pred = a_x[i] + h * a_rate[i];
    const double a_next = a_pred < 0.0 ? 0.0 : (a_pred > 1.0 ? 1.0 : a_pred);
    // Operating point: the tendon stretched to carry what the fibres hold once it has engaged (k_see s^2
    // = that force along the tendon): the CE's isometric force a fmax f(lce) plus the PEE's, less the
    // compressive element's, plus the damper's drag b v where a lengthening muscle-tendon unit pulls
    // the fibre along at v = dL/dt cos(pennation). Without the drag a relaxed fibre's operating point is
    // the slack kink itself, where the tendon has no stiffness.
    // f(lce), cos(pennation) and the passive fibre forces are the stage's own (forward() at this x
    // stored them in jac: the same values, not recomputed), and the loop has no division: each one cost
    // as much as nine multiply-adds.
    const double afl = a_next * jac.force_length[i];  // F0 / fmax
    const double F0 = mc.fmax[i] * afl;
    const double th2 = mc.thickness[i] * mc.thickness[i];
    const double lce_along = jac.lce_along[i];
    const double cos_pen = jac.cos_pennation[i];
    const double v_drag = L_rate[i] > 0.0 ? L_rate[i] * cos_pen : 0.0;
    const double b_drag = b0 + damping_floor(mc.damping_slope[i], afl);
    const double fibre_force = F0 + b_drag * v_drag + jac.pee_force[i] - jac.compress_force[i];
    const double F_op = (fibre_force > 0.0 ? fibre_force : 0.0) * cos_pen;
    const double s_op = std::sqrt(F_op * mc.inv_k_see[i]);  // the tendon's stretch at F_op: k_see s^2 = F_op
    const double along_op_raw = L_next - mc.lslack[i] - s_op;
    const double along_op = along_op_raw > mc.min_lce[i] ? along_op_raw : mc.min_lce[i];
    const double lce_op = std::sqrt(along_op * along_op + th2);
    // The CE's drive over the step: its velocity plus what the activation change adds through
    // dv/da (the first stage's activation increment, as the solve will see it). Activation onset
    // from rest moves a slack CE through dv/da alone (v = 0 at a = 0).
    const double ka = a_rate[i] / (1.0 + hg * jac.act_rate[i]);
    const double disp = h * (lce_rate[i] + hg * dvel_da[i] * ka);
    // The fraction theta = gap / disp of the step's displacement that reaches the operating point is
    // limited only from a slack tendon and where the CE is driven by its own active force (F0 > 5 % fmax):
    // a taut tendon is followed by its own tangent stiffness, and a passive element's CE moves with the
    // muscle-tendon unit; stopping those at an estimated operating point biased the motion at every
    // step size (measured: errors that did not shrink with the step). 0 < theta < 1 needs gap and disp of
    // one sign and |gap| < |disp|: tested here without the division, taken below for the few that pass.
    const double stretch_now = L_now - lce_along - mc.lslack[i];
    const double gap = lce_op - lce_x[i];
    const bool within = gap * disp > 0.0 && std::fabs(gap) < std::fabs(disp);
    const bool may_overshoot = stretch_now <= 0.0 && F0 > kEngagingActiveForce * mc.fmax[i] && within;
    op_gap[i] = may_overshoot ? gap : 0.0;
    op_disp[i] = disp;
    // The tendon's stretch at the end of the step from the unit's own motion ...
    const double stretch_pulled = stretch_now + h * L_rate[i];
    // ... or the CE's own shortening over the step (its drive disp, negative when shortening).
    const double stretch_drawn = stretch_pulled - (disp < 0.0 ? disp : 0.0) * jac.inv_cos_pennation[i];
    const double stretch_end = stretch_drawn > stretch_now ? stretch_drawn : stretch_now;
    // Tautness weight of the loading rule below: 0 while the tendon is slack and neither the unit nor the
    // CE draws it taut within the step, 1 once it is (or will be) stretched by a tenth of its stretch at
    // fmax. Without the CE's part a fibre resting just slack, activated, ran 36 mm past the engagement.
    const double taut_w = stretch_end * mc.inv_taut_stretch[i];
    taut[i] = taut_w < 0.0 ? 0.0 : (taut_w > 1.0 ? 1.0 : taut_w);
    L_op[i] = L_next;
    lce_at_op[i] = lce_op;
    along_at_op[i] = along_op;
    a_op[i] = a_next;
  }
  // The elements whose CE runs through its operating point within the step: rare (a slack tendon
  // engaging), so a scalar loop that calls out for them (a vectorised one did the divisions for all).
  for (int i = 0; i < n; ++i)
    if (op_gap[i] != 0.0) limited += stiffen_to_operating_point(op_gap[i] / op_disp[i], hg, &dvel_dlce[i]);
  // A taut tendon that will carry more force by the end of the step (activation rising) is stiffer
  // there than now (quadratic tendon): linearise at the operating point when that is stiffer. (A
  // separate loop: with the kernel inside the one above, GCC 12 gave up vectorising it.)
#pragma omp simd reduction(+ : limited)
  for (int i = 0; i < n; ++i) {
    double force_op, vel_op;
    MuscleDerivatives op;
    // lce_op >= min_lce (along_op is at least min_lce), and its projection on the tendon is along_op.
    muscle_kernel_derivatives_along(mc.fmax[i], mc.inv_lceopt[i], mc.lslack[i], mc.thickness[i], mc.vmax[i], mc.k_see[i],
                                    mc.k_pee[i], mc.pee_slack[i], mc.compress_length[i], mc.k_compress[i], mc.ecc_c[i],
                                    mc.damping_slope[i], b0, L_op[i], lce_at_op[i], along_at_op[i],
                                    lce_at_op[i] > mc.min_lce[i], a_op[i], &force_op, &vel_op, &op);
    // Blended, not switched: weight 0 where the operating point is no stiffer, rising to 1 where it is
    // 1.5x stiffer, times the tendon's tautness. A switch here made the step, and so the trajectory,
    // jump with a 1e-9 rad change of the start.
    const double gap = dvel_dlce[i] - op.dvel_dlce;
    const double w_stiff_raw = gap / (0.5 * std::fabs(op.dvel_dlce) + 1e-300);
    const double w_stiff = w_stiff_raw < 0.0 ? 0.0 : (w_stiff_raw > 1.0 ? 1.0 : w_stiff_raw);
    const double w = w_stiff * taut[i];
    dvel_dlce[i] += w * (op.dvel_dlce - dvel_dlce[i]);
    dvel_dL[i] += w * (op.dvel_dL - dvel_dL[i]);
    dvel_da[i] += w * (op.dvel_da - dvel_da[i]);
    dforce_dL[i] += w * (op.dforce_dL - dforce_dL[i]);
    dforce_dlce[i] += w * (op.dforce_dlce - dforce_dlce[i]);
    limited += w > 0.0 ? 1 : 0;
  }
  d.limited_fibre_steps += limited;
}

namespace {

// Paths extrapolated from the last two exact evaluations (PathHistory's anchors, at q_old and q_new) instead
// of the polynomials (evaluated at both stages of every step, they were 30 % of a das3 step):
//   R_out = R_new + c (R_new - R_old)                   (linear in time: c = steps past q_new / anchor spacing)
//   L_out = L_from - (R_from + R_out)/2 . (q_to - q_from)   (trapezoid along the step, R = -dL/dq)
// The anchors are at most kRos2PathPeriod steps apart and the extrapolation reaches at most that far past the
// newest, each step h qd + O(h^2), so the moment arms' error is O(h^2) and the lengths' O(h^3): ROS2 stays second
// order (tests/test_rosenbrock.cc checks 4x per halving of h), as with any O(h^2) error in an evaluation of f.
// Moment arms by DOF (data.h), so each line below runs across eight elements at a time; each block of eight
// only over the DOFs its run crosses (Model::element_runs): the other rows of R_out are left as they are (zero
// in every buffer this writes), and their terms of L_out's sum are zero. The last block's ghost lanes are
// zero in R and L_from and written as zeros (L_out has room for them).
template <int nq>
void extrapolate_paths_n(const Model& m, const double* R_old, const double* R_new, double c, const double* L_from,
                         const double* R_from, const double* q_from, const double* q_to, double* L_out,
                         double* R_out) {
  using detail::v8d;
  double dq[nq];
  for (int a = 0; a < nq; ++a) dq[a] = q_to[a] - q_from[a];
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    for (int i = run.begin; i < run.end; i += 8) {
      v8d s = {};
      for (int a = run.dof_lo; a <= run.dof_hi; ++a) {
        const int o = a * kMaxElements + i;
        v8d rn, ro, rf;
        std::memcpy(&rn, R_new + o, sizeof(v8d));
        std::memcpy(&ro, R_old + o, sizeof(v8d));
        std::memcpy(&rf, R_from + o, sizeof(v8d));
        const v8d e = rn + c * (rn - ro);
        std::memcpy(R_out + o, &e, sizeof(v8d));
        s += (rf + e) * dq[a];
      }
      v8d lf;
      std::memcpy(&lf, L_from + i, sizeof(v8d));
      const v8d lo = lf - 0.5 * s;
      std::memcpy(L_out + i, &lo, sizeof(v8d));
    }
  }
}

void extrapolate_paths(const Model& m, const PathHistory& ph, double c, const double* L_from, const double* R_from,
                       const double* q_from, const double* q_to, double* L_out, double* R_out) {
  const double* R_new = ph.anchor_moment_arm[ph.newest].data();
  const double* R_old = ph.anchor_moment_arm[1 - ph.newest].data();
  detail::dispatch_dofs(m.num_dofs, [&](auto N) {
    extrapolate_paths_n<N>(m, R_old, R_new, c, L_from, R_from, q_from, q_to, L_out, R_out);
  });
}

// The exact paths just evaluated at q (jac) become the newest anchor; the newest becomes the old one.
void add_anchor(const Model& m, PathHistory& ph, const double* q, const StepJacobian& jac) {
  const int nq = m.num_dofs, n = m.num_elements;
  if (ph.num_anchors >= 1) {
    ph.anchor_spacing = ph.steps_since_anchor;
    std::copy(ph.anchor_q_new.begin(), ph.anchor_q_new.begin() + nq, ph.anchor_q_old.begin());
    ph.newest ^= 1;
    ph.num_anchors = 2;
  } else {
    ph.anchor_spacing = 0;
    ph.num_anchors = 1;
  }
  // The rows the runs cross (the other rows are zero in both), eight at a time (a library copy per row and run
  // cost more in calls than in bytes).
  double* R = ph.anchor_moment_arm[ph.newest].data();
  const double* src = jac.moment_arm.data();
  for (int r = 0; r < m.num_element_runs; ++r) {
    const Model::ElementRun& run = m.element_runs[r];
    for (int a = run.dof_lo; a <= run.dof_hi; ++a)
      for (int i = run.begin; i < run.end; i += 8) {
        detail::v8d v;
        std::memcpy(&v, src + a * kMaxElements + i, sizeof v);
        std::memcpy(R + a * kMaxElements + i, &v, sizeof v);
      }
  }
  std::copy(jac.muscle_length.begin(), jac.muscle_length.begin() + n, ph.anchor_muscle_length.begin());
  std::copy(q, q + nq, ph.anchor_q_new.begin());
  ph.steps_since_anchor = 0;
}

// One ROS2 step of h from d.x; leaves the two stage vectors in d.k2 (k1) and d.k4 (k2), x untouched.
// Paths: a step that continues the history extrapolates its second stage's from the anchors, and so do the
// kRos2PathPeriod - 1 steps after an exact one their first stage's; the rest evaluate the polynomials.
void ros2_stages(const Model& m, Data& d, double h, bool record) {
  const int ns = state_size(m);
  const double* x = d.x.data();
  const double* q = x + q_offset(m);
  PathHistory& ph = d.path_history;
  StepJacobian& jac = d.jac;
  if (!ros2_continues_history(m, d, h)) ph.num_anchors = 0;
  if (ph.num_anchors == 2 && ph.steps_since_anchor < kRos2PathPeriod) {
    extrapolate_paths(m, ph, static_cast<double>(ph.steps_since_anchor) / ph.anchor_spacing,
                      ph.anchor_muscle_length.data(),
                      ph.anchor_moment_arm[ph.newest].data(), ph.anchor_q_new.data(), q, jac.muscle_length.data(),
                      jac.moment_arm.data());
    forward_from_paths(m, d, x, jac.muscle_length.data(), jac.moment_arm.data(), d.k1.data(), record, &jac);
  } else {
    forward(m, d, x, d.k1.data(), record, &jac);
    add_anchor(m, ph, q, jac);
  }
  limit_fibre_overshoot(m, d, x, d.k1.data(), h);
  jacobian_factor(m, jac, kRos2Gamma * h);
  jacobian_solve(m, jac, d.k1.data(), d.k2.data());
  double* xt = d.xtmp.data();
  for (int k = 0; k < ns; ++k) xt[k] = x[k] + h * d.k2[k];
  if (ph.num_anchors == 2) {
    // The second stage is one step past the first (q2 = q_n + h k1_q).
    double L2[kMaxElements];
    double* R2 = ph.stage2_moment_arm.data();
    extrapolate_paths(m, ph, static_cast<double>(ph.steps_since_anchor + 1) / ph.anchor_spacing,
                      jac.muscle_length.data(), jac.moment_arm.data(), q, xt + q_offset(m), L2, R2);
    forward_from_paths(m, d, xt, L2, R2, d.k3.data(), false);
  } else {
    forward(m, d, xt, d.k3.data(), false);
  }
  ph.h = 0;  // until ros2_update takes the step
  for (int k = 0; k < ns; ++k) d.k3[k] -= 2.0 * d.k2[k];
  jacobian_solve(m, jac, d.k3.data(), d.k4.data());
}

// The embedded first-order solution is x_n + h k1 (linearly implicit Euler); their difference
// h/2 (k1 + k2) estimates the local error. Scaled by kRos2AdaptiveTolQ (rad) on the joint angles and
// kRos2AdaptiveTolLce (x lceopt) on the CE lengths, where the stiff slack-to-taut events show first.
double ros2_error_estimate(const Model& m, const Data& d, double h) {
  double err = 0;
  const int iq = q_offset(m), il = lce_offset(m);
  for (int j = 0; j < m.num_dofs; ++j)
    err = std::max(err, std::fabs(0.5 * h * (d.k2[iq + j] + d.k4[iq + j])) / kRos2AdaptiveTolQ);
  const MuscleArrays& mc = m.muscles;
  for (int i = 0; i < m.num_elements; ++i)
    err = std::max(err, std::fabs(0.5 * h * (d.k2[il + i] + d.k4[il + i])) * mc.inv_lceopt[i] /
                            kRos2AdaptiveTolLce);
  return err;
}

void ros2_update(const Model& m, Data& d, double h) {
  const int ns = state_size(m);
  for (int k = 0; k < ns; ++k) d.x[k] += h * (1.5 * d.k2[k] + 0.5 * d.k4[k]);
  PathHistory& ph = d.path_history;
  ph.h = h;
  ++ph.steps_since_anchor;
  for (int j = 0; j < m.num_dofs; ++j) {
    ph.q_end[j] = d.x[q_offset(m) + j];
    ph.qd_end[j] = d.x[qd_offset(m) + j];
  }
}

}  // namespace

bool ros2_continues_history(const Model& m, const Data& d, double h) {
  const PathHistory& ph = d.path_history;
  if (ph.h != h || h <= 0) return false;
  const int iq = q_offset(m), iqd = qd_offset(m);
  bool same = true;
  for (int j = 0; j < m.num_dofs; ++j) same &= d.x[iq + j] == ph.q_end[j] && d.x[iqd + j] == ph.qd_end[j];
  return same;
}

std::string ros2_history_error(int num_anchors, int anchor_spacing, int steps_since_anchor) {
  if (num_anchors < 0 || num_anchors > 2) return "0, 1 or 2 path anchors, got " + std::to_string(num_anchors);
  if (num_anchors == 0) return "";
  // Only what a run of steps leaves: one anchor after its first step; then anchors 1 step apart (its first two
  // evaluations) or kRos2PathPeriod apart, the newest 1 to kRos2PathPeriod steps back.
  const std::string period = std::to_string(kRos2PathPeriod);
  if (num_anchors == 2 ? (anchor_spacing != 1 && anchor_spacing != kRos2PathPeriod) : anchor_spacing != 0)
    return "anchor spacing " + std::to_string(anchor_spacing) + " with " + std::to_string(num_anchors) +
           " anchors (a run leaves 1 or " + period + " steps with two, 0 with one)";
  if (steps_since_anchor < 1 || steps_since_anchor > (num_anchors == 2 ? kRos2PathPeriod : 1))
    return "steps since the newest anchor must be 1 to " + std::string(num_anchors == 2 ? period : "1") + " with " +
           std::to_string(num_anchors) + " anchor(s), got " + std::to_string(steps_since_anchor);
  return "";
}

void ros2_restore_history(const Model& m, Data& d, const double* anchor_q, int num_anchors, int anchor_spacing,
                          int steps_since_anchor, double h) {
  PathHistory& ph = d.path_history;
  ph.h = 0;
  ph.num_anchors = 0;
  if (!(h > 0) || num_anchors == 0) return;
  const std::string error = ros2_history_error(num_anchors, anchor_spacing, steps_since_anchor);
  if (!error.empty()) throw std::invalid_argument("ROS2 history: " + error);
  const int nq = m.num_dofs;
  const double* q_new = anchor_q + (num_anchors - 1) * nq;
  // The polynomials again at the anchors' q: the same function of the same q, so the same bits.
  double L_old[kMaxElements];
  ph.newest = 0;
  m.def->muscle_paths(q_new, ph.anchor_muscle_length.data(), ph.anchor_moment_arm[0].data());
  std::copy(q_new, q_new + nq, ph.anchor_q_new.begin());
  if (num_anchors == 2) {
    m.def->muscle_paths(anchor_q, L_old, ph.anchor_moment_arm[1].data());
    std::copy(anchor_q, anchor_q + nq, ph.anchor_q_old.begin());
  }
  ph.num_anchors = num_anchors;
  ph.anchor_spacing = anchor_spacing;
  ph.steps_since_anchor = steps_since_anchor;
  for (int j = 0; j < nq; ++j) {
    ph.q_end[j] = d.x[q_offset(m) + j];
    ph.qd_end[j] = d.x[qd_offset(m) + j];
  }
  ph.h = h;
}

void step_ros2(const Model& m, Data& d, double h, bool record) {
  ros2_stages(m, d, h, record);
  ros2_update(m, d, h);
}

int step_ros2_adaptive(const Model& m, Data& d, double h, bool record) {
  ros2_stages(m, d, h, record);
  if (ros2_error_estimate(m, d, h) <= 1.0) {
    ros2_update(m, d, h);
    return 1;
  }
  // Rejected: redo as two halves, accepted without a further check (fixed worst case, ~3 steps' work).
  step_ros2(m, d, 0.5 * h, false);
  step_ros2(m, d, 0.5 * h, false);
  ++d.halved_steps;
  return 2;
}

}  // namespace armrt
