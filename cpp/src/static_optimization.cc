// Stage: static optimisation, rigid tendon. (q, qd, qdd, hand load, the arm's settings) -> activations a in
// [0, max_activation] minimising sum w a^2 subject to R^T (Fa a + Fp) = tau_muscle (inverse dynamics) and the
// GHstab polygon rows on f0 + P (Fa a + Fp): one ProxQP dense QP, warm started from the previous solve; the same
// QP as python/armrt/control.py's StaticOptimizer(tendon="rigid") (docs/control.md).
//
// ProxQP (proxsuite, header-only; Bambade et al. 2022, RSS) is the solver the Python path already uses: the same
// algorithm and settings here keep the two answers within its tolerance. Its dense workspace is sized once in
// set-up, but its line search copies a strided block into an Eigen::Ref when the active set changes (a malloc):
// the fallback is not allocation-free, the dual Newton method (no Eigen, fixed arrays) is.
#include "armrt/static_optimization.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fmt.h"
#include "static_optimization_solver.h"

namespace armrt {

namespace {
constexpr double kInf = 1e20;  // control.py's _INF: an absent bound
using proxsuite::nullopt;
namespace pq = proxsuite::proxqp;
using static_optimization_detail::QP;
using static_optimization_detail::RowMatrix;

void set_qp_settings(QP& qp, const StaticOptimizationOptions& o, int max_iter) {
  qp.settings.eps_abs = o.eps_abs;
  qp.settings.eps_rel = 0.0;
  qp.settings.max_iter = max_iter;
  qp.settings.verbose = false;
  qp.settings.primal_infeasibility_solving = false;
  qp.settings.initial_guess = pq::InitialGuessStatus::WARM_START_WITH_PREVIOUS_RESULT;
}

// Forgets a QP's last solve where it did not succeed: ProxQP warm starts from its previous result and proximal and
// penalty parameters (results.info.mu_eq, mu_in), init included, and after an infeasible QP those held the next one
// from converging (das2 rigid, the frame of an EndpointController told to move the hand at 1 km/s: 4 ms and 22 ProxQP
// iterations the first time, then 340-380 ms and 7600-7800 iterations each time the same frame came again;
// control.py's _drop_qp is the same fix). cleanup() zeroes the result and workspace in place (no allocation) and
// sets the parameters to their defaults, the status included.
void forget_failed(QP& qp, bool& ready) {
  qp.cleanup();
  ready = false;
}

}  // namespace

StaticOptimizationWorkspace::StaticOptimizationWorkspace() = default;
StaticOptimizationWorkspace::~StaticOptimizationWorkspace() = default;
StaticOptimizationWorkspace::StaticOptimizationWorkspace(StaticOptimizationWorkspace&&) noexcept = default;
StaticOptimizationWorkspace& StaticOptimizationWorkspace::operator=(StaticOptimizationWorkspace&&) noexcept = default;

void gh_polygon(double theta_a, double phi_a, double bound, int sides, double* rows) {
  if (!(bound > 0 && std::isfinite(bound)))
    throw std::invalid_argument("gh_stab_max must be a finite number > 0, got " + detail::fmt(bound));
  if (bound < kMinGhStabMax)
    throw std::invalid_argument("gh_stab_max = " + detail::fmt(bound) + " is below the smallest bound solved, " +
                                detail::fmt(kMinGhStabMax) + " (a cone under 1 mrad about the glenoid normal)");
  if (sides < 3 || sides > kMaxGhPolygonSides)
    throw std::invalid_argument("polygon_sides must be in [3, " + std::to_string(kMaxGhPolygonSides) + "], got " +
                                std::to_string(sides));
  const double r = std::sqrt(bound);
  const double widest = std::max(theta_a, phi_a);
  if (widest * r >= kMaxBoundHalfAngle) {
    const double lim = std::pow(kMaxBoundHalfAngle / widest, 2);
    throw std::invalid_argument("gh_stab_max = " + detail::fmt(bound) + " puts the bound's ellipse beyond " +
                                detail::fmt(kMaxBoundHalfAngle) +
                                " rad from the glenoid normal (towards the glenoid plane); give gh_stab_max < " +
                                detail::fmt(lim));
  }
  // control.py gh_polygon: vertices on the ellipse, pulled in (angles x0.99) until every edge, checked at 64
  // points, is inside {GHstab <= bound} (conservative beyond the convexity limit).
  constexpr double kTwoPi = 6.283185307179586;
  double u[kMaxGhPolygonSides], v[kMaxGhPolygonSides];
  double scale = 1.0;
  for (int attempt = 0; attempt < 200; ++attempt) {
    for (int k = 0; k < sides; ++k) {
      const double psi = k * (kTwoPi / sides);  // np.linspace(0, 2 pi, sides, endpoint=False)
      u[k] = std::tan(theta_a * r * scale * std::cos(psi));
      v[k] = std::tan(phi_a * r * scale * std::sin(psi));
    }
    double worst = 0;
    for (int k = 0; k < sides; ++k) {
      const int kn = (k + 1) % sides;
      for (int s = 0; s < 64; ++s) {
        const double t = s == 63 ? 1.0 : s * (1.0 / 63);  // np.linspace(0, 1, 64)
        const double eu = u[k] + (u[kn] - u[k]) * t, ev = v[k] + (v[kn] - v[k]) * t;
        worst = std::max(worst, std::pow(std::atan(eu) / theta_a, 2) + std::pow(std::atan(ev) / phi_a, 2));
      }
    }
    if (worst <= bound * (1 + 1e-12)) break;  // the vertices' rounding must not shrink it (control.py)
    scale *= 0.99;
  }
  // Counter-clockwise vertices: the outward normal of edge k is (dv, -du); n . (u, v) <= n . p_k. Divided by
  // sqrt(bound), so the rows' length does not shrink with the bound (control.py gh_polygon).
  for (int k = 0; k < sides; ++k) {
    const int kn = (k + 1) % sides;
    const double nu = (v[kn] - v[k]) / r, nv = -(u[kn] - u[k]) / r;
    rows[3 * k + 0] = -(nu * u[k] + nv * v[k]);
    rows[3 * k + 1] = nu;
    rows[3 * k + 2] = nv;
  }
}

void static_optimization_setup(const Model& m, const StaticOptimizationOptions& options, StaticOptimizationWorkspace& w) {
  const ModelDef& def = *m.def;
  const int n = m.num_elements, nq = m.num_dofs;
  if (!options.weights.empty()) {
    if (static_cast<int>(options.weights.size()) != n)
      throw std::invalid_argument("weights must have " + std::to_string(n) + " values (one per element), got " +
                                  std::to_string(options.weights.size()));
    for (double x : options.weights)
      if (!(std::isfinite(x) && x > 0)) throw std::invalid_argument("weights must be finite and > 0");
  }
  if (!(options.eps_abs > 0 && std::isfinite(options.eps_abs)))
    throw std::invalid_argument("eps_abs must be a finite number > 0");
  if (options.dense_backend < 0 || options.dense_backend > 2)
    throw std::invalid_argument("dense_backend must be 0 (automatic), 1 (primal-dual LDLT) or 2 (primal LDLT)");
  if (options.max_qp_iterations < 1) throw std::invalid_argument("max_qp_iterations must be >= 1");
  if (options.gh_stab_max < 0 || !std::isfinite(options.gh_stab_max))
    throw std::invalid_argument("gh_stab_max must be a finite number > 0 (0: no GH constraint)");
  StaticOptimizationWorkspace fresh;
  fresh.num_elements = n;
  fresh.num_dofs = nq;
  fresh.options = options;
  if (fresh.options.weights.empty()) fresh.options.weights.assign(n, 1.0);
  for (int k = 0; k < 3; ++k) {
    fresh.glenoid_axes[k] = def.glenoid_normal[k];
    fresh.glenoid_axes[3 + k] = def.glenoid_major_axis[k];
    fresh.glenoid_axes[6 + k] = def.glenoid_minor_axis[k];
  }
  if (options.gh_stab_max > 0) {
    gh_polygon(def.rim_half_angle_major, def.rim_half_angle_minor, options.gh_stab_max, options.polygon_sides,
               fresh.gh_rows);
    const int s = options.polygon_sides;
    fresh.gh_rows[3 * s] = -1.0;  // F.normal >= 0
    fresh.num_gh_rows = s + 1;
  }
  const int n_in = fresh.num_gh_rows;
  const pq::DenseBackend backend = options.dense_backend == 1   ? pq::DenseBackend::PrimalDualLDLT
                                   : options.dense_backend == 2 ? pq::DenseBackend::PrimalLDLT
                                                                : pq::DenseBackend::Automatic;
  fresh.solver = std::make_unique<StaticOptimizationSolver>(
      n, nq, n_in, options.diagonal_hessian ? pq::HessianType::Diagonal : pq::HessianType::Dense, backend);
  StaticOptimizationSolver& s = *fresh.solver;
  set_qp_settings(s.qp, fresh.options, fresh.options.max_qp_iterations);
  set_qp_settings(s.slack, fresh.options, 300);
  // Constant parts: the objective's Hessian (2 w; the slack QP: 2e-4 w on a, 2 on the residuals, control.py),
  // zero linear terms, the GH rows' open lower side, the lower bound 0 and the slack's free residuals.
  s.H.setZero();
  s.Hs.setZero();
  for (int i = 0; i < n; ++i) {
    s.d[i] = 2.0 * fresh.options.weights[i];
    s.H(i, i) = 2.0 * fresh.options.weights[i];
    s.Hs(i, i) = 2e-4 * fresh.options.weights[i];
  }
  for (int j = 0; j < nq; ++j) s.Hs(n + j, n + j) = 2.0;
  s.g.setZero();
  s.gs.setZero();
  s.l.setConstant(-kInf);
  s.lbox.setZero();
  s.lboxs.setZero();
  s.As.setZero();
  s.Cs.setZero();
  for (int j = 0; j < nq; ++j) {
    s.As(j, n + j) = 1.0;
    s.lboxs(n + j) = -kInf;
    s.uboxs(n + j) = kInf;
  }
  w = std::move(fresh);
}

void static_optimization_reset(StaticOptimizationWorkspace& w) {
  if (!w.solver) return;
  forget_failed(w.solver->qp, w.solver->qp_ready);
  forget_failed(w.solver->slack, w.solver->slack_ready);
  w.solver->z_ready = false;
  w.solver->elastic_ready = false;
}

namespace {

// Solves H x = b in place (b -> x) for a symmetric positive definite n x n H (row-major, overwritten by its
// Cholesky factor); false if H is not positive definite to rounding.
bool cholesky_solve(double* H, int n, double* b) {
  for (int j = 0; j < n; ++j) {
    double djj = H[j * n + j];
    for (int k = 0; k < j; ++k) djj -= H[j * n + k] * H[j * n + k];
    if (!(djj > 0)) return false;
    const double ljj = std::sqrt(djj);
    H[j * n + j] = ljj;
    for (int i = j + 1; i < n; ++i) {
      double v = H[i * n + j];
      for (int k = 0; k < j; ++k) v -= H[i * n + k] * H[j * n + k];
      H[i * n + j] = v / ljj;
    }
  }
  for (int i = 0; i < n; ++i) {
    double v = b[i];
    for (int k = 0; k < i; ++k) v -= H[i * n + k] * b[k];
    b[i] = v / H[i * n + i];
  }
  for (int i = n - 1; i >= 0; --i) {
    double v = b[i];
    for (int k = i + 1; k < n; ++k) v -= H[k * n + i] * b[k];
    b[i] = v / H[i * n + i];
  }
  return true;
}

// The dual of min 1/2 a^T diag(d) a subject to A a = b, C a <= u, 0 <= a <= amax (the QP above: d = 2 w) is
// phi(z) = min over the box of 1/2 a^T diag(d) a - s^T a + z^T k with s = K^T z, K = [A; -C], k = [b; -u], z =
// (lambda, nu), nu >= 0: concave, piecewise quadratic, with a(z) = clip(s / d, 0, amax) and grad phi = k - K a(z).
// Only nq + GH rows (5 + 25 for das2) dual variables against 102 primal ones, so a projected Newton method on it
// (Bertsekas 1982, "Projected Newton methods for optimization problems with simple constraints", SIAM J Control
// Optim 20:221) costs a few small Cholesky factorisations: its Hessian on the rows S not held at nu = 0 is
// -K_SF diag(1/d_F) K_SF^T over the elements F strictly inside their bounds, and on a quadratic piece the step is
// exact. Warm started from the previous solve's z. Returns true with a = a(z) when the moments balance to tol_eq,
// the GH rows hold to tol_in and nu is complementary; false (after max_iter, or a step that makes no progress)
// hands the problem to ProxQP, which also decides infeasibility.
// Weak duality certifies infeasibility early: phi(z) <= f(a) for every feasible a (nu >= 0), and f's largest value
// over the box is phi_max = sum_i max(0, d_i amax_i^2 / 2 + lin_i amax_i) (f is separable and convex: its maximum
// on [0, amax_i] is at an end). An ascent past phi_max proves that no feasible a exists (*infeasible then): an
// infeasible request's dual is unbounded, and the ascent used to run all max_iter iterations before giving up
// (armrt-rt's loop, which has no ProxQP fallback: 200-340 us a cycle, a new-user trial 2026-12-07).
// d: the Hessian's diagonal (s.d: 2 w); lin: a linear term of the objective (+ lin' a), or nullptr.
bool dual_newton(StaticOptimizationSolver& s, int n, int m, int p, const double* amax, const double* d,
                 const double* lin, double tol_eq, double tol_in, int max_iter, int* iterations,
                 bool* infeasible = nullptr) {
  const int nr = m + p;
  constexpr int E = kMaxElements;
  if (infeasible) *infeasible = false;
  double phi_max = 0;
  for (int i = 0; i < n; ++i) phi_max += std::max(0.0, 0.5 * d[i] * amax[i] * amax[i] + (lin ? lin[i] * amax[i] : 0.0));
  // Margin for rounding: a feasible problem whose only solutions are at the box's far corner has phi* = phi_max.
  const double phi_certificate = phi_max * (1 + 1e-6) + 1e-12;
  auto primal = [&](const double* z, double* a, double* phi) {
    double val = 0;
    for (int r = 0; r < nr; ++r) val += z[r] * s.k[r];
    for (int i = 0; i < n; ++i) s.s_[i] = lin ? -lin[i] : 0.0;
    for (int r = 0; r < nr; ++r) {
      if (z[r] == 0) continue;
      const double* Kr = &s.K[r * E];
      for (int i = 0; i < n; ++i) s.s_[i] += Kr[i] * z[r];
    }
    for (int i = 0; i < n; ++i) {
      a[i] = std::clamp(s.s_[i] / d[i], 0.0, amax[i]);
      val += 0.5 * d[i] * a[i] * a[i] - s.s_[i] * a[i];
    }
    *phi = val;
  };
  double* z = s.z;
  if (!s.z_ready) {
    // Cold: the equality-only, unbounded solution's lambda, (A D^-1 A^T) lambda = b, nu = 0.
    for (int r = 0; r < nr; ++r) z[r] = 0;
    for (int r = 0; r < m; ++r)
      for (int c = 0; c <= r; ++c) {
        double h = 0;
        for (int i = 0; i < n; ++i) h += s.K[r * E + i] * s.K[c * E + i] / d[i];
        s.Hs_[r * m + c] = s.Hs_[c * m + r] = h;
      }
    for (int r = 0; r < m; ++r) {
      s.dz_[r] = s.k[r];
      if (lin)  // the unbounded minimiser is D^-1 (A^T lambda - lin): A D^-1 A^T lambda = b + A D^-1 lin
        for (int i = 0; i < n; ++i) s.dz_[r] += s.K[r * E + i] * lin[i] / d[i];
    }
    if (!cholesky_solve(s.Hs_, m, s.dz_)) return false;
    for (int r = 0; r < m; ++r) z[r] = s.dz_[r];
  }
  for (int r = m; r < nr; ++r) z[r] = std::max(z[r], 0.0);
  double phi;
  primal(z, s.a_, &phi);
  for (int it = 0; it < max_iter; ++it) {
    *iterations = it;
    // Gradient k - K a and the optimality test.
    bool optimal = true;
    for (int r = 0; r < nr; ++r) {
      const double* Kr = &s.K[r * E];
      double g = s.k[r];
      for (int i = 0; i < n; ++i) g -= Kr[i] * s.a_[i];
      s.g_[r] = g;
      if (r < m) optimal &= std::abs(g) <= tol_eq;
      else optimal &= g <= tol_in && (z[r] == 0 || g >= -tol_in);  // g = C a - u: held, and active where nu > 0
    }
    if (optimal) return true;
    // Rows in the step: the equalities and the GH rows not held at nu = 0 with a gradient pushing nu negative.
    int ns = 0;
    for (int r = 0; r < nr; ++r)
      if (r < m || z[r] > 0 || s.g_[r] > 0) s.rows_[ns++] = r;
    int nf = 0;
    for (int i = 0; i < n; ++i) {
      const double x = s.s_[i] / d[i];
      if (x > 0 && x < amax[i]) s.free_[nf++] = i;
    }
    double trace = 0;
    for (int a = 0; a < ns; ++a) {
      const double* Ka = &s.K[s.rows_[a] * E];
      for (int b = 0; b <= a; ++b) {
        const double* Kb = &s.K[s.rows_[b] * E];
        double h = 0;
        for (int f = 0; f < nf; ++f) {
          const int i = s.free_[f];
          h += Ka[i] * Kb[i] / d[i];
        }
        s.Hs_[a * ns + b] = s.Hs_[b * ns + a] = h;
      }
      trace += s.Hs_[a * ns + a];
    }
    // A row no free element reaches (its elements all at a bound) makes the matrix singular: a small
    // Levenberg-Marquardt term keeps the step finite, the line search its length.
    const double reg = 1e-10 * trace / std::max(ns, 1) + 1e-300;
    for (int a = 0; a < ns; ++a) {
      s.Hs_[a * ns + a] += reg;
      s.dz_[a] = s.g_[s.rows_[a]];
    }
    if (!cholesky_solve(s.Hs_, ns, s.dz_)) return false;
    // Projected line search (Armijo on phi along z(t) = P(z + t dz)).
    double t = 1.0;
    bool moved = false;
    for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
      for (int r = 0; r < nr; ++r) s.zt_[r] = z[r];
      for (int a = 0; a < ns; ++a) {
        const int r = s.rows_[a];
        s.zt_[r] = r < m ? z[r] + t * s.dz_[a] : std::max(0.0, z[r] + t * s.dz_[a]);
      }
      double gain = 0;
      for (int r = 0; r < nr; ++r) gain += s.g_[r] * (s.zt_[r] - z[r]);
      double phi_t;
      primal(s.zt_, s.a_, &phi_t);
      if (phi_t >= phi + 1e-4 * gain && gain > 0) {
        for (int r = 0; r < nr; ++r) z[r] = s.zt_[r];
        phi = phi_t;
        moved = true;
        break;
      }
    }
    if (!moved) return false;
    if (phi > phi_certificate) {
      if (infeasible) *infeasible = true;
      return false;
    }
  }
  return false;
}

// Runs one of the two QPs with the matrices in s; init on its first use (which computes the preconditioner),
// update afterwards (the preconditioner kept, the previous result the warm start).
pq::QPSolverOutput run(QP& qp, bool& ready, const RowMatrix& H, const Eigen::VectorXd& g,
                       const RowMatrix& A, const Eigen::VectorXd& b, const RowMatrix& C,
                       const Eigen::VectorXd& l, const Eigen::VectorXd& u, const Eigen::VectorXd& lbox,
                       const Eigen::VectorXd& ubox, int n_in) {
  if (!ready) {
    if (n_in) qp.init(H, g, A, b, C, l, u, lbox, ubox);
    else qp.init(H, g, A, b, nullopt, nullopt, nullopt, lbox, ubox);
    ready = true;
  } else {
    // The warm start carries the last solve's proximal parameters too; one that ended on ProxQP's cold restart
    // (mu_eq, mu_in reset to 1/1.1 once the residuals stalled at mu_in <= 1e-5) would start every later problem
    // there: in control.py's Python path, das2's bench motion with GHstab <= 0.1 took 76-81 ProxQP iterations a
    // frame instead of 3 for the rest of the motion after one such frame. Parameters above ProxQP's defaults go
    // back to the defaults; the primal-dual warm start is kept.
    const bool reset = qp.results.info.mu_in > qp.settings.default_mu_in ||
                       qp.results.info.mu_eq > qp.settings.default_mu_eq;
    const proxsuite::optional<double> mu_eq = reset ? proxsuite::optional<double>(qp.settings.default_mu_eq) : nullopt;
    const proxsuite::optional<double> mu_in = reset ? proxsuite::optional<double>(qp.settings.default_mu_in) : nullopt;
    if (n_in) qp.update(nullopt, nullopt, A, b, C, nullopt, u, nullopt, ubox, false, nullopt, mu_eq, mu_in);
    else qp.update(nullopt, nullopt, A, b, nullopt, nullopt, nullopt, nullopt, ubox, false, nullopt, mu_eq, mu_in);
  }
  qp.solve();
  return qp.results.info.status;
}

// The QP's rows for forces F = Fa a + Fp (s.Fa, s.Fp): moments R^T diag(Fa) a = tau_required - R^T Fp (rows
// 0..nq-1 of K, k) and the GH rows c . (f0 + P (Fa a + Fp)) <= 0, i.e. (c P) diag(Fa) a <= -c . (f0 + P Fp) (rows
// nq.. of K, k, negated).
void fill_rows(const StaticOptimizationWorkspace& w, StaticOptimizationSolver& s, int n, int nq, int n_in,
               const double* tau_required, const double* f0) {
  constexpr int E = kMaxElements;
  for (int j = 0; j < nq; ++j) {
    const double* Rj = &s.R[j * E];
    double* Kj = &s.K[j * E];
    double passive = 0;
    for (int i = 0; i < n; ++i) {
      Kj[i] = Rj[i] * s.Fa[i];
      passive += Rj[i] * s.Fp[i];
    }
    s.k[j] = tau_required[j] - passive;
  }
  double f_passive[3];
  for (int k = 0; k < 3; ++k) {
    double acc = f0[k];
    for (int i = 0; i < n; ++i) acc += s.P[k * E + i] * s.Fp[i];
    f_passive[k] = acc;
  }
  for (int row = 0; row < n_in; ++row) {
    const double* c = &w.gh_rows[3 * row];
    double* Kr = &s.K[(nq + row) * E];
    for (int i = 0; i < n; ++i) Kr[i] = -(c[0] * s.P[i] + c[1] * s.P[E + i] + c[2] * s.P[2 * E + i]) * s.Fa[i];
    s.k[nq + row] = c[0] * f_passive[0] + c[1] * f_passive[1] + c[2] * f_passive[2];  // -u
  }
}

// The state's inverse dynamics, paths, GH directions (as P, the (normal, major, minor) components per unit tendon
// force), fibre velocities dL/dt = -R qd and the upper bounds; f0: the GH force of everything but the muscles.
void prepare(const Model& m, const Data& d, StaticOptimizationWorkspace& w, const double* q, const double* qd,
             const double* qdd, const double* hand_force, const double* hand_moment, InverseDynamics* id, double* f0,
             StaticOptimizationReport& r) {
  const ModelDef& def = *m.def;
  StaticOptimizationSolver& s = *w.solver;
  const int n = m.num_elements, nq = m.num_dofs;
  inverse_dynamics(m, d.settings.gravity.data(), q, qd, qdd, hand_force, hand_moment, id);
  def.muscle_paths(q, s.L, s.R);  // R[j * kMaxElements + i]: element i's moment arm about DOF j
  def.gh_directions(q, s.dir);
  for (int k = 0; k < 3; ++k) {
    const double* ax = &w.glenoid_axes[3 * k];
    f0[k] = ax[0] * id->gh_force_without_muscles[0] + ax[1] * id->gh_force_without_muscles[1] +
            ax[2] * id->gh_force_without_muscles[2];
  }
  for (int i = 0; i < n; ++i) {
    double v = 0;  // dL/dt: moment arms are -dL/dq
    for (int j = 0; j < nq; ++j) v -= s.R[j * kMaxElements + i] * qd[j];
    r.fibre_velocity[i] = v;
    for (int k = 0; k < 3; ++k) {
      const double* ax = &w.glenoid_axes[3 * k];
      s.P[k * kMaxElements + i] = ax[0] * s.dir[3 * i] + ax[1] * s.dir[3 * i + 1] + ax[2] * s.dir[3 * i + 2];
    }
    s.ubox(i) = d.settings.max_activation[i];
  }
  for (int j = 0; j < nq; ++j) r.tau_required[j] = id->tau_muscle[j];
}

// The report's GH force (scapula frame) of f0 and r.force, its GHstab, whether a polygon row binds, the elements at
// their upper bound.
void finish_report(const ModelDef& def, const StaticOptimizationWorkspace& w, const StaticOptimizationSolver& s,
                   int n, int n_in, const double* f0, const double* amax, const double* activation,
                   StaticOptimizationReport& r) {
  double gh_local[3];
  for (int k = 0; k < 3; ++k) {
    double acc = f0[k];
    for (int i = 0; i < n; ++i) acc += s.P[k * kMaxElements + i] * r.force[i];
    gh_local[k] = acc;
  }
  for (int k = 0; k < 3; ++k)
    r.gh_force[k] = w.glenoid_axes[k] * gh_local[0] + w.glenoid_axes[3 + k] * gh_local[1] +
                    w.glenoid_axes[6 + k] * gh_local[2];
  r.gh_stab = gh_stability(def, r.gh_force).stab;
  r.gh_bound_active = false;
  for (int row = 0; row + 1 < n_in; ++row) {
    const double* c = &w.gh_rows[3 * row];
    if (c[0] * gh_local[0] + c[1] * gh_local[1] + c[2] * gh_local[2] > -1e-6 * std::max(1.0, std::abs(gh_local[0])))
      r.gh_bound_active = true;
  }
  r.at_upper_bound = 0;
  for (int i = 0; i < n; ++i)
    if (amax[i] > 0 && activation[i] >= amax[i] - 1e-6) ++r.at_upper_bound;
}

// ProxQP's A, b (moment rows) and C, u (GH rows, C a <= u) from the dual Newton method's K, k (fill_rows).
void proxqp_rows(StaticOptimizationSolver& s, int n, int nq, int n_in) {
  constexpr int E = kMaxElements;
  for (int j = 0; j < nq; ++j) {
    for (int i = 0; i < n; ++i) s.A(j, i) = s.K[j * E + i];
    s.b(j) = s.k[j];
  }
  for (int row = 0; row < n_in; ++row) {
    for (int i = 0; i < n; ++i) s.C(row, i) = -s.K[(nq + row) * E + i];
    s.u(row) = -s.k[nq + row];
  }
}

// One QP of the elastic SQP by ProxQP (where the dual Newton method did not solve it): Hessian diag(s.d_sqp), linear
// term s.lin_sqp (the proximal term; zero without), the rows fill_rows left in K, k. The solution goes to s.a_.
// ProxQP keeps the Hessian it is given, so the rigid path's QP (2 w, no linear term) is initialised afresh next.
bool proxqp_sqp_step(const StaticOptimizationWorkspace& w, StaticOptimizationSolver& s, int n, int nq, int n_in,
                     StaticOptimizationReport& r, pq::QPSolverOutput& status) {
  for (int i = 0; i < n; ++i) {
    s.H(i, i) = s.d_sqp[i];
    s.g(i) = s.lin_sqp[i];
  }
  proxqp_rows(s, n, nq, n_in);
  if (n_in) s.qp.init(s.H, s.g, s.A, s.b, s.C, s.l, s.u, s.lbox, s.ubox);
  else s.qp.init(s.H, s.g, s.A, s.b, nullopt, nullopt, nullopt, s.lbox, s.ubox);
  s.qp.solve();
  r.qp_iterations += static_cast<int>(s.qp.results.info.iter);
  for (int i = 0; i < n; ++i) {
    s.H(i, i) = 2.0 * w.options.weights[i];
    s.g(i) = 0.0;
  }
  s.qp_ready = false;
  status = s.qp.results.info.status;  // before forget_failed, which resets it
  if (status != pq::QPSolverOutput::PROXQP_SOLVED) {
    forget_failed(s.qp, s.qp_ready);
    return false;
  }
  for (int i = 0; i < n; ++i) s.a_[i] = s.qp.results.x[i];
  return true;
}

// The elastic SQP's step where its QP (the rows proxqp_sqp_step left in A, b, C, u) has no solution: the closest
// moments its linearisation reaches (the slack QP, control.py's elastic-mode step: SNOPT's elastic mode, Gill, Murray
// & Saunders, SIAM J Optim 12:979, 2002, with a squared penalty). The activations go to s.a_.
bool elastic_mode_step(StaticOptimizationSolver& s, int n, int n_in, StaticOptimizationReport& r) {
  s.As.leftCols(n) = s.A;
  if (n_in) s.Cs.leftCols(n) = s.C;
  s.uboxs.head(n) = s.ubox;
  const pq::QPSolverOutput st = run(s.slack, s.slack_ready, s.Hs, s.gs, s.As, s.b, s.Cs, s.l, s.u, s.lboxs, s.uboxs, n_in);
  r.qp_iterations += static_cast<int>(s.slack.results.info.iter);
  if (st != pq::QPSolverOutput::PROXQP_SOLVED) {
    forget_failed(s.slack, s.slack_ready);
    return false;
  }
  for (int i = 0; i < n; ++i) s.a_[i] = s.slack.results.x[i];
  return true;
}

}  // namespace

