// arm.cc: (ModelDef, integrator, dt, substeps) -> an Arm on the shared Model at rest; reset to a posture.
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

}  // namespace armrt
