// armrt-rt: runs the arm model at a fixed rate on a SCHED_FIFO thread, with UDP excitation input and
// state output (docs/realtime.md). Prints TET / wake-up latency percentiles and overruns on exit
// (end of --duration, SIGINT, SIGTERM, SIGHUP or SIGQUIT) and writes them as JSON (--json).
#include <signal.h>
#include <time.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "hmac.h"
#include "rt_loop.h"

using armrt::rt::RtConfig;
using armrt::rt::RtLoop;

namespace {

RtLoop* g_loop = nullptr;

void on_signal(int) {
  if (g_loop) g_loop->request_stop_signal();
}

void print_pct(const char* name, const armrt::rt::Percentiles& p) {
  std::printf("  %-8s min %8.1f  median %8.1f  p99 %8.1f  p99.9 %8.1f  max %9.1f  us\n", name, p.min / 1e3,
              p.median / 1e3, p.p99 / 1e3, p.p999 / 1e3, p.max / 1e3);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diag = up;
    }
  }
  return row[b.size()];
}

// "unknown option --stat-rate; did you mean --state-rate?"
std::string unknown_option_message(const CLI::App& app, const std::string& arg) {
  const std::string given = arg.substr(0, arg.find('='));
  std::string best;
  std::size_t best_d = 1000;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) {
      const std::size_t d = edit_distance(given, "--" + n);
      if (d < best_d) { best_d = d; best = "--" + n; }
    }
  }
  std::string msg = "unknown option or argument '" + arg + "'";
  if (!best.empty() && best_d <= std::max<std::size_t>(3, given.size() / 3)) msg += "; did you mean " + best + "?";
  return msg;
}

}  // namespace

