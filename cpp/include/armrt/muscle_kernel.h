// The Hill-type muscle element as one branch-free inline kernel, so that forward() can run it over all
// elements as a vectorised loop (structure-of-arrays constants) and the scalar API shares the formula.
// The physics and the choices behind it are described in cpp/src/muscle.cc.
#pragma once

#include <cmath>

#include "armrt/fast_math.h"
#include "armrt/model.h"

namespace armrt {

// Derivatives of one element's outputs with respect to its inputs (muscle_kernel_derivatives). Tendon
// force T (N) and CE velocity v (m/s) as functions of the muscle-tendon length L (m), the CE length lce
// (m) and the activation a; T does not depend on a.
struct MuscleDerivatives {
  double dforce_dL;     // N/m
  double dforce_dlce;   // N/m
  double dvel_dL;       // 1/s
  double dvel_dlce;     // 1/s
  double dvel_da;       // m/s
  // Terms of the same evaluation that depend on lce alone (at lce floored to min_lce), kept for the ROS2
  // step's overshoot limiter, which needs them at this lce and would otherwise recompute them.
  double force_length;  // f(lce), the active force-length factor (F0 = a fmax f)
  double lce_along;     // m, lce cos(pennation)
  double cos_pennation;      // lce_along / lce
  double inv_cos_pennation;  // lce / lce_along
  double pee_force;     // N, parallel elastic element, along the fibre
  double compress_force;  // N, fibre compressive element, along the fibre
};

// Damping the damper gains below kLowActivation (muscle.cc), N s/m: it tops the damper up to the CE's own
// damping at a = 0.02 and optimal length, and is zero once the CE carries more than 2 % of fmax
// isometrically. afl = F0 / fmax = a f(lce).
inline double damping_floor(double damping_slope, double afl) {
  const double missing = damping_slope * (kLowActivation - afl);
  return missing > 0 ? missing : 0.0;
}

// Inputs: constants of one element, the fixed damper b0 (N s/m), muscle-tendon length L (m), CE
// length lce (m), activation a. Outputs: tendon force (N), CE velocity (m/s, lengthening positive) and
// their derivatives (used by the linearly implicit integrator's Jacobian, step_jacobian.h).
//
// The velocity solves F0 g(v) + b v = F (muscle.cc), so its derivatives follow from implicit
// differentiation of that relation, not of the root formula:
//   (F0 g'(v) + b) dv = dF - (g(v) + v db/dF0) dF0.
// Where the formula has kinks the derivative is one-sided (the value of the branch taken):
//   - lce at its geometric floor min_lce: derivatives with respect to lce are 0 (floor side);
//   - the damping floor's fade-out at F0 = 0.02 fmax (db/dF0 jumps from -damping_slope/fmax to 0);
//   - the slack points of tendon, PEE and compressive element are C1 (quadratics from zero), so the
//     first derivatives are continuous there; the concentric/eccentric switch at v = 0 is C1 too (g and
//     g' match).
//
// muscle_kernel_derivatives_along is the same at a CE length lce >= min_lce whose projection on the tendon,
// lce_along = sqrt(lce^2 - thickness^2), the caller has already (fibre_limiter.cc's operating point is built
// from it: one square root fewer per element).
inline void muscle_kernel_derivatives_along(double fmax, double inv_lceopt, double lslack, double thickness,
                                            double vmax, double k_see, double k_pee, double pee_slack,
                                            double compress_length, double k_compress, double ecc_c,
                                            double damping_slope, double b0, double L, double lce, double lce_along,
                                            bool above_floor, double a, double* force, double* velocity,
                                            MuscleDerivatives* der) {
  // One division gives 1/lce_along and 1/lce, so cos(pennation) and its inverse (division and square root
  // dominate the loop: one 8-wide division costs about nine multiply-adds on this machine).
  const double inv_lce_lce_along = 1.0 / (lce * lce_along);
  const double inv_lce_along = lce * inv_lce_lce_along;
  const double inv_lce = lce_along * inv_lce_lce_along;
  const double inv_cos = lce * inv_lce_along;
  const double see_stretch = L - lce_along - lslack;
  const double see_pos = see_stretch > 0 ? see_stretch : 0.0;
  const double f_see = k_see * see_pos * see_pos;  // a tendon pulls, never pushes
  const double pee_stretch = lce - pee_slack;
  const double pee_pos = pee_stretch > 0 ? pee_stretch : 0.0;
  const double f_pee = k_pee * pee_pos * pee_pos;
  const double compression = compress_length - lce;  // fibre compressive element (muscle.cc)
  const double compress_pos = compression > 0 ? compression : 0.0;
  const double f_compress = k_compress * compress_pos * compress_pos;
  const double F = f_see * inv_cos - f_pee + f_compress;  // what the CE and damper must carry along the fibres
  const double xfl = (lce * inv_lceopt - 1.0) * (1.0 / kForceLengthWidth);
  const double fl = exp_nonpositive(-xfl * xfl);
  const double afl = a * fl;  // F0 / fmax
  const double F0 = fmax * afl;
  // Damping floor (muscle.cc): the CE's own damping at v = 0 is F0 (1+A)/(A vmax) = F0 damping_slope/fmax.
  const double floor_damping = damping_floor(damping_slope, afl);
  const bool floor_active = floor_damping > 0;
  const double b = b0 + floor_damping;

  // Concentric (F <= F0): (b/A) u^2 + beta_c u - gamma_c = 0 with v = -u; eccentric (F > F0):
  // b u^2 + beta_e u - gamma_e = 0 with v = u. One quadratic with the branch's coefficients, its
  // non-negative root u taken in the form that does not cancel.
  const bool eccentric = F > F0;
  const double alpha = eccentric ? b : b * (1.0 / kHillA);
  const double beta = eccentric ? kEccentricFmax * F0 + b * ecc_c - F : F0 + b * vmax + F * (1.0 / kHillA);
  const double gamma_raw = eccentric ? (F - F0) * ecc_c : (F0 - F) * vmax;
  const double gamma = gamma_raw > 0 ? gamma_raw : 0.0;
  const double disc = std::sqrt(beta * beta + 4.0 * alpha * gamma);
  const double num = beta > 0 ? 2.0 * gamma : disc - beta;
  const double den = beta > 0 ? beta + disc : 2.0 * alpha;
  const double u = num / den;
  const double v = eccentric ? u : -u;
  *velocity = v;
  *force = f_see;

  // Derivatives (dead code, removed by the compiler, where the caller drops them: muscle_kernel).
  const double dfsee = 2.0 * k_see * see_pos;  // d f_see / d see_stretch
  const double dfpee = 2.0 * k_pee * pee_pos;
  const double dfcompress = -2.0 * k_compress * compress_pos;  // d f_compress / d lce
  // d(lce cos)/dlce = 1/cos; d(1/cos)/dlce = -s^2 / (lce cos^3).
  const double dF_dL = dfsee * inv_cos;
  const double sin2_over_lce_cos = thickness * thickness * inv_lce * inv_lce * inv_lce_along;  // s^2 / (lce cos)
  const double dF_dlce = -inv_cos * inv_cos * (dfsee + f_see * sin2_over_lce_cos) - dfpee + dfcompress;
  const double dfl_dlce = -2.0 * xfl * fl * inv_lceopt * (1.0 / kForceLengthWidth);
  const double dF0_dlce = fmax * a * dfl_dlce;
  const double dF0_da = fmax * fl;
  // g(v) and g'(v) of the branch taken (muscle.cc): concentric (vmax + v)/(vmax - v/A),
  // eccentric (gmax v + c)/(v + c).
  const double g_den = eccentric ? v + ecc_c : vmax - v * (1.0 / kHillA);
  const double g_num = eccentric ? kEccentricFmax * v + ecc_c : vmax + v;
  const double g_slope_num = eccentric ? (kEccentricFmax - 1.0) * ecc_c : vmax * (1.0 + 1.0 / kHillA);
  // 1/g_den and 1/D, D = F0 g'(v) + b = P / g_den^2 with P = F0 g_slope_num + b g_den^2 > 0, from one
  // division: 1/(g_den P).
  const double P = F0 * g_slope_num + b * g_den * g_den;
  const double inv_g_den_P = 1.0 / (g_den * P);
  const double inv_g_den = P * inv_g_den_P;
  const double g = g_num * inv_g_den;
  const double db_dF0 = floor_active ? -damping_slope / fmax : 0.0;
  const double inv_D = g_den * g_den * g_den * inv_g_den_P;
  const double via_F0 = g + v * db_dF0;
  const double on_floor = above_floor ? 1.0 : 0.0;
  der->dforce_dL = dfsee;
  der->dforce_dlce = -dfsee * inv_cos * on_floor;
  der->dvel_dL = dF_dL * inv_D;
  der->dvel_dlce = (dF_dlce - via_F0 * dF0_dlce) * inv_D * on_floor;
  der->dvel_da = -via_F0 * dF0_da * inv_D;
  der->force_length = fl;
  der->lce_along = lce_along;
  der->cos_pennation = lce_along * inv_lce;
  der->inv_cos_pennation = inv_cos;
  der->pee_force = f_pee;
  der->compress_force = f_compress;
}

inline void muscle_kernel_derivatives(double fmax, double inv_lceopt, double lslack, double thickness,
                                      double min_lce, double vmax, double k_see, double k_pee, double pee_slack,
                                      double compress_length, double k_compress, double ecc_c,
                                      double damping_slope, double b0, double L, double lce, double a,
                                      double* force, double* velocity, MuscleDerivatives* der) {
  const bool above_floor = lce > min_lce;
  lce = above_floor ? lce : min_lce;
  // Fibre length projected on the tendon, lce cos(pennation) = sqrt(lce^2 - thickness^2).
  const double lce_along = std::sqrt(lce * lce - thickness * thickness);
  muscle_kernel_derivatives_along(fmax, inv_lceopt, lslack, thickness, vmax, k_see, k_pee, pee_slack, compress_length,
                                  k_compress, ecc_c, damping_slope, b0, L, lce, lce_along, above_floor, a, force,
                                  velocity, der);
}

// The same element without derivatives: what forward() evaluates at every RK4 stage.
inline void muscle_kernel(double fmax, double inv_lceopt, double lslack, double thickness, double min_lce,
                          double vmax, double k_see, double k_pee, double pee_slack, double compress_length,
                          double k_compress, double ecc_c, double damping_slope, double b0, double L, double lce,
                          double a, double* force, double* velocity) {
  MuscleDerivatives unused;
  muscle_kernel_derivatives(fmax, inv_lceopt, lslack, thickness, min_lce, vmax, k_see, k_pee, pee_slack,
                            compress_length, k_compress, ecc_c, damping_slope, b0, L, lce, a, force, velocity,
                            &unused);
}

}  // namespace armrt