void static_optimization_rigid(const Model& m, const Data& d, StaticOptimizationWorkspace& w, const double* q,
                               const double* qd, const double* qdd, const double* hand_force,
                               const double* hand_moment, double* activation, StaticOptimizationReport* rep) {
  if (!w.solver || w.num_elements != m.num_elements || w.num_dofs != m.num_dofs)
    throw std::invalid_argument("static_optimization_rigid: the workspace was not set up for this model");
  const ModelDef& def = *m.def;
  StaticOptimizationSolver& s = *w.solver;
  const int n = m.num_elements, nq = m.num_dofs, n_in = w.num_gh_rows;
  const double* amax = d.settings.max_activation.data();
  StaticOptimizationReport& r = *rep;

  InverseDynamics id;
  double f0[3];
  prepare(m, d, w, q, qd, qdd, hand_force, hand_moment, &id, f0, r);
  for (int i = 0; i < n; ++i) {
    const RigidTendonForce f = muscle_rigid_tendon_force(data_element(m, d, i), m.fibre_damping, s.L[i], r.fibre_velocity[i]);
    r.lce[i] = f.lce;
    s.Fa[i] = f.force_per_activation;
    s.Fp[i] = f.passive_force;
  }
  constexpr int E = kMaxElements;
  fill_rows(w, s, n, nq, n_in, id.tau_muscle, f0);
  auto balance = [&](const double* sol) {
    double worst = 0;
    for (int i = 0; i < n; ++i) {
      activation[i] = std::clamp(sol[i], 0.0, amax[i]);
      r.force[i] = s.Fa[i] * activation[i] + s.Fp[i];
    }
    for (int j = 0; j < nq; ++j) {
      const double* Rj = &s.R[j * E];
      double tau = 0;
      for (int i = 0; i < n; ++i) tau += Rj[i] * r.force[i];
      r.tau_muscle[j] = tau;
      r.residual[j] = tau - r.tau_required[j];
      worst = std::max(worst, std::abs(tau - r.tau_required[j]));
    }
    r.residual_max = worst;
  };

  r.qps = 0;
  r.qp_iterations = 0;
  r.newton_iterations = 0;
  r.solver = StaticOptimizationSolverUsed::kDualNewton;
  bool solved = false, certified = false;  // certified: the Newton method proved the request infeasible
  if (w.options.dual_newton) {
    solved = dual_newton(s, n, nq, n_in, amax, s.d, nullptr, 1e-9, 1e-9, 50, &r.newton_iterations, &certified);
    if (solved) {
      balance(s.a_);
      solved = r.residual_max < kStaticOptimizationMomentTolerance;
    }
    s.z_ready = solved;  // a failed iterate is no warm start
  }
  r.feasible = solved;
  r.status = StaticOptimizationStatus::kSolved;
  if (!solved && w.options.dual_newton && !w.options.proxqp_fallback) {
    // Reported as such, the Newton iterate's residuals (its weak-duality certificate tells infeasible apart).
    r.status = certified ? StaticOptimizationStatus::kInfeasible : StaticOptimizationStatus::kNotConverged;
    balance(s.a_);
  } else if (!solved) {
    r.solver = StaticOptimizationSolverUsed::kProxQP;
    proxqp_rows(s, n, nq, n_in);
    const pq::QPSolverOutput st = run(s.qp, s.qp_ready, s.H, s.g, s.A, s.b, s.C, s.l, s.u, s.lbox, s.ubox, n_in);
    r.qps = 1;
    r.qp_iterations = static_cast<int>(s.qp.results.info.iter);
    balance(s.qp.results.x.data());
    r.feasible = st == pq::QPSolverOutput::PROXQP_SOLVED && r.residual_max < kStaticOptimizationMomentTolerance;
    if (!r.feasible) {
      // The closest moments instead (free residuals, control.py's slack QP), reported, never returned as a solution.
      r.status = st == pq::QPSolverOutput::PROXQP_MAX_ITER_REACHED ? StaticOptimizationStatus::kNotConverged
                                                                   : StaticOptimizationStatus::kInfeasible;
      s.As.leftCols(n) = s.A;
      if (n_in) s.Cs.leftCols(n) = s.C;
      s.uboxs.head(n) = s.ubox;
      const pq::QPSolverOutput st_slack =
          run(s.slack, s.slack_ready, s.Hs, s.gs, s.As, s.b, s.Cs, s.l, s.u, s.lboxs, s.uboxs, n_in);
      r.qps = 2;
      r.qp_iterations += static_cast<int>(s.slack.results.info.iter);
      balance(s.slack.results.x.data());
      // The problem's own QP starts cold next time: its last iterate is not a solution to warm start from.
      forget_failed(s.qp, s.qp_ready);
      if (st_slack != pq::QPSolverOutput::PROXQP_SOLVED) forget_failed(s.slack, s.slack_ready);
    }
  }
  finish_report(def, w, s, n, n_in, f0, amax, activation, r);
}

