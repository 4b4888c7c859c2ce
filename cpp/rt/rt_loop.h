// The hard-real-time loop: one armrt::Simulator stepped at a fixed rate on a SCHED_FIFO thread, with
// absolute-deadline sleeping, per-cycle TET / wake-up latency / overrun records in preallocated
// storage, and patient-in-the-loop I/O over UDP (packet format: packet.h, docs/realtime.md).
//
// Everything that allocates, locks or makes system calls other than clock_nanosleep, clock_gettime and
// non-blocking recvfrom / sendto happens in prepare() (or start()) and in the statistics after the
// loop; run_cycles() (the hot loop) does none of it (cpp/rt/test_rt.cc checks).
#pragma once

#include <netinet/in.h>
#include <pthread.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "armrt/simulator.h"
#include "packet.h"

namespace armrt::rt {

struct RtConfig {
  // Model and integrator.
  std::string model = "das2";
  std::string integrator = "ros2";
  double rate_hz = 1000.0;     // loop rate
  double dt = 0;               // largest integration step (s); each 1/rate cycle takes ceil(period/dt) substeps; 0: default_max_step() (ros2 1 ms, rk4 0.17 ms, euler 0.1 ms)
  std::vector<double> q0;      // initial joint angles (5, rad); empty: rest posture
  double duration = 0;         // s; 0: until stop() / a signal
  // Real-time set-up.
  bool realtime = true;        // try SCHED_FIFO; false: normal scheduling on purpose
  int priority = 80;           // SCHED_FIFO priority (1..99)
  bool lock_memory = true;     // mlockall(MCL_CURRENT | MCL_FUTURE)
  bool require_rt = false;     // fail (instead of falling back) without SCHED_FIFO / mlockall
  int cpu = -1;                // pin the loop thread to this CPU; -1: no affinity
  double busy_wait_us = 0;     // sleep until deadline - busy_wait_us, then spin on the clock
  std::size_t record_capacity = 0;  // per-cycle records kept; 0: duration * rate (or 10 min if unbounded)
  // UDP I/O. Empty listen: no excitation input.
  std::string listen;          // "host:port" (port 0: ephemeral, see RtLoop::bound_port())
  std::string state_to;        // "host:port"; empty: reply to the last valid controller
  double state_rate_hz = 100;  // state packets per second (0: none); at most rate_hz
  bool send_forces = false;    // append the 102 muscle forces to state packets
  double input_timeout = 0.1;  // s of silence after which the excitation falls to zero
  std::vector<std::string> channels;  // names (element, muscle or group) of the kChannels mapping
  int max_packets_per_cycle = 32;     // bound on the receive work per cycle
};

// Order statistics of one per-cycle quantity, in nanoseconds.
struct Percentiles {
  double min = 0, median = 0, p99 = 0, p999 = 0, max = 0, mean = 0;
  std::int64_t count = 0;
};

struct PacketCounters {
  std::uint64_t received = 0;      // datagrams read
  std::uint64_t applied = 0;       // valid excitation packets applied
  std::uint64_t bad_magic = 0, bad_version = 0, bad_size = 0, bad_type = 0, bad_count = 0;
  std::uint64_t non_finite = 0;    // NaN / inf values
  std::uint64_t stale = 0;         // duplicate sequence number
  std::uint64_t out_of_order = 0;  // sequence number older than the last applied one
  std::uint64_t clipped = 0;       // packets with values outside [0, 1] (applied, clipped)
  std::uint64_t timeouts = 0;      // silences longer than input_timeout (excitation set to zero)
  std::uint64_t state_sent = 0;
  std::uint64_t send_errors = 0;
  std::uint64_t dropped() const {
    return bad_magic + bad_version + bad_size + bad_type + bad_count + non_finite + stale + out_of_order;
  }
};

struct RtStats {
  std::int64_t cycles = 0;        // cycles run
  std::int64_t recorded = 0;      // cycles in the percentiles (the last record_capacity cycles)
  std::int64_t overruns = 0;      // cycles whose work ended after the next deadline
  std::int64_t missed_deadlines = 0;  // whole periods skipped after an overrun
  double elapsed_s = 0;           // wall time of the loop
  double sim_time = 0;            // simulated time at the end
  Percentiles tet;                // model step (Simulator::step) execution time
  Percentiles cycle;              // whole cycle work: receive + step + send
  Percentiles latency;            // wake-up latency: actual wake-up - deadline
  PacketCounters packets;
  std::string scheduler;          // "SCHED_FIFO" or "SCHED_OTHER"
  int priority = 0;
  bool memory_locked = false;
  int cpu = -1;
  std::string rt_note;            // why SCHED_FIFO / mlockall are not in effect ("" when they are)
  std::string stop_reason;        // "duration", "stop", "signal", "diverged", "error"
  std::string error;              // divergence message, or set-up error
  double rate_hz = 0, dt = 0;
  std::string integrator;
};

class RtLoop {
 public:
  explicit RtLoop(const RtConfig& config);  // allocates everything; throws std::invalid_argument
  ~RtLoop();
  RtLoop(const RtLoop&) = delete;
  RtLoop& operator=(const RtLoop&) = delete;

