// snapshot.cc: (model, data, stepper, signature) <-> a flat vector of the signature's parts (layouts.h
// ARMRT_SNAPSHOT), checked against the physical domain before it is set.
#include "armrt/snapshot.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "armrt/engine.h"
#include "armrt/path_history.h"

namespace armrt {

namespace {

// Every joint within its range (margin rad) once q is read as degrees, and some value beyond a full turn, which no
// joint angle in rad is: without that, with the margin, almost any radian pose read as degrees lands in range, and
// GHy = 1.4 rad got the hint (checks.joint_range, the same rule).
bool looks_like_degrees(const ModelDef& def, const double* q, double margin) {
  bool in_range = true, beyond_a_turn = false;
  for (int j = 0; j < def.num_dofs; ++j) {
    const double r = q[j] * (M_PI / 180.0);
    in_range &= r >= def.dofs[j].range_min - margin && r <= def.dofs[j].range_max + margin;
    beyond_a_turn |= std::abs(q[j]) > 2 * M_PI;
  }
  return in_range && beyond_a_turn;
}

bool holds(unsigned signature, SnapshotPart p) { return (signature & snapshot_bit(p)) != 0; }

// One part of a snapshot: which, and where its values lie in the flat vector.
struct PartSpan {
  SnapshotPart part;
  int offset, size;
};

// The parts a signature holds, in table order; returns how many.
int signature_parts(const ModelDef& def, unsigned signature, PartSpan* out, int num_channels) {
  int count = 0, offset = 0;
  for (int k = 0; k < kNumSnapshotParts; ++k) {
    const SnapshotPart p = static_cast<SnapshotPart>(k);
    if (!holds(signature, p)) continue;
    const int n = layout_size(snapshot_rows()[k].size, def, num_channels);
    out[count++] = {p, offset, n};
    offset += n;
  }
  return count;
}

const LayoutRow& row(SnapshotPart p) { return snapshot_rows()[static_cast<int>(p)]; }

// Offset of a state block in x: the blocks lie in x in ARMRT_STATE_BLOCKS order.
int state_block_offset(const ModelDef& def, SnapshotPart p) {
  int offset = 0;
#define ARMRT_X(name, size, ...)                               \
  if (p == SnapshotPart::name) return offset;                  \
  offset += layout_size(SizeRule::size, def);
  ARMRT_STATE_BLOCKS(ARMRT_X)
#undef ARMRT_X
  return -1;
}

// Where a time or input part lives in Data (the field of the row's name), or nullptr for the others.
#define ARMRT_X(name, ...) \
  if (p == SnapshotPart::name) return row_values(d.name);
const double* data_field(const Data& d, SnapshotPart p) {
  ARMRT_SNAPSHOT_TIME(ARMRT_X)
  ARMRT_SNAPSHOT_INPUTS(ARMRT_X)
  ARMRT_SNAPSHOT_STIMULATION(ARMRT_X)
  return nullptr;
}
double* data_field(Data& d, SnapshotPart p) {
  ARMRT_SNAPSHOT_TIME(ARMRT_X)
  ARMRT_SNAPSHOT_INPUTS(ARMRT_X)
  ARMRT_SNAPSHOT_STIMULATION(ARMRT_X)
  return nullptr;
}
#undef ARMRT_X

// ROS2's packed path history (the ros2_path_history row): h, anchors, spacing, steps since the newest, then
// two rows of q.
enum { kHistH = 0, kHistAnchors = 1, kHistSpacing = 2, kHistSince = 3, kHistQ = 4 };

void pack_path_history(const Model& m, const Data& d, const PathHistory& ph, double* out) {
  const int nq = m.num_dofs;
  std::fill(out, out + kHistQ + 2 * nq, 0.0);
  const double* x = d.x.data();
  if (ph.num_anchors == 0 || !path_history_continues(m, ph, x + q_offset(m), x + qd_offset(m), ph.h)) return;
  out[kHistH] = ph.h;
  out[kHistAnchors] = ph.num_anchors;
  out[kHistSpacing] = ph.anchor_spacing;
  out[kHistSince] = ph.steps_since_anchor;
  if (ph.num_anchors == 2) std::copy(ph.anchor_q_old.begin(), ph.anchor_q_old.begin() + nq, out + kHistQ);
  std::copy(ph.anchor_q_new.begin(), ph.anchor_q_new.begin() + nq, out + kHistQ + (ph.num_anchors - 1) * nq);
}

bool whole(double v) { return v >= 0 && v < 1e6 && v == std::floor(v); }

// The element's, DOF's or axis' name of value k of a part, for messages.
std::string value_name(const Model& m, SnapshotPart p, int k) {
  char buf[128];
  const SizeRule size = row(p).size;
  if (size == SizeRule::kDofs) std::snprintf(buf, sizeof buf, "%s[%s]", row(p).name, m.def->dofs[k].name);
  else if (size == SizeRule::kElements) std::snprintf(buf, sizeof buf, "%s[%s]", row(p).name, m.def->elements[k].name);
  else if (size == SizeRule::kOne) std::snprintf(buf, sizeof buf, "%s", row(p).name);
  else std::snprintf(buf, sizeof buf, "%s[%d]", row(p).name, k);
  return buf;
}

std::string path_history_problem(const Model& m, const Data& d, const double* q, const double* hist) {
  const double h = hist[kHistH];
  if (!(h >= 0)) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "its step size h must be >= 0 s, got %g", h);
    return buf;
  }
  if (!whole(hist[kHistAnchors]) || !whole(hist[kHistSpacing]) || !whole(hist[kHistSince]))
    return "its anchor counts must be whole numbers >= 0";
  const int k = static_cast<int>(hist[kHistAnchors]), spacing = static_cast<int>(hist[kHistSpacing]),
            since = static_cast<int>(hist[kHistSince]);
  if (k == 0) {
    if (spacing != 0 || since != 0) return "anchor spacing and steps since the newest anchor must be 0 without anchors";
    return "";
  }
  const std::string counts = path_history_error(k, spacing, since);
  if (!counts.empty()) return counts;
  if (!(h > 0)) return "its step size h must be > 0 s with anchors";
  // The anchors some steps before q: no joint faster than the arm's bound between them. This catches a mistaken
  // anchor that would otherwise only show as a distorted or diverging next step; anchors are the q of exact
  // evaluations and must come from get_snapshot unchanged (an edit within the bound moves the continuation by
  // what it implies).
  const int nq = m.num_dofs;
  const double* newest = hist + kHistQ + (k - 1) * nq;
  struct Gap { const char* name; const double* from; const double* to; int steps; };
  const Gap gaps[2] = {{"the newest anchor", newest, q, since}, {"the oldest anchor", hist + kHistQ, newest, spacing}};
  for (int g = 0; g < (k == 2 ? 2 : 1); ++g) {
    for (int j = 0; j < nq; ++j) {
      const double speed = std::fabs(gaps[g].to[j] - gaps[g].from[j]) / (gaps[g].steps * h);
      if (speed > d.settings.max_joint_speed) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "%s is not %d step(s) of %g s before %s: %s would have moved at %.6g rad/s, beyond "
                      "max_joint_speed %g rad/s (a state whose q or qdot was changed must be set without its "
                      "ROS2 memory)",
                      gaps[g].name, gaps[g].steps, h, g == 0 ? "q" : "the newest anchor", m.def->dofs[j].name, speed,
                      d.settings.max_joint_speed);
        return buf;
      }
    }
  }
  return "";
}

