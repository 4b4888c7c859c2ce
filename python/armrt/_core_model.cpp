// Bindings of the model registry and of a ModelDef's functions at any pose (armrt/model.py wraps them).
// A ModelDef is static data of the engine or of a model library that is never unloaded, so Python holds
// plain pointers to it (py::nodelete).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "armrt/engine.h"
#include "armrt/model_def.h"
#include "armrt/registry.h"

namespace py = pybind11;
using namespace armrt;

const double* checked(const py::array_t<double, py::array::c_style | py::array::forcecast>& a, py::ssize_t n,
                      const char* what);  // _core.cpp

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Shape = std::vector<py::ssize_t>;

// Leading (batch) shape of q: () for one pose (ndof,), (k,) for k poses (k, ndof); likewise for any
// per-row input of width ndof (a force: 3).
Shape batch_shape(const Array& q, int ndof, const char* what) {
  if (q.ndim() == 1 && q.shape(0) == ndof) return {};
  if (q.ndim() == 2 && q.shape(1) == ndof) return {q.shape(0)};
  std::string got = "(";
  for (py::ssize_t k = 0; k < q.ndim(); ++k) got += (k ? ", " : "") + std::to_string(q.shape(k));
  throw py::value_error(std::string(what) + " must have shape (" + std::to_string(ndof) + ",) or (k, " +
                        std::to_string(ndof) + "), got " + got + (q.ndim() == 1 ? ",)" : ")"));
}

Shape concat(const Shape& a, Shape b) {
  Shape s = a;
  s.insert(s.end(), b.begin(), b.end());
  return s;
}

py::ssize_t count_of(const Shape& s) {
  py::ssize_t n = 1;
  for (auto v : s) n *= v;
  return n;
}

// Applies f(x_k, out_k...) to every row x_k (of `width` values) of x; outputs have shape batch + tails[i].
template <class F>
std::vector<Array> per_row(const Array& q, int width, const char* what, const std::vector<Shape>& tails, F f) {
  const Shape batch = batch_shape(q, width, what);
  const py::ssize_t k = count_of(batch);
  std::vector<Array> out;
  std::vector<py::ssize_t> stride;
  for (const Shape& t : tails) {
    out.emplace_back(concat(batch, t));
    stride.push_back(count_of(t));
  }
  std::vector<double*> ptr(out.size());
  for (py::ssize_t i = 0; i < k; ++i) {
    for (size_t j = 0; j < out.size(); ++j) ptr[j] = out[j].mutable_data() + i * stride[j];
    f(q.data() + i * width, ptr.data());
  }
  return out;
}

// per_row over poses q (ndof,) or (k, ndof).
template <class F>
std::vector<Array> per_pose(const ModelDef& def, const Array& q, const std::vector<Shape>& tails, F f) {
  return per_row(q, def.num_dofs, "q", tails, f);
}

}  // namespace

// inverse_dynamics.cc's result as a dict of arrays (ndof,), gh_force_without_muscles (3,).
py::dict inverse_dynamics_dict(const Model& m, const double* gravity, const double* q, const double* qd,
                               const double* qdd, const double* hand_force, const double* hand_moment) {
  InverseDynamics r;
  inverse_dynamics(m, gravity, q, qd, qdd, hand_force, hand_moment, &r);
  const int nq = m.num_dofs;
  auto arr = [](const double* p, int n) {
    Array a({n});
    std::copy(p, p + n, a.mutable_data());
    return a;
  };
  return py::dict(py::arg("tau_muscle") = arr(r.tau_muscle, nq), py::arg("mass_times_qddot") = arr(r.mass_times_qdd, nq),
                  py::arg("bias") = arr(r.bias, nq), py::arg("passive") = arr(r.passive, nq),
                  py::arg("external") = arr(r.external, nq), py::arg("girdle") = arr(r.girdle, nq),
                  py::arg("gh_force_without_muscles") = arr(r.gh_force_without_muscles, 3));
}

