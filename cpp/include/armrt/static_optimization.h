// static_optimization.cc. (q, qd, qdd, hand load, the arm's settings) -> activations a (num_elements) in
// [0, max_activation] minimising sum w_i a_i^2 with the rigid-tendon muscle forces supplying the inverse
// dynamics' moments, optionally with GHstab <= a bound as a polygon of linear constraints on the GH force: the
// QP python/armrt/control.py's StaticOptimizer(tendon="rigid") solves, in C++ for the 1 kHz loop
// (docs/control.md): a dual projected Newton method, ProxQP where it does not converge. Set-up allocates (the ProxQP
// workspace); a solve by the Newton method does not (cpp/tests/test_alloc.cc), the ProxQP fallback may (inside
// proxsuite, when its active set changes).
#pragma once

#include <memory>
#include <vector>

#include "armrt/data.h"
#include "armrt/engine.h"
#include "armrt/model.h"

namespace armrt {

// Sides of the GHstab polygon (python/armrt/control.py POLYGON_SIDES).
inline constexpr int kGhPolygonSides = 24;
inline constexpr int kMaxGhPolygonSides = 64;
// Below |theta| tan|theta| = 1/2 the set {GHstab <= s} is convex (control.py CONVEX_HALF_ANGLE); beyond
// kMaxBoundHalfAngle (rad) from the normal a bound is refused (MAX_BOUND_HALF_ANGLE).
inline constexpr double kMaxBoundHalfAngle = 1.45;
// Smaller bounds are refused (control.py MIN_GH_STAB_MAX, armrt-rt's --so-gh-stab-max): the bound's cone is then
// theta_a sqrt(s), under 1 mrad about the glenoid normal, and below about 1e-7 the solvers' tolerances no longer
// resolve it (a new user's trial: answers marked feasible 5.8e7 times above a 1e-30 bound, the two backends
// disagreeing there). 1e-6 keeps a factor 10 from the smallest bound both backends were tested to hold (1e-7).
inline constexpr double kMinGhStabMax = 1e-6;
// Moments balanced to this (N m, |.|_inf) or the solve is infeasible (the Python API's acceptance).
inline constexpr double kStaticOptimizationMomentTolerance = 1e-6;
// Inputs beyond these are refused, not solved (control.py's check, armrt-rt's target packets and its computed
// qddot): far above anything an arm bears or does (1e5 N is ten tonnes in the hand; a baseball pitch's shoulder
// reaches about 1e3-1e4 rad/s^2), and at a 1e16 N load ProxQP's closest-solution QPs ran for seconds to minutes.
inline constexpr double kStaticOptimizationMaxHandForce = kMaxHandForce;    // N, |hand force| (engine.h: every load's)
inline constexpr double kStaticOptimizationMaxHandMoment = kMaxHandMoment;  // N m, |hand moment|
inline constexpr double kStaticOptimizationMaxJointAcceleration = 1e5;  // rad/s^2, |qddot| per DOF
// The elastic tendon's SQP stops after this many QPs (control.py's max_iterations default, which the C++ path
// holds fixed: StaticOptimizer refuses another max_iterations with backend "cpp").
inline constexpr int kStaticOptimizationMaxSqpIterations = 50;

// Rows c (sides x 3, row-major) of the constraints c . (F.normal, F.major, F.minor) <= 0 on a GH force F that
// imply GHstab(F) <= bound: control.py's gh_polygon, the same polygon to rounding (docs/control.md).
// Throws std::invalid_argument for a bound below kMinGhStabMax, non-finite, or whose ellipse reaches kMaxBoundHalfAngle.
void gh_polygon(double theta_a, double phi_a, double bound, int sides, double* rows);

struct StaticOptimizationOptions {
  double gh_stab_max = 0;              // > 0: GHstab <= gh_stab_max; 0: no GH constraint
  int polygon_sides = kGhPolygonSides;
  std::vector<double> weights;         // num_elements, > 0; empty: all 1
  double eps_abs = 1e-9;               // ProxQP's absolute tolerance (control.py's setting)
  int max_qp_iterations = 1000;        // ProxQP's max_iter (control.py's)
  // ProxQP's structure hints (docs/control.md has their measured cost): the Hessian declared diagonal (it is:
  // 2 w), and the dense factorisation, 0 ProxQP's automatic choice, 1 primal-dual LDLT, 2 primal LDLT.
  bool diagonal_hessian = false;
  // First the dual projected Newton method (static_optimization.cc dual_newton: exact on this QP's structure, a
  // diagonal Hessian and few rows), ProxQP where it does not converge; false: ProxQP only.
  bool dual_newton = true;
  // Where the Newton method does not converge: ProxQP decides (and gives the closest solution when infeasible),
  // or, false, the solve is reported at once with the Newton iterate's residuals, kInfeasible where the method's
  // weak-duality certificate proves it (static_optimization.cc dual_newton), kNotConverged otherwise: a bounded
  // time and no allocation, what the 1 kHz loop takes (it applies zero excitation then anyway).
  bool proxqp_fallback = true;
  int dense_backend = 0;
};

enum class StaticOptimizationSolverUsed { kDualNewton = 0, kProxQP = 1 };

enum class StaticOptimizationStatus {
  kSolved = 0,        // moments balanced to kStaticOptimizationMomentTolerance, bounds and GH rows held
  kInfeasible = 1,    // no activations within the bounds (and GH bound) supply the moments: closest solution
  kNotConverged = 2,  // ProxQP did not reach its tolerance within max_qp_iterations (closest solution)
};

// One solve's outcome. On kInfeasible / kNotConverged the activations are the closest solution's
// (min |residual|^2 + 1e-4 sum w a^2 within the bounds and GH rows, as control.py's slack QP).
struct StaticOptimizationReport {
  StaticOptimizationStatus status = StaticOptimizationStatus::kSolved;
  bool feasible = false;
  int qp_iterations = 0;                  // ProxQP iterations, both QPs
  int qps = 0;                            // ProxQP QPs solved (0: the dual Newton method answered; 1, or 2
                                          // with the closest-solution QP)
  int newton_iterations = 0;              // of the dual Newton method
  int elastic_mode_steps = 0;             // elastic SQP: QPs whose linearisation could not balance the moments,
                                          // stepped to its closest moments instead (static_optimization.cc)
  StaticOptimizationSolverUsed solver = StaticOptimizationSolverUsed::kDualNewton;
  double tau_required[kMaxDofs] = {};     // N m, inverse dynamics
  double tau_muscle[kMaxDofs] = {};       // N m, R^T F(a)
  double residual[kMaxDofs] = {};         // N m, tau_muscle - tau_required
  double residual_max = 0;                // N m, |residual|_inf
  double gh_force[3] = {};                // N, scapula frame, of the loads and these muscle forces
  double gh_stab = 0;                     // GHstab of gh_force (gh_stability)
  bool gh_bound_active = false;           // a polygon row binds
  int at_upper_bound = 0;                 // elements with max_activation > 0 at it
  double lce[kMaxElements] = {};          // m, rigid-tendon CE lengths
  double force[kMaxElements] = {};        // N, tendon forces at the activations
  double fibre_velocity[kMaxElements] = {};  // m/s, dL/dt = -R qd
};

struct StaticOptimizationSolver;  // the ProxQP objects and their matrices (static_optimization.cc)

// The problem's constants (weights, GH rows) and the solver's preallocated state, which warm starts each
// solve from the previous one. One workspace per arm and options.
struct StaticOptimizationWorkspace {
  StaticOptimizationWorkspace();
  ~StaticOptimizationWorkspace();
  StaticOptimizationWorkspace(StaticOptimizationWorkspace&&) noexcept;
  StaticOptimizationWorkspace& operator=(StaticOptimizationWorkspace&&) noexcept;
  int num_elements = 0, num_dofs = 0;
  StaticOptimizationOptions options;
  int num_gh_rows = 0;                          // polygon sides + 1 (F.normal >= 0), or 0
  double gh_rows[(kMaxGhPolygonSides + 1) * 3] = {};
  double glenoid_axes[9] = {};                  // rows: normal, major, minor (scapula frame)
  std::unique_ptr<StaticOptimizationSolver> solver;
};

// Checks the options against m (std::invalid_argument naming the problem) and allocates w for them.
void static_optimization_setup(const Model& m, const StaticOptimizationOptions& options, StaticOptimizationWorkspace& w);

// The rigid-tendon static optimisation at (q, qd, qdd) (rad, rad/s, rad/s^2) with the hand load (N, N m, thorax
// frame), d's gravity, strength and max_activation: activations (num_elements) and the report. Reads d only.
// Never a silent best effort: report.feasible false (status names why) with the closest solution's residuals.
void static_optimization_rigid(const Model& m, const Data& d, StaticOptimizationWorkspace& w, const double* q,
                               const double* qd, const double* qdd, const double* hand_force,
                               const double* hand_moment, double* activation, StaticOptimizationReport* report);

// The same with the elastic tendon (control.py's tendon="elastic"): the force of element i as a function of a_i is
// muscle_steady_force's, the tendon force at the CE length where the fibre velocity equals the path's dL/dt;
// sequential QP on its linearisation, each QP solved by the dual Newton method, until the moments balance to 1e-7 N m
// and the activations move less than 1e-6 (at most 50 QPs; after the 50th the moments balanced to 1e-6 N m are
// accepted, as control.py does), with control.py's safeguards at the damper floor's kink. A QP the Newton method does
// not solve goes to ProxQP (options.proxqp_fallback; report.solver kProxQP then). A solve that does not converge is
// reported kNotConverged (feasible false), never returned as a solution; there is no closest-solution QP here.
// report.lce holds the CE lengths, report.qps the QPs solved.
void static_optimization_elastic(const Model& m, const Data& d, StaticOptimizationWorkspace& w, const double* q,
                                 const double* qd, const double* qdd, const double* hand_force,
                                 const double* hand_moment, double* activation, StaticOptimizationReport* report);

// Forgets the previous solution (the next solve starts cold).
void static_optimization_reset(StaticOptimizationWorkspace& w);

}  // namespace armrt
