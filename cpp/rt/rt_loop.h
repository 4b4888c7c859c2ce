// RtConfig -> one armrt::Arm stepped at a fixed rate on a SCHED_FIFO thread, with
// absolute-deadline sleeping; the options are checked in rt_config, the UDP session (excitations in,
// state out) is rt_session's, the per-cycle records rt_stats' (packet format: packet.h, docs/realtime.md).
//
// Everything that allocates, locks or makes system calls other than clock_nanosleep, clock_gettime and
// non-blocking recvmmsg / sendto happens in prepare() (or start()) and in the statistics after the
// loop; run_cycles() (the hot loop) does none of it (cpp/rt/test_rt.cc checks).
//
#pragma once

#include <pthread.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "armrt/arm.h"
#include "armrt/static_optimization.h"
#include "packet.h"
#include "rt_config.h"
#include "rt_session.h"
#include "rt_stats.h"

namespace armrt::rt {

// The simulation failed while settling (--settle): not a bad option (exit status 1, as a divergence in the loop).
struct SettleError : std::runtime_error {
  using std::runtime_error::runtime_error;
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
  int bound_port() const { return session_->bound_port(); }
  const RtConfig& config() const { return cfg_; }
  Arm& arm() { return *sim_; }
  static Percentiles percentiles(const LogHistogram& h) { return rt::percentiles(h); }
  bool authenticated() const { return session_->authenticated(); }
  double hold_s() const { return session_->hold_s(); }  // zero held after an owner's timeout (rt_session.h)

 private:
  static void* thread_main(void* self);
  void send_state();

  // The loop's only contact with the engine core's Model / Data (the core's redesign adapts these).
  void make_simulator(const ModelDef& def, const Schedule& sched);
  void apply_command(const double* u, const double* stimulation);
  void zero_command();  // apply_command of zeros: the loop's end
  // --static-optimization: the cycle's solve at the session's target, its activations applied (zero without one).
  void static_optimization_cycle();
  StateValues state_values(double& lag, double& overruns);

  RtConfig cfg_;
  Schedule sched_;
  std::unique_ptr<Arm> sim_;
  std::unique_ptr<Session> session_;
  double period_ns_ = 0;
  CycleRecorder rec_{0};
  bool overrun_since_state_ = false;
  // --static-optimization (rt_config.h): the solver's workspace, the solve times and counts.
  StaticOptimizationWorkspace so_;
  StaticOptimizationReport so_report_;
  std::array<double, kMaxElements> so_activation_{};
  // --support: the cycles it lasts after the first command, the cycle it ends (-1: no command yet) and the
  // joints' (q, qdot) held, a q|qdot snapshot (snapshot.h).
  bool supported(std::int64_t cycle);
  std::int64_t support_cycles_ = 0, support_end_ = -1;
  std::array<double, 2 * kMaxDofs> support_state_{};
  LogHistogram so_hist_;
  std::int64_t so_solves_ = 0, so_infeasible_ = 0, so_not_converged_ = 0;
  std::int64_t so_refused_ = 0;  // cycles whose computed qddot was beyond kStaticOptimizationMaxJointAcceleration
  double so_residual_max_ = 0;

  // Loop state and results.
  std::atomic<bool> stop_{false}, by_signal_{false}, running_{false}, finished_{false};
  std::atomic<std::int64_t> cycles_{0};
  double elapsed_s_ = 0;
  std::string scheduler_ = "SCHED_OTHER", rt_note_, stop_reason_, error_;
  std::vector<std::string> warnings_;
  std::array<double, kMaxChannels> fatigue_now_{};  // each channel's fatigue at the state packet's time
  int priority_ = 0, cpu_ = -1;
  bool memory_locked_ = false;
  bool diverged_ = false, lagged_ = false;
  pthread_t thread_{};
  bool thread_started_ = false;
  std::atomic<int> setup_state_{0};     // 0 pending, 1 ok, -1 failed (require_rt)
};

}  // namespace armrt::rt
