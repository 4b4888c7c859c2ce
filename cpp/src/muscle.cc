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
// The damper b = 10 N/(m/s) is kept at all activations instead of only below a = 0.02 as in the paper:
// the switch would make the right-hand side discontinuous (bad for CVODE and for stable step sizes),
// and above a = 0.02 its force is under 1% of the CE's own force-velocity damping. With it,
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
                e.ecc_c, b, L, lce, a, &out.force, &out.fibre_velocity);
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
