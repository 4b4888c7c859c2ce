// One simulated arm: the shared Model of its ModelDef, the arm's Data and its Stepper (Python's armrt.Arm
// holds the same three, plus its input checks). What the bindings, the batch and the real-time runner drive.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "armrt/data.h"
#include "armrt/model.h"
#include "armrt/registry.h"
#include "armrt/stepper.h"

namespace armrt {

class Arm {
 public:
  // An arm of def at its rest posture, with def's own settings; throws std::invalid_argument for a bad dt or
  // substeps (stepper_init).
  Arm(const ModelDef& def, Integrator integrator, double dt, int substeps = 1);
  Arm(Arm&&) noexcept = default;  // (a CVODE stepper is bound to this Data: move an Arm only before stepping it)

  // Joint angles (num_dofs, rad; nullptr: rest posture), velocities (nullptr: zero) and activations
  // (nullptr: zero); contractile elements start in static equilibrium at those activations. Settings and
  // inputs are kept; the integrator's memory is forgotten.
  void reset(const double* q, const double* qdot, const double* activation);
  // One control step (step(model, data, stepper, 1, record), stepper.h).
  bool step(bool record = true) { return armrt::step(model, data, stepper, 1, record); }
  // Relaxes the arm from its current state (Python's Arm.settle; the real-time runner's --settle): n_steps control
  // steps with zero excitation, under the hand load as set, then the clock back to 0 and the excitation as it
  // was. das3 starts at DAS3's equilibrium.mat posture, which is not this model's equilibrium (docs/das3.md).
  // False if a step failed (data.status says why) or `interrupted` (polled between steps; may be empty) returned
  // true: the excitation is restored, the clock is not reset, the state is the last completed step's.
  bool settle(std::int64_t n_steps, const std::function<bool()>& interrupted = {});
  // Outputs (forces, GH stability, ...) at the current state, without advancing: computed only if they do not
  // already describe it (outputs_current), so reading them twice costs one forward() at most.
  void evaluate_outputs() {
    if (!outputs_current(model, data)) armrt::evaluate_outputs(model, data, stepper);
  }
  // After a change of data.settings' strength or maximum activation (data_apply_settings).
  void apply_settings() { data_apply_settings(model, data); }
  std::string error_message() const { return step_error_message(model, data, stepper); }
  void set_integrator(Integrator integrator, double dt, int substeps = 1) {
    stepper_init(model, data, stepper, integrator, dt, substeps);
  }

  const Model& model;  // shared_model(def): one per ModelDef, never changed
  Data data;
  Stepper stepper;
};

}  // namespace armrt
