// Stage: skeleton dynamics. (q, qd, generalised forces tau, gravity) -> (M(q), qdd) with
// M(q) qdd = tau + b(q, qd, g): the generated equations of motion and a Cholesky solve.
#include <algorithm>
#include <cmath>

#include "armrt/engine.h"
#include "dof_dispatch.h"

namespace armrt {

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

}  // namespace

void solve_spd(const double* A, const double* b, int n, double* x) {
  detail::dispatch_dofs(n, [&](auto N) { solve_spd_n<N>(A, b, x); });
}

void skeleton_dynamics(const Model& m, const double* q, const double* qd, const double* tau, double* M, double* qdd) {
  const int nq = m.num_dofs;
  double rhs[kMaxDofs];
  m.def->dynamics(q, qd, m.gravity_base.data(), M, rhs);
  for (int j = 0; j < nq; ++j) rhs[j] += tau[j];
  solve_spd(M, rhs, nq, qdd);
}

}  // namespace armrt
