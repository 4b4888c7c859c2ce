// Stage: GH reaction. (q, qd, qdd, tendon forces F, hand load) -> force of the humeral head on the
// glenoid (scapula frame) and its stability: the muscle forces along their lines of action, the hand
// load, the arm's weight minus its mass times acceleration (docs/conventions.md).
#include <cmath>

#include "armrt/engine.h"

namespace armrt {

void gh_stability(const ModelDef& def, const double* f, double* theta, double* phi, double* stab) {
  double fn = 0, fmaj = 0, fmin = 0;
  for (int k = 0; k < 3; ++k) {
    fn += f[k] * def.glenoid_normal[k];
    fmaj += f[k] * def.glenoid_major_axis[k];
    fmin += f[k] * def.glenoid_minor_axis[k];
  }
  *theta = std::atan2(fmaj, fn);
  *phi = std::atan2(fmin, fn);
  const double rt = *theta / def.rim_half_angle_major, rp = *phi / def.rim_half_angle_minor;
  *stab = rt * rt + rp * rp;
}

void gh_reaction(const Model& m, const double* q, const double* qd, const double* qdd, const double* force,
                 const double* f_ext_scapula, double* gh_force, double* theta, double* phi, double* stab) {
  const ModelDef& def = *m.def;
  const int nq = m.num_dofs, n = m.num_elements;
  double dir[kMaxElements * 3];
  def.gh_directions(q, dir);
  double A[3 * kMaxDofs], c[3];
  def.arm_momentum_rate(q, qd, A, c);
  for (int k = 0; k < 3; ++k) {
    double Aqdd = 0.0;
    for (int j = 0; j < nq; ++j) Aqdd += A[k * nq + j] * qdd[j];
    const double inertial = Aqdd + c[k];
    double fk = f_ext_scapula[k] + def.arm_mass * m.gravity_scapula[k] - inertial;
    for (int i = 0; i < n; ++i) fk += force[i] * dir[i * 3 + k];
    gh_force[k] = fk;
  }
  gh_stability(def, gh_force, theta, phi, stab);
}

}  // namespace armrt
