// Monotonic wall clock for TET and benchmarks: one clock_gettime, no allocation, no locks.
#pragma once

#include <cstdint>
#include <ctime>

namespace armrt {

// ns since an arbitrary fixed point (CLOCK_MONOTONIC: unaffected by wall-clock changes).
inline std::int64_t now_ns() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

}  // namespace armrt
