// Shoulder-girdle passive forces of the DAS3 model: scapulothoracic contact of the TS and AI landmarks on
// the thorax ellipsoid, and the conoid ligament. Smooth, conservative force laws with DAS3's parameters
// (model_struct.mat: thorax_center, thorax_radii, scap_thorax_k, scap_thorax_eps; conoid_origin,
// conoid_insertion, conoid_length, conoid_stiffness, conoid_eps); their derivation is in docs/das3.md.
// Header-only free functions on plain structs, no allocation: for the real-time step and its Jacobian.
#pragma once

#include <cmath>

namespace armrt {

// Thorax ellipsoid and contact parameters. Points are in the thorax frame (m).
struct ThoraxEllipsoid {
  double centre[3];  // thorax_center (m)
  double radii[3];   // thorax_radii (m)
  double k;          // scap_thorax_k: penalty stiffness; the force is k (rx^2+ry^2+rz^2)/2 per unit of grad f
  double eps;        // scap_thorax_eps: smoothing width in units of the ellipsoid function f (dimensionless)
};

// Smooth min(f, 0) = (f - sqrt(f^2 + eps^2)) / 2, written without cancellation on either side, and its
// derivative (1 - f / sqrt(f^2 + eps^2)) / 2 in (0, 1).
inline double smooth_negative_part(double f, double eps, double* d_df) {
  const double r = std::sqrt(f * f + eps * eps);
  *d_df = 0.5 * (1.0 - f / r);
  return f <= 0.0 ? 0.5 * (f - r) : -0.5 * eps * eps / (f + r);
}

// Ellipsoid function f(p) = sum ((p_i - c_i) / r_i)^2 - 1: negative inside the thorax, zero on its surface.
inline double thorax_ellipsoid_function(const ThoraxEllipsoid& e, const double p[3]) {
  double f = -1.0;
  for (int i = 0; i < 3; ++i) {
    const double u = (p[i] - e.centre[i]) / e.radii[i];
    f += u * u;
  }
  return f;
}

// First-order signed distance (m) of p from the ellipsoid surface, f / |grad f|: negative inside; exact on
// the surface, within a few percent for the millimetres a contact point penetrates.
inline double thorax_signed_distance(const ThoraxEllipsoid& e, const double p[3]) {
  double grad2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double gi = 2.0 * (p[i] - e.centre[i]) / (e.radii[i] * e.radii[i]);
    grad2 += gi * gi;
  }
  return thorax_ellipsoid_function(e, p) / std::sqrt(grad2);
}

// Contact force on a scapula point at p: F = -K m(f) grad f with K = k (rx^2 + ry^2 + rz^2) / 2 and
// m(f) the smooth negative part of f, so F points out of the thorax along the surface normal, grows
// linearly with penetration and fades within about eps of the surface outside. It is -grad of
// scapulothoracic_potential. Outputs F (N, thorax frame) and, if dF_dp is not null, dF/dp (3x3
// row-major, N/m, symmetric); returns f.
inline double scapulothoracic_contact(const ThoraxEllipsoid& e, const double p[3], double F[3], double* dF_dp) {
  const double K = 0.5 * e.k * (e.radii[0] * e.radii[0] + e.radii[1] * e.radii[1] + e.radii[2] * e.radii[2]);
  double g[3], h[3];  // grad f and the diagonal Hessian of f
  for (int i = 0; i < 3; ++i) {
    h[i] = 2.0 / (e.radii[i] * e.radii[i]);
    g[i] = h[i] * (p[i] - e.centre[i]);
  }
  const double f = thorax_ellipsoid_function(e, p);
  double dm;
  const double m = smooth_negative_part(f, e.eps, &dm);
  for (int i = 0; i < 3; ++i) F[i] = -K * m * g[i];
  if (dF_dp != nullptr) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) dF_dp[3 * i + j] = -K * (dm * g[i] * g[j] + (i == j ? m * h[i] : 0.0));
  }
  return f;
}

// Potential energy (J) of the contact at p, zero on the ellipsoid surface: K P(f) with
// P(f) = (f^2 - f sqrt(f^2 + eps^2) - eps^2 asinh(f / eps)) / 4, whose derivative is the smooth negative part.
inline double scapulothoracic_potential(const ThoraxEllipsoid& e, const double p[3]) {
  const double K = 0.5 * e.k * (e.radii[0] * e.radii[0] + e.radii[1] * e.radii[1] + e.radii[2] * e.radii[2]);
  const double f = thorax_ellipsoid_function(e, p);
  const double r = std::sqrt(f * f + e.eps * e.eps);
  const double f_minus_r_times_f = f <= 0.0 ? f * (f - r) : -f * e.eps * e.eps / (f + r);
  return 0.25 * K * (f_minus_r_times_f - e.eps * e.eps * std::asinh(f / e.eps));
}

// Conoid ligament from the clavicle (origin) to the scapula (insertion).
struct ConoidLigament {
  double origin[3];     // conoid_origin, clavicle frame (m)
  double insertion[3];  // conoid_insertion, scapula frame (m)
  double length;        // conoid_length: slack length (m)
  double stiffness;     // conoid_stiffness (N/m) beyond slack
  double eps;           // conoid_eps: smoothing width of the slack-to-taut transition (m)
};

// Tension T(L) = stiffness * (d + sqrt(d^2 + eps^2)) / 2 with d = L - length: a smooth max(0, stiffness d),
// eps * stiffness / 2 at the slack length. Returns T (N) and dT/dL (N/m) if dT_dL is not null.
inline double conoid_tension(const ConoidLigament& c, double L, double* dT_dL) {
  const double d = L - c.length;
  const double r = std::sqrt(d * d + c.eps * c.eps);
  if (dT_dL != nullptr) *dT_dL = 0.5 * c.stiffness * (1.0 + d / r);
  return d >= 0.0 ? 0.5 * c.stiffness * (d + r) : 0.5 * c.stiffness * c.eps * c.eps / (r - d);
}

// Elastic energy (J): stiffness (d^2 + d sqrt(d^2 + eps^2) + eps^2 asinh(d / eps)) / 4, zero at d = 0.
inline double conoid_potential(const ConoidLigament& c, double L) {
  const double d = L - c.length;
  const double r = std::sqrt(d * d + c.eps * c.eps);
  const double d_plus_r_times_d = d >= 0.0 ? d * (d + r) : d * c.eps * c.eps / (r - d);
  return 0.25 * c.stiffness * (d_plus_r_times_d + c.eps * c.eps * std::asinh(d / c.eps));
}

// Force of the ligament on its insertion point xi, pulled toward the origin point xo (both in one frame, m):
// F = -T(L) u with u = (xi - xo) / L; the origin gets -F. dF_dxi (3x3 row-major, N/m, symmetric, may be
// null) = -(dT/dL u u^T + T / L (I - u u^T)). Returns L (m). L must be positive (the points are
// centimetres apart in every posture of the model).
inline double conoid_force(const ConoidLigament& c, const double xo[3], const double xi[3], double F[3],
                           double* dF_dxi) {
  double u[3];
  for (int i = 0; i < 3; ++i) u[i] = xi[i] - xo[i];
  const double L = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& v : u) v /= L;
  double dT;
  const double T = conoid_tension(c, L, &dT);
  for (int i = 0; i < 3; ++i) F[i] = -T * u[i];
  if (dF_dxi != nullptr) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        dF_dxi[3 * i + j] = -(dT * u[i] * u[j] + T / L * ((i == j ? 1.0 : 0.0) - u[i] * u[j]));
  }
  return L;
}

}  // namespace armrt