// Why a channel's memory cannot be an arm's: values no run of stimulation reaches.
std::string stimulation_state_problem(const Data& d, const double* in) {
  for (int c = 0; c < d.stimulation_map.num_channels; ++c) {
    const double* st = in + c * kStimStateSize;
    const std::string ch = std::string("channel '") + d.stimulation_map.channels[c].name + "': ";
    if (st[kStimCalciumSum] < 0 || st[kStimCalcium] < 0 || st[kStimForce] < 0 || st[kStimForce] > 2)
      return ch + "calcium sum, CN and force level must be >= 0 (force level <= 2)";
    if (!(st[kStimFatigueA] >= 0 && st[kStimFatigueA] <= 1) || !(st[kStimFatigueTau1] >= 1) || !(st[kStimFatigueKm] >= 1))
      return ch + "fatigue must hold A/A_rest in [0, 1] and tau1, Km at least their rested values";
    if (!(st[kStimRecruitment] >= 0 && st[kStimRecruitment] <= 1)) return ch + "recruitment must lie in [0, 1]";
    const double q = st[kStimQueued];
    if (!(q >= 0 && q <= kMaxQueuedPulses && q == std::floor(q)))
      return ch + "queued pulses must be a whole number in [0, " + std::to_string(kMaxQueuedPulses) + "]";
    for (int i = 1; i < static_cast<int>(q); ++i)
      if (st[kStimQueue + i] < st[kStimQueue + i - 1]) return ch + "queued pulse times must increase";
  }
  return "";
}

}  // namespace

