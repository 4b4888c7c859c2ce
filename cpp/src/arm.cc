// arm.cc: (ModelDef, integrator, dt, substeps) -> an Arm on the shared Model at rest; reset to a posture; settled.
#include "armrt/arm.h"

#include "armrt/engine.h"
#include "armrt/registry.h"

namespace armrt {

Arm::Arm(const ModelDef& def, Integrator integrator, double dt, int substeps) : model(shared_model(def)) {
  data_init(model, data);
  stepper_init(model, data, stepper, integrator, dt, substeps);
}

void Arm::reset(const double* q, const double* qdot, const double* activation) {
  data_reset(model, data, q);
  if (qdot)
    for (int j = 0; j < model.num_dofs; ++j) data.x[qd_offset(model) + j] = qdot[j];
  if (activation) {
    double L[kMaxElements];
    model.def->muscle_lengths(&data.x[q_offset(model)], L);
    const int ia = act_offset(model), il = lce_offset(model);
    for (int i = 0; i < model.num_elements; ++i) {
      data.x[ia + i] = activation[i];
      data.x[il + i] = muscle_equilibrium_lce(data_element(model, data, i), model.fibre_damping, L[i], activation[i]);
    }
  }
  stepper_restart(model, data, stepper);
}

bool Arm::settle(std::int64_t n_steps, const std::function<bool()>& interrupted) {
  const auto held = data.excitation;  // already capped (data_set_excitation): restoring it changes nothing else
  const std::array<double, kMaxElements> zero{};
  data_set_excitation(model, data, zero.data());
  bool ok = true;
  for (std::int64_t k = 0; k < n_steps && ok; ++k) {
    // No outputs while stepping: they are computed when read (evaluate_outputs).
    ok = step(false);
    if (ok && interrupted && interrupted()) ok = false;
  }
  data_set_excitation(model, data, held.data());
  if (ok) data.time = 0.0;
  return ok;
}

}  // namespace armrt
