// Stage: skeleton dynamics. (q, qd, generalised forces tau, gravity) -> (M(q), qdd) with
// M(q) qdd = tau + b(q, qd, g): the generated equations of motion and a Cholesky (L D L^T) solve.
#include <algorithm>
#include <cmath>

#include "armrt/engine.h"
#include "dof_dispatch.h"
#include "lanes.h"

namespace armrt {

namespace {

template <int n>
void solve_spd_n(const double* A, const double* b, double* x) {
  if constexpr (n < 8) {
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
  } else {
    // 8-16 DOFs (das3): A = L D L^T (L unit lower triangular) right-looking, the rows as lane pairs in
    // registers. Step k turns row k into column k of L (by symmetry of what is left of A) and updates the rows
    // below it with one multiply-add per lane pair, so the dependent chain is one division and one update per
    // column (Cholesky's square root on that chain cost a third more; the row-by-row dot products before that
    // chained ~n^3/6 multiply-adds). Lanes <= k of row k are spent after step k.
    using detail::v8d;
    v8d lo[n], hi[n];
    for (int i = 0; i < n; ++i) detail::load_row(A + i * n, n, lo[i], hi[i]);
    double inv_d[n];  // 1 / D's diagonal
#pragma GCC unroll 16
    for (int k = 0; k < n; ++k) {
      inv_d[k] = 1.0 / (k < 8 ? lo[k][k % 8] : hi[k][k % 8]);
      const v8d a_lo = lo[k], a_hi = hi[k];  // lanes j > k: A[j][k] after the steps before (= L[j][k] d_k)
      lo[k] *= inv_d[k];  // lanes j > k: L[j][k]
      hi[k] *= inv_d[k];
#pragma GCC unroll 16
      for (int i = k + 1; i < n; ++i) {
        const double a_ik = i < 8 ? a_lo[i % 8] : a_hi[i % 8];
        lo[i] -= a_ik * lo[k];
        hi[i] -= a_ik * hi[k];
      }
    }
    // L y = b, column by column: lanes <= k of the running right-hand side are spent.
    v8d r_lo, r_hi;
    detail::load_row(b, n, r_lo, r_hi);
    double y[n];
#pragma GCC unroll 16
    for (int k = 0; k < n; ++k) {
      y[k] = k < 8 ? r_lo[k % 8] : r_hi[k % 8];
      r_lo -= y[k] * lo[k];
      r_hi -= y[k] * hi[k];
    }
    // L^T x = D^-1 y from the last row up: x's lanes <= k are still zero, so column k's dot with x sums j > k.
    v8d x_lo = {}, x_hi = {};
#pragma GCC unroll 16
    for (int k = n - 1; k >= 0; --k) {
      const double xk = y[k] * inv_d[k] - detail::lane_sum(lo[k] * x_lo + hi[k] * x_hi);
      if (k < 8) x_lo[k % 8] = xk;
      else x_hi[k % 8] = xk;
      x[k] = xk;
    }
  }
}

}  // namespace

void solve_spd(const double* A, const double* b, int n, double* x) {
  detail::dispatch_dofs(n, [&](auto N) { solve_spd_n<N>(A, b, x); });
}

void skeleton_dynamics(const Model& m, const double* gravity, const double* q, const double* qd, const double* tau, double* M, double* qdd) {
  const int nq = m.num_dofs;
  double rhs[kMaxDofs];
  m.def->dynamics(q, qd, gravity, M, rhs);
  for (int j = 0; j < nq; ++j) rhs[j] += tau[j];
  solve_spd(M, rhs, nq, qdd);
}

}  // namespace armrt
