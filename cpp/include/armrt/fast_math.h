// Elementary functions without library calls or branches, so that loops over them vectorise and the
// generated dynamics do not spend their time in libm: exp on x <= 0 (the muscle force-length curve) and
// sin/cos of joint angles. Accurate to about one unit in the last place (tests/test_model.cc checks them
// against the C library).
#pragma once

#include <cstdint>
#include <cstring>

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

// sin(x) and cos(x) for |x| < 1e5 (joint angles): reduction to r = x - k pi/2, |r| <= pi/4 (Cody-Waite,
// pi/2 in two parts, exact for such k), Taylor polynomials to r^17 and r^16 (truncation below 1e-17),
// and the quadrant k mod 4 chosen by selects.
inline void sin_cos(double x, double* sin_x, double* cos_x) {
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  const double y = x * 0.63661977236758134 + kRound;  // x * 2/pi, rounded to an integer in the low bits
  const double k = y - kRound;
  std::int64_t ybits;
  std::memcpy(&ybits, &y, sizeof ybits);
  const int quadrant = static_cast<int>(ybits & 3);
  const double r = (x - k * 1.57079632673412561417e+00) - k * 6.07710050650619224932e-11;
  const double z = r * r;
  double ps = 1.0 / 355687428096000.0;  // 1/17!
  ps = ps * z - 1.0 / 1307674368000.0;
  ps = ps * z + 1.0 / 6227020800.0;
  ps = ps * z - 1.0 / 39916800.0;
  ps = ps * z + 1.0 / 362880.0;
  ps = ps * z - 1.0 / 5040.0;
  ps = ps * z + 1.0 / 120.0;
  ps = ps * z - 1.0 / 6.0;
  const double sr = r + r * z * ps;
  double pc = 1.0 / 20922789888000.0;  // 1/16!
  pc = pc * z - 1.0 / 87178291200.0;
  pc = pc * z + 1.0 / 479001600.0;
  pc = pc * z - 1.0 / 3628800.0;
  pc = pc * z + 1.0 / 40320.0;
  pc = pc * z - 1.0 / 720.0;
  pc = pc * z + 1.0 / 24.0;
  pc = pc * z - 0.5;
  const double cr = 1.0 + z * pc;
  const bool swap = quadrant & 1;
  const double s = swap ? cr : sr;
  const double c = swap ? sr : cr;
  *sin_x = (quadrant & 2) ? -s : s;
  *cos_x = ((quadrant + 1) & 2) ? -c : c;
}

}  // namespace armrt
