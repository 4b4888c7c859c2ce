// pybind11 bindings of armrt::Batch (armrt/batch.py validates inputs and names things). State, inputs
// and outputs are zero-copy (n, ...) views whose row stride is one Arm: no copy per step.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "armrt/batch.h"
#include "armrt/layouts.h"
#include "armrt/engine.h"
#include "armrt/snapshot.h"
#include "armrt/stimulation.h"

namespace py = pybind11;
using namespace armrt;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<long, py::array::c_style | py::array::forcecast>;

// A (n,) or (n, width) view of one field of every arm's Arm, kept alive by `owner`.
py::array arm_view(Batch& b, const double* field_of_arm0, py::ssize_t width, py::handle owner) {
  const py::ssize_t n = b.size();
  const auto row = static_cast<py::ssize_t>(Batch::stride());
  auto* ptr = const_cast<double*>(field_of_arm0);
  if (width == 0) return py::array_t<double>({n}, {row}, ptr, owner);
  return py::array_t<double>({n, width}, {row, static_cast<py::ssize_t>(sizeof(double))}, ptr, owner);
}

// Number of girdle contact points of the batch's model; AttributeError for a model with a fixed girdle.
py::ssize_t contact_points(Batch& b) {
  const ModelDef& def = *b.arm(0).model.def;
  if (!def.girdle) throw py::attribute_error(std::string("model ") + def.name + " has no moving girdle");
  return def.girdle->num_contact_points;
}

const ModelDef& require_model(const std::string& name) {
  const ModelDef* def = find_model(name);
  if (!def) throw py::value_error("unknown model '" + name + "' (registered models: " + model_names() + ")");
  return *def;
}

// Rows of an (m, width) array, m = number of selected arms; nullptr for None.
const double* rows(const py::object& o, Array& keep, py::ssize_t m, py::ssize_t width, const char* what) {
  if (o.is_none()) return nullptr;
  keep = o.cast<Array>();
  if (keep.ndim() != 2 || keep.shape(0) != m || keep.shape(1) != width)
    throw py::value_error(std::string(what) + ": expected shape (" + std::to_string(m) + ", " + std::to_string(width) + ")");
  return keep.data();
}

std::vector<int> arm_indices(Batch& b, const IndexArray& idx) {
  std::vector<int> out(idx.data(), idx.data() + idx.size());
  for (int i : out)
    if (i < 0 || i >= b.size()) throw py::index_error("arm index " + std::to_string(i) + " out of range for " + std::to_string(b.size()) + " arms");
  return out;
}

}  // namespace

