// Stage: passive joints. (q, qd) -> tau_passive (N m), and its diagonal derivatives for the ROS2
// Jacobian: DAS3's linear spring and damper inside the range of motion, a stiff quadratic spring
// beyond it (docs/engine.md "Joints, loads, GH stability").
#include <cmath>

#include "armrt/engine.h"

namespace armrt {

namespace {

// Signed excursion beyond the range of motion (rad): q - range_max above it, q - range_min below,
// 0 inside. The torque and its derivative below are written in terms of it.
double range_excursion(const DofParams& dof, double q) {
  return q > dof.range_max ? q - dof.range_max : (q < dof.range_min ? q - dof.range_min : 0.0);
}

}  // namespace

void passive_joint_torque(const ModelDef& def, const double* q, const double* qd, double* tau) {
  for (int j = 0; j < def.num_dofs; ++j) {
    const DofParams& dof = def.dofs[j];
    const double e = range_excursion(dof, q[j]);
    tau[j] = -def.passive_stiffness_inside * (q[j] - dof.rest) - def.passive_damping * qd[j] -
             def.passive_stiffness_outside * e * std::fabs(e);
  }
}

void passive_joint_stiffness(const ModelDef& def, const double* q, double* dtau_dq, double* dtau_dqd) {
  for (int j = 0; j < def.num_dofs; ++j) {
    const double e = range_excursion(def.dofs[j], q[j]);
    dtau_dq[j] = -def.passive_stiffness_inside - 2.0 * def.passive_stiffness_outside * std::fabs(e);
    dtau_dqd[j] = -def.passive_damping;
  }
}

}  // namespace armrt
