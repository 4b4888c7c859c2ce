// A number in an engine error message, "%.6g": std::to_string's "%f" wrote 1e300 with 300 digits and 1e-9 as
// 0.000000. Internal to the engine (stimulation_map.cc, static_optimization.cc).
#pragma once

#include <cstdio>
#include <string>

namespace armrt::detail {

inline std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace armrt::detail
