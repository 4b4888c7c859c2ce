// forward(): the state derivative (paper eq. 1), the stages in order, one file each (as MuJoCo's
// mj_forward runs position, velocity, actuation, acceleration stages):
//   paths           q -> muscle-tendon lengths L, moment arms R            (generated polynomials)
//   muscles         u, L, R, lce, a -> da/dt, dlce/dt, F, tau_muscle        muscles.cc
//                   (elements a stimulation map drives: the stimulation stage's target and rate, stimulation.cc)
//   passive joints  q, qd -> tau_passive                                   passive_joints.cc
//   external loads  q, hand force/moment -> tau_ext                        external_loads.cc
//   girdle          q -> tau_girdle: scapulothoracic contact, conoid        girdle.cc (das3 only)
//   skeleton        q, qd, tau -> M(q), qdd from M qdd = tau + b(q, qd, g)  skeleton.cc
//   GH reaction     q, qd, qdd, F, hand load -> GH force, GHstab           gh_reaction.cc (record only)
//   kinematics      q -> thorax-humerus angles                             kinematics.cc (record only)
// With record, each stage's outputs go to Data's ARMRT_OUTPUTS fields (layouts.h).
#include <algorithm>

#include "armrt/engine.h"

namespace armrt {

void forward(const Model& m, Data& d, const double* x, double* xdot, bool record, StepJacobian* jac) {
  // Paths. The Jacobian keeps the path geometry for the step's linear solves.
  double L_local[kMaxElements];
  double R_local[kMaxDofs * kMaxElements];
  double* L = jac ? jac->muscle_length.data() : L_local;
  double* R = jac ? jac->moment_arm.data() : R_local;
  m.def->muscle_paths(x + q_offset(m), L, R);
  forward_from_paths(m, d, x, L, R, xdot, record, jac);
}

void forward_from_paths(const Model& m, Data& d, const double* x, const double* L, const double* R, double* xdot,
                        bool record, StepJacobian* jac) {
  const ModelDef& def = *m.def;
  const int n = m.num_elements, nq = m.num_dofs;
  const int iq = q_offset(m), iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  const double* q = x + iq;
  const double* qd = x + iqd;

  // Muscles.
  double force[kMaxElements];
  double tau_muscle[kMaxDofs];
  const ActivationDrive drive{d.stimulation_map.driven.data(), d.drive_target.data(), d.drive_rate.data()};
  muscle_dynamics(m, d.muscles, d.excitation.data(), L, R, x + ia, x + il, xdot + ia, xdot + il, force, tau_muscle, jac,
                  d.stimulation_map.num_channels > 0 ? &drive : nullptr);

  // Passive joints.
  double tau_passive[kMaxDofs];
  passive_joint_torque(def, q, qd, tau_passive);
  if (jac) passive_joint_stiffness(def, q, jac->dtau_passive_dq.data(), jac->dtau_passive_dqd.data());

  // External loads.
  double f_ext[3], t_ext[3], tau_ext[kMaxDofs];
  external_load(m, q, d.hand_force.data(), d.hand_moment.data(), f_ext, t_ext, tau_ext);

  // Girdle.
  double tau_girdle[kMaxDofs];
  GirdleState girdle;
  if (def.girdle) girdle_forces(m, q, tau_girdle, jac ? jac->dtau_girdle_dq.data() : nullptr, record ? &girdle : nullptr);
  else std::fill(tau_girdle, tau_girdle + nq, 0.0);

  // Skeleton.
  double tau[kMaxDofs];
  for (int j = 0; j < nq; ++j) tau[j] = tau_muscle[j] + tau_passive[j] + tau_ext[j] + tau_girdle[j] + d.applied_moment[j];
  double M[kMaxDofs * kMaxDofs];
  double qdd[kMaxDofs];
  skeleton_dynamics(m, d.settings.gravity.data(), q, qd, tau, M, qdd);
  if (jac) std::copy(M, M + nq * nq, jac->mass_matrix.begin());
  for (int j = 0; j < nq; ++j) {
    xdot[iq + j] = qd[j];
    xdot[iqd + j] = qdd[j];
  }

  if (!record) return;
  std::copy(q, q + nq, d.output_q.begin());
  std::copy(x, x + state_size(m), d.output_state.begin());
  output_loads_of(d, d.output_loads.data());
  d.output_settings_version = d.settings_version;
  d.outputs_computed = true;
  std::copy(L, L + n, d.muscle_length.begin());
  std::copy(force, force + n, d.muscle_force.begin());
  std::copy(xdot + il, xdot + il + n, d.fibre_velocity.begin());
  for (int j = 0; j < nq; ++j) {
    d.muscle_torque[j] = tau_muscle[j];
    d.passive_torque[j] = tau_passive[j];
    d.external_torque[j] = tau_ext[j];
    d.girdle_torque[j] = tau_girdle[j];
    d.qddot[j] = qdd[j];
  }
  hand_position_in_thorax(m, q, d.hand_position.data());
  if (def.girdle) {
    d.contact_distance = girdle.contact_distance;
    d.contact_force = girdle.contact_force;
    d.conoid_length = girdle.conoid_length;
    d.conoid_tension = girdle.conoid_tension;
  }
  // GH reaction.
  GHStability gh;
  gh_reaction(m, d.settings.gravity.data(), q, qd, qdd, force, f_ext, d.gh_force.data(), &gh);
  d.gh_angles = {gh.theta, gh.phi};
  d.gh_stab = gh.stab;
  d.gh_rim_direction = gh.rim_direction;
  d.gh_rim_margin = gh.rim_margin;
  // Kinematics.
  thorax_humerus_angles(m, q, d.thorax_humerus.data());
#ifdef ARMRT_EXTRA_OUTPUT_STAGES
  ARMRT_EXTRA_OUTPUT_STAGES(m, d, q);
#endif
}

}  // namespace armrt
