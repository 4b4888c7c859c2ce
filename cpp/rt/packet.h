// packet layout, state-packet table -> the bytes on the wire: the armrt real-time UDP packet format,
// version 3 (specification: docs/realtime.md). This header is the only definition of the layout:
// armrt._rt exports it to Python (armrt.realtime reads offsets, sizes, types, flags and the state
// packet's table from there). All fields are little-endian; values
// are IEEE-754 float64.
//
//   offset size  field
//   0      4     magic    "ARMR" (0x41 0x52 0x4D 0x52)
//   4      2     version  3
//   6      2     type     PacketType
//   8      4     seq      sender's sequence number (wraps modulo 2^32)
//   12     4     length   total packet length in bytes, = 24 + 8 * count (+ 32 with kFlagAuth)
//   16     2     count    number of float64 values that follow
//   18     2     flags    PacketFlags
//   20     4     session  the runner's session id (0: none known yet)
//   24     8*count values
//   24+8*count 32 tag     HMAC-SHA256(key, bytes [0, 24 + 8 * count)), only with kFlagAuth
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace armrt::rt {

inline constexpr std::uint8_t kMagic[4] = {'A', 'R', 'M', 'R'};
// 3: the GH force's angles, rim margin and rim direction follow gh_stab in the state (moving the later values).
inline constexpr std::uint16_t kVersion = 3;
inline constexpr int kHeaderSize = 24;
inline constexpr int kMaxValues = 512;
inline constexpr int kTagSize = 32;  // HMAC-SHA256
inline constexpr int kMaxPacket = kHeaderSize + 8 * kMaxValues + kTagSize;

// Field offsets and sizes (exported to Python as armrt._rt.LAYOUT).
struct FieldDef { const char* name; int offset, size; };
inline constexpr FieldDef kHeaderFields[] = {
    {"magic", 0, 4}, {"version", 4, 2}, {"type", 6, 2}, {"seq", 8, 4},
    {"length", 12, 4}, {"count", 16, 2}, {"flags", 18, 2}, {"session", 20, 4}};

enum PacketType : std::uint16_t {
  kExcitationElements = 1,  // count = number of elements of the model: one excitation per element
  kExcitationMuscles = 2,   // count = number of muscles, in the model's muscle order
  kExcitationGroups = 3,    // count = number of groups, in the model's group order
  kExcitationChannels = 4,  // count = number of configured channels (--channels), each a name
  kRelease = 5,             // controller -> runner, count 0: the owner ends its session
  kHello = 6,               // controller -> runner, count 0: asks for a session id (answered by kOffer)
  kStatePacket = 16,        // runner -> controller / subscribers: see ARMRT_STATE_PACKET_FIELDS below
  kStimulation = 7,         // count = 3 * channels of the runner's --stimulation map, in its order: per channel
                            // pulse width (s), amplitude (A), frequency (Hz); beyond a channel's limits: clamped
  kOffer = 17,              // runner -> controller, count 0: the session id to put in excitation packets
  kSessionEnded = 18,       // runner -> the owner whose session timed out, count 3: reason (1: timeout), hold (s),
                            // resume grace (s); the session field is the ended session's id (docs/realtime.md)
  kTarget = 8,              // count = 3 * DOFs, only with --static-optimization: the desired joint angles (rad),
                            // velocities (rad/s) and accelerations (rad/s^2), in the model's DOF order
};

enum PacketFlags : std::uint16_t {
  kFlagForces = 1,      // state: the muscle forces follow the fixed part
  kFlagStopped = 2,     // state: the loop has stopped (last packet); diverged if kFlagError too
  kFlagError = 4,       // state: the simulation diverged (or lagged beyond --max-lag)
  kFlagTimedOut = 8,    // state: no session (input silence or released): excitation is zero
  kFlagAuth = 16,       // any: a 32-byte HMAC-SHA256 tag follows the values
  kFlagOverrun = 32,    // state: at least one cycle overran since the previous state packet
  kFlagExcitation = 64, // state: the applied element excitations follow (after the forces, if any)
  kFlagStimulation = 128, // state: the applied stimulation and each channel's fatigue follow (a --stimulation map)
};

// The state packet's payload: ONE table, in packet order (MuJoCo's mjxmacro.h style). The runner's
// encoder (put_state_values), the offsets (StateOffsets), armrt._rt.state_packet_fields (the Python
// decoder armrt.realtime.StatePacket, the LSL bridge's channels) and docs/realtime.md come from it.
// Version 3's bytes: tests/data/state_packet_v3_das2.hex. A change here is a new version.
//
//   X(name, size, unit, flag, integer, label, lsl_type, description)
//   size: kOne, kDofs (the model's DOFs, in its order), kThree (x, y, z), kElements (the model's elements),
//         kChannels (the stimulation map's channels), kChannelInputs (3 per channel: pulse width, amplitude, frequency)
//   flag: 0, always sent; else the row is sent only with that PacketFlags bit (in that order, at the end)
//   integer: 1 if the value is an integer carried as a float64 (counts, sequence numbers)
//   label: the value's name (state_fields, LSL channel labels); "{}" is the DOF / axis / element name
#define ARMRT_STATE_PACKET_FIELDS(X)                                                                                   \
  X(time, kOne, "s", 0, 0, "time", "time", "simulated time")                                                           \
  X(q, kDofs, "rad", 0, 0, "{}", "angle", "joint angles, in the model's DOF order (das2: GHy GHz GHyy ELx PSy)")      \
  X(qdot, kDofs, "rad/s", 0, 0, "{}_dot", "angular_velocity", "joint angular velocities")                            \
  X(hand_position, kThree, "m", 0, 0, "hand_{}", "position", "hand position, thorax frame")                           \
  X(gh_stab, kOne, "1", 0, 0, "gh_stab", "stability", "(theta/theta_a)^2 + (phi/phi_a)^2; > 1 beyond the rim")       \
  X(gh_theta, kOne, "rad", 0, 0, "gh_theta", "angle",                                                                  \
    "GH force from the glenoid normal along the major axis (+ superior)")                                              \
  X(gh_phi, kOne, "rad", 0, 0, "gh_phi", "angle", "GH force from the glenoid normal along the minor axis (+ anterior)") \
  X(gh_rim_margin, kOne, "rad", 0, 0, "gh_rim_margin", "margin",                                                       \
    "how far the GH force can still turn towards the rim (< 0: beyond it)")                                           \
  X(gh_rim_direction, kOne, "rad", 0, 0, "gh_rim_direction", "direction",                                              \
    "atan2(gh_phi, gh_theta): 0 superior, pi/2 anterior (armrt/engine.h GHStability)")                                \
  X(last_applied_seq, kOne, "1", 0, 1, "last_seq", "sequence", "last applied excitation seq (-1: none in this session)") \
  X(lag, kOne, "s", 0, 0, "lag", "lag", "simulated time behind the wall-clock schedule")                              \
  X(overruns, kOne, "1", 0, 1, "overruns", "count", "overrun cycles since the start")                                 \
  X(muscle_force, kElements, "N", kFlagForces, 0, "force_{}", "force", "muscle force of each element")                \
  X(excitation, kElements, "1", kFlagExcitation, 0, "excitation_{}", "excitation",                                     \
    "applied element excitations (capped at max activation)")                                                       \
  X(stimulation, kChannelInputs, "s,A,Hz", kFlagStimulation, 0, "{}", "stimulation",                                   \
    "applied stimulation per channel (pulse width s, amplitude A, frequency Hz), after the runner's clamp")           \
  X(fatigue, kChannels, "1", kFlagStimulation, 0, "{}/fatigue", "fatigue",                                            \
    "1 - A/A_rest of each channel's muscle (Ding 2003; 0 rested)")

enum FieldSize { kOne, kDofs, kThree, kElements, kChannels, kChannelInputs };
// The three values of a kChannelInputs row per channel, as labels ("<channel>/pulse_width", ...).
inline constexpr const char* kChannelInputNames[3] = {"pulse_width", "amplitude", "frequency"};
inline int field_size(FieldSize size, int num_dofs, int num_elements, int num_channels) {
  switch (size) {
    case kOne: return 1;
    case kDofs: return num_dofs;
    case kThree: return 3;
    case kElements: return num_elements;
    case kChannels: return num_channels;
    case kChannelInputs: return 3 * num_channels;
  }
  return 0;
}

// One pointer per row, to field_size() values: what fills the packet (the runner points them at the
// simulator's data and its own counters).
struct StateValues {
#define ARMRT_X(name, ...) const double* name = nullptr;
  ARMRT_STATE_PACKET_FIELDS(ARMRT_X)
#undef ARMRT_X
};

// Value offsets of each row in a packet carrying `flags` (-1: a row not sent with those flags), and
// the total count.
struct StateOffsets {
#define ARMRT_X(name, ...) int name = -1;
  ARMRT_STATE_PACKET_FIELDS(ARMRT_X)
#undef ARMRT_X
  int fixed_values = 0;  // values of the rows always sent
  int count = 0;         // values in a packet with these flags
};
inline StateOffsets state_offsets(int num_dofs, int num_elements, std::uint16_t flags, int num_channels = 0) {
  StateOffsets o;
  int c = 0;
#define ARMRT_X(name, size, unit, flag, ...)                        \
  if ((flag) == 0 || (flags & (flag))) {                            \
    o.name = c;                                                     \
    c += field_size(size, num_dofs, num_elements, num_channels);    \
  }                                                                 \
  if ((flag) == 0) o.fixed_values = c;
  ARMRT_STATE_PACKET_FIELDS(ARMRT_X)
#undef ARMRT_X
  o.count = c;
  return o;
}

// The encoder, generated from the table: the rows sent with `flags`, in order, into v; returns the
// number of values. No allocation (the runner's hot loop).
inline int put_state_values(const StateValues& s, std::uint16_t flags, int num_dofs, int num_elements, int num_channels,
                            double* v) {
  int c = 0;
#define ARMRT_X(name, size, unit, flag, ...)                        \
  if ((flag) == 0 || (flags & (flag))) {                            \
    const int n = field_size(size, num_dofs, num_elements, num_channels); \
    for (int k = 0; k < n; ++k) v[c++] = s.name[k];                 \
  }
  ARMRT_STATE_PACKET_FIELDS(ARMRT_X)
#undef ARMRT_X
  return c;
}

// One row of the table for a model (armrt._rt.state_packet_fields).
struct StateFieldInfo {
  std::string name, unit, lsl_type, description;
  std::string rule;  // the size rule: "one", "dofs", "three", "elements", "channels", "channel_inputs"
  int size = 0;
  std::uint16_t flag = 0;
  bool integer = false;
  std::vector<std::string> labels;  // one per value
};
inline std::vector<StateFieldInfo> state_field_table(const std::vector<std::string>& dof_names,
                                                     const std::vector<std::string>& element_names,
                                                     const std::vector<std::string>& channel_names = {}) {
  std::vector<StateFieldInfo> rows;
  static const std::vector<std::string> xyz{"x", "y", "z"};
  std::vector<std::string> channel_inputs;
  for (const std::string& c : channel_names)
    for (const char* v : kChannelInputNames) channel_inputs.push_back(c + "/" + v);
  auto items = [&](FieldSize size) -> const std::vector<std::string>& {
    switch (size) {
      case kDofs: return dof_names;
      case kThree: return xyz;
      case kChannels: return channel_names;
      case kChannelInputs: return channel_inputs;
      default: return element_names;
    }
  };
  static const char* const rule_names[] = {"one", "dofs", "three", "elements", "channels", "channel_inputs"};
#define ARMRT_X(name_, size_, unit_, flag_, integer_, label_, lsl_type_, description_)                        \
  {                                                                                                           \
    StateFieldInfo r;                                                                                         \
    r.name = #name_;                                                                                          \
    r.unit = unit_;                                                                                           \
    r.rule = rule_names[size_];                                                                               \
    r.lsl_type = lsl_type_;                                                                                   \
    r.description = description_;                                                                             \
    r.size = field_size(size_, static_cast<int>(dof_names.size()), static_cast<int>(element_names.size()),   \
                        static_cast<int>(channel_names.size()));                                              \
    r.flag = flag_;                                                                                           \
    r.integer = integer_;                                                                                     \
    const std::string label = label_;                                                                         \
    const auto brace = label.find("{}");                                                                     \
    if (size_ == kOne) r.labels = {label};                                                                    \
    else                                                                                                      \
      for (const std::string& item : items(size_))                                                            \
        r.labels.push_back(label.substr(0, brace) + item + label.substr(brace + 2));                          \
    rows.push_back(std::move(r));                                                                             \
  }
  ARMRT_STATE_PACKET_FIELDS(ARMRT_X)
#undef ARMRT_X
  return rows;
}
// The labels of the values always sent, in order (armrt._rt.state_fields(model)).
inline std::vector<std::string> state_field_names(const std::vector<std::string>& dof_names) {
  std::vector<std::string> out;
  for (const StateFieldInfo& r : state_field_table(dof_names, {}))
    if (r.flag == 0) out.insert(out.end(), r.labels.begin(), r.labels.end());
  return out;
}

inline void put_u16(std::uint8_t* p, std::uint16_t v) { p[0] = v & 0xff; p[1] = v >> 8; }
inline void put_u32(std::uint8_t* p, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) p[k] = (v >> (8 * k)) & 0xff;
}
inline std::uint16_t get_u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
inline std::uint32_t get_u32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}
inline void put_f64(std::uint8_t* p, double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, 8);
  for (int k = 0; k < 8; ++k) p[k] = (u >> (8 * k)) & 0xff;
}
inline double get_f64(const std::uint8_t* p) {
  std::uint64_t u = 0;
  for (int k = 0; k < 8; ++k) u |= static_cast<std::uint64_t>(p[k]) << (8 * k);
  double v;
  std::memcpy(&v, &u, 8);
  return v;
}

