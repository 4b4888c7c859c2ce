// armrt-rt: runs the arm model at a fixed rate on a SCHED_FIFO thread, with UDP excitation input and
// state output (docs/realtime.md). Prints TET / wake-up latency percentiles and overruns on exit
// (end of --duration, SIGINT or SIGTERM) and writes them as JSON (--json).
#include <signal.h>
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rt_loop.h"

using armrt::rt::RtConfig;
using armrt::rt::RtLoop;

namespace {

RtLoop* g_loop = nullptr;

void on_signal(int) {
  if (g_loop) g_loop->request_stop_signal();
}

const char* kUsage =
    "usage: armrt-rt [options]\n"
    "  --rate HZ            loop rate (default 1000)\n"
    "  --integrator NAME    ros2 (default: linearly implicit, one step per 1 ms), rk4 or euler\n"
    "  --dt S               largest integration step; each cycle takes ceil(1/rate / dt) substeps\n"
    "                       (default 0.00017 for rk4, 0.0001 for euler)\n"
    "  --model NAME         compiled-in model (default das2)\n"
    "  --q0 A,B,C,D,E       initial joint angles, rad (default: rest posture)\n"
    "  --duration S         run for S seconds (default 0: until SIGINT/SIGTERM)\n"
    "  --priority P         SCHED_FIFO priority 1..99 (default 80)\n"
    "  --no-rt              normal scheduling on purpose (no SCHED_FIFO)\n"
    "  --no-mlock           do not mlockall\n"
    "  --require-rt         exit with status 3 if SCHED_FIFO or mlockall is not available\n"
    "  --cpu N              pin the loop thread to CPU N\n"
    "  --busy-wait US       wake US microseconds early and spin to the deadline\n"
    "  --listen HOST:PORT   UDP excitation input (port 0: any free port, printed)\n"
    "  --state-to HOST:PORT state packets to this address (default: the last valid controller)\n"
    "  --state-rate HZ      state packets per second (default 100; 0: none)\n"
    "  --forces             append the muscle forces to state packets\n"
    "  --timeout S          input silence after which the excitation falls to zero (default 0.1)\n"
    "  --channels A,B,...   names (element, muscle or group) of the channel mapping (packet type 4)\n"
    "  --records N          per-cycle records kept (default: duration * rate, or 10 min)\n"
    "  --json PATH          write the statistics as JSON\n"
    "  --quiet              print only the summary\n";

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) if (!item.empty()) out.push_back(item);
  return out;
}

double to_double(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0') throw std::invalid_argument(opt + ": '" + v + "' is not a number");
  return x;
}

void print_pct(const char* name, const armrt::rt::Percentiles& p) {
  std::printf("  %-8s min %8.1f  median %8.1f  p99 %8.1f  p99.9 %8.1f  max %9.1f  us\n", name, p.min / 1e3,
              p.median / 1e3, p.p99 / 1e3, p.p999 / 1e3, p.max / 1e3);
}

}  // namespace

