// Recording (recorder.h): moved out of the Python bindings so that it is one C++ loop, tested in C++.
#include "armrt/recorder.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "armrt/engine.h"

namespace armrt {

namespace {

// One row: the state x at `time` and the outputs forward() left in s.data for that state, channel by channel
// in layouts.h's order.
void add_row(Recording& r, const Arm& s, const double* x, double time, double tet_ns) {
  const Model& m = s.model;
  const Data& d = s.data;
  int c = 0;
  auto put = [&](const double* p) {
    if (r.into[c]) {
      std::copy(p, p + r.width[c], r.into[c] + r.num_rows * r.width[c]);
    } else {
      std::vector<double>& v = r.channel[c];
      v.insert(v.end(), p, p + r.width[c]);
    }
    ++c;
  };
  put(&time);
  int offset = 0;
#define ARMRT_X(name, size, ...)  \
  put(x + offset);                \
  offset += layout_size(SizeRule::size, *m.def);
  ARMRT_STATE_BLOCKS(ARMRT_X)
#undef ARMRT_X
#define ARMRT_X(name, ...) put(row_values(d.name));
  ARMRT_RECORDED_INPUTS(ARMRT_X)
#undef ARMRT_X
#define ARMRT_X(name, size, unit, stage, girdle_only, recorded, description) \
  if (recorded) put(row_values(d.name));
  ARMRT_OUTPUTS(ARMRT_X)
#undef ARMRT_X
  put(&tet_ns);
  ++r.num_rows;
}

}  // namespace

std::array<int, kNumChannels> recording_widths(const Arm& s) {
  const ModelDef& def = *s.model.def;
  const LayoutRow* rows = recorded_channels();
  std::array<int, kNumChannels> width{};
  for (int c = 0; c < kNumChannels; ++c)
    width[c] = rows[c].girdle_only && !def.girdle ? 0 : layout_size(rows[c].size, def, s.data.stimulation_map.num_channels);
  return width;
}

long simulate_recorded(Arm& s, const double* u, bool held, long n_steps, long record_every, Recording& r,
                       bool (*stop)(void*), void* ctx) {
  const int n = s.model.num_elements, nq = s.model.num_dofs;
  const ModelDef& def = *s.model.def;
  r.num_dofs = nq;
  r.num_elements = n;
  r.num_contact_points = def.girdle ? def.girdle->num_contact_points : 0;
  const long n_rec = recorded_rows(n_steps, record_every);
  r.width = recording_widths(s);
  const bool external = r.into[0] != nullptr;
  for (int c = 0; c < kNumChannels; ++c) {
    if (external && (r.into[c] == nullptr) != (r.width[c] == 0))
      throw std::invalid_argument(std::string("simulate_recorded: storage for channel ") + recorded_channels()[c].name +
                                  (r.width[c] == 0 ? " given but the arm records none" : " missing"));
    if (!external) r.channel[c].reserve(r.channel[c].size() + n_rec * r.width[c]);
  }
  if (external && r.capacity - r.num_rows < n_rec)
    throw std::invalid_argument("simulate_recorded: " + std::to_string(n_rec) + " rows to record, room for " +
                                std::to_string(r.capacity - r.num_rows));
  // Only a recorded step keeps a copy of its start state (its outputs describe that state).
  std::vector<double> x0(state_size(s.model));
  long done = 0;
  bool stopped = false;
  for (long k = 0; k < n_steps; ++k) {
    const double* uk = u + (held ? 0 : k) * n;
    data_set_excitation(s.model, s.data, uk);  // recorded as the dynamics use it
    const bool rec = k % record_every == 0;
    const double t0 = s.data.time;
    if (rec) std::copy(s.data.x.begin(), s.data.x.begin() + x0.size(), x0.begin());
    if (!s.step(rec)) break;
    ++done;
    if (rec) add_row(r, s, x0.data(), t0, s.data.tet.last_ns);
    if (stop && stop(ctx)) {
      stopped = true;
      break;
    }
  }
  if (!stopped && s.data.status == Status::kOk && n_steps % record_every == 0) {
    s.evaluate_outputs();
    add_row(r, s, s.data.x.data(), s.data.time, 0.0);
  }
  return done;
}

}  // namespace armrt
