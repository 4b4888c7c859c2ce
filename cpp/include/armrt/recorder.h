// Recording a simulation as time series (the arrays of armrt.Result): one row per recorded control
// step, each row a consistent time point (the step's start state and the outputs forward() gave for
// it). Offline only: the rows live in std::vector, reserved once before the loop, or in the caller's arrays
// (Recording::into: Arm.simulate's Result arrays, written once instead of copied twice more).
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
  // The caller's storage instead of `channel`: into[c] holds capacity rows of channel c's width (every channel of
  // non-zero width set, see recording_widths), rows written from row num_rows on. Null: the vectors above.
  std::array<double*, kNumChannels> into{};
  long capacity = 0;
  long num_rows = 0;
  const std::vector<double>& operator[](Channel c) const { return channel[static_cast<int>(c)]; }
  long rows() const { return num_rows; }
};

// The width (values per row) of each recorded channel for arm s: 0 for a girdle channel of a model without girdle
// forces and for a stimulation channel of an arm without a stimulation map.
std::array<int, kNumChannels> recording_widths(const Arm& s);

// Rows simulate_recorded writes for n_steps steps recorded every record_every-th (the final state included when
// n_steps % record_every == 0).
inline long recorded_rows(long n_steps, long record_every) {
  return (n_steps + record_every - 1) / record_every + (n_steps % record_every == 0 ? 1 : 0);
}

// Steps s n_steps control steps. The excitation is row k of u (n_steps x num_elements), or its only
// row when held. Every record_every-th step is recorded, and the final state too when
// n_steps % record_every == 0. Stops early on divergence (s.data.status) or when stop(ctx) returns
// true (checked after every step; e.g. Ctrl-C in Python). Returns the number of steps done. With r.into set,
// throws std::invalid_argument unless the rows fit (capacity - num_rows >= recorded_rows(n_steps, record_every)).
long simulate_recorded(Arm& s, const double* u, bool held, long n_steps, long record_every, Recording& r,
                       bool (*stop)(void*) = nullptr, void* ctx = nullptr);

}  // namespace armrt
