// Recording (recorder.h): moved out of the Python bindings so that it is one C++ loop, tested in C++.
#include "armrt/recorder.h"

#include <algorithm>

#include "armrt/engine.h"

namespace armrt {

namespace {

// One row: the state x at `time` and the outputs forward() left in s.data for that state.
void add_row(Recording& r, const Arm& s, const double* x, double time, double tet_ns) {
  const Model& m = s.model;
  const Data& d = s.data;
  const int n = m.num_elements, nq = m.num_dofs;
  auto put = [](std::vector<double>& v, const double* p, int k) { v.insert(v.end(), p, p + k); };
  r.time.push_back(time);
  put(r.q, x + q_offset(m), nq);
  put(r.qdot, x + qd_offset(m), nq);
  put(r.lce, x + lce_offset(m), n);
  put(r.activation, x + act_offset(m), n);
  put(r.excitation, d.excitation.data(), n);
  put(r.muscle_force, d.muscle_force.data(), n);
  put(r.muscle_length, d.muscle_length.data(), n);
  put(r.gh_force, d.gh_force.data(), 3);
  r.gh_stab.push_back(d.gh_stab);
  r.gh_angles.push_back(d.gh_theta);
  r.gh_angles.push_back(d.gh_phi);
  r.gh_rim_margin.push_back(d.gh_rim_margin);
  r.gh_rim_direction.push_back(d.gh_rim_direction);
  put(r.hand_position, d.hand_position.data(), 3);
  double angles[3];
  thorax_humerus_angles(m, x + q_offset(m), angles);
  put(r.thorax_humerus, angles, 3);
  r.tet_ns.push_back(tet_ns);
  if (r.num_contact_points > 0) {
    put(r.contact_distance, d.girdle.contact_distance.data(), r.num_contact_points);
    r.conoid_tension.push_back(d.girdle.conoid_tension);
  }
}

}  // namespace

long simulate_recorded(Arm& s, const double* u, bool held, long n_steps, long record_every, Recording& r,
                       bool (*stop)(void*), void* ctx) {
  const int n = s.model.num_elements, nq = s.model.num_dofs;
  r.num_dofs = nq;
  r.num_elements = n;
  r.num_contact_points = s.model.def->girdle ? s.model.def->girdle->num_contact_points : 0;
  const long n_rec = n_steps / record_every + 1;
  for (auto* v : {&r.time, &r.gh_stab, &r.gh_rim_margin, &r.gh_rim_direction, &r.tet_ns}) v->reserve(n_rec);
  for (auto* v : {&r.q, &r.qdot}) v->reserve(n_rec * nq);
  for (auto* v : {&r.lce, &r.activation, &r.excitation, &r.muscle_force, &r.muscle_length}) v->reserve(n_rec * n);
  for (auto* v : {&r.gh_force, &r.hand_position, &r.thorax_humerus}) v->reserve(n_rec * 3);
  r.gh_angles.reserve(n_rec * 2);
  r.contact_distance.reserve(n_rec * r.num_contact_points);
  r.conoid_tension.reserve(r.num_contact_points > 0 ? n_rec : 0);
  // Only a recorded step keeps a copy of its start state (its outputs describe that state).
  std::vector<double> x0(state_size(s.model));
  long done = 0;
  bool stopped = false;
  for (long k = 0; k < n_steps; ++k) {
    const double* uk = u + (held ? 0 : k) * n;
    std::copy(uk, uk + n, s.data.excitation.begin());
    const bool rec = k % record_every == 0;
    const double t0 = s.data.time;
    if (rec) std::copy(s.data.x.begin(), s.data.x.begin() + x0.size(), x0.begin());
    if (!s.step(rec)) break;
    ++done;
    if (rec) add_row(r, s, x0.data(), t0, s.data.tet.last_ns);
    if (stop && stop(ctx)) {
      stopped = true;
      break;
    }
  }
  if (!stopped && s.data.status == Status::kOk && n_steps % record_every == 0) {
    s.evaluate_outputs();
    add_row(r, s, s.data.x.data(), s.data.time, 0.0);
  }
  return done;
}

}  // namespace armrt