struct Header {
  std::uint16_t version = kVersion, type = 0, count = 0, flags = 0;
  std::uint32_t seq = 0, length = 0, session = 0;
};

// Writes header + values into buf (at least kHeaderSize + 8 * count (+ kTagSize) bytes); returns the
// length. With kFlagAuth in flags the length field counts the tag, which the caller appends at
// kHeaderSize + 8 * count (HmacKey::sign).
inline int encode(std::uint8_t* buf, std::uint16_t type, std::uint32_t seq, std::uint16_t flags,
                  const double* values, int count, std::uint32_t session = 0) {
  std::memcpy(buf, kMagic, 4);
  put_u16(buf + 4, kVersion);
  put_u16(buf + 6, type);
  put_u32(buf + 8, seq);
  const int length = kHeaderSize + 8 * count + ((flags & kFlagAuth) ? kTagSize : 0);
  put_u32(buf + 12, static_cast<std::uint32_t>(length));
  put_u16(buf + 16, static_cast<std::uint16_t>(count));
  put_u16(buf + 18, flags);
  put_u32(buf + 20, session);
  for (int k = 0; k < count; ++k) put_f64(buf + kHeaderSize + 8 * k, values[k]);
  return length;
}

enum class DecodeError { kOk, kBadMagic, kBadVersion, kBadSize };

// Checks the header of a received datagram of n bytes (magic, version, length field = n = 24 + 8
// count (+ 32 with kFlagAuth), count <= kMaxValues) and reads it into h.
inline DecodeError decode_header(const std::uint8_t* buf, long n, Header& h) {
  if (n < 4 || std::memcmp(buf, kMagic, 4) != 0) return DecodeError::kBadMagic;
  if (n < 6) return DecodeError::kBadSize;
  h.version = get_u16(buf + 4);
  if (h.version != kVersion) return DecodeError::kBadVersion;
  if (n < kHeaderSize) return DecodeError::kBadSize;
  h.type = get_u16(buf + 6);
  h.seq = get_u32(buf + 8);
  h.length = get_u32(buf + 12);
  h.count = get_u16(buf + 16);
  h.flags = get_u16(buf + 18);
  h.session = get_u32(buf + 20);
  const long tag = (h.flags & kFlagAuth) ? kTagSize : 0;
  if (h.count > kMaxValues || h.length != static_cast<std::uint32_t>(n) ||
      static_cast<long>(kHeaderSize) + 8L * h.count + tag != n)
    return DecodeError::kBadSize;
  return DecodeError::kOk;
}

}  // namespace armrt::rt
