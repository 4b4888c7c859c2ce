// SUNDIALS CVODE (BDF, Newton with a dense Jacobian by finite differences): the accurate reference
// integrator. Not for the real-time loop: it allocates at setup and its step cost varies.
#pragma once

#include "armrt/data.h"
#include "armrt/model.h"

namespace armrt {

class CvodeIntegrator {
 public:
  CvodeIntegrator(const Model& m, Data& d, double rtol = 1e-8, double atol = 1e-10);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;
  // Re-reads d.x and d.time (after a reset or an external change of state).
  void reinit();
  // Advances to d.time + dt with the current inputs held; outputs of d describe the state at the
  // start of the interval, as with the fixed-step integrators. Returns false and sets d.status on failure.
  bool advance(double dt);
  long num_steps() const;

 private:
  const Model& m_;
  Data& d_;
  void* ctx_ = nullptr;  // SUNContext
  void* y_ = nullptr;    // N_Vector
  void* A_ = nullptr;    // SUNMatrix
  void* ls_ = nullptr;   // SUNLinearSolver
  void* mem_ = nullptr;  // CVODE memory
  void* user_ = nullptr;
  bool have_inputs_ = false;
  double last_excitation_[kMaxElements] = {};
  double last_load_[6 + kMaxDofs] = {};  // hand force, hand moment, applied moments
  double xdot_scratch_[kMaxState] = {};  // the derivative of the outputs' forward(), discarded
};

}  // namespace armrt