int main(int argc, char** argv) {
  RtConfig cfg;
  std::string json_path, key_file;
  bool quiet = false, no_rt = false, no_mlock = false;
  CLI::App app{"armrt-rt: runs the arm model at a fixed rate on a SCHED_FIFO thread, with UDP excitation input "
               "and state output (docs/realtime.md). Prints TET / wake-up latency percentiles and overruns on exit."};
  app.allow_extras(true);  // unknown options are reported below with the closest known one
  app.add_option("--rate", cfg.rate_hz, "loop rate, Hz, 1..10000")->capture_default_str();
  app.add_option("--integrator", cfg.integrator, "ros2 (linearly implicit, one step per 1 ms), rk4 or euler "
                                                 "(armrt::parse_integrator; not cvode)")->capture_default_str();
  // dt is the control step everywhere in armrt (Arm.dt; here 1/--rate); the integrator's own step has its own name.
  app.add_option("--integration-step", cfg.integration_step,
                 "largest integration step, s (<= 1/rate, the control step); each cycle takes "
                 "ceil(1/rate / integration step) substeps (default: ros2 0.001, rk4 0.00017, euler 0.0001)");
  double deprecated_dt = 0;
  app.add_option("--dt", deprecated_dt, "deprecated: --integration-step");
  std::vector<std::string> model_libraries;
  app.add_option("--model", cfg.model, "registered model: das2, das3, participant_A (built in) or one loaded with --model-library")
      ->capture_default_str();
  app.add_option("--model-library", model_libraries, "load a model built on demand (the library `armrt model build` "
                                                     "prints; repeatable); `armrt-rt --model FILE.json` does both")
      ->take_all();
  app.add_option("--q0", cfg.q0, "initial joint angles, rad, one per DOF of the model in its order, comma-separated "
                                  "(das2: GHy,GHz,GHyy,ELx,PSy; default: rest posture)")
      ->delimiter(',')->expected(1, armrt::kMaxDofs)->type_name("Q,Q,...");  // CLI11 would say FLOAT: one number
  app.add_option("--duration", cfg.duration, "run for S seconds (0: until SIGINT/SIGTERM)")->capture_default_str();
  app.add_option("--hand-force", cfg.hand_force, "FX,FY,FZ: a constant force (N) at the hand point, thorax frame (x "
                                                "lateral, y up, z posterior; a 1 kg weight: 0,-9.81,0), as Arm.set_hand_load")
      ->delimiter(',')->allow_extra_args(false);
  app.add_option("--hand-moment", cfg.hand_moment, "MX,MY,MZ: a constant moment (N m) on the hand, thorax frame")
      ->delimiter(',')->allow_extra_args(false);
  app.add_option("--support", cfg.support_s, "hold the joints where the loop starts (qdot 0) until S seconds after "
                                           "the first command applied, the muscles responding as usual: the arm "
                                           "supported while stimulation builds up (fes_control.run_offline's hold_s)");
  app.add_option("--settle", cfg.settle_s, "first relax the arm S seconds with zero excitation, then start the loop "
                                         "at time 0 (Arm.settle; das3's start posture is not its equilibrium)")
      ->capture_default_str();
  app.add_option("--priority", cfg.priority, "SCHED_FIFO priority 1..99")->capture_default_str();
  app.add_flag("--no-rt", no_rt, "normal scheduling on purpose (no SCHED_FIFO)");
  app.add_flag("--no-mlock", no_mlock, "do not mlockall");
  app.add_flag("--require-rt", cfg.require_rt, "exit with status 3 if SCHED_FIFO or mlockall is not available");
  app.add_option("--cpu", cfg.cpu, "pin the loop thread to CPU N");
  app.add_option("--busy-wait", cfg.busy_wait_us, "wake US microseconds early and spin to the deadline");
  app.add_option("--max-lag", cfg.max_lag, "stop (state flagged stopped + error) once simulated time lags wall time "
                                           "by more than S seconds (0: never)")->capture_default_str();
  app.add_option("--listen", cfg.listen, "UDP excitation input HOST:PORT (port 0: any free port, printed)");
  app.add_option("--state-to", cfg.state_to, "subscriber HOST:PORT that always gets state packets (repeatable); "
                                             "the session's owner gets them too")->take_all();
  app.add_option("--allow", cfg.allow, "only HOST or HOST:PORT may own the session (repeatable)")->take_all();
  app.add_option("--key-file", key_file, "shared key (>= 16 bytes) for HMAC-SHA256 on every packet");
  app.add_option("--state-rate", cfg.state_rate_hz, "state packets per second, rate / an integer (0: none)")->capture_default_str();
  app.add_flag("--forces", cfg.send_forces, "append the muscle forces to state packets");
  app.add_flag("--excitations", cfg.send_excitation, "append the applied element excitations to state packets");
  app.add_flag("--static-optimization", cfg.static_optimization,
               "feedforward: the owner sends targets (packet type 8: desired q, qdot, qddot) and every cycle the runner "
               "solves the rigid-tendon static optimisation for them and applies the activations (docs/realtime.md)");
  app.add_option("--so-gh-stab-max", cfg.so_gh_stab_max, "with --static-optimization: GHstab <= S (> 0) in the solve (without it: no GH bound)");
  app.add_option("--so-kp", cfg.so_kp, "with --static-optimization: qddot += KP (q_d - q), 1/s^2, the solve then at "
                                       "the arm's state (computed torque; 0 with --so-kd 0: pure feedforward)");
  app.add_option("--so-kd", cfg.so_kd, "with --static-optimization: qddot += KD (qdot_d - qdot), 1/s");
  app.add_option("--timeout", cfg.input_timeout, "s of input silence after which the session ends and the excitation "
                                                 "falls to zero (2 periods .. 10 s)")->capture_default_str();
  app.add_option("--resume-grace", cfg.resume_grace, "s after the hold that follows a timeout in which only the timed-out "
                                                     "owner may claim the session again (0 .. 60 s)")->capture_default_str();
  app.add_option("--channels", cfg.channels, "names (element, muscle or group) of the channel mapping (packet type 4)")
      ->delimiter(',');
  app.add_option("--max-activation", cfg.max_activation, "paralysis/weakness: NAME=V caps the activation of "
                                                       "element, muscle or group NAME at V in [0, 1] (comma-separated)")
      ->delimiter(',');
  app.add_option("--strength", cfg.strength, "weakness: NAME=V scales the maximum isometric force (DAS3 fmax) of "
                                           "element, muscle or group NAME by V >= 0 (1: intact; comma-separated)")
      ->delimiter(',');
  app.add_option("--profile-name", cfg.profile, "the participant profile's name, recorded in the statistics (the "
                                              "armrt-rt console script sets it from --profile)");
  std::string profile_unresolved;
  app.add_option("--profile", profile_unresolved, "participant profile NAME|FILE (.mat / .json): resolved by the "
                                                  "armrt-rt console script (python -m armrt.realtime), not here");
  app.add_option("--stimulation", cfg.stimulation, "stimulation map (docs/fes.md): FILE.toml / FILE.json, per_muscle, or default (the model's shipped "
                                                 "map, resolved by the armrt-rt entry point); "
                                                 "packet type 7 then carries pulse width s, amplitude A, frequency Hz "
                                                 "per channel (beyond a channel's limits: the packet refused, counted, the previous command held)");
  app.add_option("--rx-budget", cfg.rx_budget_us, "receive work per cycle, us (default: min(150, period / 4))");
  app.add_option("--json", json_path, "write the statistics as JSON");
  app.add_flag("--quiet", quiet, "print only the summary (and the bound udp port with --listen)");
  try {
    app.parse(argc, argv);
    if (!app.remaining().empty()) throw std::invalid_argument(unknown_option_message(app, app.remaining().front()));
    if (app.count("--dt")) {
      if (app.count("--integration-step"))
        throw std::invalid_argument("--dt (deprecated) and --integration-step both given; use --integration-step");
      std::fprintf(stderr, "armrt-rt: warning: --dt is deprecated, use --integration-step (the integrator's step; "
                           "dt in armrt is the control step, here 1/--rate)\n");
      cfg.integration_step = deprecated_dt;
    }
    if (app.count("--profile"))
      throw std::invalid_argument("--profile " + profile_unresolved + ": profiles are resolved in Python by the armrt-rt "
                                  "console script (python -m armrt.realtime, Arm.apply_profile), which passes "
                                  "--strength, --max-activation and --profile-name here; run that, or give those");
    cfg.realtime = !no_rt;
    cfg.lock_memory = !no_mlock;
    if (cfg.require_rt && !cfg.realtime) throw std::invalid_argument("--require-rt and --no-rt contradict each other");
    if (!key_file.empty()) cfg.key = armrt::rt::read_key_file(key_file);
    for (const auto& lib : model_libraries) armrt::rt::load_checked_model_library(lib);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "armrt-rt: %s (armrt-rt --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armrt-rt: %s (armrt-rt --help)\n", e.what());
    return 2;
  }

  std::unique_ptr<RtLoop> loop;
  try {
    loop = std::make_unique<RtLoop>(cfg);
  } catch (const armrt::rt::SettleError& e) {
    std::fprintf(stderr, "armrt-rt: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armrt-rt: %s\n", e.what());
    return 2;
  }
  for (const auto& w : loop->stats().warnings) std::fprintf(stderr, "armrt-rt: warning: %s\n", w.c_str());
  g_loop = loop.get();
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  // SIGHUP (the terminal or ssh session closed) and SIGQUIT (Ctrl-backslash) end the run as SIGINT / SIGTERM do: their
  // default actions would kill the runner without its statistics and without the last state packet
  // flagged stopped, which tells the controller and subscribers that the excitation is gone.
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaction(sig, &sa, nullptr);

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
    std::printf("armrt-rt: %s %s at %g Hz (control step %g s, integration step %g s), %s priority %d, memory %s, "
                "cpu %d\n", cfg.model.c_str(), cfg.integrator.c_str(), cfg.rate_hz, 1.0 / cfg.rate_hz,
                loop->config().integration_step, st0.scheduler.c_str(), st0.priority,
                st0.memory_locked ? "locked" : "not locked", st0.cpu);
    std::fflush(stdout);
  }
  // The bound port is printed even with --quiet: with --listen HOST:0 it is the only way to learn it.
  if (!cfg.listen.empty()) {
    std::printf("armrt-rt: listening on udp port %d\n", loop->bound_port());
    std::fflush(stdout);
  }
  while (!loop->finished()) {
    timespec ts{0, 20000000};
    nanosleep(&ts, nullptr);  // a signal interrupts it; the handler has already asked the loop to stop
  }
  loop->join();
  g_loop = nullptr;

  const auto st = loop->stats();
  std::printf("armrt-rt: %s%s%s stopped (%s) after %lld cycles, %.3f s, sim time %.3f s\n", st.model.c_str(),
              st.profile.empty() ? "" : ", profile ", st.profile.c_str(), st.stop_reason.c_str(),
              static_cast<long long>(st.cycles), st.elapsed_s, st.sim_time);
  print_pct("TET", st.tet);
  print_pct("cycle", st.cycle);
  print_pct("latency", st.latency);
  if (st.static_optimization) {
    // On the console too: a run whose every solve was infeasible delivered zero excitation throughout.
    print_pct("solve", st.so_solve);
    std::printf("  static optimisation: solves %lld, infeasible %lld (not converged %lld; zero excitation), refused "
                "%lld\n", static_cast<long long>(st.so_solves), static_cast<long long>(st.so_infeasible),
                static_cast<long long>(st.so_not_converged), static_cast<long long>(st.so_refused));
  }
  std::printf("  overruns %lld (missed periods %lld) over %lld cycles; %s, priority %d, memory %s\n",
              static_cast<long long>(st.overruns), static_cast<long long>(st.missed_deadlines),
              static_cast<long long>(st.cycles), st.scheduler.c_str(), st.priority,
              st.memory_locked ? "locked" : "not locked");
  const auto& k = st.packets;
  std::printf("  packets: received %llu, applied %llu, dropped %llu (foreign %llu), sessions %llu, owner changes %llu, "
              "timeouts %llu, state sent %llu; lag %.3f s\n",
              (unsigned long long)k.received, (unsigned long long)k.applied, (unsigned long long)k.dropped(),
              (unsigned long long)k.foreign, (unsigned long long)k.sessions, (unsigned long long)k.owner_changes,
              (unsigned long long)k.timeouts, (unsigned long long)k.state_sent, st.lag_s);
  std::printf("  kernel drops %llu (receive buffers %d and %d bytes)\n", (unsigned long long)k.kernel_drops,
              st.rcvbuf_bytes, st.owner_rcvbuf_bytes);
  if (!cfg.stimulation.empty())
    std::printf("  stimulation: %d channels, packets applied %llu, refused beyond the channels' limits %llu\n",
                loop->arm().data.stimulation_map.num_channels, (unsigned long long)k.stimulation_applied,
                (unsigned long long)k.stimulation_refused);
  std::fflush(stdout);
  // A run whose statistics were asked for and lost is not a success: a script reading the JSON would
  // otherwise find an old file or none after exit status 0. The error is checked after close (a full disk
  // shows only when the buffer is flushed).
  bool json_failed = false;
  if (!json_path.empty()) {
    errno = 0;
    std::ofstream f(json_path);
    if (f) f << loop->stats_json();
    if (f) f.close();
    if (!f) {
      json_failed = true;
      std::fprintf(stderr, "armrt-rt: could not write the statistics to --json %s%s%s\n", json_path.c_str(),
                   errno ? ": " : "", errno ? std::strerror(errno) : "");
    }
  }
  if (st.stop_reason == "diverged" || st.stop_reason == "lag") {
    std::fprintf(stderr, "armrt-rt: %s\n", st.error.c_str());
    return 1;
  }
  return json_failed ? 4 : 0;
}
