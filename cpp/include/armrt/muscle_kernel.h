// The Hill-type muscle element as one branch-free inline kernel, so that forward() can run it over all
// elements as a vectorised loop (structure-of-arrays constants) and the scalar API shares the formula.
// The physics and the choices behind it are described in cpp/src/muscle.cc.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "armrt/model.h"

namespace armrt {

// exp(x) for x <= 0 without branches or library calls (vectorisable): Cody-Waite reduction to
// |r| <= ln2/2 and a degree-12 Taylor polynomial; relative error below 1e-15 (tests check it).
// Rounding uses the 1.5 * 2^52 trick (valid without -ffast-math) so it vectorises on plain SSE2.
inline double exp_nonpositive(double x) {
  x = x < -700.0 ? -700.0 : x;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  constexpr std::int64_t kRoundBits = 0x4338000000000000;
  const double y = x * 1.4426950408889634 + kRound;
  const double n = y - kRound;
  std::int64_t ybits;
  std::memcpy(&ybits, &y, sizeof ybits);
  const double r = (x - n * 0.6931471803691238) - n * 1.9082149292705877e-10;
  double p = 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  const std::int64_t bits = (ybits - kRoundBits + 1023) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

// Inputs: constants of one element, the fixed damper b0 (N s/m), muscle-tendon length L (m), CE
// length lce (m), activation a. Outputs: tendon force (N) and CE velocity (m/s, lengthening positive).
inline void muscle_kernel(double fmax, double inv_lceopt, double lslack, double thickness, double min_lce,
                          double vmax, double k_see, double k_pee, double pee_slack, double ecc_c,
                          double damping_slope, double b0, double L, double lce, double a, double* force,
                          double* velocity) {
  lce = lce > min_lce ? lce : min_lce;
  const double s = thickness / lce;
  const double cos_pen = std::sqrt(1.0 - s * s);
  const double see_stretch = L - lce * cos_pen - lslack;
  const double see_pos = see_stretch > 0 ? see_stretch : 0.0;
  const double f_see = kLinearStiffness * see_stretch + k_see * see_pos * see_pos;
  const double pee_stretch = lce - pee_slack;
  const double pee_pos = pee_stretch > 0 ? pee_stretch : 0.0;
  const double f_pee = kLinearStiffness * pee_stretch + k_pee * pee_pos * pee_pos;
  const double F = f_see / cos_pen - f_pee;  // what the CE and damper must carry along the fibres
  const double xfl = (lce * inv_lceopt - 1.0) * (1.0 / kForceLengthWidth);
  const double F0 = a * fmax * exp_nonpositive(-xfl * xfl);
  // Damping floor (muscle.cc): the CE's own damping at v = 0 is F0 (1+A)/(A vmax) = F0 damping_slope/fmax.
  const double missing_damping = damping_slope * (kLowActivation - F0 / fmax);
  const double b = b0 + (missing_damping > 0 ? missing_damping : 0.0);

  // Concentric (F <= F0): (b/A) v^2 - beta v - gamma = 0, root <= 0.
  const double alpha_c = b * (1.0 / kHillA);
  const double beta_c = F0 + b * vmax + F * (1.0 / kHillA);
  const double gamma_c = (F0 - F) * vmax;
  const double disc_c = std::sqrt(beta_c * beta_c + 4.0 * alpha_c * (gamma_c > 0 ? gamma_c : 0.0));
  const double v_c = beta_c > 0 ? -2.0 * (gamma_c > 0 ? gamma_c : 0.0) / (beta_c + disc_c)
                                : (beta_c - disc_c) / (2.0 * alpha_c);
  // Eccentric (F > F0): b v^2 + beta v - gamma = 0, root > 0.
  const double beta_e = kEccentricFmax * F0 + b * ecc_c - F;
  const double gamma_e = (F - F0) * ecc_c;
  const double disc_e = std::sqrt(beta_e * beta_e + 4.0 * b * (gamma_e > 0 ? gamma_e : 0.0));
  const double v_e = beta_e > 0 ? 2.0 * (gamma_e > 0 ? gamma_e : 0.0) / (beta_e + disc_e)
                                : (disc_e - beta_e) / (2.0 * b);
  *velocity = F <= F0 ? v_c : v_e;
  *force = f_see;
}

}  // namespace armrt
