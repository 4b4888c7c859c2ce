// RtConfig as given -> checked and completed, with its Schedule (rt_config.h).
#include "rt_config.h"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <tuple>

#include <openssl/evp.h>

#include "armrt/arm.h"
#include "armrt/registry.h"
#include "armrt/static_optimization.h"

namespace armrt::rt {

void load_checked_model_library(const std::string& path) {
  const std::string checksum_path = path + ".sha256";
  std::ifstream checksum(checksum_path);
  std::string expected;
  if (!(checksum >> expected) || expected.size() != 64)
    throw std::invalid_argument("--model-library " + path + ": no checksum " + checksum_path +
                                " (built by an older armrt, or its build was interrupted): rebuild it with "
                                "`armrt model build`");
  std::ifstream lib(path, std::ios::binary);
  if (!lib) throw std::invalid_argument("--model-library " + path + ": cannot read it");
  const std::string bytes((std::istreambuf_iterator<char>(lib)), std::istreambuf_iterator<char>());
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (!EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr))
    throw std::runtime_error("--model-library " + path + ": SHA-256 failed");
  static const char* hex = "0123456789abcdef";
  std::string actual;
  for (unsigned int k = 0; k < length; ++k) {
    actual += hex[digest[k] >> 4];
    actual += hex[digest[k] & 15];
  }
  if (actual != expected)
    throw std::invalid_argument("--model-library " + path + " does not match its checksum (sha256 " +
                                actual.substr(0, 12) + "..., built as " + expected.substr(0, 12) +
                                "...): damaged; rebuild it with `armrt model build`");
  load_model_library(path);
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

namespace {

// A finite number in [lo, hi], else an error naming the option.
void check_range(const char* option, double v, double lo, double hi, const char* unit) {
  if (!std::isfinite(v) || v < lo || v > hi)
    throw std::invalid_argument(std::string(option) + " must be a finite number in [" + fmt(lo) + ", " + fmt(hi) +
                                "] " + unit + ", got " + fmt(v));
}

}  // namespace

Schedule check_config(RtConfig& cfg) {
  Schedule s;
  const Integrator integ = parse_integrator(cfg.integrator);
  if (!is_fixed_cost(integ))
    throw std::invalid_argument(std::string(integrator_name(integ)) +
                                " is not a real-time integrator (its step time is not bounded); use ros2, rk4 or euler");
  check_range("--rate", cfg.rate_hz, 1.0, 10000.0, "Hz");
  s.period_s = 1.0 / cfg.rate_hz;
  // Each cycle advances the simulation by one period (real time); the integrator takes as many
  // substeps of at most integration_step as that needs. Default: default_max_step() (ROS2: one 1 ms step per cycle).
  if (cfg.integration_step != 0) {
    check_range("--integration-step", cfg.integration_step, 1e-7, 1.0, "s");
    if (cfg.integration_step > s.period_s * (1 + 1e-12))
      throw std::invalid_argument("--integration-step " + fmt(cfg.integration_step) +
                                  " s does not fit in one period (1/--rate = " + fmt(s.period_s) + " s)");
  }
  if (cfg.integration_step <= 0) cfg.integration_step = default_max_step(integ);
  s.substeps = std::max(1, static_cast<int>(std::ceil(s.period_s / cfg.integration_step - 1e-9)));
  if (s.substeps > 10000)
    throw std::invalid_argument("--integration-step gives " + std::to_string(s.substeps) +
                                " substeps per period (at most 10000)");
  cfg.integration_step = s.period_s / s.substeps;
  if (cfg.priority < 1 || cfg.priority > 99) throw std::invalid_argument("--priority must be an integer in 1..99");
  if (cfg.cpu < -1 || cfg.cpu >= CPU_SETSIZE) throw std::invalid_argument("--cpu must be a CPU number >= 0");
  // The safety timeout is bounded: at least two periods (one late packet is not a silence), at most 10 s.
  if (cfg.input_timeout == RtConfig{}.input_timeout && cfg.input_timeout < 2 * s.period_s)
    // The default, not the user's number, is what fails at a low rate: say so (a trial's --rate 10 got
    // "--timeout must be ... got 0.1" for an option it never gave).
    throw std::invalid_argument("--timeout defaults to " + fmt(cfg.input_timeout) + " s, shorter than two periods at --rate " +
                                fmt(cfg.rate_hz) + " Hz: give --timeout in [" + fmt(2 * s.period_s) + ", 10] s");
  check_range("--timeout", cfg.input_timeout, 2 * s.period_s, 10.0, "s");
  check_range("--resume-grace", cfg.resume_grace, 0.0, 60.0, "s");
  check_range("--busy-wait", cfg.busy_wait_us, 0.0, 0.5e6 * s.period_s, "us (at most half the period)");
  if (cfg.duration != 0)
    check_range("--duration", cfg.duration, s.period_s, 1e7, "s (0: until stopped; else at least one period)");
  check_range("--max-lag", cfg.max_lag, 0.0, 1e6, "s");
  // --static-optimization's numbers (the GH bound's own limits are checked with the model, static_optimization.cc).
  // 0 is refused, not taken as no bound (the strictest value one would type; static_optimization refuses it too).
  if (cfg.so_gh_stab_max && !(std::isfinite(*cfg.so_gh_stab_max) && *cfg.so_gh_stab_max > 0))
    throw std::invalid_argument("--so-gh-stab-max must be a finite number > 0 (leave it out for no GH bound), got " +
                                fmt(*cfg.so_gh_stab_max));
  if (cfg.so_gh_stab_max && *cfg.so_gh_stab_max < kMinGhStabMax)
    throw std::invalid_argument("--so-gh-stab-max " + fmt(*cfg.so_gh_stab_max) +
                                " is below the smallest bound solved, " + fmt(kMinGhStabMax));
  if (cfg.so_kp && !(std::isfinite(*cfg.so_kp) && *cfg.so_kp >= 0))
    throw std::invalid_argument("--so-kp must be a finite number >= 0 (1/s^2), got " + fmt(*cfg.so_kp));
  if (cfg.so_kd && !(std::isfinite(*cfg.so_kd) && *cfg.so_kd >= 0))
    throw std::invalid_argument("--so-kd must be a finite number >= 0 (1/s), got " + fmt(*cfg.so_kd));
  if (!cfg.static_optimization && (cfg.so_gh_stab_max || cfg.so_kp || cfg.so_kd))
    throw std::invalid_argument("--so-gh-stab-max, --so-kp and --so-kd need --static-optimization");
  // checks.hand_load's rule (the Python API's): three finite values each, and the engine's hand_load_error.
  for (const auto& [name, v, moment] :
       {std::tuple<const char*, const std::vector<double>&, bool>{"--hand-force", cfg.hand_force, false},
        {"--hand-moment", cfg.hand_moment, true}}) {
    if (!v.empty() && v.size() != 3)
      throw std::invalid_argument(std::string(name) + " needs 3 values (x lateral, y up, z posterior; thorax frame), got " +
                                  std::to_string(v.size()));
    for (double x : v)
      if (!std::isfinite(x)) throw std::invalid_argument(std::string(name) + " contains NaN or infinite values");
    if (!v.empty()) {
      const std::string problem = hand_load_error(name, v.data(), moment);
      if (!problem.empty()) throw std::invalid_argument(problem);
    }
  }
  // Arm.settle's check (arm.py: any finite duration >= 0), and at most 1e7 s, as --duration: round(S x rate) cycles
  // must be a count (1e308 overflowed llround, undefined).
  if (!std::isfinite(cfg.settle_s) || cfg.settle_s < 0 || cfg.settle_s > 1e7)
    throw std::invalid_argument("--settle must be a finite number of seconds >= 0 (at most 1e7), got " +
                                fmt(cfg.settle_s));
  if (!std::isfinite(cfg.support_s) || cfg.support_s < 0 || cfg.support_s > 1e7)
    throw std::invalid_argument("--support must be a finite number of seconds >= 0 (at most 1e7), got " +
                                fmt(cfg.support_s));
  if (cfg.rx_budget_us == 0) cfg.rx_budget_us = std::min(150.0, 0.25e6 * s.period_s);
  check_range("--rx-budget", cfg.rx_budget_us, 1.0, 0.5e6 * s.period_s, "us (at most half the period)");
  if (cfg.state_rate_hz == RtConfig{}.state_rate_hz && cfg.state_rate_hz > cfg.rate_hz)
    throw std::invalid_argument("--state-rate defaults to " + fmt(cfg.state_rate_hz) + " Hz, above --rate " +
                                fmt(cfg.rate_hz) + " Hz: give --state-rate in [0, " + fmt(cfg.rate_hz) + "] Hz");
  check_range("--state-rate", cfg.state_rate_hz, 0.0, cfg.rate_hz, "Hz (at most --rate)");
  s.max_cycles = cfg.duration > 0 ? static_cast<std::int64_t>(std::llround(cfg.duration * cfg.rate_hz)) : 0;
  if (cfg.state_rate_hz > 0) {
    // Only rates the loop delivers exactly: one state packet every whole number of cycles.
    const double ratio = cfg.rate_hz / cfg.state_rate_hz;
    const long k = std::lround(ratio);
    if (k < 1 || std::fabs(ratio - static_cast<double>(k)) > 1e-9 * ratio) {
      const long lo = std::max(1L, static_cast<long>(std::floor(ratio))), hi = lo + 1;
      throw std::invalid_argument("--state-rate " + fmt(cfg.state_rate_hz) + " Hz is not --rate / an integer (" +
                                  fmt(cfg.rate_hz) + " Hz / " + fmt(ratio) + "); the nearest are " +
                                  fmt(cfg.rate_hz / lo) + " and " + fmt(cfg.rate_hz / hi) + " Hz");
    }
    s.state_every = static_cast<int>(k);
  }
  if (static_cast<int>(cfg.channels.size()) > 512) throw std::invalid_argument("too many --channels");
  return s;
}

namespace {

// "NAME=VALUE" items -> (name, value) pairs, VALUE a number in [lo, hi]; `what` and `range` word the error.
std::vector<std::pair<std::string, double>> parse_name_values(const std::vector<std::string>& items, const char* what,
                                                              double lo, double hi, const char* range) {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument(std::string(what) + " '" + item + "' is not NAME=VALUE");
    const std::string name = item.substr(0, eq);
    char* end = nullptr;
    const double v = std::strtod(item.c_str() + eq + 1, &end);
    if (end == item.c_str() + eq + 1 || *end != '\0' || !std::isfinite(v) || !(v >= lo && v <= hi))
      throw std::invalid_argument(std::string(what) + " of '" + name + "' must be " + range + ", got '" +
                                  item.substr(eq + 1) + "'");
    out.emplace_back(name, v);
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, double>> parse_max_activation(const std::vector<std::string>& items) {
  return parse_name_values(items, "max activation", 0.0, 1.0, "a number in [0, 1]");
}

std::vector<std::pair<std::string, double>> parse_strength(const std::vector<std::string>& items) {
  return parse_name_values(items, "strength", 0.0, HUGE_VAL, "a finite number >= 0");
}

}  // namespace armrt::rt
