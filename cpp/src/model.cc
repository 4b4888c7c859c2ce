#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "armrt/data.h"
#include "armrt/engine.h"

namespace armrt {

namespace {

// The stiffest CE mode of the resting arm under d's settings (Data::rest_fibre_rate).
void find_rest_fibre_rate(const Model& m, Data& d) {
  const ModelDef& def = *m.def;
  double q[kMaxDofs], L[kMaxElements];
  for (int j = 0; j < def.num_dofs; ++j) q[j] = def.dofs[j].rest;
  def.muscle_lengths(q, L);
  d.rest_fibre_rate = 0;
  d.rest_fibre_element = 0;
  for (int i = 0; i < m.num_elements; ++i) {
    const ElementConstants e = data_element(m, d, i);
    const double lce = muscle_equilibrium_lce(e, m.fibre_damping, L[i], 0.0);
    MuscleDerivatives der;
    muscle_element_derivatives(e, m.fibre_damping, L[i], lce, 0.0, &der);
    if (der.dvel_dlce < d.rest_fibre_rate) {
      d.rest_fibre_rate = der.dvel_dlce;
      d.rest_fibre_element = i;
    }
  }
}

}  // namespace

ElementConstants element_constants(const ElementParams& p, double strength_scale, double max_activation) {
  ElementConstants e{};
  e.strength_scale = strength_scale;
  e.max_activation = max_activation;
  e.fmax = p.fmax * strength_scale;
  e.lceopt = p.lceopt;
  e.lslack = p.lslack;
  e.thickness = p.lceopt * std::sin(p.pennopt);
  e.vmax = p.vmax * p.lceopt;
  const double tendon_stretch_at_fmax = kTendonStrainAtFmax * p.lslack;
  e.k_see = e.fmax / (tendon_stretch_at_fmax * tendon_stretch_at_fmax);
  const double pee_stretch_at_fmax = kForceLengthWidth * p.lceopt;
  e.k_pee = e.fmax / (pee_stretch_at_fmax * pee_stretch_at_fmax);
  e.pee_slack = p.peeslack * p.lceopt;
  e.c2 = 1.0 / p.tdeact;
  e.c1 = 1.0 / p.tact - e.c2;
  // The eccentric branch (gmax v + c)/(v + c) has slope (gmax - 1)/c at v = 0; matching the concentric
  // slope (1 + A)/(A vmax) keeps dF/dv continuous, which the explicit velocity inversion relies on.
  e.ecc_c = (kEccentricFmax - 1.0) * kHillA * e.vmax / (1.0 + kHillA);
  e.damping_slope = e.fmax * (1.0 + kHillA) / (kHillA * e.vmax);
  e.inv_lceopt = 1.0 / p.lceopt;
  // Fibres cannot be shorter than the muscle is thick; the floor also keeps 1/cos(pennation) finite.
  e.min_lce = std::max(1.001 * e.thickness, 0.05 * p.lceopt);
  e.compress_length = std::max(kCompressOnset * p.lceopt, e.min_lce + kCompressMinSpan * p.lceopt);
  const double compress_span = e.compress_length - e.min_lce;
  e.k_compress = kCompressForceAtMin * e.fmax / (compress_span * compress_span);
  e.max_lce = e.pee_slack + std::sqrt(kMaxPeeForce) * pee_stretch_at_fmax;
  return e;
}

ElementConstants data_element(const Model& m, const Data& d, int i) {
  return element_constants(m.def->elements[i], d.settings.strength_scale[i], d.settings.max_activation[i]);
}

void data_set_excitation(const Model& m, Data& d, const double* u) {
  for (int i = 0; i < m.num_elements; ++i) d.excitation[i] = capped_excitation(u[i], d.muscles.max_activation[i]);
}

void data_apply_settings(const Model& m, Data& d) {
  const ArmSettings& st = d.settings;
  for (int i = 0; i < m.num_elements; ++i) {
    const char* name = m.def->elements[i].name;
    if (!(st.strength_scale[i] >= 0.0) || !std::isfinite(st.strength_scale[i]))
      throw std::invalid_argument(std::string("strength of ") + name + " must be finite and >= 0, got " +
                                  std::to_string(st.strength_scale[i]));
    if (!(st.max_activation[i] >= 0.0 && st.max_activation[i] <= 1.0))
      throw std::invalid_argument(std::string("max_activation of ") + name + " must lie in [0, 1], got " +
                                  std::to_string(st.max_activation[i]));
  }
  if (!(st.max_joint_speed > 0.0))
    throw std::invalid_argument("max_joint_speed must be positive, got " + std::to_string(st.max_joint_speed));
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(st.gravity[k])) throw std::invalid_argument("gravity must be finite");
  MuscleArrays& a = d.muscles;
  for (int i = 0; i < m.num_elements; ++i) {
    const ElementConstants e = data_element(m, d, i);
    a.fmax[i] = e.fmax, a.inv_lceopt[i] = e.inv_lceopt, a.lslack[i] = e.lslack, a.thickness[i] = e.thickness;
    a.min_lce[i] = e.min_lce, a.vmax[i] = e.vmax, a.k_see[i] = e.k_see, a.k_pee[i] = e.k_pee;
    a.pee_slack[i] = e.pee_slack, a.compress_length[i] = e.compress_length, a.k_compress[i] = e.k_compress;
    a.ecc_c[i] = e.ecc_c, a.damping_slope[i] = e.damping_slope, a.c1[i] = e.c1, a.c2[i] = e.c2;
    a.max_activation[i] = e.max_activation;
    a.inv_k_see[i] = 1.0 / e.k_see;
    a.inv_taut_stretch[i] = 1.0 / (0.1 * kTendonStrainAtFmax * e.lslack);
    a.max_lce[i] = e.max_lce;
  }
  find_rest_fibre_rate(m, d);
  data_set_excitation(m, d, d.excitation.data());  // the held excitation stays what the dynamics use
  d.settings_applied = true;
  ++d.settings_version;
}

