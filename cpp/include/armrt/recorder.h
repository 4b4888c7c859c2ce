// Recording a simulation as time series (the arrays of armrt.Result): one row per recorded control
// step, each row a consistent time point (the step's start state and the outputs forward() gave for
// it). Offline only: the rows live in std::vector, reserved once before the loop.
#pragma once

#include <array>
#include <vector>

#include "armrt/arm.h"

namespace armrt {

struct Recording {
  int num_dofs = 0, num_elements = 0;
  int num_contact_points = 0;  // girdle contact points (das3: TS, AI); 0 for a fixed girdle
  // One array per recorded channel (layouts.h Channel: time, the state blocks, excitation, the recorded outputs,
  // tet_ns), width[c] values per row, row after row. A girdle_only channel has width 0 without girdle forces.
  std::array<std::vector<double>, kNumChannels> channel;
  std::array<int, kNumChannels> width{};
  const std::vector<double>& operator[](Channel c) const { return channel[static_cast<int>(c)]; }
  long rows() const { return static_cast<long>((*this)[Channel::time].size()); }
};

// Steps s n_steps control steps. The excitation is row k of u (n_steps x num_elements), or its only
// row when held. Every record_every-th step is recorded, and the final state too when
// n_steps % record_every == 0. Stops early on divergence (s.data.status) or when stop(ctx) returns
// true (checked after every step; e.g. Ctrl-C in Python). Returns the number of steps done.
long simulate_recorded(Arm& s, const double* u, bool held, long n_steps, long record_every, Recording& r,
                       bool (*stop)(void*) = nullptr, void* ctx = nullptr);

}  // namespace armrt
