// The armrt real-time UDP packet format, version 1 (specification: docs/realtime.md). All fields are
// little-endian; values are IEEE-754 float64.
//
//   offset size  field
//   0      4     magic    "ARMR" (0x41 0x52 0x4D 0x52)
//   4      2     version  1
//   6      2     type     PacketType
//   8      4     seq      sender's sequence number (wraps modulo 2^32)
//   12     4     length   total packet length in bytes, = 24 + 8 * count
//   16     2     count    number of float64 values that follow
//   18     2     flags    PacketFlags
//   20     4     reserved 0
//   24     8*count values
#pragma once

#include <cstdint>
#include <cstring>

namespace armrt::rt {

inline constexpr std::uint8_t kMagic[4] = {'A', 'R', 'M', 'R'};
inline constexpr std::uint16_t kVersion = 1;
inline constexpr int kHeaderSize = 24;
inline constexpr int kMaxValues = 512;
inline constexpr int kMaxPacket = kHeaderSize + 8 * kMaxValues;

enum PacketType : std::uint16_t {
  kExcitationElements = 1,  // count = number of elements (102): one excitation per element
  kExcitationMuscles = 2,   // count = number of muscles (22), in the model's muscle order
  kExcitationGroups = 3,    // count = number of groups, in the model's group order
  kExcitationChannels = 4,  // count = number of configured channels (--channels), each a name
  kState = 16,              // runner -> controller: see state layout below
};

enum PacketFlags : std::uint16_t {
  kFlagForces = 1,    // state: the muscle forces follow the fixed part
  kFlagStopped = 2,   // state: the loop has stopped (last packet); diverged if kFlagError too
  kFlagError = 4,     // state: the simulation diverged
  kFlagTimedOut = 8,  // state: input silence, excitation is zero
};

// State payload (values): time, q[5], qdot[5], hand_position[3] (thorax frame, m), gh_stab,
// last applied excitation seq (as a float64; -1 if none), then muscle_force[n] if kFlagForces.
inline constexpr int kStateFixedValues = 1 + 5 + 5 + 3 + 1 + 1;

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
  std::uint32_t seq = 0, length = 0;
};

// Writes header + values into buf (at least kHeaderSize + 8 * count bytes); returns the length.
inline int encode(std::uint8_t* buf, std::uint16_t type, std::uint32_t seq, std::uint16_t flags,
                  const double* values, int count) {
  std::memcpy(buf, kMagic, 4);
  put_u16(buf + 4, kVersion);
  put_u16(buf + 6, type);
  put_u32(buf + 8, seq);
  const int length = kHeaderSize + 8 * count;
  put_u32(buf + 12, static_cast<std::uint32_t>(length));
  put_u16(buf + 16, static_cast<std::uint16_t>(count));
  put_u16(buf + 18, flags);
  put_u32(buf + 20, 0);
  for (int k = 0; k < count; ++k) put_f64(buf + kHeaderSize + 8 * k, values[k]);
  return length;
}

enum class DecodeError { kOk, kBadMagic, kBadVersion, kBadSize };

// Checks the header of a received datagram of n bytes (magic, version, length field = n = 24 + 8
// count, count <= kMaxValues) and reads it into h.
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
  if (h.count > kMaxValues || h.length != static_cast<std::uint32_t>(n) ||
      static_cast<long>(kHeaderSize) + 8L * h.count != n)
    return DecodeError::kBadSize;
  return DecodeError::kOk;
}

}  // namespace armrt::rt