int snapshot_size(const ModelDef& def, unsigned signature, int num_channels) {
  if (signature & ~kSnapshotFull)
    throw std::invalid_argument("snapshot signature " + std::to_string(signature) + " has bits beyond the " +
                                std::to_string(kNumSnapshotParts) + " parts (layouts.h ARMRT_SNAPSHOT)");
  int size = 0;
  for (int p = 0; p < kNumSnapshotParts; ++p)
    if (signature & (1u << p)) size += layout_size(snapshot_rows()[p].size, def, num_channels);
  return size;
}

int snapshot_offset(const ModelDef& def, unsigned signature, SnapshotPart part, int num_channels) {
  if (!holds(signature, part)) return -1;
  return snapshot_size(def, signature & (snapshot_bit(part) - 1), num_channels);
}

void get_snapshot(const Model& m, const Data& d, const Stepper& s, unsigned signature, double* out) {
  const ModelDef& def = *m.def;
  PartSpan parts[kNumSnapshotParts];
  const int count = signature_parts(def, signature, parts, d.stimulation_map.num_channels);
  for (int k = 0; k < count; ++k) {
    const auto [p, o, n] = parts[k];
    // The chain's memory per channel here (the order States and pickles have always had), by column in Data.
    if (p == SnapshotPart::stimulation_state) stimulation_state_by_channel(d, out + o);
    else if (const double* field = data_field(d, p)) std::copy(field, field + n, out + o);
    else if (p == SnapshotPart::ros2_path_history) pack_path_history(m, d, s.ros2.path_history, out + o);
    else std::copy(d.x.begin() + state_block_offset(def, p), d.x.begin() + state_block_offset(def, p) + n, out + o);
  }
}

std::string snapshot_error(const Model& m, const Data& d, unsigned signature, const double* in) {
  if (signature & ~kSnapshotFull) return "signature " + std::to_string(signature) + " has unknown bits";
  const ModelDef& def = *m.def;
  StateVec x = d.x;  // the state as it would be once set
  const double* hist = nullptr;
  PartSpan parts[kNumSnapshotParts];
  const int count = signature_parts(def, signature, parts, d.stimulation_map.num_channels);
  for (int k = 0; k < count; ++k) {
    const auto [p, o, n] = parts[k];
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(in[o + i])) return value_name(m, p, i) + " is not finite";
    if (p == SnapshotPart::excitation) {
      for (int i = 0; i < n; ++i)
        if (in[o + i] < 0 || in[o + i] > 1) {
          char buf[160];
          std::snprintf(buf, sizeof buf, "%s = %.6g is outside [0, 1]", value_name(m, p, i).c_str(), in[o + i]);
          return buf;
        }
    } else if (p == SnapshotPart::hand_force || p == SnapshotPart::hand_moment) {
      // Arm.set_hand_load's bound (engine.h hand_load_error): a state vector set it around the check.
      const bool moment = p == SnapshotPart::hand_moment;
      const std::string problem = hand_load_error(moment ? "hand_moment" : "hand_force", in + o, moment);
      if (!problem.empty()) return problem;
    } else if (p == SnapshotPart::stimulation) {
      for (int c = 0; c < d.stimulation_map.num_channels; ++c) {
        const double* v = in + o + c * kStimInputs;
        const std::string problem =
            stimulation_command_error(d.stimulation_map.channels[c], v[kStimPulseWidth], v[kStimAmplitude], v[kStimFrequency]);
        if (!problem.empty()) return "stimulation: " + problem;
      }
    } else if (p == SnapshotPart::stimulation_state) {
      const std::string problem = stimulation_state_problem(d, in + o);
      if (!problem.empty()) return "stimulation_state: " + problem;
    } else if (p == SnapshotPart::ros2_path_history) {
      hist = in + o;
    } else if (!data_field(static_cast<const Data&>(d), p)) {
      std::copy(in + o, in + o + n, x.begin() + state_block_offset(def, p));
    }
  }
  if (signature & kSnapshotPhysics) {
    const DomainCheck c = check_domain(m, d, x.data());
    if (c.status == Status::kTooFast) {
      char name[96], buf[192];
      std::snprintf(buf, sizeof buf, "%s = %.4g rad/s is beyond max_joint_speed %g rad/s",
                    state_name(m, c.bad_index, name, sizeof name), x[c.bad_index], d.settings.max_joint_speed);
      return buf;
    }
    if (c.status != Status::kOk) {
      std::string problem = domain_problem(m, d, x.data(), c);
      if (c.bad_index >= 0 && c.bad_index < qd_offset(m)) {
        if (looks_like_degrees(def, x.data() + q_offset(m), kJointRangeMargin))
          problem += " (q is in rad: these values look like degrees)";
      }
      return problem;
    }
  }
  if (hist) {
    const std::string problem = path_history_problem(m, d, x.data() + q_offset(m), hist);
    if (!problem.empty()) return "ros2_path_history: " + problem;
  }
  return "";
}

