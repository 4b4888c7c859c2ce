// stepper.cc: (model, data, stepper, n) -> data advanced by n control steps, with TET; the integrators' names
// and defaults; what a failed step's status means, as a message.
#include "armrt/stepper.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ctime>
#include <stdexcept>

#include "armrt/clock.h"
#include "armrt/cvode.h"
#include "armrt/engine.h"

namespace armrt {

Integrator parse_integrator(const std::string& name) {
  if (name == "euler") return Integrator::kEuler;
  if (name == "rk4") return Integrator::kRk4;
  if (name == "cvode") return Integrator::kCvode;
  if (name == "ros2") return Integrator::kRos2;
  if (name == "ros2_adaptive") return Integrator::kRos2Adaptive;
  throw std::invalid_argument("unknown integrator '" + name +
                              "' (expected ros2, ros2_adaptive, euler, rk4 or cvode)");
}

const char* integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::kEuler: return "euler";
    case Integrator::kRk4: return "rk4";
    case Integrator::kCvode: return "cvode";
    case Integrator::kRos2: return "ros2";
    case Integrator::kRos2Adaptive: return "ros2_adaptive";
  }
  return "?";
}

double default_max_step(Integrator integrator) {
  switch (integrator) {
    case Integrator::kRos2: return 1e-3;
    case Integrator::kRos2Adaptive: return 2e-3;
    case Integrator::kRk4: return 1.7e-4;
    case Integrator::kEuler: return 1e-4;
    case Integrator::kCvode: break;
  }
  return std::numeric_limits<double>::infinity();
}

int default_substeps(Integrator integrator, double dt) {
  const double h = default_max_step(integrator);
  // A relative tolerance: dt = 1.0000001 ms is one 1 ms step, not two.
  return std::isinf(h) ? 1 : std::max(1, static_cast<int>(std::ceil(dt / h * (1.0 - 1e-6))));
}

bool is_fixed_cost(Integrator integrator) {
  return integrator != Integrator::kCvode && integrator != Integrator::kRos2Adaptive;
}

double explicit_stability_limit(Integrator integrator) {
  // Real stability intervals [-limit, 0] of the stability functions: Euler 1 + z; RK4 the degree-4
  // Taylor polynomial of exp(z) (|R(-2.785)| = 1).
  switch (integrator) {
    case Integrator::kEuler: return 2.0;
    case Integrator::kRk4: return 2.785;
    default: return std::numeric_limits<double>::infinity();
  }
}

Stepper::Stepper() = default;
Stepper::~Stepper() = default;
Stepper::Stepper(Stepper&&) noexcept = default;
Stepper& Stepper::operator=(Stepper&&) noexcept = default;

void stepper_init(const Model& m, Data& d, Stepper& s, Integrator integrator, double dt, int substeps) {
  if (!(dt > 0) || !(dt <= kMaxControlStep))
    throw std::invalid_argument("dt (the control step) must lie in (0, " + std::to_string(kMaxControlStep) +
                                "] s, got " + std::to_string(dt));
  if (substeps < 1 || substeps > kMaxSubsteps)
    throw std::invalid_argument("substeps must lie in [1, " + std::to_string(kMaxSubsteps) + "], got " +
                                std::to_string(substeps));
  s.integrator = integrator;
  s.dt = dt;
  s.substeps = substeps;
  s.ros2.path_history = PathHistory{};
  if (integrator == Integrator::kCvode) s.cvode = std::make_unique<CvodeIntegrator>(m, d);
  else s.cvode.reset();
}

void stepper_restart(const Model&, Data&, Stepper& s) {
  s.ros2.path_history = PathHistory{};
  if (s.cvode) s.cvode->reinit();
}

bool step(const Model& m, Data& d, Stepper& s, long n, bool record) {
  for (long c = 0; c < n; ++c) {
    if (d.status != Status::kOk) return false;
    // The one place TET is measured: the wall time of the whole control step, whatever the integrator
    // and however many substeps (the real-time runner reads data.tet.last_ns).
    const std::int64_t t0 = now_ns();
    bool ok = true;
    stimulation_advance(m, d, s.dt);  // the stimulation stage: its drive is held over the control step
    if (s.cvode) {
      ok = s.cvode->advance(s.dt);
    } else if (s.substeps == 1) {
      ok = integrate(m, d, s, s.dt, record);
    } else {
      const double h = s.dt / s.substeps;
      const double t_start = d.time;
      for (int k = 0; k < s.substeps && ok; ++k) ok = integrate(m, d, s, h, record && k == 0);
      if (ok) d.time = t_start + s.dt;  // no drift from adding dt / substeps repeatedly
    }
    d.tet.add(static_cast<double>(now_ns() - t0));
    if (!ok) return false;
  }
  return d.status == Status::kOk;
}

void evaluate_outputs(const Model& m, Data& d, Stepper& s) { forward(m, d, d.x.data(), s.scratch.data(), true); }

