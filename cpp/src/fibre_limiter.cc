// fibre_limiter.cc: (the Jacobian at x_n, x_n, f(x_n), h) -> the Jacobian with the CE modes stiffened where a
// tangent cannot see what happens within a ROS2 step (ROS2 stays second order with any J: it is a W-method):
// an active element whose slack tendon engages within the step, and a taut tendon loading up as activation
// rises. Measured on seeded random protocols: without it a slack-to-taut event could overshoot the CE by
// centimetres and put the joints 6-16 deg off CVODE for a while; with it the error stays ~0.1-0.2 deg
// (docs/engine.md).
#include <cmath>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"
#include "dof_dispatch.h"
#include "moment_arm_dot.h"

namespace armrt {

using detail::moment_arm_dot;

// Isometric force (x fmax) above which a slack element's CE is fast enough to need limiting.
constexpr double kEngagingActiveForce = 0.05;

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

void limit_fibre_overshoot(const Model& m, Data& d, StepJacobian& jac, const double* x, const double* xdot, double h) {
  const int nq = m.num_dofs, iqd = qd_offset(m);
  // Muscle-tendon lengthening rates dL/dt = -R qd (m/s).
  double L_rate[kMaxElements], minus_qd[kMaxDofs];
  for (int j = 0; j < nq; ++j) minus_qd[j] = -x[iqd + j];
  detail::dispatch_dofs(nq, [&](auto N) { moment_arm_dot<N>(m, jac.moment_arm.data(), minus_qd, L_rate); });
  limit_fibre_overshoot_at_rates(m, d, jac, x, xdot, h, L_rate);
}

void limit_fibre_overshoot_at_rates(const Model& m, Data& d, StepJacobian& jac, const double* x, const double* xdot,
                                    double h, const double* L_rate) {
  const MuscleArrays& mc = d.muscles;
  const int n = m.num_elements, ia = act_offset(m);
  const double hg = kRos2Gamma * h;
  const double b0 = m.fibre_damping;
  // One branch-free pass per element.
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

}  // namespace armrt