std::string start_pose_error(const ModelDef& def, const double* q) {
  std::string desc;
  bool far = false;
  for (int j = 0; j < def.num_dofs; ++j) {
    const double lo = def.dofs[j].range_min, hi = def.dofs[j].range_max;
    if (q[j] >= lo && q[j] <= hi) continue;
    far |= !(q[j] >= lo - kStartRangeMargin && q[j] <= hi + kStartRangeMargin);  // NaN too
    char buf[192];
    std::snprintf(buf, sizeof buf, "%s%s = %.4g rad (%.1f deg) outside [%.1f, %.1f] deg", desc.empty() ? "" : "; ",
                  def.dofs[j].name, q[j], q[j] * (180.0 / M_PI), lo * (180.0 / M_PI), hi * (180.0 / M_PI));
    desc += buf;
  }
  if (!far) return "";
  return "q beyond the joint limits: " + desc + "." +
         (looks_like_degrees(def, q, kStartRangeMargin) ? " These look like degrees: q is in radians." : "");
}

void set_snapshot(const Model& m, Data& d, Stepper& s, unsigned signature, const double* in) {
  const ModelDef& def = *m.def;
  snapshot_size(def, signature, d.stimulation_map.num_channels);  // refuses unknown bits
  const double* hist = nullptr;
  PartSpan parts[kNumSnapshotParts];
  const int count = signature_parts(def, signature, parts, d.stimulation_map.num_channels);
  for (int k = 0; k < count; ++k) {
    const auto [p, o, n] = parts[k];
    if (p == SnapshotPart::excitation) data_set_excitation(m, d, in + o);
    else if (p == SnapshotPart::ros2_path_history) hist = in + o;
    else if (p == SnapshotPart::stimulation_state) set_stimulation_state_by_channel(d, in + o);
    else if (double* field = data_field(d, p)) std::copy(in + o, in + o + n, field);
    else std::copy(in + o, in + o + n, d.x.begin() + state_block_offset(def, p));
  }
  if (signature & (kSnapshotPhysics | kSnapshotIntegrator)) {
    stepper_restart(m, d, s);
    if (hist) {
      const double* x = d.x.data();
      path_history_restore(m, s.ros2.path_history, x + q_offset(m), x + qd_offset(m), hist + kHistQ,
                           static_cast<int>(hist[kHistAnchors]), static_cast<int>(hist[kHistSpacing]),
                           static_cast<int>(hist[kHistSince]), hist[kHistH]);
    }
  }
  d.status = Status::kOk;
  d.bad_index = -1;
  d.bad_contact = -1;
}

}  // namespace armrt
