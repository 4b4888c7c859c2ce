// A Model, its Data and an integrator: what the Python bindings and the real-time runner drive.
#pragma once

#include <memory>
#include <string>

#include "armrt/cvode.h"
#include "armrt/data.h"
#include "armrt/engine.h"
#include "armrt/model.h"
#include "armrt/registry.h"

namespace armrt {

Integrator parse_integrator(const std::string& name);  // "ros2", "ros2_adaptive", "euler", "rk4", "cvode"; throws std::invalid_argument
const char* integrator_name(Integrator integrator);
// Largest integration step (s) the integrator takes by default inside a control step: ROS2 1 ms (one
// step per 1 ms control step), its step-halving mode 2 ms, RK4 0.17 ms (6 per 1 ms), Euler 0.1 ms, inside
// what the solver studies found accurate on the paper's tasks (docs/engine.md); CVODE picks its own (inf).
double default_max_step(Integrator integrator);
// Substeps of at most default_max_step(integrator) that make up a control step dt.
int default_substeps(Integrator integrator, double dt);
// Whether the integrator's cost per step is fixed (usable for hard real time): not CVODE, not ros2_adaptive.
bool is_fixed_cost(Integrator integrator);

// dt is the control step: inputs are held and outputs reported once per dt. Fixed-step integrators
// take `substeps` steps of dt / substeps inside it (the model's short-tendon elements are too stiff
// for one RK4 step of 1 ms at low activation; see docs/experiments.md). data.tet holds the wall time
// of whole control steps: the task execution time that must stay below dt in real time.
class Simulator {
 public:
  Simulator(const ModelDef& def, Integrator integrator, double dt, int substeps = 1);

  // Joint angles (num_dofs, rad; nullptr: rest posture), velocities (nullptr: zero) and activations
  // (nullptr: zero); contractile elements start in static equilibrium at those activations.
  void reset(const double* q, const double* qd, const double* activation);
  // One control step; false on divergence (see data.status). Never allocates except with CVODE. With
  // record = false the outputs (forces, GH stability, ...) are not computed: evaluate_outputs() gives them.
  bool step(bool record = true);
  // Outputs (forces, GH stability, ...) at the current state, without advancing.
  void evaluate_outputs();
  // Describes data.status for an error message: which state, when.
  std::string error_message() const;
  std::string domain_error_message() const;  // the kOutOfDomain case of error_message()
  void set_integrator(Integrator integrator, double dt, int substeps = 1);

  Model model;
  Data data;
  Integrator integrator;
  double dt;
  int substeps = 1;

 private:
  std::unique_ptr<CvodeIntegrator> cvode_;
};

}  // namespace armrt
