// Stage: inverse dynamics. (q, qd, qdd, hand load, gravity) -> tau_muscle (N m), the generalised forces the
// muscles must supply for forward() to give qdd: forward.cc's M(q) qdd = tau_muscle + tau_passive + tau_ext +
// tau_girdle + b(q, qd, g) solved for tau_muscle with the same stage functions, so a round trip is exact to
// rounding. Also the GH force of the loads other than the muscles (gh_reaction with zero tendon forces).
#include <algorithm>

#include "armrt/engine.h"

namespace armrt {

void inverse_dynamics(const Model& m, const double* gravity, const double* q, const double* qd, const double* qdd,
                      const double* hand_force, const double* hand_moment, InverseDynamics* out) {
  const ModelDef& def = *m.def;
  const int nq = m.num_dofs;
  double M[kMaxDofs * kMaxDofs];
  def.dynamics(q, qd, gravity, M, out->bias);
  passive_joint_torque(def, q, qd, out->passive);
  double f_ext[3], t_ext[3];
  external_load(m, q, hand_force, hand_moment, f_ext, t_ext, out->external);
  if (def.girdle) girdle_forces(m, q, out->girdle, nullptr, nullptr);
  else std::fill(out->girdle, out->girdle + nq, 0.0);
  for (int i = 0; i < nq; ++i) {
    double Mqdd = 0.0;
    for (int j = 0; j < nq; ++j) Mqdd += M[i * nq + j] * qdd[j];
    out->mass_times_qdd[i] = Mqdd;
    out->tau_muscle[i] = Mqdd - out->bias[i] - out->passive[i] - out->external[i] - out->girdle[i];
  }
  const double no_force[kMaxElements] = {};
  GHStability unused;
  gh_reaction(m, gravity, q, qd, qdd, no_force, f_ext, out->gh_force_without_muscles, &unused);
}

}  // namespace armrt