void static_optimization_elastic(const Model& m, const Data& d, StaticOptimizationWorkspace& w, const double* q,
                                 const double* qd, const double* qdd, const double* hand_force,
                                 const double* hand_moment, double* activation, StaticOptimizationReport* rep) {
  if (!w.solver || w.num_elements != m.num_elements || w.num_dofs != m.num_dofs)
    throw std::invalid_argument("static_optimization_elastic: the workspace was not set up for this model");
  const ModelDef& def = *m.def;
  StaticOptimizationSolver& s = *w.solver;
  const int n = m.num_elements, nq = m.num_dofs, n_in = w.num_gh_rows;
  const double* amax = d.settings.max_activation.data();
  StaticOptimizationReport& r = *rep;
  constexpr int E = kMaxElements;
  InverseDynamics id;
  double f0[3];
  prepare(m, d, w, q, qd, qdd, hand_force, hand_moment, &id, f0, r);
  // Start: the previous solve's activations and CE lengths if the paths moved little since (control.py's rule),
  // else 0.05 (capped) and the rigid tendon's lengths.
  double moved = s.elastic_ready ? 0.0 : 1.0;
  for (int i = 0; i < n && s.elastic_ready; ++i) moved = std::max(moved, std::abs(s.L[i] - s.L_prev[i]));
  const bool warm = moved <= 0.01;
  double* a = s.a_elastic;
  for (int i = 0; i < n; ++i) {
    if (!warm) {
      a[i] = std::min(0.05, amax[i]);
      s.lce_prev[i] = muscle_rigid_tendon_force(data_element(m, d, i), m.fibre_damping, s.L[i], r.fibre_velocity[i]).lce;
    }
    a[i] = std::clamp(a[i], 0.0, amax[i]);
    s.L_prev[i] = s.L[i];
  }
  // Sequential QP (control.py's _sqp): each QP is the rigid one's with the elastic element's linearisation
  // F(a') ~ F(a) + dF/da (a' - a), solved by the dual Newton method. control.py's safeguards at the damper floor's
  // kink: once the moment residual stops halving, slopes over +-1e-3 in activation; if it stalls again a proximal
  // term mu sum w (a' - a)^2, mu x4 per further stall (the fixed point is unchanged: the linearisation passes
  // through F(a)).
  bool converged = false, qp_failed = false;
  double step = 1e300, last_resid = 1e300, mu = 0;
  double elastic_resid = 1e300;  // the moment residual (N m) where the last elastic-mode step was taken
  int stalls = 0;
  const double* wts = w.options.weights.data();
  r.qps = 0;
  r.elastic_mode_steps = 0;
  r.qp_iterations = 0;
  r.newton_iterations = 0;
  r.solver = StaticOptimizationSolverUsed::kDualNewton;
  for (int it = 0; it <= kStaticOptimizationMaxSqpIterations; ++it) {
    double worst = 0;
    for (int i = 0; i < n; ++i) {
      const SteadyForce f = muscle_steady_force(data_element(m, d, i), m.fibre_damping, s.L[i], a[i], r.fibre_velocity[i],
                                                s.lce_prev[i]);
      s.lce_prev[i] = r.lce[i] = f.lce;
      r.force[i] = f.force;
      s.Fa[i] = f.dforce_da;
      s.Fp[i] = f.force - f.dforce_da * a[i];
    }
    for (int j = 0; j < nq; ++j) {
      double tau = 0;
      for (int i = 0; i < n; ++i) tau += s.R[j * E + i] * r.force[i];
      r.tau_muscle[j] = tau;
      r.residual[j] = tau - r.tau_required[j];
      worst = std::max(worst, std::abs(r.residual[j]));
    }
    r.residual_max = worst;
    if (worst < 1e-7 && step < 1e-6) { converged = true; break; }
    if (it == kStaticOptimizationMaxSqpIterations) break;
    if (r.qps > 1 && worst > 1e-7 && worst > 0.5 * last_resid) {
      ++stalls;
      if (stalls > 1) mu = mu == 0 ? 1.0 : 4.0 * mu;
    }
    last_resid = worst;
    if (stalls) {
      constexpr double h = 1e-3;
      for (int i = 0; i < n; ++i) {
        const double lo = std::max(a[i] - h, 0.0), hi = a[i] + h;
        const ElementConstants e = data_element(m, d, i);
        const double Fhi = muscle_steady_force(e, m.fibre_damping, s.L[i], hi, r.fibre_velocity[i], r.lce[i]).force;
        const double Flo = muscle_steady_force(e, m.fibre_damping, s.L[i], lo, r.fibre_velocity[i], r.lce[i]).force;
        s.Fa[i] = (Fhi - Flo) / (hi - lo);
        s.Fp[i] = r.force[i] - s.Fa[i] * a[i];
      }
    }
    for (int i = 0; i < n; ++i) {
      s.d_sqp[i] = 2.0 * wts[i] * (1.0 + mu);
      s.lin_sqp[i] = -2.0 * mu * wts[i] * a[i];
    }
    fill_rows(w, s, n, nq, n_in, id.tau_muscle, f0);
    int newton = 0;
    bool ok = dual_newton(s, n, nq, n_in, amax, s.d_sqp, mu > 0 ? s.lin_sqp : nullptr, 1e-9, 1e-9, 50, &newton);
    r.newton_iterations += newton;
    ++r.qps;
    s.z_ready = ok;
    if (!ok && w.options.proxqp_fallback) {
      // This QP by ProxQP, as control.py solves every one (the Newton method stalls on some of the SQP's
      // linearisations: 16 of the 400 frames of armrt_bench_static_optimization --elastic before this fallback).
      r.solver = StaticOptimizationSolverUsed::kProxQP;
      pq::QPSolverOutput status;
      ok = proxqp_sqp_step(w, s, n, nq, n_in, r, status);
      // Linearised about a, the moments may be out of reach in [0, amax] though the muscles' forces reach them
      // (dF/da at a understates F's range; control.py's _sqp, das3 in bench.static_optimization).
      // Only while each elastic step at least halves the moment residual: otherwise the frame is out of reach from
      // here (control.py's _sqp; a truly infeasible frame would run 50 QPs at their feasibility edge).
      if (!ok && status == pq::QPSolverOutput::PROXQP_PRIMAL_INFEASIBLE &&
          worst <= 0.5 * elastic_resid) {
        elastic_resid = worst;
        ok = elastic_mode_step(s, n, n_in, r);
        if (ok) ++r.elastic_mode_steps;
      }
    }
    if (!ok) { qp_failed = true; break; }
    step = 0;
    for (int i = 0; i < n; ++i) {
      const double next = std::clamp(s.a_[i], 0.0, amax[i]);  // ProxQP's box holds to its tolerance only
      step = std::max(step, std::abs(next - a[i]));
      a[i] = next;
    }
  }
  for (int i = 0; i < n; ++i) activation[i] = a[i];
  // After the last QP the moments may balance to the acceptance (1e-6 N m) without the 1e-7 stop: a solution, as
  // control.py's _sqp accepts it; a QP that failed leaves no solution.
  r.feasible = (converged || !qp_failed) && r.residual_max < kStaticOptimizationMomentTolerance;
  r.status = r.feasible ? StaticOptimizationStatus::kSolved : StaticOptimizationStatus::kNotConverged;
  s.elastic_ready = r.feasible;  // the next solve starts from these activations only if they are a solution
  finish_report(def, w, s, n, n_in, f0, amax, activation, r);
}

}  // namespace armrt
