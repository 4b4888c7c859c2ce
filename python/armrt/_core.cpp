// Thin pybind11 bindings: the Python API (armrt/arm.py) validates inputs and names things; this file
// only moves arrays across and runs loops in C++ with the GIL released.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "armrt/engine.h"
#include "armrt/layouts.h"
#include "armrt/names.h"
#include "armrt/recorder.h"
#include "armrt/arm.h"
#include "armrt/snapshot.h"
#include "armrt/static_optimization.h"

namespace py = pybind11;
using namespace armrt;

// An array's values when it has n of them; ValueError naming `what` otherwise (also used by _core_model.cpp).
const double* checked(const py::array_t<double, py::array::c_style | py::array::forcecast>& a, py::ssize_t n,
                      const char* what);

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A numpy view of memory owned by `owner` (kept alive by the array).
Array view(double* ptr, std::vector<py::ssize_t> shape, py::handle owner) {
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t s = sizeof(double);
  for (int k = static_cast<int>(shape.size()) - 1; k >= 0; --k) {
    strides[k] = s;
    s *= shape[k];
  }
  return Array(shape, strides, ptr, owner);
}


// One output row's values as Python sees them: a float for a kOne row, else a copy of the model's values.
py::object output_value(const double* p, SizeRule size, const ModelDef& def) {
  if (size == SizeRule::kOne) return py::float_(*p);
  Array a({static_cast<py::ssize_t>(layout_size(size, def))});
  std::copy(p, p + a.size(), a.mutable_data());
  return a;
}

// A table's rows as (name, size rule, unit, stage, girdle_only, description) tuples; the size rule as
// "one", "two", "three", "dofs", "elements", "contact_points", "path_history", or for stimulation channels
// "channels", "channel_inputs" (3 per channel), "channel_state" (STIM_STATE_SIZE per channel).
py::list table_rows(const LayoutRow* rows, int n) {
  static const char* rule[] = {"one",        "two",          "three",    "dofs",          "elements",
                               "contact_points", "path_history", "channels", "channel_inputs", "channel_state"};
  py::list out;
  for (int k = 0; k < n; ++k)
    out.append(py::make_tuple(rows[k].name, rule[static_cast<int>(rows[k].size)], rows[k].unit, rows[k].stage,
                              rows[k].girdle_only, rows[k].description));
  return out;
}

void raise_if_failed(const Arm& s) {
  if (s.data.status != Status::kOk) throw std::runtime_error(s.error_message());
}

const ModelDef& require_model(const std::string& name) {
  const ModelDef* def = find_model(name);
  if (!def) throw py::value_error("unknown model '" + name + "' (registered models: " + model_names() + ")");
  return *def;
}

py::dict model_info(const ModelDef& def) {
  py::dict info;
  info["name"] = def.name;
  info["source_hash"] = def.source_hash;
  info["num_dofs"] = def.num_dofs;
  info["num_elements"] = def.num_elements;
  // The state layout, defined once in data.h: {block: (offset, size)} of x = [q | qdot | lce | activation].
  const Model& m = shared_model(def);
  py::dict layout;
  layout["q"] = py::make_tuple(q_offset(m), m.num_dofs);
  layout["qdot"] = py::make_tuple(qd_offset(m), m.num_dofs);
  layout["lce"] = py::make_tuple(lce_offset(m), m.num_elements);
  layout["activation"] = py::make_tuple(act_offset(m), m.num_elements);
  info["state_layout"] = layout;
  info["state_size"] = state_size(m);
  py::list dofs, elements, muscles, groups;
  for (int j = 0; j < def.num_dofs; ++j) {
    const DofParams& d = def.dofs[j];
    dofs.append(py::dict(py::arg("name") = d.name, py::arg("osim_name") = d.osim_name,
                         py::arg("range") = py::make_tuple(d.range_min, d.range_max), py::arg("rest") = d.rest));
  }
  for (int i = 0; i < def.num_elements; ++i) {
    const ElementParams& e = def.elements[i];
    std::vector<int> crossed;
    for (int j = 0; j < def.num_dofs; ++j) if (e.dof_mask & (1 << j)) crossed.push_back(j);
    elements.append(py::dict(py::arg("name") = e.name, py::arg("muscle") = e.muscle,
                             py::arg("osim_name") = e.osim_name, py::arg("fmax") = e.fmax,
                             py::arg("lceopt") = e.lceopt, py::arg("lslack") = e.lslack,
                             py::arg("pennopt") = e.pennopt, py::arg("vmax") = e.vmax, py::arg("tact") = e.tact,
                             py::arg("tdeact") = e.tdeact, py::arg("peeslack") = e.peeslack,
                             py::arg("crosses_gh") = static_cast<bool>(e.crosses_gh), py::arg("dofs") = crossed));
  }
  auto groups_of = [](const GroupDef* g, int n, py::list& out) {
    for (int k = 0; k < n; ++k)
      out.append(py::make_tuple(g[k].name, std::vector<int>(g[k].elements, g[k].elements + g[k].num_elements)));
  };
  groups_of(def.muscles, def.num_muscles, muscles);
  groups_of(def.groups, def.num_groups, groups);
  info["dofs"] = dofs;
  info["elements"] = elements;
  info["muscles"] = muscles;
  info["groups"] = groups;
  info["arm_mass"] = def.arm_mass;
  // The passive joint law's constants (passive_joints.cc), under the model file's names.
  info["passive_joint"] = py::dict(py::arg("stiffness_inside") = def.passive_stiffness_inside,
                                   py::arg("stiffness_outside") = def.passive_stiffness_outside,
                                   py::arg("damping") = def.passive_damping);
  info["base_body"] = std::string(def.base_body);
  {
    py::list bodies;
    for (int b = 0; b < def.num_bodies; ++b) bodies.append(def.body_names[b]);
    info["body_names"] = bodies;
  }
  info["scapula_body"] = def.scapula_body;
  info["humerus_body"] = def.humerus_body;
  if (def.girdle) {
    const GirdleDef& g = *def.girdle;
    py::list names;
    for (int k = 0; k < g.num_contact_points; ++k) names.append(g.contact_point_names[k]);
    info["girdle"] = py::dict(
        py::arg("contact_points") = names,
        py::arg("thorax_centre") = std::vector<double>(g.thorax.centre, g.thorax.centre + 3),
        py::arg("thorax_radii") = std::vector<double>(g.thorax.radii, g.thorax.radii + 3),
        py::arg("contact_stiffness") = g.thorax.k, py::arg("contact_eps") = g.thorax.eps,
        py::arg("conoid_length") = g.conoid.length, py::arg("conoid_stiffness") = g.conoid.stiffness,
        py::arg("conoid_eps") = g.conoid.eps);
  } else {
    info["girdle"] = py::none();
  }
  info["gravity_base"] = std::vector<double>(def.gravity_base, def.gravity_base + 3);
  info["base_rotation_in_thorax"] = std::vector<double>(def.base_rotation_in_thorax, def.base_rotation_in_thorax + 9);
  info["base_origin_in_thorax"] = std::vector<double>(def.base_origin_in_thorax, def.base_origin_in_thorax + 3);
  info["gh_centre"] = std::vector<double>(def.gh_centre, def.gh_centre + 3);
  info["glenoid_normal"] = std::vector<double>(def.glenoid_normal, def.glenoid_normal + 3);
  info["glenoid_major_axis"] = std::vector<double>(def.glenoid_major_axis, def.glenoid_major_axis + 3);
  info["glenoid_minor_axis"] = std::vector<double>(def.glenoid_minor_axis, def.glenoid_minor_axis + 3);
  info["rim_half_angle_major"] = def.rim_half_angle_major;
  info["rim_half_angle_minor"] = def.rim_half_angle_minor;
  return info;
}

