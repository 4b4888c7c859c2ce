// RtConfig -> the real-time loop: simulator, schedule, thread (rt_loop.h).
#include "rt_loop.h"

#include <errno.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "armrt/clock.h"
#include "armrt/names.h"
#include "armrt/snapshot.h"
#include "armrt/engine.h"
#include "armrt/stimulation.h"
#include "armrt/stepper.h"

namespace armrt::rt {

namespace {

// What --support writes back after each step: the joint angles and velocities.
constexpr unsigned kSupportSignature = snapshot_bit(SnapshotPart::q) | snapshot_bit(SnapshotPart::qdot);

inline timespec to_timespec(std::int64_t ns) {
  timespec ts;
  ts.tv_sec = static_cast<time_t>(ns / 1000000000LL);
  ts.tv_nsec = static_cast<long>(ns % 1000000000LL);
  return ts;
}

}  // namespace

// ------------------------------------------------------------------ the engine core, in one place
// Creating the simulator, the paralysis caps, the excitation the dynamics use and the state the
// packets carry: the only lines of the runner that read or write the engine's Model / Data.

void RtLoop::make_simulator(const ModelDef& def, const Schedule& sched) {
  sim_ = std::make_unique<Arm>(def, parse_integrator(cfg_.integrator), sched.period_s, sched.substeps);
  if (!cfg_.q0.empty()) {
    if (static_cast<int>(cfg_.q0.size()) != def.num_dofs)
      throw std::invalid_argument("--q0 needs " + std::to_string(def.num_dofs) + " values (model '" + cfg_.model +
                                  "' has " + std::to_string(def.num_dofs) + " DOFs)");
    // The engine's snapshot check, as Arm.set_state applies it: finite, within the physical domain (joints at
    // most kJointRangeMargin beyond their range, with a hint when the values look like degrees; no girdle
    // contact point deep in the thorax), so a bad --q0 is refused here instead of diverging in the first cycle.
    // Then Arm.reset's own bound, tighter than the domain's: the runner refuses what the Python API refuses.
    std::string error = snapshot_error(sim_->model, sim_->data, snapshot_bit(SnapshotPart::q), cfg_.q0.data());
    if (error.empty()) error = start_pose_error(def, cfg_.q0.data());
    if (!error.empty()) throw std::invalid_argument("--q0 (rad): " + error);
    sim_->reset(cfg_.q0.data(), nullptr, nullptr);
  }
  sim_->data.excitation.fill(0.0);
  // max_activation lives in the model: forward() caps every excitation at it, whatever its source.
  // Overlapping names: the engine's one rule (names.h), as Arm.max_activation takes a dict.
  if (!cfg_.max_activation.empty()) {
    std::vector<double> cap;
    try {
      cap = values_from_names(def, parse_max_activation(cfg_.max_activation), sim_->data.settings.max_activation.data());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--max-activation: ") + e.what());
    }
    std::copy(cap.begin(), cap.end(), sim_->data.settings.max_activation.begin());
    sim_->apply_settings();
  }
  // strength scales fmax (weakness), by the same names and rule; apply_settings re-derives the muscle
  // constants and checks the values as Arm.strength's setter does (model.cc).
  if (!cfg_.strength.empty()) {
    try {
      const std::vector<double> scale =
          values_from_names(def, parse_strength(cfg_.strength), sim_->data.settings.strength_scale.data());
      std::copy(scale.begin(), scale.end(), sim_->data.settings.strength_scale.begin());
      sim_->apply_settings();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--strength: ") + e.what());
    }
  }
  // The stimulation map, read and checked by the engine's one reader (stimulation_map.cc), as Arm(stimulation=)
  // reads it: the channels start at zero (no pulses) until the owner's first stimulation packet.
  if (!cfg_.stimulation.empty()) {
    try {
      const StimulationMap map = cfg_.stimulation == "per_muscle" ? stimulation_map_per_muscle(def)
                                                                  : stimulation_map_from_file(def, cfg_.stimulation);
      data_set_stimulation_map(sim_->model, sim_->data, map);
    } catch (const std::exception& e) {
      throw std::invalid_argument(std::string("--stimulation: ") + e.what());
    }
  }
  // The hand load is data the dynamics and the static optimisation read (d.hand_force, d.hand_moment), set once.
  if (!cfg_.hand_force.empty()) std::copy_n(cfg_.hand_force.begin(), 3, sim_->data.hand_force.begin());
  if (!cfg_.hand_moment.empty()) std::copy_n(cfg_.hand_moment.begin(), 3, sim_->data.hand_moment.begin());
  // An explicit integration step beyond its stability limit at rest diverges in the first cycle (a trial's Euler at
  // 10 ms started, printed its port, then stopped with Python's substeps advice): refused here, in the runner's own
  // option; beyond the validated step but stable, a warning, as Arm's StepSizeWarning.
  {
    const Integrator integ = parse_integrator(cfg_.integrator);
    const double h = sched.period_s / sched.substeps, rate = std::fabs(sim_->data.rest_fibre_rate);
    const double h_stable = explicit_stability_limit(integ) / rate;
    if (h > h_stable)
      throw std::invalid_argument("--integration-step " + fmt(h) + " s is unstable for integrator '" + cfg_.integrator +
                                  "' even at rest (the fibre of " + def.elements[sim_->data.rest_fibre_element].name +
                                  ", eigenvalue " + fmt(-rate) + " 1/s, is stable for steps <= " + fmt(h_stable) +
                                  " s): give --integration-step " + fmt(default_max_step(integ)) +
                                  " (the validated step) or --integrator ros2");
    if (std::isfinite(h_stable) && h > default_max_step(integ) * (1 + 1e-9))
      warnings_.push_back("--integration-step " + fmt(h) + " s is above integrator '" + cfg_.integrator +
                          "''s validated " + fmt(default_max_step(integ)) + " s (stable at rest up to " +
                          fmt(h_stable) + " s; accuracy not validated)");
  }
  // --settle: the engine's settle (Arm::settle, as Python's Arm.settle), with the weakness and paralysis above in
  // effect and the stimulation channels at zero; the loop then starts from the relaxed state at time 0.
  if (cfg_.settle_s > 0) {
    const auto n = static_cast<std::int64_t>(std::llround(cfg_.settle_s / sched.period_s));
    if (!sim_->settle(n)) throw SettleError("--settle " + fmt(cfg_.settle_s) + " s: " + sim_->error_message());
  }
  // --support holds the joints where the loop starts (after --settle), at rest.
  support_cycles_ = static_cast<std::int64_t>(std::llround(cfg_.support_s / sched.period_s));
  const int nq = sim_->model.num_dofs;
  std::copy_n(sim_->data.x.begin() + q_offset(sim_->model), nq, support_state_.begin());
  std::fill_n(support_state_.begin() + nq, nq, 0.0);
  if (support_cycles_ > 0) set_snapshot(sim_->model, sim_->data, sim_->stepper, kSupportSignature, support_state_.data());
}

bool RtLoop::supported(std::int64_t cycle) {
  if (support_cycles_ == 0) return false;
  if (support_end_ < 0) {
    // Held while no controller has commanded anything: it may take seconds to start. Without --listen nothing
    // will: the first support_cycles_ cycles.
    const bool listening = !cfg_.listen.empty();
    if (listening) {
      const PacketCounters& pk = session_->counters();
      if (pk.applied + pk.targets_applied == 0) return true;
    }
    support_end_ = (listening ? cycle : 0) + support_cycles_;
  }
  return cycle < support_end_;
}

void RtLoop::apply_command(const double* u, const double* stimulation) {
  // Held (and streamed with --excitations) as the dynamics use it: capped at max_activation.
  data_set_excitation(sim_->model, sim_->data, u);
  // Already within every channel's limits (the session refuses the rest): the engine's held command, as
  // Arm.set_stimulation.
  const int nc = sim_->data.stimulation_map.num_channels;
  std::copy(stimulation, stimulation + kStimInputs * nc, sim_->data.stimulation.begin());
}

void RtLoop::zero_command() {
  const std::vector<double> zero(std::max(sim_->model.num_elements, kStimInputs * sim_->data.stimulation_map.num_channels),
                                 0.0);
  apply_command(zero.data(), zero.data());
}

void RtLoop::static_optimization_cycle() {
  Data& d = sim_->data;
  const Model& m = sim_->model;
  const int nq = m.num_dofs, n = m.num_elements;
  if (!session_->has_target()) {
    std::fill(so_activation_.begin(), so_activation_.begin() + n, 0.0);
    data_set_excitation(m, d, so_activation_.data());
    return;
  }
  const double* t = session_->target();  // q_d, qdot_d, qddot_d
  const double* q = &d.x[q_offset(m)];
  const double* qd = &d.x[qd_offset(m)];
  double qdd_cmd[kMaxDofs];
  const double kp = cfg_.so_kp.value_or(0.0), kd = cfg_.so_kd.value_or(0.0);
  const bool feedback = kp > 0 || kd > 0;
  bool out_of_range = false;
  for (int j = 0; j < nq; ++j) {
    qdd_cmd[j] = t[2 * nq + j] + kp * (t[j] - q[j]) + kd * (t[nq + j] - qd[j]);
    out_of_range = out_of_range || !(std::abs(qdd_cmd[j]) <= kStaticOptimizationMaxJointAcceleration);
  }
  if (out_of_range) {
    // Large gains on a large error: the solve the Python API refuses would take seconds here. Fail safe, counted
    // (not a solve).
    ++so_refused_;
    std::fill(so_activation_.begin(), so_activation_.begin() + n, 0.0);
    data_set_excitation(m, d, so_activation_.data());
    return;
  }
  const std::int64_t t0 = now_ns();
  // Feedforward: at the desired state; with gains, computed-torque style at the arm's own state.
  static_optimization_rigid(m, d, so_, feedback ? q : t, feedback ? qd : t + nq, qdd_cmd, d.hand_force.data(),
                            d.hand_moment.data(), so_activation_.data(), &so_report_);
  so_hist_.record(now_ns() - t0);
  ++so_solves_;
  if (so_report_.status == StaticOptimizationStatus::kNotConverged) ++so_not_converged_;
  if (!so_report_.feasible) {  // fail safe: no excitation rather than the closest solution
    ++so_infeasible_;
    std::fill(so_activation_.begin(), so_activation_.begin() + n, 0.0);
  } else {
    so_residual_max_ = std::max(so_residual_max_, so_report_.residual_max);
  }
  data_set_excitation(m, d, so_activation_.data());
}

StateValues RtLoop::state_values(double& lag, double& overruns) {
  Data& d = sim_->data;
  const Model& m = sim_->model;
  if (d.status == Status::kOk) sim_->evaluate_outputs();  // outputs at the current state
  lag = rec_.lag_s();
  overruns = static_cast<double>(rec_.overruns());
  StateValues v;
  v.time = &d.time;
  v.q = &d.x[q_offset(m)];
  v.qdot = &d.x[qd_offset(m)];
  v.hand_position = &d.hand_position[0];
  v.gh_stab = &d.gh_stab;
  v.gh_theta = &d.gh_angles[0];
  v.gh_phi = &d.gh_angles[1];
  v.gh_rim_margin = &d.gh_rim_margin;
  v.gh_rim_direction = &d.gh_rim_direction;
  v.lag = &lag;
  v.overruns = &overruns;
  v.muscle_force = &d.muscle_force[0];
  v.excitation = &d.excitation[0];
  v.stimulation = &d.stimulation[0];
  for (int k = 0; k < d.stimulation_map.num_channels; ++k) fatigue_now_[k] = channel_fatigue(d, k);
  v.fatigue = fatigue_now_.data();
  return v;  // last_applied_seq: the session's
}

// ------------------------------------------------------------------ set-up

RtLoop::RtLoop(const RtConfig& config) : cfg_(config) {
  const ModelDef* def = find_model(cfg_.model);
  if (!def) throw std::invalid_argument("unknown model '" + cfg_.model + "' (compiled-in models: " + model_names() + ")");
  sched_ = check_config(cfg_);
  period_ns_ = 1e9 / cfg_.rate_hz;
  rec_ = CycleRecorder(period_ns_);
  make_simulator(*def, sched_);
  const int nc = sim_->data.stimulation_map.num_channels;
  const std::uint16_t flags = (cfg_.send_forces ? kFlagForces : 0) | (cfg_.send_excitation ? kFlagExcitation : 0) |
                              (nc > 0 ? kFlagStimulation : 0);
  const StateOffsets sent = state_offsets(def->num_dofs, def->num_elements, flags, nc);
  if (def->num_elements > kMaxValues || sent.count > kMaxValues)
    throw std::invalid_argument("model '" + cfg_.model + "' with " + std::to_string(def->num_elements) + " elements, " +
                                std::to_string(nc) + " stimulation channels" + (cfg_.send_forces ? ", --forces" : "") +
                                (cfg_.send_excitation ? ", --excitations" : "") + ": " + std::to_string(sent.count) +
                                " state values, more than one packet carries (" + std::to_string(kMaxValues) + ")");
  session_ = std::make_unique<Session>(cfg_, *def, sim_->data.stimulation_map, warnings_);
  if (cfg_.static_optimization) {
    if (cfg_.listen.empty()) throw std::invalid_argument("--static-optimization needs --listen (the targets come from a client)");
    if (nc > 0) throw std::invalid_argument("--static-optimization with --stimulation: the solve computes element excitations, "
                                            "which a stimulation map's channels would override");
    StaticOptimizationOptions o;
    o.gh_stab_max = cfg_.so_gh_stab_max.value_or(0.0);  // 0: the engine's no bound
    // No ProxQP fallback in the loop: a solve the Newton method does not finish is reported not converged and
    // gives zero excitation, in bounded time and without the fallback's allocations (docs/realtime.md).
    o.proxqp_fallback = false;
    try {
      static_optimization_setup(sim_->model, o, so_);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--so-gh-stab-max: ") + e.what());
    }
  }
}

RtLoop::~RtLoop() {
  if (thread_started_) {
    request_stop();
    join();
  }
}

void RtLoop::prepare_thread() {
  std::string note;
  if (cfg_.lock_memory) {
    if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
      memory_locked_ = true;
    } else {
      note += std::string("mlockall failed: ") + std::strerror(errno) +
              " (needs CAP_IPC_LOCK or a large enough RLIMIT_MEMLOCK, `ulimit -l`); ";
    }
  }
  if (cfg_.realtime) {
    sched_param sp{};
    sp.sched_priority = cfg_.priority;
    const int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp);
    if (rc == 0) {
      scheduler_ = "SCHED_FIFO";
      priority_ = cfg_.priority;
    } else {
      note += std::string("SCHED_FIFO priority ") + std::to_string(cfg_.priority) + " refused: " +
              std::strerror(rc) + " (needs root, CAP_SYS_NICE or an RLIMIT_RTPRIO >= the priority, `ulimit -r`); ";
    }
  } else {
    note += "SCHED_FIFO not requested; ";
  }
  if (cfg_.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cfg_.cpu, &set);
    const int rc = pthread_setaffinity_np(pthread_self(), sizeof set, &set);
    if (rc == 0) cpu_ = cfg_.cpu;
    else note += "CPU affinity " + std::to_string(cfg_.cpu) + " refused: " + std::strerror(rc) + "; ";
  }
  if (note.size() >= 2) note.resize(note.size() - 2);
  rt_note_ = note;
  // Pre-fault the stack the loop will use, and warm the caches with one evaluation of the outputs.
  volatile char stack[256 * 1024];
  for (std::size_t k = 0; k < sizeof stack; k += 4096) stack[k] = 0;
  sim_->evaluate_outputs();
  (void)now_ns();
}

