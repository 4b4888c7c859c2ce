#include "armrt/simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ctime>
#include <stdexcept>

#include "armrt/clock.h"

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

Simulator::Simulator(const ModelDef& def, Integrator integ, double step, int n_sub) : integrator(integ), dt(step) {
  if (!(dt > 0)) throw std::invalid_argument("dt must be positive, got " + std::to_string(dt));
  model_init(model, def);
  data_reset(model, data, nullptr);
  set_integrator(integ, step, n_sub);
}

void Simulator::set_integrator(Integrator integ, double step, int n_sub) {
  if (!(step > 0)) throw std::invalid_argument("dt must be positive, got " + std::to_string(step));
  if (n_sub < 1) throw std::invalid_argument("substeps must be >= 1, got " + std::to_string(n_sub));
  integrator = integ;
  dt = step;
  substeps = n_sub;
  if (integrator == Integrator::kCvode) cvode_ = std::make_unique<CvodeIntegrator>(model, data);
  else cvode_.reset();
}

void Simulator::reset(const double* q, const double* qd, const double* activation) {
  const auto excitation = data.excitation;
  const auto hand_force = data.hand_force;
  const auto hand_moment = data.hand_moment;
  data_reset(model, data, q);
  data.excitation = excitation;
  data.hand_force = hand_force;
  data.hand_moment = hand_moment;
  if (qd) for (int j = 0; j < model.num_dofs; ++j) data.x[qd_offset(model) + j] = qd[j];
  if (activation) {
    double L[kMaxElements];
    model.def->muscle_lengths(&data.x[q_offset(model)], L);
    const int ia = act_offset(model), il = lce_offset(model);
    for (int i = 0; i < model.num_elements; ++i) {
      data.x[ia + i] = activation[i];
      data.x[il + i] = muscle_equilibrium_lce(model.element[i], model.fibre_damping, L[i], activation[i]);
    }
  }
  if (cvode_) cvode_->reinit();
}

bool Simulator::step(bool record) {
  if (data.status != Status::kOk) return false;
  // The one place TET is measured: the wall time of the whole control step, whatever the integrator
  // and however many substeps (the real-time runner reads data.tet.last_ns).
  const std::int64_t t0 = now_ns();
  bool ok = true;
  if (cvode_) {
    ok = cvode_->advance(dt);
  } else if (substeps == 1) {
    ok = armrt::step(model, data, integrator, dt, record);
  } else {
    const double h = dt / substeps;
    const double t_start = data.time;
    for (int k = 0; k < substeps && ok; ++k) ok = armrt::step(model, data, integrator, h, record && k == 0);
    if (ok) data.time = t_start + dt;  // no drift from adding dt / substeps repeatedly
  }
  data.tet.add(static_cast<double>(now_ns() - t0));
  return ok;
}

void Simulator::evaluate_outputs() { forward(model, data, data.x.data(), data.k1.data(), true); }

std::string Simulator::domain_error_message() const {
  char name[96];
  char what[192];
  const int k = data.bad_index, n = model.num_elements, ia = act_offset(model), il = lce_offset(model);
  if (data.bad_contact >= 0) {
    const GirdleDef& g = *model.def->girdle;
    std::snprintf(what, sizeof what, "girdle contact point %s is %.1f mm inside the thorax (more than %.0f mm)",
                  g.contact_point_names[data.bad_contact], -1e3 * data.bad_contact_distance, 1e3 * kMaxContactPenetration);
  } else {
    const double value = data.x[k];
    state_name(model, k, name, sizeof name);
    if (k < qd_offset(model)) {
      const DofParams& dof = model.def->dofs[k];
      std::snprintf(what, sizeof what, "%s = %.4g rad is more than %.2g rad beyond its range [%.4g, %.4g] rad", name,
                    value, kJointRangeMargin, dof.range_min, dof.range_max);
    } else if (k >= il && k < il + n) {
      const ElementConstants& e = model.element[k - il];
      std::snprintf(what, sizeof what, "fibre length %s = %.4g m is outside its physical range [%.4g, %.4g] m", name,
                    value, e.min_lce, e.max_lce);
    } else if (k >= ia) {
      std::snprintf(what, sizeof what, "%s = %.6g is outside [0, 1]", name, value);
    } else {
      std::snprintf(what, sizeof what, "%s = %.4g", name, value);
    }
  }
  char buf[384];
  std::snprintf(buf, sizeof buf,
                "simulation left the physical domain: %s at t = %.6f s (a step too large for integrator '%s', "
                "or inputs beyond the model)",
                what, data.bad_time, integrator_name(integrator));
  return buf;
}

std::string Simulator::error_message() const {
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
                    model.max_joint_speed, data.bad_time);
      return buf;
    case Status::kCvodeFailed:
      std::snprintf(buf, sizeof buf, "CVODE failed to advance at t = %.6f s", data.bad_time);
      return buf;
    case Status::kOutOfDomain:
      return domain_error_message();
    case Status::kUnstableStep: {
      const double rate = model.rest_fibre_rate, h = dt / substeps;
      const double h_max = explicit_stability_limit(integrator) / std::fabs(rate);
      // The substeps that hold this fibre: the validated default where that is enough (das2), else the
      // count that brings the step under h_max, which other stiff modes may still not allow (das3's girdle).
      const int needed = static_cast<int>(std::ceil(dt / h_max));
      const int validated = default_substeps(integrator, dt);
      if (needed <= validated)
        std::snprintf(buf, sizeof buf,
                      "step too large for integrator '%s': a %.3g ms step is unstable even for the resting arm "
                      "(the fibre of %s has eigenvalue %.3g 1/s at rest, stable for steps <= %.3g ms); use "
                      "integrator 'ros2', or substeps=%d (the validated %.3g ms step)",
                      integrator_name(integrator), 1e3 * h, model.def->elements[model.rest_fibre_element].name,
                      rate, 1e3 * h_max, validated, 1e3 * default_max_step(integrator));
      else
        std::snprintf(buf, sizeof buf,
                      "step too large for integrator '%s': a %.3g ms step is unstable even for the resting arm "
                      "(the fibre of %s has eigenvalue %.3g 1/s at rest, stable for steps <= %.3g ms); use "
                      "integrator 'ros2' or 'cvode': this model needs at least substeps=%d for that fibre alone "
                      "and was not validated with explicit steps",
                      integrator_name(integrator), 1e3 * h, model.def->elements[model.rest_fibre_element].name,
                      rate, 1e3 * h_max, needed);
      return buf;
    }
  }
  return "unknown error";
}

}  // namespace armrt
