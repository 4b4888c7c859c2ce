// Recording a simulation as time series (the arrays of armrt.Result): one row per recorded control
// step, each row a consistent time point (the step's start state and the outputs forward() gave for
// it). Offline only: the rows live in std::vector, reserved once before the loop.
#pragma once

#include <vector>

#include "armrt/simulator.h"

namespace armrt {

struct Recording {
  int num_dofs = 0, num_elements = 0;
  int num_contact_points = 0;  // girdle contact points (das3: TS, AI); 0 for a fixed girdle
  // Per row: time (s); q, qdot (num_dofs); lce, activation, excitation, muscle_force, muscle_length
  // (num_elements); gh_force (3, N), gh_stab, gh_angles (theta, phi, rad), gh_rim_margin (rad),
  // gh_rim_direction (rad; both engine.h GHStability), hand_position (3, m, thorax),
  // thorax_humerus (3, rad), tet_ns (the step's TET; 0 for the final state); with girdle forces also
  // contact_distance (num_contact_points, m, negative: inside the thorax) and conoid_tension (N).
  std::vector<double> time, q, qdot, lce, activation, excitation, muscle_force, muscle_length, gh_force, gh_stab,
      gh_angles, gh_rim_margin, gh_rim_direction, hand_position, thorax_humerus, tet_ns, contact_distance, conoid_tension;
  long rows() const { return static_cast<long>(time.size()); }
};

// Steps s n_steps control steps. The excitation is row k of u (n_steps x num_elements), or its only
// row when held. Every record_every-th step is recorded, and the final state too when
// n_steps % record_every == 0. Stops early on divergence (s.data.status) or when stop(ctx) returns
// true (checked after every step; e.g. Ctrl-C in Python). Returns the number of steps done.
long simulate_recorded(Arm& s, const double* u, bool held, long n_steps, long record_every, Recording& r,
                       bool (*stop)(void*) = nullptr, void* ctx = nullptr);

}  // namespace armrt
