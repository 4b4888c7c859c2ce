// A Model, its Data and an integrator: what the Python bindings and the real-time runner drive.
#pragma once

#include <memory>
#include <string>

#include "armrt/cvode.h"
#include "armrt/data.h"
#include "armrt/engine.h"
#include "armrt/model.h"

namespace armrt {

// Generated models compiled into this build, by name ("das2"); nullptr if unknown.
const ModelDef* find_model(const std::string& name);
// Comma-separated names of the compiled-in models, for error messages.
std::string model_names();

Integrator parse_integrator(const std::string& name);  // "euler", "rk4", "cvode"; throws std::invalid_argument
const char* integrator_name(Integrator integrator);

// dt is the control step: inputs are held and outputs reported once per dt. Fixed-step integrators
// take `substeps` steps of dt / substeps inside it (the model's short-tendon elements are too stiff
// for one RK4 step of 1 ms at low activation; see docs/experiments.md). data.tet holds the wall time
// of whole control steps: the task execution time that must stay below dt in real time.
class Simulator {
 public:
  Simulator(const ModelDef& def, Integrator integrator, double dt, int substeps = 1);

  // Joint angles (5, rad; nullptr: rest posture), velocities (nullptr: zero) and activations
  // (nullptr: zero); contractile elements start in static equilibrium at those activations.
  void reset(const double* q, const double* qd, const double* activation);
  // One step; false on divergence (see data.status). Never allocates except with CVODE.
  bool step();
  // Outputs (forces, GH stability, ...) at the current state, without advancing.
  void evaluate_outputs();
  // Describes data.status for an error message: which state, when.
  std::string error_message() const;
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
