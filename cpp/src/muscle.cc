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
// (peeslack + 0.56) lceopt; both have the DAS3 code's 10 N/m linear term so they are never force-free.
#include "armrt/engine.h"
#include "armrt/muscle_kernel.h"

namespace armrt {

MuscleOut muscle_element(const ElementConstants& e, double b, double L, double lce, double a) {
  MuscleOut out;
  muscle_kernel(e.fmax, e.inv_lceopt, e.lslack, e.thickness, e.min_lce, e.vmax, e.k_see, e.k_pee, e.pee_slack,
                e.ecc_c, e.damping_slope, b, L, lce, a, &out.force, &out.fibre_velocity);
  return out;
}

double muscle_equilibrium_lce(const ElementConstants& e, double b, double L, double a) {
  // The CE velocity falls monotonically as lce grows (the tendon slackens); bisect on its sign.
  // A slack muscle-tendon unit settles where the two linear slack springs balance, which can be
  // longer than L itself, hence the generous upper bracket.
  double lo = e.min_lce, hi = (L > lo ? L : lo) + e.pee_slack + e.lceopt;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (muscle_element(e, b, L, mid, a).fibre_velocity > 0) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace armrt
