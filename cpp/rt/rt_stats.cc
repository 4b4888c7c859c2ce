// Cycle records -> RtStats and its JSON (rt_stats.h).
#include "rt_stats.h"

#include <nlohmann/json.hpp>

namespace armrt::rt {

Percentiles percentiles(const LogHistogram& h) {
  Percentiles p;
  p.count = h.count();
  if (p.count <= 0) return p;
  p.min = static_cast<double>(h.min());
  p.max = static_cast<double>(h.max());
  p.median = h.quantile(0.5);
  p.p99 = h.quantile(0.99);
  p.p999 = h.quantile(0.999);
  p.mean = h.mean();
  return p;
}

void CycleRecorder::fill(RtStats& st) const {
  st.recorded = tet_.count();
  st.overruns = overruns_;
  st.missed_deadlines = missed_;
  st.lag_s = lag_s();
  st.tet = percentiles(tet_);
  st.cycle = percentiles(cycle_);
  st.latency = percentiles(latency_);
}

namespace {
nlohmann::ordered_json json_pct(const Percentiles& p) {
  return {{"min", p.min}, {"median", p.median}, {"p99", p.p99}, {"p999", p.p999},
          {"max", p.max}, {"mean", p.mean}, {"count", p.count}};
}
}  // namespace

std::string stats_json(const RtStats& s) {
  const PacketCounters& k = s.packets;
  nlohmann::ordered_json j;
  j["model"] = s.model;
  j["profile"] = s.profile.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.profile);
  j["hand_load"] = {{"force_N", s.hand_force}, {"moment_N_m", s.hand_moment}};
  j["rate_hz"] = s.rate_hz;
  j["control_step"] = s.control_step;
  j["integration_step"] = s.integration_step;
  j["integrator"] = s.integrator;
  j["cycles"] = s.cycles;
  j["recorded"] = s.recorded;
  j["overruns"] = s.overruns;
  j["missed_deadlines"] = s.missed_deadlines;
  j["lag_s"] = s.lag_s;
  j["resync"] = "skip";
  j["elapsed_s"] = s.elapsed_s;
  j["sim_time"] = s.sim_time;
  j["scheduler"] = s.scheduler;
  j["priority"] = s.priority;
  j["memory_locked"] = s.memory_locked;
  j["cpu"] = s.cpu;
  j["rt_note"] = s.rt_note;
  j["stop_reason"] = s.stop_reason;
  j["error"] = s.error;
  j["warnings"] = s.warnings;
  j["authenticated"] = s.authenticated;
  j["session_hold_s"] = s.session_hold_s;
  j["resume_grace_s"] = s.resume_grace_s;
  j["support_s"] = s.support_s;
  j["rcvbuf_bytes"] = s.rcvbuf_bytes;
  j["owner_rcvbuf_bytes"] = s.owner_rcvbuf_bytes;
  j["units"] = "ns";
  j["percentile_precision"] = "log-bucket histogram: values within 1/64 of their size";
  j["tet_ns"] = json_pct(s.tet);
  j["cycle_ns"] = json_pct(s.cycle);
  j["latency_ns"] = json_pct(s.latency);
  j["packets"] = {{"received", k.received}, {"applied", k.applied}, {"dropped", k.dropped()},
                  {"foreign", k.foreign}, {"not_allowed", k.not_allowed}, {"bad_magic", k.bad_magic},
                  {"bad_version", k.bad_version}, {"bad_size", k.bad_size}, {"bad_type", k.bad_type},
                  {"bad_count", k.bad_count}, {"bad_auth", k.bad_auth}, {"bad_session", k.bad_session},
                  {"non_finite", k.non_finite}, {"targets_applied", k.targets_applied}, {"bad_target", k.bad_target},
                  {"stale", k.stale}, {"out_of_order", k.out_of_order},
                  {"clipped", k.clipped}, {"stimulation_applied", k.stimulation_applied},
                  {"stimulation_refused", k.stimulation_refused}, {"hellos", k.hellos}, {"offers", k.offers},
                  {"replies_limited", k.replies_limited}, {"held_off", k.held_off}, {"session_ended", k.session_ended},
                  {"kernel_drops", k.kernel_drops}, {"sessions", k.sessions},
                  {"owner_changes", k.owner_changes}, {"releases", k.releases}, {"timeouts", k.timeouts},
                  {"rx_budget_hits", k.rx_budget_hits}, {"state_sent", k.state_sent},
                  {"send_errors", k.send_errors}};
  if (s.static_optimization) {
    j["static_optimization"] = {{"solve_ns", json_pct(s.so_solve)}, {"solves", s.so_solves},
                                {"infeasible", s.so_infeasible}, {"not_converged", s.so_not_converged}, {"refused", s.so_refused},
                                {"residual_max_Nm", s.so_residual_max},
                                {"gh_stab_max", s.so_gh_stab_max > 0 ? nlohmann::ordered_json(s.so_gh_stab_max)
                                                                     : nlohmann::ordered_json(nullptr)},
                                {"kp", s.so_kp}, {"kd", s.so_kd}, {"tendon", "rigid"}};
  } else {
    j["static_optimization"] = nullptr;
  }
  return j.dump(2) + "\n";
}

}  // namespace armrt::rt
