// The hard-real-time loop: one armrt::Simulator stepped at a fixed rate on a SCHED_FIFO thread, with
// absolute-deadline sleeping, per-cycle TET / wake-up latency / overrun records in preallocated
// storage, and patient-in-the-loop I/O over UDP (packet format: packet.h, docs/realtime.md).
//
// Everything that allocates, locks or makes system calls other than clock_nanosleep, clock_gettime and
// non-blocking recvmmsg / sendto happens in prepare() (or start()) and in the statistics after the
// loop; run_cycles() (the hot loop) does none of it (cpp/rt/test_rt.cc checks).
//
// Sessions: excitations are taken from one controller at a time, the session's owner. A controller
// asks for the session id (kHello -> kOffer); the first excitation carrying it claims the session
// when none is active; packets from any other source are then dropped unread beyond the address.
// The session ends on kRelease from the owner or after input_timeout s without a valid packet from
// it: the excitation falls to zero, state stops going to the owner, and a new session id is drawn,
// so no packet of the old session is ever applied again.
#pragma once

#include <netinet/in.h>
#include <pthread.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "armrt/simulator.h"
#include "endpoint.h"
#include "histogram.h"
#include "hmac.h"
#include "packet.h"

namespace armrt::rt {

struct RtConfig {
  // Model and integrator.
  std::string model = "das2";
  std::string integrator = "ros2";
  double rate_hz = 1000.0;     // loop rate
  double dt = 0;               // largest integration step (s); each 1/rate cycle takes ceil(period/dt) substeps; 0: default_max_step() (ros2 1 ms, rk4 0.17 ms, euler 0.1 ms)
  std::vector<double> q0;      // initial joint angles (one per DOF of the model, rad); empty: rest posture
  double duration = 0;         // s; 0: until stop() / a signal
  // Real-time set-up.
  bool realtime = true;        // try SCHED_FIFO; false: normal scheduling on purpose
  int priority = 80;           // SCHED_FIFO priority (1..99)
  bool lock_memory = true;     // mlockall(MCL_CURRENT | MCL_FUTURE)
  bool require_rt = false;     // fail (instead of falling back) without SCHED_FIFO / mlockall
  int cpu = -1;                // pin the loop thread to this CPU; -1: no affinity
  double busy_wait_us = 0;     // sleep until deadline - busy_wait_us, then spin on the clock
  double max_lag = 0;          // s; stop (fail safe) once simulated time lags the schedule by more; 0: never
  // UDP I/O. Empty listen: no excitation input.
  std::string listen;          // "host:port" (port 0: ephemeral, see RtLoop::bound_port())
  std::vector<std::string> state_to;  // "host:port" subscribers that always get state; the owner gets it too
  std::vector<std::string> allow;     // "host[:port]": only these may own a session; empty: anyone
  std::string key;             // shared key (>= 16 bytes): HMAC-SHA256 on every packet; empty: none
  double state_rate_hz = 100;  // state packets per second (0: none); must divide rate_hz
  bool send_forces = false;    // append the muscle forces to state packets
  bool send_excitation = false;  // append the applied element excitations to state packets
  double input_timeout = 0.1;  // s of silence from the owner after which its session ends (excitation 0)
  std::vector<std::string> channels;  // names (element, muscle or group) of the kChannels mapping
  // Paralysis / weakness: "NAME=VALUE" (element, muscle or group; VALUE in [0, 1]) caps the
  // activation every excitation source can produce; later entries override earlier ones.
  std::vector<std::string> max_activation;
  double rx_budget_us = 0;     // receive work per cycle: drain the socket until empty or this long; 0: min(150 us, period / 4)
};

// Order statistics of one per-cycle quantity, in nanoseconds.
struct Percentiles {
  double min = 0, median = 0, p99 = 0, p999 = 0, max = 0, mean = 0;
  std::int64_t count = 0;
};

struct PacketCounters {
  std::uint64_t received = 0;      // datagrams read
  std::uint64_t applied = 0;       // valid excitation packets applied
  std::uint64_t foreign = 0;       // from a source other than the session's owner (not decoded)
  std::uint64_t not_allowed = 0;   // from a source outside --allow (not decoded)
  std::uint64_t bad_magic = 0, bad_version = 0, bad_size = 0, bad_type = 0, bad_count = 0;
  std::uint64_t bad_auth = 0;      // missing or wrong HMAC tag (with a key)
  std::uint64_t bad_session = 0;   // excitation without the current session id
  std::uint64_t non_finite = 0;    // NaN / inf values
  std::uint64_t stale = 0;         // duplicate sequence number in the session
  std::uint64_t out_of_order = 0;  // sequence number older than the session's last applied one
  std::uint64_t clipped = 0;       // packets with values outside [0, 1] (applied, clipped)
  std::uint64_t hellos = 0;        // session requests read
  std::uint64_t offers = 0;        // session offers sent (at most one per cycle)
  std::uint64_t sessions = 0;      // sessions started (first excitation with the offered id)
  std::uint64_t owner_changes = 0; // sessions started by a source other than the previous owner
  std::uint64_t releases = 0;      // sessions ended by the owner
  std::uint64_t timeouts = 0;      // sessions ended by input_timeout of silence (excitation set to zero)
  std::uint64_t rx_budget_hits = 0;  // cycles that left datagrams in the socket (receive budget spent)
  std::uint64_t state_sent = 0;
  std::uint64_t send_errors = 0;
  std::uint64_t dropped() const {
    return foreign + not_allowed + bad_magic + bad_version + bad_size + bad_type + bad_count + bad_auth +
           bad_session + non_finite + stale + out_of_order;
  }
};

struct RtStats {
  std::int64_t cycles = 0;        // cycles run
  std::int64_t recorded = 0;      // cycles in the percentiles (all of them: fixed-memory histograms)
  std::int64_t overruns = 0;      // cycles whose work ended after the next deadline
  std::int64_t missed_deadlines = 0;  // whole periods skipped after an overrun
  double lag_s = 0;               // simulated time behind the wall-clock schedule (missed periods)
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
  std::string stop_reason;        // "duration", "stop", "signal", "diverged", "lag", "error"
  std::string error;              // divergence message, or set-up error
  std::vector<std::string> warnings;  // set-up warnings (e.g. a non-loopback bind without a key)
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
  static Percentiles percentiles(const LogHistogram& h);
  bool authenticated() const { return key_.enabled(); }

