#include "armrt/batch.h"

#include <omp.h>

#include <stdexcept>

namespace armrt {

Batch::Batch(const ModelDef& def, int n, Integrator integrator, double dt, int substeps) {
  if (n < 1) throw std::invalid_argument("a batch needs at least one arm, got n = " + std::to_string(n));
  arms_.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) arms_.emplace_back(def, integrator, dt, substeps);
  newly_failed_.assign(static_cast<size_t>(n), 0);
}

int Batch::step(long steps, int num_threads, bool outputs) {
  const int n = size();
  if (num_threads < 1) num_threads = omp_get_max_threads();
  if (num_threads > n) num_threads = n;  // an idle thread would only spin at the barrier
  int failed = 0;
  // dynamic: arms that diverge (stop early) or run CVODE take uneven time. One arm per chunk keeps
  // every arm on one thread for the whole call, which is all determinism needs.
#pragma omp parallel for num_threads(num_threads) schedule(dynamic, 1) reduction(+ : failed)
  for (int i = 0; i < n; ++i) {
    Arm& s = arms_[i];
    newly_failed_[i] = 0;
    if (s.data.status != Status::kOk) continue;
    // Outputs are not recorded while stepping (they would be overwritten); evaluated once at the end.
    for (long k = 0; k < steps; ++k) {
      if (!s.step(false)) {
        newly_failed_[i] = 1;
        ++failed;
        break;
      }
    }
    if (outputs && s.data.status == Status::kOk) s.evaluate_outputs();
  }
  return failed;
}

void Batch::evaluate_outputs(int num_threads) {
  const int n = size();
  if (num_threads < 1) num_threads = omp_get_max_threads();
#pragma omp parallel for num_threads(num_threads) schedule(dynamic, 1)
  for (int i = 0; i < n; ++i)
    if (arms_[i].data.status == Status::kOk) arms_[i].evaluate_outputs();
}

int batch_default_threads() { return omp_get_max_threads(); }

}  // namespace armrt
