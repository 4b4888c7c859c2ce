// Hill-type muscle element (paper II-D; McLean et al. 2003 form, as in the DAS3 real-time code).
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

}  // namespace armrt