int main(int argc, char** argv) {
  RtConfig cfg;
  std::string json_path;
  bool quiet = false;
  try {
    for (int k = 1; k < argc; ++k) {
      const std::string a = argv[k];
      auto next = [&]() -> std::string {
        if (k + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++k];
      };
      if (a == "-h" || a == "--help") { std::fputs(kUsage, stdout); return 0; }
      else if (a == "--rate") cfg.rate_hz = to_double(a, next());
      else if (a == "--integrator") cfg.integrator = next();
      else if (a == "--dt") cfg.dt = to_double(a, next());
      else if (a == "--model") cfg.model = next();
      else if (a == "--q0") { cfg.q0.clear(); for (auto& s : split(next())) cfg.q0.push_back(to_double(a, s)); }
      else if (a == "--duration") cfg.duration = to_double(a, next());
      else if (a == "--priority") cfg.priority = static_cast<int>(to_double(a, next()));
      else if (a == "--no-rt") cfg.realtime = false;
      else if (a == "--no-mlock") cfg.lock_memory = false;
      else if (a == "--require-rt") cfg.require_rt = true;
      else if (a == "--cpu") cfg.cpu = static_cast<int>(to_double(a, next()));
      else if (a == "--busy-wait") cfg.busy_wait_us = to_double(a, next());
      else if (a == "--listen") cfg.listen = next();
      else if (a == "--state-to") cfg.state_to = next();
      else if (a == "--state-rate") cfg.state_rate_hz = to_double(a, next());
      else if (a == "--forces") cfg.send_forces = true;
      else if (a == "--timeout") cfg.input_timeout = to_double(a, next());
      else if (a == "--channels") cfg.channels = split(next());
      else if (a == "--records") cfg.record_capacity = static_cast<std::size_t>(to_double(a, next()));
      else if (a == "--json") json_path = next();
      else if (a == "--quiet") quiet = true;
      else throw std::invalid_argument("unknown option " + a);
    }
    if (cfg.require_rt && !cfg.realtime) throw std::invalid_argument("--require-rt and --no-rt contradict each other");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armrt-rt: %s\n%s", e.what(), kUsage);
    return 2;
  }

  std::unique_ptr<RtLoop> loop;
  try {
    loop = std::make_unique<RtLoop>(cfg);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armrt-rt: %s\n", e.what());
    return 2;
  }
  g_loop = loop.get();
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);

  try {
    loop->start();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armrt-rt: %s\n", e.what());
    return 3;
  }
  const auto st0 = loop->stats();
  if (!st0.rt_note.empty())
    std::fprintf(stderr, "armrt-rt: running with %s%s: %s\n", st0.scheduler.c_str(),
                 st0.memory_locked ? "" : ", memory not locked", st0.rt_note.c_str());
  if (!quiet) {
    std::printf("armrt-rt: %s %s at %g Hz (dt %g s), %s priority %d, memory %s, cpu %d\n", cfg.model.c_str(),
                cfg.integrator.c_str(), cfg.rate_hz, loop->config().dt, st0.scheduler.c_str(), st0.priority,
                st0.memory_locked ? "locked" : "not locked", st0.cpu);
    if (!cfg.listen.empty()) std::printf("armrt-rt: listening on udp port %d\n", loop->bound_port());
    std::fflush(stdout);
  }
  while (!loop->finished()) {
    timespec ts{0, 20000000};
    nanosleep(&ts, nullptr);  // a signal interrupts it; the handler has already asked the loop to stop
  }
  loop->join();
  g_loop = nullptr;

  const auto st = loop->stats();
  std::printf("armrt-rt: stopped (%s) after %lld cycles, %.3f s, sim time %.3f s\n", st.stop_reason.c_str(),
              static_cast<long long>(st.cycles), st.elapsed_s, st.sim_time);
  print_pct("TET", st.tet);
  print_pct("cycle", st.cycle);
  print_pct("latency", st.latency);
  std::printf("  overruns %lld (missed periods %lld) over %lld cycles; %s, priority %d, memory %s\n",
              static_cast<long long>(st.overruns), static_cast<long long>(st.missed_deadlines),
              static_cast<long long>(st.cycles), st.scheduler.c_str(), st.priority,
              st.memory_locked ? "locked" : "not locked");
  const auto& k = st.packets;
  std::printf("  packets: received %llu, applied %llu, dropped %llu, timeouts %llu, state sent %llu\n",
              (unsigned long long)k.received, (unsigned long long)k.applied, (unsigned long long)k.dropped(),
              (unsigned long long)k.timeouts, (unsigned long long)k.state_sent);
  std::fflush(stdout);
  if (!json_path.empty()) {
    std::ofstream f(json_path);
    f << loop->stats_json();
    if (!f) std::fprintf(stderr, "armrt-rt: could not write %s\n", json_path.c_str());
  }
  if (st.stop_reason == "diverged") {
    std::fprintf(stderr, "armrt-rt: %s\n", st.error.c_str());
    return 1;
  }
  return 0;
}
