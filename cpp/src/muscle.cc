// Hill-type muscle element (paper II-D; McLean et al. 2003 form, as in the DAS3 real-time code).
// (L, lce, a) -> tendon force, CE velocity; and for control (static optimisation, docs/control.md) the force as a
// function of activation: at the CE length of a given fibre velocity (muscle_steady_force) or with a rigid tendon.
//
// Contractile element (CE) in parallel with a quadratic parallel elastic element (PEE) and a linear
// damper, pennated, in series with a quadratic series elastic element (SEE, the tendon). The state is
// the CE length; its velocity comes from inverting the force-velocity relation, so the ODE is explicit:
//   concentric  g(v) = (vmax + v) / (vmax - v/A),            A = 0.25
//   eccentric   g(v) = (1.5 v + c) / (v + c),                c matches the concentric slope at v = 0
//   F0 g(v) + b v = F_see / cos(pennation) - F_pee,          F0 = a fmax f(lce), f Gaussian (width 0.56)
// Each branch is a quadratic in v with one root on its side of zero (muscle_kernel.h).
//
// Regularisation at low activation (the paper: a 10 N/(m/s) damper below a = 0.02). A fixed 10 N/(m/s)
// cannot carry the tendon force of a relaxed muscle: with 4%-strain tendons a few mm long, the CE mode
// then has eigenvalues near -1.6e4 1/s (anconeus, 9 N passive), forcing steps under 0.2 ms. So the
// damper is b = 10 N/(m/s) + (1+A)/(A vmax) * max(0, 0.02 fmax - F0), F0 = a fmax f(lce): the CE's own
// damping at v = 0 is F0 (1+A)/(A vmax), so the total never falls below that of a muscle at a = 0.02
// and optimal length, which is what the paper relies on above its threshold. The extra term fades
// continuously (no switch, so CVODE sees a continuous right-hand side) and is zero whenever the CE
// carries more than 2% of fmax isometrically; it also covers active muscles far from optimal length,
// whose force-length factor would otherwise leave them as undamped as a relaxed one. With it,
// F0 g(v) + b v is strictly increasing in v, so the inversion has exactly one root, finite at zero
// activation. Pennation keeps the muscle's thickness lceopt sin(pennopt) constant (constant volume).
// SEE: k (L - lslack)^2 with 4% strain at fmax; PEE: k (lce - peeslack lceopt)^2 reaching fmax at
// (peeslack + 0.56) lceopt. Both are zero when slack: a tendon cannot push. (The DAS3 code adds a 10 N/m
// linear term to each so the equations stay solvable at zero activation; here the damper b > 0 does
// that, and the linear term would give negative tendon forces at rest and a force that does not scale
// with fmax, so that strength 0.5 would not halve the active force.) Every force is proportional to fmax,
// so a strength scale s multiplies the isometric force at every length and activation by exactly s.
//
// Fibre compressive element: a fibre cannot shorten without bound. A sarcomere shortened below about
// 60 % of its optimal length has its thick filaments against the Z-discs: active force is gone and the
// fibre resists further shortening (Gordon, Huxley & Julian 1966, J Physiol 184:170); OpenSim's
// Millard2012 muscles add a fibre compressive force-length curve for the same reason (Millard et al.
// 2013, J Biomech Eng 135:021005). Without it a unit shorter than its tendon slack length (supinator at
// full supination) lets an active CE shorten at vmax through zero length. Here: k_c (l_c - lce)^2 below
// l_c = max(0.3 lceopt, min_lce + 0.1 lceopt), reaching 4 fmax at the geometric minimum min_lce, in
// parallel with CE and PEE. The onset sits below the shortest fibre lengths of the paper's tasks (0.42
// lceopt: biceps at full elbow flexion), where the paper's Gaussian force-length curve still gives
// active force; an onset at 0.5 lceopt cancelled much of that force (elbow flexors at 0.4 for 6 s
// reached 132 instead of 137.5 deg). At min_lce it exceeds any active force the CE can develop there (<= fmax f(lce)),
// so the CE velocity turns to lengthening before min_lce:
// the fibre stays above its geometric minimum. A whole slack unit at zero activation carries no force and
// its fibre keeps its length (v = 0), moved only by the PEE (if stretched) and the compressive element;
// at rest (muscle_equilibrium_lce) such a fibre has taken up all but 0.2 % of its tendon's slack.
#include <cmath>

#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"

