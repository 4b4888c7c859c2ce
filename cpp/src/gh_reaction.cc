// Stage: GH reaction. (q, qd, qdd, tendon forces F, hand load) -> force of the humeral head on the
// glenoid (scapula frame) and its stability: the muscle forces along their lines of action, the hand
// load, the arm's weight minus its mass times acceleration (docs/conventions.md). The lines of action are
// in the scapula frame already; the load, weight and inertial force are in the base frame and, when the
// scapula moves (das3), are turned into the scapula's frame at q.
#include <cmath>

#include "armrt/engine.h"

namespace armrt {

void gh_rim(double theta, double phi, double theta_a, double phi_a, double* direction, double* margin) {
  // The rim along psi, from the unit direction (cos psi, sin psi) = (theta, phi) / rho rather than from
  // cos(psi) and sin(psi): no further transcendental call, and with rho = 0 taken as psi = 0 (atan2(0, -0)
  // would give pi) the margin there is theta_a, the rim's radius along the major axis.
  const double rho = std::hypot(theta, phi);
  double c = 1.0, sn = 0.0;
  *direction = 0.0;
  if (rho > 0.0) {
    c = theta / rho;
    sn = phi / rho;
    *direction = std::atan2(phi, theta);
  }
  *margin = 1.0 / std::sqrt(c * c / (theta_a * theta_a) + sn * sn / (phi_a * phi_a)) - rho;
}

GHStability gh_stability(const ModelDef& def, const double* f) {
  double fn = 0, fmaj = 0, fmin = 0;
  for (int k = 0; k < 3; ++k) {
    fn += f[k] * def.glenoid_normal[k];
    fmaj += f[k] * def.glenoid_major_axis[k];
    fmin += f[k] * def.glenoid_minor_axis[k];
  }
  GHStability s;
  s.theta = std::atan2(fmaj, fn);
  s.phi = std::atan2(fmin, fn);
  const double ta = def.rim_half_angle_major, pa = def.rim_half_angle_minor;
  const double rt = s.theta / ta, rp = s.phi / pa;
  s.stab = rt * rt + rp * rp;
  gh_rim(s.theta, s.phi, ta, pa, &s.rim_direction, &s.rim_margin);
  return s;
}

void gh_reaction(const Model& m, const double* gravity, const double* q, const double* qd, const double* qdd, const double* force,
                 const double* f_ext_base, double* gh_force, GHStability* stab) {
  const ModelDef& def = *m.def;
  const int nq = m.num_dofs, n = m.num_elements;
  double dir[kMaxElements * 3];
  def.gh_directions(q, dir);
  double A[3 * kMaxDofs], c[3];
  def.arm_momentum_rate(q, qd, A, c);
  double f_base[3];
  for (int k = 0; k < 3; ++k) {
    double Aqdd = 0.0;
    for (int j = 0; j < nq; ++j) Aqdd += A[k * nq + j] * qdd[j];
    f_base[k] = f_ext_base[k] + def.arm_mass * gravity[k] - (Aqdd + c[k]);
  }
  double f_scapula[3] = {f_base[0], f_base[1], f_base[2]};
  if (def.scapula_body >= 0) {
    double R[kMaxBodies * 9], p[kMaxBodies * 3];
    def.body_poses(q, R, p);
    const double* Rs = R + 9 * def.scapula_body;  // columns = scapula axes in the base frame
    for (int k = 0; k < 3; ++k) f_scapula[k] = Rs[k] * f_base[0] + Rs[3 + k] * f_base[1] + Rs[6 + k] * f_base[2];
  }
  // The muscles' sum as one vectorised pass (three running sums over 138 elements were dependent chains).
  double fx = 0.0, fy = 0.0, fz = 0.0;
#pragma omp simd reduction(+ : fx, fy, fz)
  for (int i = 0; i < n; ++i) {
    fx += force[i] * dir[i * 3];
    fy += force[i] * dir[i * 3 + 1];
    fz += force[i] * dir[i * 3 + 2];
  }
  gh_force[0] = f_scapula[0] + fx;
  gh_force[1] = f_scapula[1] + fy;
  gh_force[2] = f_scapula[2] + fz;
  *stab = gh_stability(def, gh_force);
}

}  // namespace armrt
