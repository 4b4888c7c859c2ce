// Per-cycle times (TET, cycle work, wake-up latency, ns) and deadline misses -> fixed-memory
// records -> RtStats (percentiles, overruns, lag, worst case) and its JSON. Recording allocates
// nothing (a day at 1 kHz needs no more memory than a second); reading the statistics does.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "histogram.h"

namespace armrt::rt {

// Order statistics of one per-cycle quantity, in nanoseconds.
struct Percentiles {
  double min = 0, median = 0, p99 = 0, p999 = 0, max = 0, mean = 0;
  std::int64_t count = 0;
};
Percentiles percentiles(const LogHistogram& h);

struct PacketCounters {
  std::uint64_t received = 0;      // datagrams read
  std::uint64_t applied = 0;       // valid excitation and stimulation packets applied
  std::uint64_t stimulation_applied = 0;  // of which stimulation packets
  std::uint64_t foreign = 0;       // from a source other than the session's owner (not decoded)
  std::uint64_t not_allowed = 0;   // from a source outside --allow (not decoded)
  std::uint64_t bad_magic = 0, bad_version = 0, bad_size = 0, bad_type = 0, bad_count = 0;
  std::uint64_t bad_auth = 0;      // missing or wrong HMAC tag (with a key)
  std::uint64_t bad_session = 0;   // excitation without the current session id
  std::uint64_t non_finite = 0;    // NaN / inf values
  std::uint64_t targets_applied = 0;  // kTarget packets applied (--static-optimization)
  std::uint64_t bad_target = 0;    // kTarget packets refused: a joint angle beyond its range (as the Python API)
  std::uint64_t stale = 0;         // duplicate sequence number in the session
  std::uint64_t out_of_order = 0;  // sequence number older than the session's last applied one
  std::uint64_t clipped = 0;       // excitation packets with values outside [0, 1] (applied, clipped)
  std::uint64_t stimulation_refused = 0;  // stimulation packets with a value Arm.set_stimulation refuses (negative,
                                          // beyond a channel's pulse width, amplitude, frequency or charge; dropped)
  std::uint64_t hellos = 0;        // session requests read
  std::uint64_t offers = 0;        // session offers sent (at most one per source per 10 ms, 4 per cycle)
  std::uint64_t replies_limited = 0;  // hellos / stale-session packets not answered: the source's share was spent
  std::uint64_t held_off = 0;      // hellos and claims refused in the hold after a timeout (anyone) or the
                                   // grace window (anyone but the timed-out owner)
  std::uint64_t session_ended = 0; // session-ended notices sent to a timed-out owner
  std::uint64_t kernel_drops = 0;  // datagrams the kernel dropped, both queues full (SO_RXQ_OVFL; never read)
  std::uint64_t sessions = 0;      // sessions started (first excitation with the offered id)
  std::uint64_t owner_changes = 0; // sessions started by a source other than the previous owner
  std::uint64_t releases = 0;      // sessions ended by the owner
  std::uint64_t timeouts = 0;      // sessions ended by input_timeout of silence (excitation set to zero)
  std::uint64_t rx_budget_hits = 0;  // cycles that left datagrams in the socket (receive budget spent)
  std::uint64_t state_sent = 0;
  std::uint64_t send_errors = 0;
  std::uint64_t dropped() const {
    return foreign + not_allowed + bad_magic + bad_version + bad_size + bad_type + bad_count + bad_auth +
           bad_session + non_finite + bad_target + stimulation_refused + stale + out_of_order;
  }
};

struct RtStats {
  std::string model;              // the registered model's name (--model)
  std::string profile;            // the participant profile's name; "" (JSON null): none given
  std::array<double, 3> hand_force{}, hand_moment{};  // N, N m (thorax frame): the constant hand load (0: none)
  std::int64_t cycles = 0;        // cycles run
  std::int64_t recorded = 0;      // cycles in the percentiles (all of them: fixed-memory histograms)
  std::int64_t overruns = 0;      // cycles whose work ended after the next deadline
  std::int64_t missed_deadlines = 0;  // whole periods skipped after an overrun
  double lag_s = 0;               // simulated time behind the wall-clock schedule (missed periods)
  double elapsed_s = 0;           // wall time of the loop
  double sim_time = 0;            // simulated time at the end
  Percentiles tet;                // model step (step(), stepper.cc) execution time
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
  double rate_hz = 0;
  double control_step = 0;        // s, 1/rate: one cycle
  double integration_step = 0;    // s, the integrator's step inside a cycle
  std::string integrator;
  bool authenticated = false;
  double session_hold_s = 0;      // zero held after an owner's timeout (ln(100) * the largest tdeact, rt_session.h)
  double support_s = 0;           // the joints were held where the loop started for this long (--support)
  double resume_grace_s = 0;      // then the timed-out owner alone may claim the session (--resume-grace)
  int rcvbuf_bytes = 0;           // the shared receive queue's buffer, as getsockopt(SO_RCVBUF) reports it
  int owner_rcvbuf_bytes = 0;     // the owner's queue's (0: none)
  // --static-optimization: the solve each cycle (its time is inside cycle, before the step).
  bool static_optimization = false;
  Percentiles so_solve;             // ns per solve
  std::int64_t so_solves = 0;       // solves run (cycles with a target)
  std::int64_t so_infeasible = 0;   // of which infeasible or not converged (excitation set to zero)
  std::int64_t so_not_converged = 0;  // of which the dual Newton method did not finish (no ProxQP fallback in the loop)
  std::int64_t so_refused = 0;  // cycles not solved: qddot_d + kp e + kd e' beyond 1e5 rad/s^2 (excitation zero)
  double so_gh_stab_max = 0, so_kp = 0, so_kd = 0;
  double so_residual_max = 0;       // N m, the largest moment residual of a feasible solve
};

// The cycle records: three histograms and the overrun / missed-period counts.
class CycleRecorder {
 public:
  explicit CycleRecorder(double period_ns) : period_ns_(period_ns) {}
  void record(std::int64_t tet_ns, std::int64_t cycle_ns, std::int64_t latency_ns) {
    tet_.record(tet_ns);
    cycle_.record(cycle_ns);
    latency_.record(latency_ns);
  }
  void overrun(std::int64_t missed_periods) {
    ++overruns_;
    missed_ += missed_periods;
  }
  std::int64_t overruns() const { return overruns_; }
  std::int64_t missed() const { return missed_; }
  double lag_s() const { return static_cast<double>(missed_) * period_ns_ * 1e-9; }
  // Fills the timing part of st (cycles, recorded, overruns, lag, percentiles).
  void fill(RtStats& st) const;

 private:
  double period_ns_;
  LogHistogram tet_, cycle_, latency_;
  std::int64_t overruns_ = 0, missed_ = 0;
};

std::string stats_json(const RtStats& s);

}  // namespace armrt::rt