namespace {

std::string domain_error_message(const Model& model, const Data& data, const Stepper& s) {
  DomainCheck c;
  c.status = data.status;
  c.bad_index = data.bad_index;
  c.bad_contact = data.bad_contact;
  c.bad_contact_distance = data.bad_contact_distance;
  char buf[384];
  std::snprintf(buf, sizeof buf,
                "simulation left the physical domain: %s at t = %.6f s (a step too large for integrator '%s', "
                "or inputs beyond the model)",
                domain_problem(model, data, data.x.data(), c).c_str(), data.bad_time, integrator_name(s.integrator));
  return buf;
}

}  // namespace

std::string domain_problem(const Model& model, const Data& data, const double* x, const DomainCheck& c) {
  char name[96];
  char what[192];
  const int k = c.bad_index, n = model.num_elements, ia = act_offset(model), il = lce_offset(model);
  if (c.bad_contact >= 0) {
    const GirdleDef& g = *model.def->girdle;
    std::snprintf(what, sizeof what, "girdle contact point %s is %.1f mm inside the thorax (more than %.0f mm)",
                  g.contact_point_names[c.bad_contact], -1e3 * c.bad_contact_distance, 1e3 * kMaxContactPenetration);
  } else if (k < 0) {
    return "no state";
  } else {
    const double value = x[k];
    state_name(model, k, name, sizeof name);
    if (k < qd_offset(model)) {
      const DofParams& dof = model.def->dofs[k];
      std::snprintf(what, sizeof what, "%s = %.4g rad is more than %.2g rad beyond its range [%.4g, %.4g] rad", name,
                    value, kJointRangeMargin, dof.range_min, dof.range_max);
    } else if (k >= il && k < il + n) {
      const double min_lce = data.muscles.min_lce[k - il], max_lce = data.muscles.max_lce[k - il];
      std::snprintf(what, sizeof what, "fibre length %s = %.4g m is outside its physical range [%.4g, %.4g] m", name,
                    value, min_lce, max_lce);
    } else if (k >= ia) {
      std::snprintf(what, sizeof what, "%s = %.6g is outside [0, 1]", name, value);
    } else {
      std::snprintf(what, sizeof what, "%s = %.4g", name, value);
    }
  }
  return what;
}

std::string step_error_message(const Model& model, const Data& data, const Stepper& s) {
  char name[96];
  char buf[512];  // the explicit-step refusal below runs to about 330 characters
  switch (data.status) {
    case Status::kOk: return "";
    case Status::kNonFinite:
      std::snprintf(buf, sizeof buf, "simulation diverged: %s became non-finite at t = %.6f s",
                    state_name(model, data.bad_index, name, sizeof name), data.bad_time);
      return buf;
    case Status::kTooFast:
      std::snprintf(buf, sizeof buf,
                    "simulation diverged: %s = %.4g rad/s exceeds the bound %.4g rad/s at t = %.6f s",
                    state_name(model, data.bad_index, name, sizeof name), data.x[data.bad_index],
                    data.settings.max_joint_speed, data.bad_time);
      return buf;
    case Status::kCvodeFailed:
      std::snprintf(buf, sizeof buf, "CVODE failed to advance at t = %.6f s", data.bad_time);
      return buf;
    case Status::kOutOfDomain:
      return domain_error_message(model, data, s);
    case Status::kUnstableStep: {
      const double rate = data.rest_fibre_rate, h = s.dt / s.substeps;
      const double h_max = explicit_stability_limit(s.integrator) / std::fabs(rate);
      // The substeps that hold this fibre: the validated default where that is enough (das2), else the
      // count that brings the step under h_max, which other stiff modes may still not allow (das3's girdle).
      const int needed = static_cast<int>(std::ceil(s.dt / h_max));
      const int validated = default_substeps(s.integrator, s.dt);
      if (needed <= validated)
        std::snprintf(buf, sizeof buf,
                      "step too large for integrator '%s': a %.3g ms step is unstable even for the resting arm "
                      "(the fibre of %s has eigenvalue %.3g 1/s at rest, stable for steps <= %.3g ms); use "
                      "integrator 'ros2', or substeps=%d (the validated %.3g ms step)",
                      integrator_name(s.integrator), 1e3 * h, model.def->elements[data.rest_fibre_element].name,
                      rate, 1e3 * h_max, validated, 1e3 * default_max_step(s.integrator));
      else
        std::snprintf(buf, sizeof buf,
                      "step too large for integrator '%s': a %.3g ms step is unstable even for the resting arm "
                      "(the fibre of %s has eigenvalue %.3g 1/s at rest, stable for steps <= %.3g ms); use "
                      "integrator 'ros2' or 'cvode': this model needs at least substeps=%d for that fibre alone "
                      "and was not validated with explicit steps",
                      integrator_name(s.integrator), 1e3 * h, model.def->elements[data.rest_fibre_element].name,
                      rate, 1e3 * h_max, needed);
      return buf;
    }
  }
  return "unknown error";
}

}  // namespace armrt