PYBIND11_MODULE(_batch, mod) {
  mod.doc() = "armrt batch bindings (use armrt.ArmBatch)";
  mod.def("default_threads", &batch_default_threads);
  // Bytes of one arm (the batch holds them in one block): ArmBatch refuses an n that cannot fit before asking.
  mod.attr("ARM_BYTES") = static_cast<py::ssize_t>(Batch::stride());
  // libarmrt holds the one model registry: a model armrt.model loaded is found here too.

  py::class_<Batch>(mod, "Batch")
      .def(py::init([](const std::string& model, int n, const std::string& integrator, double dt, int substeps) {
             return std::make_unique<Batch>(require_model(model), n, parse_integrator(integrator), dt, substeps);
           }),
           py::arg("model"), py::arg("n"), py::arg("integrator"), py::arg("dt"), py::arg("substeps") = 1)
      .def_property_readonly("n", &Batch::size)
      .def_property_readonly("num_elements", [](Batch& b) { return b.arm(0).model.num_elements; })
      .def_property_readonly("state_size", [](Batch& b) { return state_size(b.arm(0).model); })
      .def_property_readonly("substeps", [](Batch& b) { return b.arm(0).stepper.substeps; })
      .def_property_readonly("dt", [](Batch& b) { return b.arm(0).stepper.dt; })
      .def_property_readonly("integrator", [](Batch& b) { return integrator_name(b.arm(0).stepper.integrator); })
      // Zero-copy views.
      .def_property_readonly("state", [](py::object self) {
        auto& b = self.cast<Batch&>();
        return arm_view(b, b.arm(0).data.x.data(), state_size(b.arm(0).model), self);
      })
      .def_property_readonly("time", [](py::object self) { auto& b = self.cast<Batch&>(); return arm_view(b, &b.arm(0).data.time, 0, self); })
      .def_property_readonly("excitation", [](py::object self) {
        auto& b = self.cast<Batch&>();
        return arm_view(b, b.arm(0).data.excitation.data(), b.arm(0).model.num_elements, self);
      })
      .def_property_readonly("hand_force", [](py::object self) { auto& b = self.cast<Batch&>(); return arm_view(b, b.arm(0).data.hand_force.data(), 3, self); })
      .def_property_readonly("hand_moment", [](py::object self) { auto& b = self.cast<Batch&>(); return arm_view(b, b.arm(0).data.hand_moment.data(), 3, self); })
      .def_property_readonly("applied_moment", [](py::object self) {
        auto& b = self.cast<Batch&>();
        return arm_view(b, b.arm(0).data.applied_moment.data(), b.arm(0).model.num_dofs, self);
      })
      // A zero-copy (n,) or (n, width) view of one ARMRT_OUTPUTS row (layouts.h) of every arm; AttributeError for
      // a girdle row of a model without girdle forces, KeyError for a name that is not a row.
      .def("output_view", [](py::object self, const std::string& name) -> py::array {
        auto& b = self.cast<Batch&>();
        const Data& d = b.arm(0).data;
        const ModelDef& def = *b.arm(0).model.def;
#define ARMRT_X(row, size, unit, stage, girdle_only, recorded, description)                              \
        if (name == #row) {                                                                               \
          if ((girdle_only) && !def.girdle) contact_points(b);                                            \
          return arm_view(b, row_values(d.row), SizeRule::size == SizeRule::kOne ? 0 : layout_size(SizeRule::size, def), self); \
        }
        ARMRT_OUTPUTS(ARMRT_X)
#undef ARMRT_X
        throw py::key_error("no output '" + name + "' (layouts.h ARMRT_OUTPUTS)");
      }, py::arg("name"))
      // Every arm's held excitation from an (n, elements) array, stored as the dynamics use it (capped at the
      // arm's max_activation: data_set_excitation, the engine's one cap rule).
      .def("set_excitation", [](Batch& b, const Array& u) {
        const int ne = b.arm(0).model.num_elements;
        if (u.ndim() != 2 || u.shape(0) != b.size() || u.shape(1) != ne)
          throw py::value_error("excitation: expected shape (" + std::to_string(b.size()) + ", " + std::to_string(ne) + ")");
        for (int i = 0; i < b.size(); ++i) data_set_excitation(b.arm(i).model, b.arm(i).data, u.data() + i * ne);
      }, py::arg("u"))
      // Stimulation (stimulation.h): one map (JSON text, checked by the engine) for every arm; commands as an
      // (n, channels * 3) array, every arm's checked before any is written.
      .def("set_stimulation_map_json", [](Batch& b, const std::string& text) {
        const StimulationMap map = stimulation_map_from_json(*b.arm(0).model.def, text);
        for (int i = 0; i < b.size(); ++i) data_set_stimulation_map(b.arm(i).model, b.arm(i).data, map);
      }, py::arg("text"))
      .def("set_stimulation", [](Batch& b, const Array& cmd) {
        const int nc = b.arm(0).data.stimulation_map.num_channels;
        if (cmd.ndim() != 2 || cmd.shape(0) != b.size() || cmd.shape(1) != 3 * nc)
          throw py::value_error("stimulation: expected shape (" + std::to_string(b.size()) + ", " + std::to_string(3 * nc) + ")");
        const double* p = cmd.data();
        for (int i = 0; i < b.size(); ++i)
          for (int k = 0; k < nc; ++k) {
            const double* c = p + i * 3 * nc + 3 * k;
            const std::string e = stimulation_command_error(b.arm(i).data.stimulation_map.channels[k], c[0], c[1], c[2]);
            if (!e.empty()) throw py::value_error("arm " + std::to_string(i) + ": " + e);
          }
        for (int i = 0; i < b.size(); ++i) std::copy(p + i * 3 * nc, p + (i + 1) * 3 * nc, b.arm(i).data.stimulation.begin());
      }, py::arg("stimulation"))
      .def_property_readonly("num_channels", [](Batch& b) { return b.arm(0).data.stimulation_map.num_channels; })
      // (n, channels, kStimStateSize) copy of every arm's chain memory.
      .def_property_readonly("stimulation_state", [](Batch& b) {
        const int nc = b.arm(0).data.stimulation_map.num_channels;
        Array out({b.size(), nc, static_cast<int>(kStimStateSize)});
        for (int i = 0; i < b.size(); ++i) stimulation_state_by_channel(b.arm(i).data, out.mutable_data() + i * nc * kStimStateSize);
        return out;
      })
      // Snapshots by signature (snapshot.h), one row per arm.
      .def("snapshot_size", [](Batch& b, unsigned signature) { return snapshot_size(*b.arm(0).model.def, signature, b.arm(0).data.stimulation_map.num_channels); },
           py::arg("signature"))
      .def("get_snapshot", [](Batch& b, unsigned signature) {
        const int n = snapshot_size(*b.arm(0).model.def, signature, b.arm(0).data.stimulation_map.num_channels);
        Array out({static_cast<py::ssize_t>(b.size()), static_cast<py::ssize_t>(n)});
        for (int i = 0; i < b.size(); ++i)
          get_snapshot(b.arm(i).model, b.arm(i).data, b.arm(i).stepper, signature, out.mutable_data() + i * n);
        return out;
      }, py::arg("signature"))
      // Sets the selected arms (one row each); every row is checked (snapshot_error) before any is written:
      // ValueError naming the arm's index and the value.
      .def("set_snapshot", [](Batch& b, unsigned signature, const IndexArray& arms, const Array& x) {
        const std::vector<int> idx = arm_indices(b, arms);
        const auto m = static_cast<py::ssize_t>(idx.size());
        Array keep;
        const double* p = rows(x, keep, m, snapshot_size(*b.arm(0).model.def, signature, b.arm(0).data.stimulation_map.num_channels), "state vector");
        const int n = snapshot_size(*b.arm(0).model.def, signature, b.arm(0).data.stimulation_map.num_channels);
        for (py::ssize_t k = 0; k < m; ++k) {
          const Arm& a = b.arm(idx[k]);
          const std::string error = snapshot_error(a.model, a.data, signature, p + k * n);
          if (!error.empty()) throw py::value_error("state vector of arm " + std::to_string(idx[k]) + ": " + error);
        }
        for (py::ssize_t k = 0; k < m; ++k) {
          Arm& a = b.arm(idx[k]);
          set_snapshot(a.model, a.data, a.stepper, signature, p + k * n);
        }
      }, py::arg("signature"), py::arg("arms"), py::arg("x"))
      // Errors.
      .def("status", [](Batch& b) {
        py::array_t<int> s({static_cast<py::ssize_t>(b.size())});
        for (int i = 0; i < b.size(); ++i) s.mutable_data()[i] = static_cast<int>(b.arm(i).data.status);
        return s;
      })
      .def("bad_index", [](Batch& b, int i) { return b.arm(i).data.bad_index; })
      .def("error_message", [](Batch& b, int i) {
        if (i < 0 || i >= b.size()) throw py::index_error("arm index out of range");
        return b.arm(i).error_message();
      })
      // Stepping: returns the indices of the arms that diverged during this call.
      .def("step", [](Batch& b, long steps, int num_threads, bool outputs) {
        int failed;
        {
          py::gil_scoped_release release;
          failed = b.step(steps, num_threads, outputs);
        }
        py::array_t<long> idx({static_cast<py::ssize_t>(failed)});
        long k = 0;
        for (int i = 0; i < b.size() && k < failed; ++i) if (b.newly_failed()[i]) idx.mutable_data()[k++] = i;
        return idx;
      }, py::arg("steps"), py::arg("num_threads") = 0, py::arg("outputs") = true)
      .def("evaluate_outputs", [](Batch& b, int num_threads) {
        py::gil_scoped_release release;
        b.evaluate_outputs(num_threads);
      }, py::arg("num_threads") = 0)
      // reset(arms, q, qdot, activation): arrays with one row per selected arm, or None; clears errors
      // and sets time to 0.
      .def("reset", [](Batch& b, const IndexArray& arms, py::object q, py::object qd, py::object act) {
        const std::vector<int> idx = arm_indices(b, arms);
        const auto m = static_cast<py::ssize_t>(idx.size());
        Array qa, qda, aa;
        const int nq = b.arm(0).model.num_dofs;
        const double* qp = rows(q, qa, m, nq, "q");
        const double* qdp = rows(qd, qda, m, nq, "qdot");
        const int ne = b.arm(0).model.num_elements;
        const double* ap = rows(act, aa, m, ne, "activation");
        for (py::ssize_t r = 0; r < m; ++r) {
          Arm& s = b.arm(idx[r]);
          s.data.status = Status::kOk;
          s.data.bad_index = -1;
          s.data.bad_contact = -1;
          s.reset(qp ? qp + r * nq : nullptr, qdp ? qdp + r * nq : nullptr, ap ? ap + r * ne : nullptr);
          s.data.time = 0.0;
          s.evaluate_outputs();
        }
      }, py::arg("arms"), py::arg("q") = py::none(), py::arg("qdot") = py::none(), py::arg("activation") = py::none())
      .def("get_strength", [](Batch& b) {
        const int ne = b.arm(0).model.num_elements;
        Array a({static_cast<py::ssize_t>(b.size()), static_cast<py::ssize_t>(ne)});
        for (int i = 0; i < b.size(); ++i)
          for (int e = 0; e < ne; ++e) a.mutable_data()[i * ne + e] = b.arm(i).data.settings.strength_scale[e];
        return a;
      })
      .def("get_max_activation", [](Batch& b) {
        const int ne = b.arm(0).model.num_elements;
        Array a({static_cast<py::ssize_t>(b.size()), static_cast<py::ssize_t>(ne)});
        for (int i = 0; i < b.size(); ++i)
          for (int e = 0; e < ne; ++e) a.mutable_data()[i * ne + e] = b.arm(i).data.settings.max_activation[e];
        return a;
      })
      // strength and max_activation: (n, elements) each.
      .def("set_strength_and_max_activation", [](Batch& b, const Array& strength, const Array& maxact) {
        const int ne = b.arm(0).model.num_elements;
        Array sa, ma;
        const double* st = rows(strength, sa, b.size(), ne, "strength");
        const double* mx = rows(maxact, ma, b.size(), ne, "max_activation");
        for (int i = 0; i < b.size(); ++i) {
          Arm& arm = b.arm(i);
          const ArmSettings before = arm.data.settings;
          for (int e = 0; e < ne; ++e) {
            arm.data.settings.strength_scale[e] = st[i * ne + e];
            arm.data.settings.max_activation[e] = mx[i * ne + e];
          }
          try {
            arm.apply_settings();
          } catch (...) {
            arm.data.settings = before;  // refused: this arm keeps what it had
            throw;
          }
        }
      })
      .def("tet_mean_ns", [](Batch& b) {
        Array a({static_cast<py::ssize_t>(b.size())});
        for (int i = 0; i < b.size(); ++i) a.mutable_data()[i] = b.arm(i).data.tet.mean_ns;
        return a;
      });
}