bool outputs_current(const Model& m, const Data& d) {
  if (!d.outputs_computed || d.output_settings_version != d.settings_version) return false;
  std::array<double, 9 + kMaxDofs> loads;
  output_loads_of(d, loads.data());
  // Bitwise: a state that differs in any bit (or a NaN) is another state.
  return std::memcmp(loads.data(), d.output_loads.data(), sizeof loads) == 0 &&
         std::memcmp(d.x.data(), d.output_state.data(), sizeof(double) * state_size(m)) == 0;
}

void model_init(Model& m, const ModelDef& def) {
  const std::string name = def.name ? def.name : "?";
  if (def.num_dofs < 1 || def.num_dofs > kMaxDofs)
    throw std::invalid_argument("model '" + name + "' has " + std::to_string(def.num_dofs) +
                                " DOFs; the engine takes 1 to " + std::to_string(kMaxDofs));
  if (def.num_elements < 1 || def.num_elements > kMaxElements)
    throw std::invalid_argument("model '" + name + "' has " + std::to_string(def.num_elements) +
                                " elements; the engine takes 1 to " + std::to_string(kMaxElements));
  if (def.num_bodies < 1 || def.num_bodies > kMaxBodies || def.humerus_body < 0 || def.humerus_body >= def.num_bodies ||
      def.scapula_body >= def.num_bodies)
    throw std::invalid_argument("model '" + name + "' has " + std::to_string(def.num_bodies) +
                                " bodies (humerus " + std::to_string(def.humerus_body) + "); the engine takes 1 to " +
                                std::to_string(kMaxBodies) + " with the humerus among them");
  if (def.girdle && (def.girdle->num_contact_points < 1 || def.girdle->num_contact_points > kMaxContactPoints ||
                     def.scapula_body < 0 || !def.girdle->points))
    throw std::invalid_argument("model '" + name + "': girdle forces need a moving scapula, 1 to " +
                                std::to_string(kMaxContactPoints) + " contact points and their points function");
  m.def = &def;
  m.num_dofs = def.num_dofs;
  m.num_elements = def.num_elements;
  for (int k = 0; k < 3; ++k) m.gravity_base[k] = def.gravity_base[k];
  for (int j = 0; j < m.num_dofs; ++j) {
    m.dof_elements_begin[j] = m.num_elements;
    m.dof_elements_end[j] = 0;
  }
  for (int i = 0; i < m.num_elements; ++i) {
    const unsigned mask = static_cast<unsigned>(def.elements[i].dof_mask);
    for (int j = 0; j < m.num_dofs; ++j) {
      // An element crossing no DOF (none in the shipped models) counts as crossing all of them.
      if (mask && !(mask >> j & 1u)) continue;
      m.dof_elements_begin[j] = std::min(m.dof_elements_begin[j], i);
      m.dof_elements_end[j] = std::max(m.dof_elements_end[j], i + 1);
    }
    m.element[i] = element_constants(def.elements[i], 1.0, def.elements[i].max_activation);
  }
  m.num_element_runs = 0;
  const unsigned all_dofs = (1u << m.num_dofs) - 1u;
  for (int b = 0; b < m.num_elements; b += 8) {
    unsigned crossed = 0;
    for (int i = b; i < std::min(b + 8, m.num_elements); ++i) {
      const unsigned mask = static_cast<unsigned>(def.elements[i].dof_mask) & all_dofs;
      crossed |= mask ? mask : all_dofs;
    }
    const int lo = __builtin_ctz(crossed), hi = 31 - __builtin_clz(crossed);
    Model::ElementRun* last = m.num_element_runs ? &m.element_runs[m.num_element_runs - 1] : nullptr;
    if (last && last->dof_lo == lo && last->dof_hi == hi) last->end = b + 8;
    else m.element_runs[m.num_element_runs++] = {b, b + 8, lo, hi};
  }
}

