// Many independent arms of one model stepped together across threads (OpenMP): offline sweeps,
// optimisation and vectorised reinforcement-learning environments: one shared Model and n arms, each its own
// Data and Stepper (arm.h), stepped with step(), so every integrator works here and each
// arm's trajectory is bit-identical to stepping it alone, whatever the thread count: arms share no
// state, and each arm is advanced by one thread at a time in its own sequential order.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "armrt/arm.h"

namespace armrt {

class Batch {
 public:
  // n arms of `def`, each at the rest posture; throws std::invalid_argument for n < 1 or a bad dt.
  Batch(const ModelDef& def, int n, Integrator integrator, double dt, int substeps = 1);
  Batch(const Batch&) = delete;             // CVODE steppers keep pointers into their arm's Data
  Batch& operator=(const Batch&) = delete;

  int size() const { return static_cast<int>(arms_.size()); }
  Arm& arm(int i) { return arms_[i]; }
  const Arm& arm(int i) const { return arms_[i]; }
  // Bytes from one arm to the next: the stride of zero-copy (n, ...) views.
  static constexpr std::ptrdiff_t stride() { return sizeof(Arm); }

  // Advances each arm whose status is kOk by up to `steps` control steps on `num_threads` threads
  // (< 1: OpenMP's default; never more than the arms). An arm that diverges stops there; the others
  // go on. With `outputs`, each live arm's outputs (forces, hand position, GH stability) are evaluated
  // at its final state; without, they are left as they were (Arm::step(false)).
  // Writes 1 to newly_failed[i] for each arm that diverged during this call (0 otherwise) and
  // returns how many did. No heap allocation after the first call (OpenMP keeps its thread pool).
  int step(long steps, int num_threads, bool outputs);

  // Evaluates the outputs of every live arm at its current state (in parallel).
  void evaluate_outputs(int num_threads);

  const std::vector<unsigned char>& newly_failed() const { return newly_failed_; }

 private:
  std::vector<Arm> arms_;            // reserved once, never reallocated
  std::vector<unsigned char> newly_failed_;
};

// OpenMP's default thread count (OMP_NUM_THREADS, else the cores available).
int batch_default_threads();

}  // namespace armrt