  // Starts the loop thread (real-time set-up, then run_cycles()). Throws std::runtime_error if
  // require_rt and SCHED_FIFO or mlockall is not available. Returns once the thread runs.
  void start();
  void request_stop() { stop_.store(true, std::memory_order_relaxed); }  // async-signal-safe
  void request_stop_signal() { by_signal_.store(true, std::memory_order_relaxed); request_stop(); }
  void join();                   // waits for the thread to end
  bool running() const { return running_.load(std::memory_order_acquire); }
  bool finished() const { return finished_.load(std::memory_order_acquire); }

  // For tests: the synchronous pieces run() is made of. prepare_thread() does the real-time set-up of
  // the calling thread; run_cycles(n) is the hot loop (n <= 0: until stop/duration).
  void prepare_thread();
  void run_cycles(std::int64_t n);

  RtStats stats() const;         // statistics so far (after join(): final). Allocates.
  std::string stats_json() const;
  int bound_port() const { return bound_port_; }
  const RtConfig& config() const { return cfg_; }
  Simulator& simulator() { return *sim_; }
  // Percentiles of an array of ns (sorted copy).
  static Percentiles percentiles(const std::int32_t* v, std::int64_t n);

 private:
  static void* thread_main(void* self);
  void receive_packets(double now_s);
  void apply_packet(const std::uint8_t* buf, long n, const sockaddr_in& from, double now_s);
  void send_state();

  RtConfig cfg_;
  std::unique_ptr<Simulator> sim_;
  int n_el_ = 0;
  double period_ns_ = 0;
  std::int64_t max_cycles_ = 0;         // from duration; 0: unbounded
  int state_every_ = 0;                 // cycles between state packets; 0: none

  // Per-cycle records (ring buffers of record_capacity).
  std::vector<std::int32_t> rec_tet_, rec_cycle_, rec_latency_;
  std::int64_t cap_ = 0;

  // Excitation mappings: element lists per muscle / group / channel (CSR).
  struct Mapping { std::vector<int> offsets, elements; int size() const { return (int)offsets.size() - 1; } };
  Mapping muscles_, groups_, channels_;
  void apply_mapping(const Mapping& m, const double* values);

  // UDP.
  int sock_ = -1;
  int bound_port_ = 0;
  bool have_dest_ = false, fixed_dest_ = false;
  sockaddr_in dest_{};
  std::vector<std::uint8_t> rx_buf_, tx_buf_;
  std::vector<double> values_;          // decoded packet values (kMaxValues)
  bool have_seq_ = false;
  std::uint32_t last_seq_ = 0;
  double last_valid_s_ = -1;            // loop time of the last applied excitation
  bool timed_out_ = true;
  std::uint32_t tx_seq_ = 0;

  // Loop state and results.
  std::atomic<bool> stop_{false}, by_signal_{false}, running_{false}, finished_{false};
  std::atomic<std::int64_t> cycles_{0};
  std::int64_t overruns_ = 0, missed_ = 0;
  double elapsed_s_ = 0;
  PacketCounters pk_;
  std::string scheduler_ = "SCHED_OTHER", rt_note_, stop_reason_, error_;
  int priority_ = 0, cpu_ = -1;
  bool memory_locked_ = false;
  bool diverged_ = false;
  pthread_t thread_{};
  bool thread_started_ = false;
  std::atomic<int> setup_state_{0};     // 0 pending, 1 ok, -1 failed (require_rt)
};

// "host:port" -> sockaddr_in (IPv4, numeric host or "localhost"); throws std::invalid_argument.
sockaddr_in parse_endpoint(const std::string& s);

}  // namespace armrt::rt
