// The armrt real-time UDP packet format, version 3 (specification: docs/realtime.md). This header is
// the only definition of the layout: armrt._rt exports it to Python (armrt.realtime reads offsets,
// sizes, types, flags and the state value names from there). All fields are little-endian; values
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
  kState = 16,              // runner -> controller / subscribers: see the state layout below
  kOffer = 17,              // runner -> controller, count 0: the session id to put in excitation packets
};

enum PacketFlags : std::uint16_t {
  kFlagForces = 1,      // state: the muscle forces follow the fixed part
  kFlagStopped = 2,     // state: the loop has stopped (last packet); diverged if kFlagError too
  kFlagError = 4,       // state: the simulation diverged (or lagged beyond --max-lag)
  kFlagTimedOut = 8,    // state: no session (input silence or released): excitation is zero
  kFlagAuth = 16,       // any: a 32-byte HMAC-SHA256 tag follows the values
  kFlagOverrun = 32,    // state: at least one cycle overran since the previous state packet
  kFlagExcitation = 64, // state: the applied element excitations follow (after the forces, if any)
};

// State payload (values): the fixed part below, then muscle_force[n_elements] if kFlagForces, then
// excitation[n_elements] if kFlagExcitation. The fixed part depends on the model's number of DOFs n:
//   time                 s, simulated
//   q0 .. q{n-1}         rad, in the model's DOF order (das2: GHy GHz GHyy ELx PSy)
//   qd0 .. qd{n-1}       rad/s
//   hand_x hand_y hand_z m, thorax frame
//   gh_stab              1, (theta/theta_a)^2 + (phi/phi_a)^2
//   gh_theta gh_phi      rad, GH force from the glenoid normal along the major (+ superior) / minor (+ anterior) axis
//   gh_rim_margin        rad, how far the GH force can still turn towards the rim (< 0: beyond it)
//   gh_rim_direction     rad, atan2(gh_phi, gh_theta): 0 superior, pi/2 anterior (armrt/engine.h GHStability)
//   last_seq             last applied excitation seq (-1: none in this session)
//   lag                  s, simulated time behind the wall-clock schedule
//   overruns             overrun cycles since the start
struct StateLayout {
  int time = 0, q = 1, qd = 0, hand = 0, gh_stab = 0, gh_theta = 0, gh_phi = 0, gh_rim_margin = 0, gh_rim_direction = 0;
  int last_seq = 0, lag = 0, overruns = 0;
  int fixed_values = 0;  // values before the optional force / excitation blocks
};
inline StateLayout state_layout(int num_dofs) {
  StateLayout s;
  s.qd = s.q + num_dofs;
  s.hand = s.qd + num_dofs;
  s.gh_stab = s.hand + 3;
  s.gh_theta = s.gh_stab + 1;
  s.gh_phi = s.gh_theta + 1;
  s.gh_rim_margin = s.gh_phi + 1;
  s.gh_rim_direction = s.gh_rim_margin + 1;
  s.last_seq = s.gh_rim_direction + 1;
  s.lag = s.last_seq + 1;
  s.overruns = s.lag + 1;
  s.fixed_values = s.overruns + 1;
  return s;
}
// The names of the fixed values, in order (exported to Python as armrt._rt.state_fields(model)).
inline std::vector<std::string> state_field_names(int num_dofs) {
  std::vector<std::string> f{"time"};
  for (int j = 0; j < num_dofs; ++j) f.push_back("q" + std::to_string(j));
  for (int j = 0; j < num_dofs; ++j) f.push_back("qd" + std::to_string(j));
  for (const char* n : {"hand_x", "hand_y", "hand_z", "gh_stab", "gh_theta", "gh_phi", "gh_rim_margin", "gh_rim_direction",
                        "last_seq", "lag", "overruns"}) f.push_back(n);
  return f;
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