void bind_model(py::module_& mod) {
  py::class_<ModelDef, std::unique_ptr<ModelDef, py::nodelete>>(mod, "ModelDef",
      "A generated model's tables and functions (engine side of armrt.Model).")
      .def_property_readonly("name", [](const ModelDef& d) { return std::string(d.name); })
      .def_property_readonly("source_hash", [](const ModelDef& d) { return std::string(d.source_hash); })
      .def_property_readonly("num_dofs", [](const ModelDef& d) { return d.num_dofs; })
      .def_property_readonly("num_elements", [](const ModelDef& d) { return d.num_elements; })
      .def_property_readonly("address", [](const ModelDef& d) { return reinterpret_cast<std::uintptr_t>(&d); })
      // Shapes: q is (ndof,) or (k, ndof); outputs gain the same leading k. Frames: scapula.
      .def("muscle_paths", [](const ModelDef& d, const Array& q) {
        const py::ssize_t n = d.num_elements;
        auto o = per_pose(d, q, {{n}, {n, d.num_dofs}},
                          [&](const double* qk, double** out) { muscle_paths_by_element(d, qk, out[0], out[1]); });
        return py::make_tuple(o[0], o[1]);
      }, py::arg("q"))
      .def("muscle_lengths", [](const ModelDef& d, const Array& q) {
        return per_pose(d, q, {{d.num_elements}}, [&](const double* qk, double** out) { d.muscle_lengths(qk, out[0]); })[0];
      }, py::arg("q"))
      .def("gh_directions", [](const ModelDef& d, const Array& q) {
        return per_pose(d, q, {{d.num_elements, 3}}, [&](const double* qk, double** out) { d.gh_directions(qk, out[0]); })[0];
      }, py::arg("q"))
      .def("mass_matrix", [](const ModelDef& d, const Array& q) {
        return per_pose(d, q, {{d.num_dofs, d.num_dofs}}, [&](const double* qk, double** out) { d.mass_matrix(qk, out[0]); })[0];
      }, py::arg("q"))
      .def("hand_position", [](const ModelDef& d, const Array& q) {
        return per_pose(d, q, {{3}}, [&](const double* qk, double** out) { d.hand_position(qk, out[0]); })[0];
      }, py::arg("q"))
      .def("hand_jacobian", [](const ModelDef& d, const Array& q) {
        auto o = per_pose(d, q, {{3, d.num_dofs}, {3, d.num_dofs}}, [&](const double* qk, double** out) { d.hand_jacobian(qk, out[0], out[1]); });
        return py::make_tuple(o[0], o[1]);
      }, py::arg("q"))
      .def("body_poses", [](const ModelDef& d, const Array& q) {
        auto o = per_pose(d, q, {{d.num_bodies, 3, 3}, {d.num_bodies, 3}}, [&](const double* qk, double** out) { d.body_poses(qk, out[0], out[1]); });
        return py::make_tuple(o[0], o[1]);
      }, py::arg("q"))
      // The engine's gh_stability of forces (3,) or (k, 3) (N, scapula frame): theta, phi, GHstab, rim margin,
      // rim direction, each () or (k,).
      .def("gh_stability", [](const ModelDef& d, const Array& f) {
        auto o = per_row(f, 3, "force", {{}, {}, {}, {}, {}}, [&](const double* fk, double** out) {
          const GHStability g = gh_stability(d, fk);
          *out[0] = g.theta;
          *out[1] = g.phi;
          *out[2] = g.stab;
          *out[3] = g.rim_margin;
          *out[4] = g.rim_direction;
        });
        return py::make_tuple(o[0], o[1], o[2], o[3], o[4]);
      }, py::arg("force"))
      // The engine's gh_rim of recorded angles (2,) or (k, 2) (theta, phi, rad) on this model's rim: rim
      // margin and rim direction, each () or (k,).
      .def("gh_rim_of_angles", [](const ModelDef& d, const Array& a) {
        auto o = per_row(a, 2, "gh_angles", {{}, {}}, [&](const double* ak, double** out) {
          gh_rim(ak[0], ak[1], d.rim_half_angle_major, d.rim_half_angle_minor, out[1], out[0]);
        });
        return py::make_tuple(o[0], o[1]);
      }, py::arg("angles"))
      .def("bias_force", [](const ModelDef& d, const Array& q, const Array& qd, const Array& g) {
        if (qd.size() != d.num_dofs || g.size() != 3 || q.ndim() != 1)
          throw py::value_error("bias_force takes one pose: q and qdot of " + std::to_string(d.num_dofs) + ", gravity of 3");
        return per_pose(d, q, {{d.num_dofs}}, [&](const double* qk, double** out) { d.bias_force(qk, qd.data(), g.data(), out[0]); })[0];
      }, py::arg("q"), py::arg("qdot"), py::arg("gravity_base"))
      .def("inverse_dynamics", [](const ModelDef& d, const Array& q, const Array& qd, const Array& qdd, const Array& g,
                                  const Array& hf, const Array& hm) {
        const int nq = d.num_dofs;
        return inverse_dynamics_dict(shared_model(d), checked(g, 3, "gravity"), checked(q, nq, "q"),
                                     checked(qd, nq, "qdot"), checked(qdd, nq, "qddot"), checked(hf, 3, "hand force"),
                                     checked(hm, 3, "hand moment"));
      }, py::arg("q"), py::arg("qdot"), py::arg("qddot"), py::arg("gravity_base"), py::arg("hand_force"),
         py::arg("hand_moment"));

  mod.attr("MODEL_ABI_VERSION") = kModelDefAbiVersion;
  mod.def("find_model", [](const std::string& name) -> const ModelDef* { return find_model(name); },
          py::return_value_policy::reference, "The registered model of that name, or None.");
  mod.def("registered_models", []() { return registered_models(); }, py::return_value_policy::reference,
          "Every registered model (built in first, then in load order).");
  mod.def("load_model_library", [](const std::string& path) -> const ModelDef* {
    try {
      return &load_model_library(path);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
  }, py::arg("path"), py::return_value_policy::reference,
     "Loads (dlopen) and registers a model library built by `armrt model build`; it is never unloaded.");
}