namespace armrt {

MuscleOut muscle_element(const ElementConstants& e, double b, double L, double lce, double a) {
  MuscleOut out;
  muscle_kernel(e.fmax, e.inv_lceopt, e.lslack, e.thickness, e.min_lce, e.vmax, e.k_see, e.k_pee, e.pee_slack,
                e.compress_length, e.k_compress, e.ecc_c, e.damping_slope, b, L, lce, a, &out.force, &out.fibre_velocity);
  return out;
}

MuscleOut muscle_element_derivatives(const ElementConstants& e, double b, double L, double lce, double a,
                                     MuscleDerivatives* der) {
  MuscleOut out;
  muscle_kernel_derivatives(e.fmax, e.inv_lceopt, e.lslack, e.thickness, e.min_lce, e.vmax, e.k_see, e.k_pee,
                            e.pee_slack, e.compress_length, e.k_compress, e.ecc_c, e.damping_slope, b, L, lce, a,
                            &out.force, &out.fibre_velocity, der);
  return out;
}

double muscle_equilibrium_lce(const ElementConstants& e, double b, double L, double a) {
  // The CE velocity falls monotonically as lce grows (the tendon slackens); bisect on its sign.
  // A muscle of zero strength carries no force at any length: its fibre rests at its slack length.
  if (e.fmax == 0.0) return e.pee_slack;
  double lo = e.min_lce, hi = (L > lo ? L : lo) + e.pee_slack + e.lceopt;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (muscle_element(e, b, L, mid, a).fibre_velocity >= 0) lo = mid; else hi = mid;
  }
  const double lce = 0.5 * (lo + hi);
  // A relaxed slack unit is force-free over a range of fibre lengths (v = 0), and the bisection returned
  // the range's long end, the PEE's slack length. That can be longer than the whole unit (latdorsi6 at
  // rest: a 0.34 m fibre in a 0.24 m unit): the relaxed fibre rests instead where it has taken up all
  // but kRestTendonSlack of its tendon's slack, inside the unit, so it pulls as soon as it is activated.
  // (Not exactly at the taut point: that is the tendon's kink, where a 1e-9 perturbation of the start
  // would flip the ROS2 step's slack/taut decisions.)
  const double along_rest = L - e.lslack * (1.0 - kRestTendonSlack);
  if (a != 0.0 || along_rest <= 0.0) return lce;
  double lce_rest = std::sqrt(along_rest * along_rest + e.thickness * e.thickness);
  lce_rest = lce_rest > e.compress_length ? lce_rest : e.compress_length;
  if (lce_rest < lce && muscle_element(e, b, L, lce_rest, 0.0).fibre_velocity == 0.0) return lce_rest;
  return lce;
}

double muscle_lce_at_velocity(const ElementConstants& e, double b, double L, double a, double fibre_velocity,
                              double lce_guess) {
  if (e.fmax == 0.0) return e.pee_slack;
  // The CE velocity falls monotonically as lce grows (muscle_equilibrium_lce's bracket). Newton's steps on
  // v(lce) - fibre_velocity with the kernel's dv/dlce from lce_guess, kept inside the bracket that each
  // evaluation narrows; a bisection step where Newton's would leave it or the slope vanishes (a slack unit's
  // force-free range, the kinks of the slack points). Stops when the bracket or the step is below 1e-13 m. A Newton
  // step that small is tested before the bracket: at a converged x the step rounds to x itself, which is the
  // bracket's end just set, and bisecting from there cost 25-40 more evaluations (the elastic static optimisation's
  // 400-frame bench motion averaged 12.4 evaluations per call before this test).
  double lo = e.min_lce, hi = (L > lo ? L : lo) + e.pee_slack + e.lceopt;
  double x = lce_guess > lo && lce_guess < hi ? lce_guess : 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    MuscleDerivatives der;
    const double g = muscle_element_derivatives(e, b, L, x, a, &der).fibre_velocity - fibre_velocity;
    if (g == 0.0) return x;
    if (der.dvel_dlce < 0.0 && std::fabs(g / der.dvel_dlce) < 1e-13) return x;
    if (g > 0) lo = x; else hi = x;
    if (hi - lo < 1e-13) break;
    const double newton = der.dvel_dlce < 0.0 ? x - g / der.dvel_dlce : lo - 1.0;
    const double next = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    if (std::fabs(next - x) < 1e-13) return next;
    x = next;
  }
  return 0.5 * (lo + hi);
}

SteadyForce muscle_steady_force(const ElementConstants& e, double b, double L, double a, double fibre_velocity,
                                double lce_guess) {
  SteadyForce out;
  out.lce = muscle_lce_at_velocity(e, b, L, a, fibre_velocity, lce_guess);
  MuscleDerivatives der;
  out.force = muscle_element_derivatives(e, b, L, out.lce, a, &der).force;
  // Implicit function theorem on v(L, lce, a) = fibre_velocity at fixed L: dlce/da = -(dv/da) / (dv/dlce).
  // Where the velocity does not depend on lce (a relaxed slack unit, the fibre at its floor) the force does
  // not change with a small change of activation: 0.
  out.dforce_da = der.dvel_dlce != 0.0 ? -der.dforce_dlce * der.dvel_da / der.dvel_dlce : 0.0;
  return out;
}

RigidTendonForce muscle_rigid_tendon_force(const ElementConstants& e, double b, double L, double dL_dt) {
  RigidTendonForce out;
  const double along = L - e.lslack;  // the fibre's projection on the path, the tendon at its slack length
  double lce = std::sqrt((along > 0 ? along * along : 0.0) + e.thickness * e.thickness);
  lce = lce > e.min_lce ? lce : e.min_lce;
  out.lce = lce;
  if (along <= 0.0 || e.fmax == 0.0) return out;  // the unit is shorter than its tendon: no force either way
  const double cos_pen = std::sqrt(lce * lce - e.thickness * e.thickness) / lce;
  const double v = dL_dt * cos_pen;  // d lce / dt of lce = sqrt(along^2 + thickness^2), d along/dt = dL/dt
  const double x = (lce * e.inv_lceopt - 1.0) / kForceLengthWidth;
  const double fl = std::exp(-x * x);
  // The force-velocity factor g(v) of muscle.cc's header (concentric / eccentric), 0 below -vmax.
  double g = v <= 0.0 ? (e.vmax + v) / (e.vmax - v / kHillA) : (kEccentricFmax * v + e.ecc_c) / (v + e.ecc_c);
  g = g > 0.0 ? g : 0.0;
  const double pee = lce > e.pee_slack ? e.k_pee * (lce - e.pee_slack) * (lce - e.pee_slack) : 0.0;
  const double compress = lce < e.compress_length ? e.k_compress * (e.compress_length - lce) * (e.compress_length - lce) : 0.0;
  out.force_per_activation = e.fmax * fl * g * cos_pen;
  out.passive_force = (pee - compress + b * v) * cos_pen;
  return out;
}

}  // namespace armrt
