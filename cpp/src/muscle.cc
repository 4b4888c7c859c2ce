// Hill-type muscle element (paper II-D; McLean et al. 2003 form, as in the DAS3 real-time code).
//
// Contractile element (CE) in parallel with a quadratic parallel elastic element (PEE) and a linear
// damper, pennated, in series with a quadratic series elastic element (SEE, the tendon). The state is
// the CE length; its velocity comes from inverting the force-velocity relation, so the ODE is explicit.
//
// The damper (10 N/(m/s)) is kept at all activations instead of only below a = 0.02 as in the paper:
// the switch would make the right-hand side discontinuous (bad for CVODE and for stable step sizes),
// and above a = 0.02 the damper's force is under 1% of the CE's force-velocity damping. With the
// damper, F0 g(v) + b v is strictly increasing in v, so the inversion has exactly one root, which is
// finite at zero activation.
#include <algorithm>
#include <cmath>

#include "armrt/engine.h"

namespace armrt {
namespace {

double see_force(const ElementConstants& e, double l_see) {
  const double stretch = l_see - e.lslack;
  double f = kLinearStiffness * stretch;
  if (stretch > 0) f += e.k_see * stretch * stretch;
  return f;
}

double pee_force(const ElementConstants& e, double lce) {
  const double stretch = lce - e.pee_slack;
  double f = kLinearStiffness * stretch;
  if (stretch > 0) f += e.k_pee * stretch * stretch;
  return f;
}

double force_length(const ElementConstants& e, double lce) {
  const double x = (lce / e.lceopt - 1.0) / kForceLengthWidth;
  return std::exp(-x * x);
}

// Smallest CE length for which the pennation geometry exists (fibres cannot be shorter than the
// muscle is thick).
double min_lce(const ElementConstants& e) { return std::max(1.001 * e.thickness, 0.05 * e.lceopt); }

double cos_pennation(const ElementConstants& e, double lce) {
  const double s = e.thickness / lce;
  return std::sqrt(1.0 - s * s);
}

// Solves F0 g(v) + b v = F for v (m/s), F0 = a fmax f(lce) the isometric active force.
// Concentric (F <= F0): g = (vmax + v) / (vmax - v/A)  ->  (b/A) v^2 - (F0 + b vmax + F/A) v - (F0 - F) vmax = 0
// Eccentric  (F >  F0): g = (gmax v + c) / (v + c)     ->  b v^2 + (gmax F0 + b c - F) v + (F0 - F) c = 0
// Each quadratic has exactly one root on its side of zero; written in the cancellation-free form.
double fibre_velocity(const ElementConstants& e, double b, double F0, double F) {
  const double vm = e.vmax;
  if (F <= F0) {
    const double alpha = b / kHillA;
    const double beta = F0 + b * vm + F / kHillA;  // minus the linear coefficient
    const double gamma = (F0 - F) * vm;            // minus the constant, >= 0
    const double disc = std::sqrt(beta * beta + 4.0 * alpha * gamma);
    // root <= 0: v = (beta - disc) / (2 alpha) = -2 gamma / (beta + disc)
    if (beta > 0) return -2.0 * gamma / (beta + disc);
    return (beta - disc) / (2.0 * alpha);
  }
  const double c = e.ecc_c;
  const double beta = kEccentricFmax * F0 + b * c - F;
  const double gamma = (F - F0) * c;  // minus the constant, > 0
  const double disc = std::sqrt(beta * beta + 4.0 * b * gamma);
  // root > 0: v = (-beta + disc) / (2 b) = 2 gamma / (beta + disc)
  if (beta > 0) return 2.0 * gamma / (beta + disc);
  return (disc - beta) / (2.0 * b);
}

}  // namespace

MuscleOut muscle_element(const ElementConstants& e, double b, double L, double lce, double a) {
  lce = std::max(lce, min_lce(e));
  const double cos_pen = cos_pennation(e, lce);
  const double f_see = see_force(e, L - lce * cos_pen);
  const double f_fibre = f_see / cos_pen;  // the tendon force resolved along the fibres
  const double F0 = a * e.fmax * force_length(e, lce);
  const double v = fibre_velocity(e, b, F0, f_fibre - pee_force(e, lce));
  return {f_see, v};
}

double muscle_equilibrium_lce(const ElementConstants& e, double b, double L, double a) {
  // fibre_velocity is monotonic in the force imbalance; bisection on its sign is robust everywhere.
  double lo = min_lce(e), hi = std::max(L, lo * 1.0001);
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (muscle_element(e, b, L, mid, a).fibre_velocity > 0) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace armrt
