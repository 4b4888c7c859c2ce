// step_jacobian.cc: the structured Jacobian forward() filled (StepJacobian), h gamma -> its factorisation
// (jacobian_factor), and a right-hand side r -> (I - h gamma J)^-1 r (jacobian_solve). The state-sized system is
// never formed (214 x 214 for das2): the activation rows are scalar, each CE-length row is scalar once the joint
// part is known, and what remains is an n x n Schur complement (n = num_dofs) in the joint-velocity part
// (docs/engine.md derives it). Cost: fixed, two passes over the elements and one n x n LU; no iteration, no heap.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "armrt/engine.h"
#include "armrt/step_jacobian.h"
#include "dof_dispatch.h"
#include "lanes.h"
#include "moment_arm_dot.h"

namespace armrt {

using detail::moment_arm_dot;

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


}  // namespace armrt
