// pybind11 bindings of the real-time loop (cpp/rt/rt_loop.h): armrt.realtime.RealtimeSession wraps
// them. The loop runs on its own C++ thread (SCHED_FIFO when permitted) and never touches Python;
// blocking calls release the GIL.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <time.h>

#include <string>
#include <vector>

#include <arpa/inet.h>

#include "endpoint.h"
#include "hmac.h"
#include "packet.h"
#include "rt_loop.h"

namespace py = pybind11;
using namespace armrt::rt;

namespace {

// The runner's statistics as a dict: rt_stats.cc's JSON, the one place they are written (armrt-rt --json gives
// the same document).
py::object stats_dict(const RtLoop& loop) {
  return py::module_::import("json").attr("loads")(loop.stats_json());
}

}  // namespace

PYBIND11_MODULE(_rt, m) {
  m.doc() = "armrt real-time loop (C++ thread, SCHED_FIFO when permitted) with UDP I/O";
  // libarmrt's one model registry: a model armrt.model loaded is found here too.
  // The packet layout, defined once in cpp/rt/packet.h; armrt.realtime builds its codec from it.
  m.attr("MAGIC") = py::bytes(reinterpret_cast<const char*>(kMagic), 4);
  m.attr("VERSION") = static_cast<int>(kVersion);
  m.attr("HEADER_SIZE") = kHeaderSize;
  m.attr("MAX_VALUES") = kMaxValues;
  m.attr("TAG_SIZE") = kTagSize;
  py::list fields;
  for (const auto& f : kHeaderFields) fields.append(py::make_tuple(f.name, f.offset, f.size));
  m.attr("HEADER_FIELDS") = fields;
  py::dict types;
  types["elements"] = static_cast<int>(kExcitationElements);
  types["muscles"] = static_cast<int>(kExcitationMuscles);
  types["groups"] = static_cast<int>(kExcitationGroups);
  types["channels"] = static_cast<int>(kExcitationChannels);
  types["release"] = static_cast<int>(kRelease);
  types["hello"] = static_cast<int>(kHello);
  types["state"] = static_cast<int>(kStatePacket);
  types["offer"] = static_cast<int>(kOffer);
  types["target"] = static_cast<int>(kTarget);
  types["stimulation"] = static_cast<int>(kStimulation);
  types["session_ended"] = static_cast<int>(kSessionEnded);
  m.attr("TYPES") = types;
  py::dict flags;
  flags["forces"] = static_cast<int>(kFlagForces);
  flags["stopped"] = static_cast<int>(kFlagStopped);
  flags["error"] = static_cast<int>(kFlagError);
  flags["timed_out"] = static_cast<int>(kFlagTimedOut);
  flags["auth"] = static_cast<int>(kFlagAuth);
  flags["overrun"] = static_cast<int>(kFlagOverrun);
  flags["excitation"] = static_cast<int>(kFlagExcitation);
  flags["stimulation"] = static_cast<int>(kFlagStimulation);
  m.attr("FLAGS") = flags;
  // The state packet's table (packet.h ARMRT_STATE_PACKET_FIELDS) for a model: its sizes and labels
  // depend on the model's DOFs and elements.
  auto require = [](const std::string& model) -> const armrt::ModelDef& {
    const armrt::ModelDef* def = armrt::find_model(model);
    if (!def) throw py::value_error("unknown model '" + model + "' (registered models: " + armrt::model_names() + ")");
    return *def;
  };
  auto names_of = [](const armrt::ModelDef& def) {
    std::vector<std::string> dofs, els;
    for (int j = 0; j < def.num_dofs; ++j) dofs.emplace_back(def.dofs[j].name);
    for (int i = 0; i < def.num_elements; ++i) els.emplace_back(def.elements[i].name);
    return std::pair{dofs, els};
  };
  m.def("state_packet_fields", [require, names_of](const std::string& model, const std::vector<std::string>& channels) {
        const auto [dofs, els] = names_of(require(model));
        py::list rows;
        for (const StateFieldInfo& r : state_field_table(dofs, els, channels)) {
          py::dict d;
          d["name"] = r.name;
          d["size"] = r.size;
          d["rule"] = r.rule;
          d["unit"] = r.unit;
          d["flag"] = static_cast<int>(r.flag);
          d["integer"] = r.integer;
          d["labels"] = r.labels;
          d["lsl_type"] = r.lsl_type;
          d["description"] = r.description;
          rows.append(d);
        }
        return rows;
      }, py::arg("model") = "das2", py::arg("channels") = std::vector<std::string>{},
      "The state packet's rows in packet order: dicts of name, size (values), rule (one, dofs, three, elements, channels, "
      "channel_inputs), unit, flag (0: always sent, else the PacketFlags bit that adds it), integer, labels (one per value), "
      "lsl_type, description. channels: the stimulation map's channel names (the runner's --stimulation), in its order");
  m.def("state_fields", [require, names_of](const std::string& model) {
        return state_field_names(names_of(require(model)).first);
      }, py::arg("model") = "das2",
      "Labels of the values a state packet of this model always carries, in order (time, GHy.., GHy_dot.., hand_x, ...)");
  m.def("parse_endpoint", [](const std::string& s, bool require_port) {
        const sockaddr_in a = parse_endpoint(s, require_port);
        char b[INET_ADDRSTRLEN] = {};
        inet_ntop(AF_INET, &a.sin_addr, b, sizeof b);
        return py::make_tuple(std::string(b), static_cast<int>(ntohs(a.sin_port)));
      }, py::arg("endpoint"), py::arg("require_port") = false,
      "'host:port' -> (numeric IPv4 host, port) as the runner reads it (empty host or localhost: 127.0.0.1); "
      "ValueError naming the problem");

  m.def("read_key_file", [](const std::string& path) {
        try {
          return py::bytes(read_key_file(path));
        } catch (const KeyFileOpenError& e) {
          errno = e.error;  // OSError (FileNotFoundError, PermissionError, ...) naming the file, as open() raises it
          PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
          throw py::error_already_set();
        }
      }, py::arg("path"),
      "The shared key in a file, by armrt-rt --key-file's rules (cpp/rt/hmac.cc, the one implementation): ValueError "
      "naming the problem, OSError if it cannot be opened");

  py::class_<RtLoop>(m, "RtLoop")
      .def(py::init([](const std::string& model, const std::string& integrator, double rate_hz, double integration_step,
                       std::vector<double> q0, double duration, bool realtime, int priority, bool lock_memory,
                       bool require_rt, int cpu, double busy_wait_us, double max_lag, const std::string& listen,
                       std::vector<std::string> state_to, std::vector<std::string> allow, py::bytes key,
                       double state_rate_hz, bool send_forces, bool send_excitation, double input_timeout,
                       std::vector<std::string> channels, double rx_budget_us,
                       std::vector<std::string> max_activation, const std::string& stimulation,
                       std::vector<std::string> strength, const std::string& profile, double settle,
                       double resume_grace, bool static_optimization, std::optional<double> so_gh_stab_max, std::optional<double> so_kp, std::optional<double> so_kd,
                       double support, std::vector<double> hand_force, std::vector<double> hand_moment) {
             RtConfig c;
             c.model = model;
             c.integrator = integrator;
             c.rate_hz = rate_hz;
             c.integration_step = integration_step;
             c.q0 = std::move(q0);
             c.duration = duration;
             c.realtime = realtime;
             c.priority = priority;
             c.lock_memory = lock_memory;
             c.require_rt = require_rt;
             c.cpu = cpu;
             c.busy_wait_us = busy_wait_us;
             c.max_lag = max_lag;
             c.listen = listen;
             c.state_to = std::move(state_to);
             c.allow = std::move(allow);
             c.key = std::string(key);
             c.state_rate_hz = state_rate_hz;
             c.send_forces = send_forces;
             c.send_excitation = send_excitation;
             c.input_timeout = input_timeout;
             c.channels = std::move(channels);
             c.rx_budget_us = rx_budget_us;
             c.max_activation = std::move(max_activation);
             c.strength = std::move(strength);
             c.stimulation = stimulation;
             c.profile = profile;
             c.settle_s = settle;
             c.support_s = support;
             c.resume_grace = resume_grace;
             c.static_optimization = static_optimization;
             c.so_gh_stab_max = so_gh_stab_max;
             c.so_kp = so_kp;
             c.so_kd = so_kd;
             c.hand_force = std::move(hand_force);
             c.hand_moment = std::move(hand_moment);
             return std::make_unique<RtLoop>(c);
           }),
           py::arg("model") = "das2", py::arg("integrator") = RtConfig{}.integrator, py::arg("rate_hz") = 1000.0,
           py::arg("integration_step") = 0.0, py::arg("q0") = std::vector<double>{}, py::arg("duration") = 0.0,
           py::arg("realtime") = true, py::arg("priority") = 80, py::arg("lock_memory") = false,
           py::arg("require_rt") = false, py::arg("cpu") = -1, py::arg("busy_wait_us") = 0.0,
           py::arg("max_lag") = 0.0, py::arg("listen") = "", py::arg("state_to") = std::vector<std::string>{},
           py::arg("allow") = std::vector<std::string>{}, py::arg("key") = py::bytes(""),
           py::arg("state_rate_hz") = 100.0, py::arg("send_forces") = false, py::arg("send_excitation") = false,
           py::arg("input_timeout") = 0.1, py::arg("channels") = std::vector<std::string>{},
           py::arg("rx_budget_us") = 0.0, py::arg("max_activation") = std::vector<std::string>{},
           py::arg("stimulation") = "", py::arg("strength") = std::vector<std::string>{},
           py::arg("profile") = "", py::arg("settle") = 0.0,
           py::arg("resume_grace") = RtConfig{}.resume_grace, py::arg("static_optimization") = false,
           py::arg("so_gh_stab_max") = py::none(), py::arg("so_kp") = py::none(), py::arg("so_kd") = py::none(), py::arg("support") = 0.0,
           py::arg("hand_force") = std::vector<double>{}, py::arg("hand_moment") = std::vector<double>{})
      .def("start", [](RtLoop& l) {
        py::gil_scoped_release release;
        l.start();
      })
      .def("request_stop", &RtLoop::request_stop)
      .def("stop", [](RtLoop& l) {
        l.request_stop();
        py::gil_scoped_release release;
        l.join();
      })
      // Waits up to timeout s (negative: forever) for the loop to end (duration, divergence); True if it has.
      .def("wait", [](RtLoop& l, double timeout) {
        {
          py::gil_scoped_release release;
          timespec t0;
          clock_gettime(CLOCK_MONOTONIC, &t0);
          while (!l.finished()) {
            timespec now;
            clock_gettime(CLOCK_MONOTONIC, &now);
            const double el = (now.tv_sec - t0.tv_sec) + 1e-9 * (now.tv_nsec - t0.tv_nsec);
            if (timeout >= 0 && el >= timeout) break;
            timespec ts{0, 2000000};
            nanosleep(&ts, nullptr);
          }
          if (l.finished()) l.join();
        }
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        return l.finished();
      }, py::arg("timeout") = -1.0)
      .def_property_readonly("running", &RtLoop::running)
      .def_property_readonly("finished", &RtLoop::finished)
      .def_property_readonly("port", &RtLoop::bound_port)
      .def_property_readonly("integration_step", [](const RtLoop& l) { return l.config().integration_step; })
      .def_property_readonly("n_elements", [](RtLoop& l) { return l.arm().model.num_elements; })
      .def_property_readonly("stimulation_channels", [](RtLoop& l) {
        std::vector<std::string> out;
        const auto& map = l.arm().data.stimulation_map;
        for (int k = 0; k < map.num_channels; ++k) out.emplace_back(map.channels[k].name);
        return out;
      })
      .def("stats", &stats_dict)
      .def("stats_json", &RtLoop::stats_json);
}
