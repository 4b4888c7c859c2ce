// integrate.cc: (model, data, stepper, h) -> data advanced by one integration step of h (explicit Euler and
// RK4, the paper's; the linearly implicit ROS2 in ros2.cc), then checked against the physical domain.
// TET (task execution time) is measured around whole control steps by step() (stepper.cc).
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>

#include "armrt/engine.h"

namespace armrt {

const char* state_name(const Model& m, int index, char* buf, int buflen) {
  const int iqd = qd_offset(m), il = lce_offset(m), ia = act_offset(m);
  if (index < iqd) std::snprintf(buf, buflen, "q[%s]", m.def->dofs[index].name);
  else if (index < il) std::snprintf(buf, buflen, "qdot[%s]", m.def->dofs[index - iqd].name);
  else if (index < ia) std::snprintf(buf, buflen, "lce[%s]", m.def->elements[index - il].name);
  else std::snprintf(buf, buflen, "activation[%s]", m.def->elements[index - ia].name);
  return buf;
}

DomainCheck check_domain(const Model& m, const Data& d, const double* x) {
  DomainCheck c;
  const int ns = state_size(m);
  // Every step passes: one vectorised test of the whole state first, the search for the culprit only on
  // failure (both read the CE-length bounds from MuscleArrays).
  int nonfinite = 0;
#pragma omp simd reduction(| : nonfinite)
  for (int k = 0; k < ns; ++k) nonfinite |= !std::isfinite(x[k]);
  for (int k = 0; nonfinite && k < ns; ++k) {
    if (!std::isfinite(x[k])) {
      c.status = Status::kNonFinite;
      c.bad_index = k;
      return c;
    }
  }
  // A scapula driven into the thorax is ejected fast: name the cause before the speed it caused.
  if (const GirdleDef* g = m.def->girdle) {
    double p[(kMaxContactPoints + 2) * 3], J[(kMaxContactPoints + 2) * 3 * kMaxDofs];
    g->points(&x[q_offset(m)], p, J);
    for (int k = 0; k < g->num_contact_points; ++k) {
      const double dist = thorax_signed_distance(g->thorax, p + 3 * k);
      if (dist < -kMaxContactPenetration) {
        c.status = Status::kOutOfDomain;
        c.bad_contact = k;
        c.bad_contact_distance = dist;
        return c;
      }
    }
  }
  const int iqd = qd_offset(m);
  for (int j = 0; j < m.num_dofs; ++j) {
    if (std::fabs(x[iqd + j]) > d.settings.max_joint_speed) {
      c.status = Status::kTooFast;
      c.bad_index = iqd + j;
      return c;
    }
  }
  // The physical domain (model.h): an integrator that cannot take the step shows here long before the
  // joint angles are visibly wrong; the forces clamp lce at min_lce, so without this check a state below
  // it would go on silently.
  const int n = m.num_elements, iq = q_offset(m), il = lce_offset(m), ia = act_offset(m);
  const MuscleArrays& mc = d.muscles;
  int outside = 0;
#pragma omp simd reduction(| : outside)
  for (int i = 0; i < n; ++i) {
    const double lce = x[il + i], a = x[ia + i];
    outside |= (lce < mc.min_lce[i]) | (lce > mc.max_lce[i]) | (a < -kActivationTolerance) |
               (a > 1.0 + kActivationTolerance);
  }
  int bad = -1;
  for (int i = n - 1; outside && i >= 0; --i) {
    const double lce = x[il + i], a = x[ia + i];
    if (lce < mc.min_lce[i] || lce > mc.max_lce[i]) bad = il + i;
    if (a < -kActivationTolerance || a > 1.0 + kActivationTolerance) bad = ia + i;
  }
  for (int j = m.num_dofs - 1; j >= 0; --j) {
    const DofParams& dof = m.def->dofs[j];
    if (x[iq + j] < dof.range_min - kJointRangeMargin || x[iq + j] > dof.range_max + kJointRangeMargin)
      bad = iq + j;
  }
  if (bad >= 0) {
    c.status = Status::kOutOfDomain;
    c.bad_index = bad;
  }
  return c;
}

bool check_state(const Model& m, Data& d) {
  const DomainCheck c = check_domain(m, d, d.x.data());
  if (c.status == Status::kOk) return true;
  d.status = c.status;
  d.bad_index = c.bad_index;
  d.bad_contact = c.bad_contact;
  d.bad_contact_distance = c.bad_contact_distance;
  d.bad_time = d.time;
  return false;
}

bool integrate(const Model& m, Data& d, Stepper& s, double dt, bool record) {
  const Integrator integrator = s.integrator;
  // An explicit step beyond the stability limit of the model at rest cannot hold even the resting arm:
  // refuse it before producing any data (measured: RK4 at 1 ms otherwise runs for 0.3-0.9 s, up to tens
  // of degrees off CVODE, before anything diverges).
  if (dt * -d.rest_fibre_rate > explicit_stability_limit(integrator)) {
    d.status = Status::kUnstableStep;
    d.bad_index = lce_offset(m) + d.rest_fibre_element;
    d.bad_time = d.time;
    return false;
  }
  const int ns = state_size(m);
  double* x = d.x.data();
  switch (integrator) {
    case Integrator::kRos2:
      step_ros2(m, d, s.ros2, dt, record);
      break;
    case Integrator::kRos2Adaptive:
      step_ros2_adaptive(m, d, s.ros2, dt, record);
      break;
    case Integrator::kEuler: {
      ExplicitWorkspace& w = s.explicit_ws;
      forward(m, d, x, w.k1.data(), record);
      for (int k = 0; k < ns; ++k) x[k] += dt * w.k1[k];
      break;
    }
    default: {  // RK4 (CVODE is driven by step(), never by integrate())
      ExplicitWorkspace& w = s.explicit_ws;
      forward(m, d, x, w.k1.data(), record);
      double* xt = w.x_stage.data();
      for (int k = 0; k < ns; ++k) xt[k] = x[k] + 0.5 * dt * w.k1[k];
      forward(m, d, xt, w.k2.data(), false);
      for (int k = 0; k < ns; ++k) xt[k] = x[k] + 0.5 * dt * w.k2[k];
      forward(m, d, xt, w.k3.data(), false);
      for (int k = 0; k < ns; ++k) xt[k] = x[k] + dt * w.k3[k];
      forward(m, d, xt, w.k4.data(), false);
      const double h6 = dt / 6.0;
      for (int k = 0; k < ns; ++k) x[k] += h6 * (w.k1[k] + 2.0 * (w.k2[k] + w.k3[k]) + w.k4[k]);
    }
  }
  d.time += dt;
  return check_state(m, d);
}

}  // namespace armrt