void data_init(const Model& m, Data& d) {
  d = Data{};
  for (int i = 0; i < m.num_elements; ++i) {
    d.settings.strength_scale[i] = 1.0;
    d.settings.max_activation[i] = m.def->elements[i].max_activation;
  }
  d.settings.gravity = m.gravity_base;
  d.settings.max_joint_speed = kDefaultMaxJointSpeed;
  data_apply_settings(m, d);
  data_reset(m, d, nullptr);
}

void data_reset(const Model& m, Data& d, const double* q) {
  if (!d.settings_applied)
    throw std::logic_error("data_reset: this Data has no settings yet (data_init it for its model first)");
  // Everything but the settings (and what they derive) and the inputs starts afresh.
  Data fresh;
  fresh.settings_applied = true;
  fresh.settings_version = d.settings_version;
  fresh.settings = d.settings;
  fresh.muscles = d.muscles;
  fresh.rest_fibre_rate = d.rest_fibre_rate;
  fresh.rest_fibre_element = d.rest_fibre_element;
  fresh.excitation = d.excitation;
  fresh.hand_force = d.hand_force;
  fresh.hand_moment = d.hand_moment;
  fresh.applied_moment = d.applied_moment;
  fresh.stimulation_map = d.stimulation_map;
  fresh.stimulation = d.stimulation;
  d = fresh;
  stimulation_reset(d);  // rested channels: no pulse yet, no fatigue
  for (int j = 0; j < m.num_dofs; ++j) d.x[q_offset(m) + j] = q ? q[j] : m.def->dofs[j].rest;
  double L[kMaxElements];
  m.def->muscle_lengths(&d.x[q_offset(m)], L);
  const int ia = act_offset(m), il = lce_offset(m);
  for (int i = 0; i < m.num_elements; ++i) {
    d.x[ia + i] = 0.0;
    d.x[il + i] = muscle_equilibrium_lce(data_element(m, d, i), m.fibre_damping, L[i], 0.0);
  }
}

}  // namespace armrt