// Ctrl-C during a long loop without the GIL: every ~50 ms of work the loop re-takes the GIL briefly
// and lets Python run its signal handlers, so KeyboardInterrupt arrives within 0.1 s, not at the end.
class InterruptCheck {
 public:
  static constexpr std::chrono::milliseconds kPeriod{50};
  // True if a Python signal handler raised (the error is set; throw py::error_already_set with the GIL).
  bool interrupted() {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_) return false;
    next_ = now + kPeriod;
    py::gil_scoped_acquire gil;
    return PyErr_CheckSignals() != 0;
  }

 private:
  std::chrono::steady_clock::time_point next_ = std::chrono::steady_clock::now() + kPeriod;
};

}  // namespace

const double* checked(const Array& a, py::ssize_t n, const char* what) {
  if (a.size() != n) throw py::value_error(std::string(what) + ": expected " + std::to_string(n) +
                                           " values, got " + std::to_string(a.size()));
  return a.data();
}

py::dict inverse_dynamics_dict(const Model& m, const double* gravity, const double* q, const double* qd,
                               const double* qdd, const double* hand_force, const double* hand_moment);  // _core_model.cpp
void bind_model(py::module_& mod);  // _core_model.cpp

PYBIND11_MODULE(_core, mod) {
  mod.doc() = "armrt engine bindings (use armrt.Arm)";
  // The instruction set this extension and the engine were compiled for (one set of options for both, CMakeLists.txt):
  // floating-point results are bit for bit only between builds for the same target (tests/test_golden.py).
  {
    py::dict build;
#if defined(__znver3__)
    build["march_znver3"] = true;
#else
    build["march_znver3"] = false;
#endif
#if defined(__AVX512F__)
    build["avx512f"] = true;
#else
    build["avx512f"] = false;
#endif
#if defined(__AVX2__)
    build["avx2"] = true;
#else
    build["avx2"] = false;
#endif
    build["compiler"] = std::string(__VERSION__);
    mod.attr("BUILD") = build;
  }
  mod.attr("MAX_DOFS") = kMaxDofs;
  mod.attr("MAX_ELEMENTS") = kMaxElements;
  mod.attr("MAX_CONTACT_PENETRATION") = kMaxContactPenetration;  // m, the domain check's limit (model.h)
  bind_model(mod);
  mod.def("model_info", [](const std::string& name) { return model_info(require_model(name)); });
  mod.def("model_info", [](const ModelDef& def) { return model_info(def); });
  mod.def("default_max_step", [](const std::string& integrator) { return default_max_step(parse_integrator(integrator)); },
          "Largest integration step (s) the integrator takes by default inside a control step (inf: CVODE).");
  mod.def("default_substeps", [](const std::string& integrator, double dt) { return default_substeps(parse_integrator(integrator), dt); },
          "Integration steps per control step dt (s) by default.");
  mod.def("model_names", []() { return model_names(); });
  // The layout tables (layouts.h), read by armrt.Result, ArmBatch and the docs.
  mod.def("recorded_channels", []() { return table_rows(recorded_channels(), kNumChannels); },
          "Recorded channels in order: (name, size rule, unit, stage, girdle_only, description)");
  mod.def("output_rows", []() {
    int n = 0;
    const LayoutRow* rows = output_rows(&n);
    return table_rows(rows, n);
  }, "forward()'s outputs in stage order: (name, size rule, unit, stage, girdle_only, description)");
  mod.def("snapshot_rows", []() { return table_rows(snapshot_rows(), kNumSnapshotParts); },
          "The snapshot's parts in order, part k being signature bit 1 << k: (name, size rule, unit, stage, "
          "girdle_only, description)");
  // engine.h hand_load_error: "" or why a hand force (moment=False, N) or moment (N m), three finite values, is
  // refused (the one rule of every hand load; checks.hand_load calls it).
  mod.def("hand_load_error", [](const std::string& what, const Array& v, bool moment) {
    return hand_load_error(what.c_str(), checked(v, 3, what.c_str()), moment);
  }, py::arg("what"), py::arg("v"), py::arg("moment"));
  mod.attr("STATIC_OPTIMIZATION_MAX_HAND_FORCE") = kStaticOptimizationMaxHandForce;    // N (static_optimization.h)
  mod.attr("STATIC_OPTIMIZATION_MIN_GH_STAB_MAX") = kMinGhStabMax;                     // 1 (static_optimization.h)
  mod.attr("STATIC_OPTIMIZATION_MAX_HAND_MOMENT") = kStaticOptimizationMaxHandMoment;  // N m
  mod.attr("STATIC_OPTIMIZATION_MAX_JOINT_ACCELERATION") = kStaticOptimizationMaxJointAcceleration;  // rad/s^2
  mod.attr("DEFAULT_MAX_JOINT_SPEED") = kDefaultMaxJointSpeed;  // rad/s: an arm's max_joint_speed, armrt-rt's
  mod.attr("STATIC_OPTIMIZATION_MAX_SQP_ITERATIONS") = kStaticOptimizationMaxSqpIterations;  // the elastic SQP's QPs
  mod.attr("START_RANGE_MARGIN") = kStartRangeMargin;  // rad, model.h: Arm.reset's and armrt-rt --q0's bound
  mod.attr("JOINT_RANGE_MARGIN") = kJointRangeMargin;  // rad, model.h: the physical domain's joint bound
  mod.attr("SNAPSHOT_TIME") = kSnapshotTime;
  mod.attr("SNAPSHOT_PHYSICS") = kSnapshotPhysics;
  mod.attr("SNAPSHOT_INPUTS") = kSnapshotInputs;
  mod.attr("SNAPSHOT_INTEGRATOR") = kSnapshotIntegrator;
  mod.attr("SNAPSHOT_STIMULATION") = kSnapshotStimulation;
  mod.attr("STIM_STATE_SIZE") = static_cast<int>(kStimStateSize);
  {
    py::dict cols;
    cols["calcium_sum"] = static_cast<int>(kStimCalciumSum);
    cols["calcium"] = static_cast<int>(kStimCalcium);
    cols["force"] = static_cast<int>(kStimForce);
    cols["fatigue_A"] = static_cast<int>(kStimFatigueA);
    cols["fatigue_tau1"] = static_cast<int>(kStimFatigueTau1);
    cols["fatigue_Km"] = static_cast<int>(kStimFatigueKm);
    cols["last_pulse"] = static_cast<int>(kStimLastPulse);
    cols["recruitment"] = static_cast<int>(kStimRecruitment);
    cols["queued"] = static_cast<int>(kStimQueued);
    mod.attr("STIM_STATE_COLUMNS") = cols;
  }
  mod.attr("SNAPSHOT_FULL") = kSnapshotFull;
  // The name service (names.h): the Python API's lookups and messages come from here.
  mod.def("find_elements", [](const std::string& model, const std::string& name) {
        std::vector<int> ix;
        if (!find_elements(require_model(model), name, ix)) throw py::key_error(unknown_names_message(require_model(model), {name}));
        return ix;
      }, py::arg("model"), py::arg("name"),
      "Element indices of an element, muscle or group name (or OpenSim force / muscle alias); KeyError with close matches");
  mod.def("is_name", [](const std::string& model, const std::string& name) {
        std::vector<int> ix;
        return find_elements(require_model(model), name, ix);
      }, py::arg("model"), py::arg("name"));
  mod.def("unknown_names_message", [](const std::string& model, const std::vector<std::string>& names) {
        return unknown_names_message(require_model(model), names);
      }, py::arg("model"), py::arg("names"));
  // The one rule for overlapping names in an excitation dict (names.h): every excitation path uses it.
  mod.def("excitations_from_names", [](const std::string& model, const std::vector<std::pair<std::string, double>>& items) {
        try {
          return excitations_from_names(require_model(model), items);
        } catch (const std::invalid_argument& e) {
          throw py::key_error(e.what());
        }
      }, py::arg("model"), py::arg("items"),
      "[(name, value)] -> one value per element: the most specific name wins (element over muscle over group, in "
      "any order), equal specificity takes the largest; 0 where no name applies; KeyError naming unknown names");
  mod.def("values_from_names", [](const std::string& model, const std::vector<std::pair<std::string, double>>& items,
                                  const Array& unnamed) {
        const ModelDef& def = require_model(model);
        try {
          return values_from_names(def, items, checked(unnamed, def.num_elements, "unnamed"));
        } catch (const std::invalid_argument& e) {
          throw py::key_error(e.what());
        }
      }, py::arg("model"), py::arg("items"), py::arg("unnamed"),
      "excitations_from_names' rule for any per-element setting: elements no name covers keep unnamed (n,)");
  mod.def("find_dof", [](const std::string& model, const std::string& name) {
        const ModelDef& def = require_model(model);
        const int j = find_dof(def, name);
        if (j < 0) throw py::key_error(unknown_dof_message(def, name));
        return j;
      }, py::arg("model"), py::arg("name"), "DOF index by armrt or OpenSim name; KeyError with close matches");
  mod.def("close_matches", [](const std::string& model, const std::string& name, bool dofs) {
        return close_matches(require_model(model), name, dofs ? NameKind::kDofs : NameKind::kElementsMusclesGroups);
      }, py::arg("model"), py::arg("name"), py::arg("dofs") = false);

  // linearize()'s workspace (engine.h), held by a Python Arm and reused, so that no call after the first allocates in
  // the engine.
  py::class_<LinearizeWorkspace>(mod, "LinearizeWorkspace").def(py::init([]() { return std::make_unique<LinearizeWorkspace>(); }));
  // static_optimization.h: the rigid-tendon static optimisation of an arm (python/armrt/control.py's
  // StaticOptimizer(backend="cpp") drives it). solve(arm, q, qd, qdd, hand_force, hand_moment) -> (activation (n,),
  // report dict); the solve runs without the GIL.
  mod.def("gh_polygon", [](double theta_a, double phi_a, double bound, int sides) {
    if (sides < 3 || sides > kMaxGhPolygonSides) throw py::value_error("sides must be in [3, " + std::to_string(kMaxGhPolygonSides) + "]");
    Array rows({sides, 3});
    gh_polygon(theta_a, phi_a, bound, sides, rows.mutable_data());
    return rows;
  }, py::arg("theta_a"), py::arg("phi_a"), py::arg("bound"), py::arg("sides"));
  py::class_<StaticOptimizationWorkspace>(mod, "StaticOptimizationWorkspace")
      .def(py::init([](const Arm& s, double gh_stab_max, py::object weights, int sides, bool dual_newton) {
        StaticOptimizationOptions o;
        o.gh_stab_max = gh_stab_max;
        o.polygon_sides = sides;
        o.dual_newton = dual_newton;
        if (!weights.is_none()) {
          const Array w = weights.cast<Array>();
          const double* p = checked(w, s.model.num_elements, "weights");
          o.weights.assign(p, p + s.model.num_elements);
        }
        auto ws = std::make_unique<StaticOptimizationWorkspace>();
        static_optimization_setup(s.model, o, *ws);
        return ws;
      }), py::arg("arm"), py::arg("gh_stab_max"), py::arg("weights"), py::arg("polygon_sides"), py::arg("dual_newton") = true)
      .def("reset", [](StaticOptimizationWorkspace& w) { static_optimization_reset(w); })
      .def("solve", [](StaticOptimizationWorkspace& w, const Arm& s, const Array& q, const Array& qd, const Array& qdd,
                       const Array& hf, const Array& hm, const std::string& tendon) {
        if (tendon != "rigid" && tendon != "elastic")
          throw py::value_error("tendon must be 'rigid' or 'elastic', got '" + tendon + "'");
        const int n = s.model.num_elements, nq = s.model.num_dofs;
        const double *qp = checked(q, nq, "q"), *qdp = checked(qd, nq, "qdot"), *qddp = checked(qdd, nq, "qddot");
        const double *hfp = checked(hf, 3, "hand force"), *hmp = checked(hm, 3, "hand moment");
        Array a({n});
        StaticOptimizationReport r;
        {
          py::gil_scoped_release release;
          if (tendon == "rigid") static_optimization_rigid(s.model, s.data, w, qp, qdp, qddp, hfp, hmp, a.mutable_data(), &r);
          else static_optimization_elastic(s.model, s.data, w, qp, qdp, qddp, hfp, hmp, a.mutable_data(), &r);
        }
        auto vec = [](const double* p, py::ssize_t k) {
          Array out({k});
          std::copy(p, p + k, out.mutable_data());
          return out;
        };
        const char* status = r.status == StaticOptimizationStatus::kSolved ? "solved"
                             : r.status == StaticOptimizationStatus::kInfeasible ? "infeasible" : "not_converged";
        py::dict d;
        d["feasible"] = r.feasible;
        d["status"] = status;
        d["solver"] = r.solver == StaticOptimizationSolverUsed::kDualNewton ? "dual_newton" : "proxqp";
        d["newton_iterations"] = r.newton_iterations;
        d["qp_iterations"] = r.qp_iterations;
        d["elastic_mode_steps"] = r.elastic_mode_steps;
        d["qps"] = r.qps;
        d["tau_required"] = vec(r.tau_required, nq);
        d["tau_muscle"] = vec(r.tau_muscle, nq);
        d["residual"] = vec(r.residual, nq);
        d["gh_force"] = vec(r.gh_force, 3);
        d["gh_stab"] = r.gh_stab;
        d["gh_bound_active"] = r.gh_bound_active;
        d["lce"] = vec(r.lce, n);
        d["force"] = vec(r.force, n);
        d["fibre_velocity"] = vec(r.fibre_velocity, n);
        return py::make_tuple(a, d);
      }, py::arg("arm"), py::arg("q"), py::arg("qdot"), py::arg("qddot"), py::arg("hand_force"), py::arg("hand_moment"),
         py::arg("tendon") = "rigid");

  py::class_<Arm>(mod, "Arm")
      .def(py::init([](const std::string& model, const std::string& integrator, double dt, int substeps) {
             return std::make_unique<Arm>(require_model(model), parse_integrator(integrator), dt, substeps);
           }),
           py::arg("model"), py::arg("integrator"), py::arg("dt"), py::arg("substeps") = 1)
      .def(py::init([](const ModelDef& model, const std::string& integrator, double dt, int substeps) {
             return std::make_unique<Arm>(model, parse_integrator(integrator), dt, substeps);
           }),
           py::arg("model"), py::arg("integrator"), py::arg("dt"), py::arg("substeps") = 1)
      .def_property_readonly("substeps", [](const Arm& s) { return s.stepper.substeps; })
      .def_property_readonly("num_elements", [](const Arm& s) { return s.model.num_elements; })
      .def_property_readonly("num_dofs", [](const Arm& s) { return s.model.num_dofs; })
      .def_property_readonly("model_name", [](const Arm& s) { return std::string(s.model.def->name); })
      .def_property_readonly("dt", [](const Arm& s) { return s.stepper.dt; })
      .def_property_readonly("integrator", [](const Arm& s) { return integrator_name(s.stepper.integrator); })
      .def("set_integrator", [](Arm& s, const std::string& name, double dt, int substeps) { s.set_integrator(parse_integrator(name), dt, substeps); },
           py::arg("integrator"), py::arg("dt"), py::arg("substeps") = 1)
      .def_property("time", [](const Arm& s) { return s.data.time; }, [](Arm& s, double t) { s.data.time = t; })
      // Zero-copy views of the state and inputs.
      .def_property_readonly("state", [](py::object self) {
        auto& s = self.cast<Arm&>();
        return view(s.data.x.data(), {state_size(s.model)}, self);
      })
      .def_property_readonly("excitation", [](py::object self) {
        auto& s = self.cast<Arm&>();
        return view(s.data.excitation.data(), {s.model.num_elements}, self);
      })
      .def_property_readonly("hand_force", [](py::object self) { return view(self.cast<Arm&>().data.hand_force.data(), {3}, self); })
      .def_property_readonly("hand_moment", [](py::object self) { return view(self.cast<Arm&>().data.hand_moment.data(), {3}, self); })
      .def_property_readonly("applied_moment", [](py::object self) {
        auto& s = self.cast<Arm&>();
        return view(s.data.applied_moment.data(), {s.model.num_dofs}, self);
      })
      .def("reset", [](Arm& s, py::object q, py::object qd, py::object act) {
        Array qa, qda, aa;
        const double *qp = nullptr, *qdp = nullptr, *ap = nullptr;
        const int nq = s.model.num_dofs;
        if (!q.is_none()) { qa = q.cast<Array>(); qp = checked(qa, nq, "q"); }
        if (!qd.is_none()) { qda = qd.cast<Array>(); qdp = checked(qda, nq, "qdot"); }
        if (!act.is_none()) { aa = act.cast<Array>(); ap = checked(aa, s.model.num_elements, "activation"); }
        s.reset(qp, qdp, ap);
      }, py::arg("q") = py::none(), py::arg("qdot") = py::none(), py::arg("activation") = py::none())
      .def("step", [](Arm& s, long n) {
        bool interrupted = false;
        {
          py::gil_scoped_release release;
          InterruptCheck check;
          // No outputs while stepping: they are computed when read, at the state they are read at
          // (evaluate_outputs, once per state).
          for (long k = 0; k < n; ++k) {
            if (!s.step(false)) break;
            if (check.interrupted()) { interrupted = true; break; }
          }
        }
        if (interrupted) throw py::error_already_set();
        raise_if_failed(s);
      }, py::arg("n") = 1)
      // Arm.settle: n control steps with zero excitation, then the clock back to 0 and the excitation as it was
      // (Arm::settle, arm.h: the one settle path, also armrt-rt --settle's). Ctrl-C stops it as step does.
      .def("settle", [](Arm& s, long n) {
        bool interrupted = false;
        {
          py::gil_scoped_release release;
          InterruptCheck check;
          s.settle(n, [&] { return interrupted = check.interrupted(); });
        }
        if (interrupted) throw py::error_already_set();
        raise_if_failed(s);
      }, py::arg("n"))
      // What the dynamics use for excitations u (n,) or (T, n): capped_excitation with this arm's maximum
      // activation (data.h), the engine's one cap rule.
      .def("cap_excitation", [](const Arm& s, const Array& u) {
        const int n = s.model.num_elements;
        if (u.ndim() < 1 || u.shape(u.ndim() - 1) != n)
          throw py::value_error("excitation: expected a last axis of " + std::to_string(n) + " values");
        Array out(std::vector<py::ssize_t>(u.shape(), u.shape() + u.ndim()));
        const double* in = u.data();
        double* o = out.mutable_data();
        const double* cap = s.data.muscles.max_activation.data();
        for (py::ssize_t row = 0; row < u.size() / n; ++row)
          for (int i = 0; i < n; ++i) o[row * n + i] = capped_excitation(in[row * n + i], cap[i]);
        return out;
      }, py::arg("u"))
      .def("clear_error", [](Arm& s) { s.data.status = Status::kOk; s.data.bad_index = -1; s.data.bad_contact = -1; })
      // The held excitation (n,), stored as the dynamics use it (data_set_excitation: the one cap rule).
      .def("set_excitation", [](Arm& s, const Array& u) {
        data_set_excitation(s.model, s.data, checked(u, s.model.num_elements, "excitation"));
      }, py::arg("u"))
      // Snapshots by signature (snapshot.h): get_snapshot -> (snapshot_size,) array; snapshot_error -> why an
      // array is not a snapshot this arm may be set to ("" if it is); set_snapshot writes one, refusing what
      // snapshot_error refuses (ValueError) unless validate is False (an arm's copy of a diverged state).
      .def("snapshot_size", [](const Arm& s, unsigned signature) { return snapshot_size(*s.model.def, signature, s.data.stimulation_map.num_channels); },
           py::arg("signature"))
      .def("get_snapshot", [](const Arm& s, unsigned signature) {
        Array out({snapshot_size(*s.model.def, signature, s.data.stimulation_map.num_channels)});
        get_snapshot(s.model, s.data, s.stepper, signature, out.mutable_data());
        return out;
      }, py::arg("signature"))
      .def("snapshot_error", [](const Arm& s, unsigned signature, const Array& in) {
        return snapshot_error(s.model, s.data, signature, checked(in, snapshot_size(*s.model.def, signature, s.data.stimulation_map.num_channels), "snapshot"));
      }, py::arg("signature"), py::arg("snapshot"))
      .def("set_snapshot", [](Arm& s, unsigned signature, const Array& in, bool validate) {
        const double* p = checked(in, snapshot_size(*s.model.def, signature, s.data.stimulation_map.num_channels), "snapshot");
        if (validate) {
          const std::string error = snapshot_error(s.model, s.data, signature, p);
          if (!error.empty()) throw py::value_error("snapshot: " + error);
        }
        set_snapshot(s.model, s.data, s.stepper, signature, p);
      }, py::arg("signature"), py::arg("snapshot"), py::arg("validate") = true)
      // Stimulation (stimulation.h): the map from JSON text, a file (.json/.toml) or one channel per muscle;
      // commands (channels, 3) of [pulse width s, amplitude A, frequency Hz], refused beyond a channel's limits.
      .def("set_stimulation_map_json", [](Arm& s, const std::string& text) {
        data_set_stimulation_map(s.model, s.data, stimulation_map_from_json(*s.model.def, text));
      }, py::arg("text"))
      .def("set_stimulation_map_file", [](Arm& s, const std::string& path) {
        data_set_stimulation_map(s.model, s.data, stimulation_map_from_file(*s.model.def, path));
      }, py::arg("path"))
      .def("set_stimulation_map_per_muscle", [](Arm& s) {
        data_set_stimulation_map(s.model, s.data, stimulation_map_per_muscle(*s.model.def));
      })
      .def("clear_stimulation_map", [](Arm& s) { data_set_stimulation_map(s.model, s.data, StimulationMap{}); })
      .def("stimulation_map_json", [](const Arm& s) { return stimulation_map_to_json(*s.model.def, s.data.stimulation_map); })
      .def_property_readonly("num_channels", [](const Arm& s) { return s.data.stimulation_map.num_channels; })
      .def_property_readonly("channel_names", [](const Arm& s) {
        std::vector<std::string> out;
        for (int k = 0; k < s.data.stimulation_map.num_channels; ++k) out.emplace_back(s.data.stimulation_map.channels[k].name);
        return out;
      })
      .def_property_readonly("stimulation_driven", [](const Arm& s) {
        std::vector<bool> out(s.model.num_elements);
        for (int i = 0; i < s.model.num_elements; ++i) out[i] = s.data.stimulation_map.driven[i] != 0;
        return out;
      })
      .def("stimulation_command_error", [](const Arm& s, const Array& cmd) {
        const int nc = s.data.stimulation_map.num_channels;
        const double* p = checked(cmd, 3 * nc, "stimulation");
        for (int k = 0; k < nc; ++k) {
          const std::string e = stimulation_command_error(s.data.stimulation_map.channels[k], p[3 * k], p[3 * k + 1], p[3 * k + 2]);
          if (!e.empty()) return e;
        }
        return std::string();
      }, py::arg("stimulation"))
      .def("set_stimulation", [](Arm& s, const Array& cmd) {
        const int nc = s.data.stimulation_map.num_channels;
        const double* p = checked(cmd, 3 * nc, "stimulation");
        for (int k = 0; k < nc; ++k) {
          const std::string e = stimulation_command_error(s.data.stimulation_map.channels[k], p[3 * k], p[3 * k + 1], p[3 * k + 2]);
          if (!e.empty()) throw py::value_error(e);
        }
        std::copy(p, p + 3 * nc, s.data.stimulation.begin());
      }, py::arg("stimulation"))
      .def_property_readonly("stimulation", [](py::object self) {
        auto& s = self.cast<Arm&>();
        Array out({s.data.stimulation_map.num_channels, 3});
        std::copy(s.data.stimulation.begin(), s.data.stimulation.begin() + 3 * s.data.stimulation_map.num_channels, out.mutable_data());
        return out;
      })
      .def("queue_pulses", [](Arm& s, int channel, const Array& times) {
        stimulation_queue_pulses(s.model, s.data, channel, times.data(), static_cast<int>(times.size()));
      }, py::arg("channel"), py::arg("times"))
      // The chain's memory (channels, kStimStateSize) as a copy, one row per channel (Data stores it by column).
      .def_property_readonly("stimulation_state", [](const Arm& s) {
        const int nc = s.data.stimulation_map.num_channels;
        Array out({nc, static_cast<int>(kStimStateSize)});
        stimulation_state_by_channel(s.data, out.mutable_data());
        return out;
      })
      .def("recruitment_fraction", [](const Arm& s, int channel, double pw, double amp) {
        if (channel < 0 || channel >= s.data.stimulation_map.num_channels) throw py::index_error("no such channel");
        return recruitment_fraction(s.data.stimulation_map.channels[channel].recruitment, pw, amp);
      }, py::arg("channel"), py::arg("pulse_width"), py::arg("amplitude"))
      .def("evaluate_outputs", &Arm::evaluate_outputs, "outputs at the current state (computed only if stale)")
      .def("outputs_current", [](const Arm& s) { return outputs_current(s.model, s.data); })
      // One ARMRT_OUTPUTS row at the current state (a float or a copy); KeyError for an unknown name.
      .def("output", [](Arm& s, const std::string& name) -> py::object {
        s.evaluate_outputs();
        const Data& d = s.data;
        const ModelDef& def = *s.model.def;
#define ARMRT_X(row, size, unit, stage, girdle_only, recorded, description) \
        if (name == #row && (!(girdle_only) || def.girdle)) return output_value(row_values(d.row), SizeRule::size, def);
        ARMRT_OUTPUTS(ARMRT_X)
#undef ARMRT_X
        throw py::key_error("no output '" + name + "' for model " + def.name);
      }, py::arg("name"))
      // Every ARMRT_OUTPUTS row (layouts.h) that the model has, as copies; "moment_arm" (element, DOF) at the
      // outputs' q, and gh_theta / gh_phi (gh_angles' two values) for the API's older names.
      .def("outputs", [](Arm& s) {
        const Data& d = s.data;
        const ModelDef& def = *s.model.def;
        py::dict o;
#define ARMRT_X(name, size, unit, stage, girdle_only, recorded, description) \
        if (!(girdle_only) || def.girdle) o[#name] = output_value(row_values(d.name), SizeRule::size, def);
        ARMRT_OUTPUTS(ARMRT_X)
#undef ARMRT_X
        {
          const int n = s.model.num_elements, nq = s.model.num_dofs;
          double L[kMaxElements];
          Array r({n, nq});
          muscle_paths_by_element(def, d.output_q.data(), L, r.mutable_data());
          o["moment_arm"] = r;
        }
        o["gh_theta"] = d.gh_angles[0];
        o["gh_phi"] = d.gh_angles[1];
        return o;
      })
      .def("tet_stats", [](const Arm& s) {
        const TetStats& t = s.data.tet;
        return py::dict(py::arg("count") = t.count, py::arg("mean_ns") = t.mean_ns, py::arg("min_ns") = t.min_ns,
                        py::arg("max_ns") = t.max_ns, py::arg("last_ns") = t.last_ns);
      })
      .def("reset_tet", [](Arm& s) { s.data.tet = TetStats{}; })
      .def("get_strength", [](const Arm& s) {
        Array a({s.model.num_elements});
        for (int i = 0; i < s.model.num_elements; ++i) a.mutable_data()[i] = s.data.settings.strength_scale[i];
        return a;
      })
      .def("get_max_activation", [](const Arm& s) {
        Array a({s.model.num_elements});
        for (int i = 0; i < s.model.num_elements; ++i) a.mutable_data()[i] = s.data.settings.max_activation[i];
        return a;
      })
      .def("set_strength_and_max_activation", [](Arm& s, const Array& strength, const Array& maxact) {
        const double* st = checked(strength, s.model.num_elements, "strength");
        const double* ma = checked(maxact, s.model.num_elements, "max_activation");
        const ArmSettings before = s.data.settings;
        for (int i = 0; i < s.model.num_elements; ++i) {
          s.data.settings.strength_scale[i] = st[i];
          s.data.settings.max_activation[i] = ma[i];
        }
        try {
          s.apply_settings();
        } catch (...) {
          s.data.settings = before;  // refused: the arm keeps what it had
          throw;
        }
      })
      .def_property("gravity", [](const Arm& s) { return std::vector<double>(s.data.settings.gravity.begin(), s.data.settings.gravity.end()); },
                    [](Arm& s, const Array& g) { const double* p = checked(g, 3, "gravity"); for (int k = 0; k < 3; ++k) s.data.settings.gravity[k] = p[k]; })
      .def_property("max_joint_speed", [](const Arm& s) { return s.data.settings.max_joint_speed; },
                    [](Arm& s, double v) { s.data.settings.max_joint_speed = v; })
      // simulate: excitation is (T, n) (one row per step) or (1, n) (held); the loop runs without the GIL.
      // With out (a dict of C-contiguous float64 arrays, one per channel of recording_shapes(rows)), the rows go
      // straight into them from row `row` on and only {"steps", "rows"} is returned: Arm.simulate's Result arrays,
      // filled block by block without the copies in between.
      .def("simulate", [](Arm& s, const Array& excitation, long n_steps, long record_every, py::object storage, long row) {
        const int n = s.model.num_elements, nq = s.model.num_dofs;
        if (excitation.ndim() != 2 || excitation.shape(1) != n || (excitation.shape(0) != n_steps && excitation.shape(0) != 1))
          throw py::value_error("excitation must have shape (" + std::to_string(n_steps) + ", " + std::to_string(n) + ") or (1, " + std::to_string(n) + ")");
        if (record_every < 1) throw py::value_error("record_every must be >= 1");
        Recording r;
        const bool into = !storage.is_none();
        if (into) {
          const py::dict arrays = storage.cast<py::dict>();
          const auto width = recording_widths(s);
          const LayoutRow* rows = recorded_channels();
          long capacity = -1;
          for (int c = 0; c < kNumChannels; ++c) {
            if (width[c] == 0) continue;
            if (!arrays.contains(rows[c].name)) throw py::value_error(std::string("simulate: out has no array ") + rows[c].name);
            py::array a = arrays[rows[c].name].cast<py::array>();
            const bool scalar = rows[c].size == SizeRule::kOne;
            if (!a.dtype().is(py::dtype::of<double>()) || !(a.flags() & py::array::c_style) || !a.writeable() ||
                a.ndim() != (scalar ? 1 : 2) || (!scalar && a.shape(1) != width[c]) || (capacity >= 0 && a.shape(0) != capacity))
              throw py::value_error(std::string("simulate: out[") + rows[c].name + "] must be a writeable C-contiguous float64 array of "
                                    "recording_shapes' shape");
            capacity = a.shape(0);
            r.into[c] = static_cast<double*>(a.mutable_data());
          }
          if (row < 0 || row > capacity) throw py::value_error("simulate: row outside out's rows");
          r.capacity = capacity;
          r.num_rows = row;  // whether the rows fit is simulate_recorded's check (engine, recorder.cc)
        }
        long steps_done = 0;
        bool interrupted = false;
        {
          py::gil_scoped_release release;
          InterruptCheck check;
          struct Ctx { InterruptCheck* check; bool* interrupted; } ctx{&check, &interrupted};
          auto stop = [](void* p) {
            auto* c = static_cast<Ctx*>(p);
            return *c->interrupted = c->check->interrupted();
          };
          steps_done = simulate_recorded(s, excitation.data(), excitation.shape(0) == 1, n_steps, record_every, r, stop, &ctx);
        }
        if (interrupted) throw py::error_already_set();
        raise_if_failed(s);
        if (into) {
          py::dict done;
          done["steps"] = steps_done;
          done["rows"] = r.rows() - row;
          return done;
        }
        const py::ssize_t T = static_cast<py::ssize_t>(r.rows());
        auto arr = [T](const std::vector<double>& v, py::ssize_t w) {
          Array a(w == 0 ? std::vector<py::ssize_t>{T} : std::vector<py::ssize_t>{T, w});
          std::copy(v.begin(), v.end(), a.mutable_data());
          return a;
        };
        py::dict out;
        const LayoutRow* rows = recorded_channels();
        for (int c = 0; c < kNumChannels; ++c) {
          if (r.width[c] == 0) continue;  // a girdle channel of a model without girdle forces
          out[rows[c].name] = arr(r.channel[c], rows[c].size == SizeRule::kOne ? 0 : r.width[c]);
        }
        out["steps"] = steps_done;
        return out;
      }, py::arg("excitation"), py::arg("n_steps"), py::arg("record_every") = 1, py::arg("out") = py::none(),
         py::arg("row") = 0)
      // {channel: shape} of `rows` recorded rows of this arm (the channels it records, as simulate returns them).
      .def("recording_shapes", [](const Arm& s, long rows) {
        const auto width = recording_widths(s);
        const LayoutRow* table = recorded_channels();
        py::dict shapes;
        for (int c = 0; c < kNumChannels; ++c) {
          if (width[c] == 0) continue;
          if (table[c].size == SizeRule::kOne) shapes[table[c].name] = py::make_tuple(rows);
          else shapes[table[c].name] = py::make_tuple(rows, width[c]);
        }
        return shapes;
      }, py::arg("rows"))
      // linearize (engine.h) at the current state and inputs: (dfdx, dfdu) or, with step, (dfdx, dfdu, A, B, x_next,
      // in_domain) of one ROS2 step of dt / substeps.
      .def("linearize", [](Arm& s, LinearizeWorkspace& w, bool step) -> py::tuple {
        raise_if_failed(s);  // a diverged state (qdot 1e29 rad/s) gave NaN matrices, or a set-state error, before
        const int ns = state_size(s.model), n = s.model.num_elements;
        Array dfdx({ns, ns}), dfdu({ns, n});
        if (!step) {
          {
            py::gil_scoped_release release;
            linearize(s.model, s.data, w, 0.0, dfdx.mutable_data(), dfdu.mutable_data(), nullptr, nullptr);
          }
          return py::make_tuple(dfdx, dfdu);
        }
        Array A({ns, ns}), B({ns, n}), x_next({ns});
        bool in_domain = false;
        {
          py::gil_scoped_release release;
          linearize(s.model, s.data, w, s.stepper.dt / s.stepper.substeps, dfdx.mutable_data(), dfdu.mutable_data(),
                    A.mutable_data(), B.mutable_data());
          in_domain = check_domain(s.model, s.data, w.x_next.data()).status == Status::kOk;
        }
        std::copy(w.x_next.begin(), w.x_next.begin() + ns, x_next.mutable_data());
        // x_next: where the step lands; in_domain false where the step itself would stop (step() says why).
        return py::make_tuple(dfdx, dfdu, A, B, x_next, in_domain);
      }, py::arg("workspace"), py::arg("step"))
      // forward()'s dx/dt (state_size) at the current state and inputs, without outputs (linearize's tests difference it).
      .def("state_derivative", [](Arm& s) {
        Array xdot({state_size(s.model)});
        StateVec scratch{};
        forward(s.model, s.data, s.data.x.data(), scratch.data(), false);
        std::copy(scratch.begin(), scratch.begin() + state_size(s.model), xdot.mutable_data());
        return xdot;
      })
      // Model functions at any pose.
      .def("muscle_paths", [](const Arm& s, const Array& q) {
        const int nq = s.model.num_dofs;
        const double* qp = checked(q, nq, "q");
        const int n = s.model.num_elements;
        Array L({n}), R({n, nq});
        muscle_paths_by_element(*s.model.def, qp, L.mutable_data(), R.mutable_data());
        return py::make_tuple(L, R);
      })
      .def("gh_directions", [](const Arm& s, const Array& q) {
        Array d({s.model.num_elements, 3});
        s.model.def->gh_directions(checked(q, s.model.num_dofs, "q"), d.mutable_data());
        return d;
      })
      .def("mass_matrix", [](const Arm& s, const Array& q) {
        Array M({s.model.num_dofs, s.model.num_dofs});
        s.model.def->mass_matrix(checked(q, s.model.num_dofs, "q"), M.mutable_data());
        return M;
      })
      .def("bias_force", [](const Arm& s, const Array& q, const Array& qd) {
        Array b({s.model.num_dofs});
        s.model.def->bias_force(checked(q, s.model.num_dofs, "q"), checked(qd, s.model.num_dofs, "qdot"), s.data.settings.gravity.data(), b.mutable_data());
        return b;
      })
      .def("body_poses", [](const Arm& s, const Array& q) {
        const int nb = s.model.def->num_bodies;
        Array R({nb, 3, 3}), p({nb, 3});
        s.model.def->body_poses(checked(q, s.model.num_dofs, "q"), R.mutable_data(), p.mutable_data());
        return py::make_tuple(R, p);
      })
      .def("arm_momentum_rate", [](const Arm& s, const Array& q, const Array& qd) {
        const int nq = s.model.num_dofs;
        Array A({3, nq}), c({3});
        s.model.def->arm_momentum_rate(checked(q, nq, "q"), checked(qd, nq, "qdot"), A.mutable_data(), c.mutable_data());
        return py::make_tuple(A, c);
      })
      .def("girdle_forces", [](const Arm& s, const Array& q) {
        const int nq = s.model.num_dofs;
        Array tau({nq}), K({nq, nq});
        GirdleState st;
        girdle_forces(s.model, checked(q, nq, "q"), tau.mutable_data(), K.mutable_data(), &st);
        const int P = s.model.def->girdle ? s.model.def->girdle->num_contact_points : 0;
        Array dist({P}), force({P});
        std::copy(st.contact_distance.begin(), st.contact_distance.begin() + P, dist.mutable_data());
        std::copy(st.contact_force.begin(), st.contact_force.begin() + P, force.mutable_data());
        return py::dict(py::arg("tau") = tau, py::arg("stiffness") = K, py::arg("contact_distance") = dist,
                        py::arg("contact_force") = force, py::arg("conoid_length") = st.conoid_length,
                        py::arg("conoid_tension") = st.conoid_tension);
      })
      .def("thorax_humerus_angles", [](const Arm& s, const Array& q) {
        Array a({3});
        thorax_humerus_angles(s.model, checked(q, s.model.num_dofs, "q"), a.mutable_data());
        return a;
      })
      .def("passive_joint_torque", [](const Arm& s, const Array& q, const Array& qd) {
        Array t({s.model.num_dofs});
        passive_joint_torque(*s.model.def, checked(q, s.model.num_dofs, "q"), checked(qd, s.model.num_dofs, "qdot"), t.mutable_data());
        return t;
      })
      .def("muscle_element", [](const Arm& s, int i, double L, double lce, double a) {
        if (i < 0 || i >= s.model.num_elements) throw py::index_error("element index out of range");
        const MuscleOut o = muscle_element(data_element(s.model, s.data, i), s.model.fibre_damping, L, lce, a);
        return py::make_tuple(o.force, o.fibre_velocity);
      })
      .def("muscle_equilibrium_lce", [](const Arm& s, int i, double L, double a) {
        if (i < 0 || i >= s.model.num_elements) throw py::index_error("element index out of range");
        return muscle_equilibrium_lce(data_element(s.model, s.data, i), s.model.fibre_damping, L, a);
      })
      .def("gh_stability", [](const Arm& s, const Array& f) {
        const GHStability g = gh_stability(*s.model.def, checked(f, 3, "force"));
        return py::make_tuple(g.theta, g.phi, g.stab);
      })
      // inverse_dynamics.cc with this arm's gravity: a dict of tau_muscle and its parts (ndof,) and the GH force
      // of the non-muscle loads (3,).
      .def("inverse_dynamics", [](const Arm& s, const Array& q, const Array& qd, const Array& qdd, const Array& hf,
                                  const Array& hm) {
        return inverse_dynamics_dict(s.model, s.data.settings.gravity.data(), checked(q, s.model.num_dofs, "q"),
                                     checked(qd, s.model.num_dofs, "qdot"), checked(qdd, s.model.num_dofs, "qddot"),
                                     checked(hf, 3, "hand force"), checked(hm, 3, "hand moment"));
      }, py::arg("q"), py::arg("qdot"), py::arg("qddot"), py::arg("hand_force"), py::arg("hand_moment"))
      // Every element at once with this arm's constants (strength, maximum activation): muscle_steady_force at
      // lengths L (n,), fibre velocities v (n,) and activations a (n,) from CE lengths lce_guess (n,) (NaN: none)
      // -> (lce, F, dF/da), each (n,).
      .def("steady_forces", [](const Arm& s, const Array& L, const Array& v, const Array& a, const Array& guess) {
        const int n = s.model.num_elements;
        const double *Lp = checked(L, n, "L"), *vp = checked(v, n, "fibre velocity"), *ap = checked(a, n, "activation");
        const double* gp = checked(guess, n, "lce guess");
        Array lce({n}), F({n}), dF({n});
        {
          py::gil_scoped_release release;
          for (int i = 0; i < n; ++i) {
            const SteadyForce o = muscle_steady_force(data_element(s.model, s.data, i), s.model.fibre_damping, Lp[i], ap[i], vp[i], gp[i]);
            lce.mutable_data()[i] = o.lce;
            F.mutable_data()[i] = o.force;
            dF.mutable_data()[i] = o.dforce_da;
          }
        }
        return py::make_tuple(lce, F, dF);
      }, py::arg("L"), py::arg("fibre_velocity"), py::arg("activation"), py::arg("lce_guess"))
      // muscle_rigid_tendon_force of every element at lengths L (n,) and rates dL/dt (n,) -> (lce, F per unit
      // activation, passive F), each (n,).
      .def("rigid_tendon_forces", [](const Arm& s, const Array& L, const Array& Ldot) {
        const int n = s.model.num_elements;
        const double *Lp = checked(L, n, "L"), *vp = checked(Ldot, n, "dL/dt");
        Array lce({n}), Fa({n}), Fp({n});
        for (int i = 0; i < n; ++i) {
          const RigidTendonForce o = muscle_rigid_tendon_force(data_element(s.model, s.data, i), s.model.fibre_damping, Lp[i], vp[i]);
          lce.mutable_data()[i] = o.lce;
          Fa.mutable_data()[i] = o.force_per_activation;
          Fp.mutable_data()[i] = o.passive_force;
        }
        return py::make_tuple(lce, Fa, Fp);
      }, py::arg("L"), py::arg("dL_dt"));
}