 private:
  static void* thread_main(void* self);
  void receive_packets(double now_s);
  void handle_datagram(const std::uint8_t* buf, long n, const sockaddr_in& from, double now_s);
  void end_session(bool released);
  void send_offer(const sockaddr_in& to);
  void send_state();
  void send_to(const std::uint8_t* b, int len, const sockaddr_in& to);

  RtConfig cfg_;
  std::unique_ptr<Simulator> sim_;
  int n_el_ = 0;
  StateLayout layout_;                  // of this model's state packets
  double period_ns_ = 0;
  std::int64_t max_cycles_ = 0;         // from duration; 0: unbounded
  int state_every_ = 0;                 // cycles between state packets; 0: none

  // Per-cycle records in fixed memory, whatever the duration.
  LogHistogram rec_tet_, rec_cycle_, rec_latency_;

  // Excitation mappings: element lists per muscle / group / channel (CSR).
  struct Mapping { std::vector<int> offsets, elements; int size() const { return (int)offsets.size() - 1; } };
  Mapping muscles_, groups_, channels_;
  void apply_mapping(const Mapping& m, const double* values);

  // UDP.
  static constexpr int kBatch = 32;     // datagrams per recvmmsg
  int sock_ = -1;
  // The owner's own queue: a second socket on the same port (SO_REUSEPORT), connect()ed to the owner
  // while a session lasts, so the kernel delivers the owner's datagrams there and a flood from others
  // fills only sock_'s queue. Between sessions it is connected to sock_'s own address (silent).
  int owner_sock_ = -1;
  sockaddr_in bound_addr_{};
  bool drain(int fd, double now_s, std::int64_t budget_end);
  void isolate_owner(const sockaddr_in* owner);
  int bound_port_ = 0;
  std::vector<sockaddr_in> subscribers_;
  std::vector<SourceFilter> allow_;
  HmacKey key_;
  std::vector<std::uint8_t> rx_buf_, tx_buf_;
  std::vector<sockaddr_in> rx_from_;
  std::vector<char> rx_hdr_storage_;    // mmsghdr[kBatch] + iovec[kBatch], preallocated
  std::vector<double> values_;          // decoded packet values (kMaxValues)
  std::uint32_t tx_seq_ = 0;

  // Session.
  std::uint64_t session_rng_ = 0;       // splitmix64 state: session ids are unique, not secret
  std::uint32_t session_id_ = 0;        // current (offered or owned) session id, never 0
  bool have_owner_ = false;
  sockaddr_in owner_{}, previous_owner_{};
  bool had_owner_ = false, notify_previous_ = false;
  bool have_seq_ = false;
  std::uint32_t last_seq_ = 0;
  double last_valid_s_ = -1;            // loop time of the owner's last applied excitation
  bool offered_this_cycle_ = false;
  bool overrun_since_state_ = false;

  // Loop state and results.
  std::atomic<bool> stop_{false}, by_signal_{false}, running_{false}, finished_{false};
  std::atomic<std::int64_t> cycles_{0};
  std::int64_t overruns_ = 0, missed_ = 0;
  double elapsed_s_ = 0;
  PacketCounters pk_;
  std::string scheduler_ = "SCHED_OTHER", rt_note_, stop_reason_, error_;
  std::vector<std::string> warnings_;
  int priority_ = 0, cpu_ = -1;
  bool memory_locked_ = false;
  bool diverged_ = false, lagged_ = false;
  pthread_t thread_{};
  bool thread_started_ = false;
  std::atomic<int> setup_state_{0};     // 0 pending, 1 ok, -1 failed (require_rt)
};

}  // namespace armrt::rt