void RtLoop::send_state() {
  if (!session_->wants_state()) return;
  std::uint16_t flags = 0;
  if (finished_.load(std::memory_order_relaxed) || diverged_ || lagged_) flags |= kFlagStopped;
  if (diverged_ || lagged_) flags |= kFlagError;
  if (overrun_since_state_) flags |= kFlagOverrun;
  double lag = 0, overruns = 0;
  session_->send_state(state_values(lag, overruns), flags);
  overrun_since_state_ = false;
}

void RtLoop::run_cycles(std::int64_t n) {
  const std::int64_t period = static_cast<std::int64_t>(std::llround(period_ns_));
  const std::int64_t busy = static_cast<std::int64_t>(cfg_.busy_wait_us * 1000.0);
  const std::int64_t max_missed = cfg_.max_lag > 0 ? static_cast<std::int64_t>(cfg_.max_lag * cfg_.rate_hz) : -1;
  const std::int64_t t_start = now_ns();
  std::int64_t deadline = t_start + period;
  std::int64_t cycle = cycles_.load(std::memory_order_relaxed);
  const std::int64_t first = cycle;
  const char* reason = "stop";
  for (;;) {
    if (stop_.load(std::memory_order_relaxed)) {
      reason = by_signal_.load(std::memory_order_relaxed) ? "signal" : "stop";
      break;
    }
    if (sched_.max_cycles > 0 && cycle >= sched_.max_cycles) { reason = "duration"; break; }
    if (n > 0 && cycle - first >= n) { reason = "cycles"; break; }

    // Sleep to the absolute deadline (optionally to deadline - busy, then spin).
    const std::int64_t wake_at = deadline - busy;
    const timespec ts = to_timespec(wake_at);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
    std::int64_t woke = now_ns();
    if (busy > 0) while (woke < deadline) woke = now_ns();
    const std::int64_t latency = woke - deadline;

    if (session_) {
      session_->receive(static_cast<double>(woke - t_start) * 1e-9);
      if (session_->take_changed()) apply_command(session_->command(), session_->stimulation_command());
      if (cfg_.static_optimization) static_optimization_cycle();
    }
    const bool ok = sim_->step();  // measures its TET (step(), stepper.cc: the one place)
    if (!ok) {
      // The diverging cycle ran, so its times are statistics too (a divergence in the first cycle reported
      // no TET at all).
      rec_.record(static_cast<std::int64_t>(sim_->data.tet.last_ns), now_ns() - woke, latency);
      diverged_ = true;
      reason = "diverged";
      ++cycle;
      break;
    }
    // Supported: the joints back where they were (the integrator restarts its memory: no allocation for ROS2's).
    if (supported(cycle))
      set_snapshot(sim_->model, sim_->data, sim_->stepper, kSupportSignature, support_state_.data());
    if (sched_.state_every > 0 && (cycle + 1) % sched_.state_every == 0) send_state();
    const std::int64_t t_end = now_ns();

    rec_.record(static_cast<std::int64_t>(sim_->data.tet.last_ns), t_end - woke, latency);
    ++cycle;
    cycles_.store(cycle, std::memory_order_relaxed);

    deadline += period;
    if (t_end > deadline) {
      // Resynchronisation policy: skip and report. The periods already past are not simulated
      // (catching up would make the next cycles overrun too); the simulated time falls behind the
      // wall-clock schedule by one period per skipped deadline, reported as `lag` in the state
      // packets and statistics, with the overrun flag on the next state packet.
      overrun_since_state_ = true;
      std::int64_t missed = 0;
      while (deadline < t_end) {
        deadline += period;
        ++missed;
      }
      rec_.overrun(missed);
      if (max_missed >= 0 && rec_.missed() > max_missed) {
        lagged_ = true;
        reason = "lag";
        break;
      }
    }
  }
  cycles_.store(cycle, std::memory_order_relaxed);
  elapsed_s_ += static_cast<double>(now_ns() - t_start) * 1e-9;
  stop_reason_ = reason;
  if (diverged_) error_ = sim_->error_message();
  if (lagged_)
    error_ = "the simulation fell " + fmt(rec_.lag_s()) +
             " s behind wall time, more than --max-lag " + fmt(cfg_.max_lag) + " s";
}

