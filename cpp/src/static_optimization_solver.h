// The static optimisation's solver state (static_optimization.cc): its two ProxQP objects, their matrices and the
// dual Newton method's arrays. Internal to the engine; here, not in the .cc, so that cpp/tests can put a QP into a
// state a solve leaves (test_static_optimization.cc: the cold restart's proximal parameters).
#pragma once

#include <Eigen/Dense>
#include <proxsuite/proxqp/dense/dense.hpp>

#include "armrt/static_optimization.h"

namespace armrt {

namespace static_optimization_detail {
using QP = proxsuite::proxqp::dense::QP<double>;
// ProxQP's matrix arguments are row-major Eigen::Refs: column-major ones would be copied (allocated) per call.
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
}  // namespace static_optimization_detail

// The two QPs (the problem; its closest-solution variant with free moment residuals) and their matrices,
// sized for the model in set-up.
struct StaticOptimizationSolver {
  using QP = static_optimization_detail::QP;
  using RowMatrix = static_optimization_detail::RowMatrix;
  StaticOptimizationSolver(int n, int nq, int n_in, proxsuite::proxqp::HessianType hessian,
                           proxsuite::proxqp::DenseBackend backend)
      : qp(n, nq, n_in, true, hessian, backend),
        slack(n + nq, nq, n_in, true, hessian, backend),
        H(n, n), g(n), A(nq, n), b(nq), C(n_in, n), l(n_in), u(n_in), lbox(n), ubox(n),
        Hs(n + nq, n + nq), gs(n + nq), As(nq, n + nq), Cs(n_in, n + nq), lboxs(n + nq), uboxs(n + nq) {}
  QP qp, slack;
  bool qp_ready = false, slack_ready = false;
  RowMatrix H;
  Eigen::VectorXd g;
  RowMatrix A;
  Eigen::VectorXd b;
  RowMatrix C;
  Eigen::VectorXd l, u, lbox, ubox;
  RowMatrix Hs;
  Eigen::VectorXd gs;
  RowMatrix As, Cs;
  Eigen::VectorXd lboxs, uboxs;
  // Per solve: paths (moment arms by DOF, as ModelDef::muscle_paths writes them), GH directions, forces.
  double L[kMaxElements], R[kMaxDofs * kMaxElements], dir[kMaxElements * 3];
  double P[3 * kMaxElements];  // (normal, major, minor) of the GH force per unit tendon force
  double Fa[kMaxElements], Fp[kMaxElements];
  // The dual Newton method's problem (dual_newton below): K = [A; -C] by row (kMaxElements apart), k = [b; -u],
  // d = 2 w, the multipliers z = (lambda, nu) kept as the next solve's warm start, and its scratch.
  static constexpr int kMaxRows = kMaxDofs + kMaxGhPolygonSides + 1;
  double K[kMaxRows * kMaxElements], k[kMaxRows], d[kMaxElements], z[kMaxRows];
  bool z_ready = false;
  double s_[kMaxElements], a_[kMaxElements], g_[kMaxRows], dz_[kMaxRows], zt_[kMaxRows], Hs_[kMaxRows * kMaxRows];
  int rows_[kMaxRows], free_[kMaxElements];
  // The elastic SQP's iterate and warm start: activations, CE lengths, the paths they were found at.
  double a_elastic[kMaxElements], lce_prev[kMaxElements], L_prev[kMaxElements];
  double d_sqp[kMaxElements], lin_sqp[kMaxElements];  // the QP's Hessian diagonal and linear term (proximal mu)
  bool elastic_ready = false;
};

}  // namespace armrt