void* RtLoop::thread_main(void* arg) {
  auto* self = static_cast<RtLoop*>(arg);
  self->prepare_thread();
  if (self->cfg_.require_rt && !self->rt_note_.empty()) {
    self->error_ = "real time required (--require-rt) but not available: " + self->rt_note_;
    self->stop_reason_ = "error";
    self->finished_.store(true, std::memory_order_release);
    self->setup_state_.store(-1, std::memory_order_release);
    return nullptr;
  }
  self->running_.store(true, std::memory_order_release);
  self->setup_state_.store(1, std::memory_order_release);
  self->run_cycles(0);
  self->running_.store(false, std::memory_order_release);
  self->finished_.store(true, std::memory_order_release);
  // The loop no longer runs, so nothing would lower the held command: it goes to zero (no excitation, no
  // stimulation) before the last state packet, so that what follows the runner's output (a stimulator driven from
  // the state packets) does not hold the last command after SIGINT / SIGTERM, --duration or a divergence.
  self->zero_command();
  self->send_state();  // last state, flagged stopped (and error if diverged), its command zero
  return nullptr;
}

void RtLoop::start() {
  if (thread_started_ || finished()) throw std::runtime_error("the real-time loop was already started (a loop runs once)");
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, 1 << 20);
  // The loop thread takes no signals: SIGINT / SIGTERM go to the main thread, which calls request_stop().
  sigset_t all, old;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &old);
  const int rc = pthread_create(&thread_, &attr, &RtLoop::thread_main, this);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  pthread_attr_destroy(&attr);
  if (rc != 0) throw std::runtime_error(std::string("pthread_create: ") + std::strerror(rc));
  thread_started_ = true;
  while (setup_state_.load(std::memory_order_acquire) == 0) {
    timespec ts{0, 200000};
    nanosleep(&ts, nullptr);
  }
  if (setup_state_.load() < 0) {
    join();
    throw std::runtime_error(error_);
  }
}

void RtLoop::join() {
  if (thread_started_) {
    pthread_join(thread_, nullptr);
    thread_started_ = false;
  }
}

RtStats RtLoop::stats() const {
  RtStats st;
  st.model = cfg_.model;
  st.profile = cfg_.profile;
  std::copy(cfg_.hand_force.begin(), cfg_.hand_force.end(), st.hand_force.begin());  // validated: 0 or 3 values
  std::copy(cfg_.hand_moment.begin(), cfg_.hand_moment.end(), st.hand_moment.begin());
  st.cycles = cycles_.load(std::memory_order_relaxed);
  rec_.fill(st);
  st.elapsed_s = elapsed_s_;
  st.sim_time = sim_->data.time;
  st.packets = session_->counters();
  st.scheduler = scheduler_;
  st.priority = priority_;
  st.memory_locked = memory_locked_;
  st.cpu = cpu_;
  st.rt_note = rt_note_;
  st.stop_reason = stop_reason_;
  st.error = error_;
  st.warnings = warnings_;
  st.rate_hz = cfg_.rate_hz;
  st.control_step = sched_.period_s;
  st.integration_step = cfg_.integration_step;
  st.integrator = cfg_.integrator;
  st.authenticated = session_->authenticated();
  st.session_hold_s = session_->hold_s();
  st.support_s = static_cast<double>(support_cycles_) * sched_.period_s;
  st.resume_grace_s = session_->resume_grace_s();
  st.rcvbuf_bytes = session_->rcvbuf_bytes();
  st.owner_rcvbuf_bytes = session_->owner_rcvbuf_bytes();
  st.static_optimization = cfg_.static_optimization;
  if (st.static_optimization) {
    st.so_solve = rt::percentiles(so_hist_);
    st.so_solves = so_solves_;
    st.so_infeasible = so_infeasible_;
    st.so_not_converged = so_not_converged_;
    st.so_refused = so_refused_;
    st.so_gh_stab_max = cfg_.so_gh_stab_max.value_or(0.0);
    st.so_kp = cfg_.so_kp.value_or(0.0);
    st.so_kd = cfg_.so_kd.value_or(0.0);
    st.so_residual_max = so_residual_max_;
  }
  return st;
}

std::string RtLoop::stats_json() const { return rt::stats_json(stats()); }

}  // namespace armrt::rt
