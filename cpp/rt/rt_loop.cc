#include "rt_loop.h"

#include <arpa/inet.h>
#include <errno.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "armrt/clock.h"

namespace armrt::rt {

namespace {

inline timespec to_timespec(std::int64_t ns) {
  timespec ts;
  ts.tv_sec = static_cast<time_t>(ns / 1000000000LL);
  ts.tv_nsec = static_cast<long>(ns % 1000000000LL);
  return ts;
}

inline std::int32_t clamp_i32(std::int64_t v) {
  if (v > 2000000000LL) return 2000000000;
  if (v < -2000000000LL) return -2000000000;
  return static_cast<std::int32_t>(v);
}

const GroupDef* find_group(const GroupDef* g, int n, const std::string& name) {
  for (int k = 0; k < n; ++k)
    if (name == g[k].name) return &g[k];
  return nullptr;
}

}  // namespace

sockaddr_in parse_endpoint(const std::string& s) {
  const auto colon = s.rfind(':');
  if (colon == std::string::npos) throw std::invalid_argument("expected HOST:PORT, got '" + s + "'");
  std::string host = s.substr(0, colon);
  const std::string port = s.substr(colon + 1);
  if (host.empty() || host == "localhost") host = "127.0.0.1";
  sockaddr_in a{};
  a.sin_family = AF_INET;
  char* end = nullptr;
  const long p = std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || p < 0 || p > 65535)
    throw std::invalid_argument("bad port in '" + s + "'");
  a.sin_port = htons(static_cast<std::uint16_t>(p));
  if (inet_pton(AF_INET, host.c_str(), &a.sin_addr) != 1)
    throw std::invalid_argument("bad IPv4 address in '" + s + "' (numeric addresses or localhost)");
  return a;
}

RtLoop::RtLoop(const RtConfig& config) : cfg_(config) {
  const ModelDef* def = find_model(cfg_.model);
  if (!def) throw std::invalid_argument("unknown model '" + cfg_.model + "' (compiled-in models: " + model_names() + ")");
  const Integrator integ = parse_integrator(cfg_.integrator);
  if (!is_fixed_cost(integ))
    throw std::invalid_argument(std::string(integrator_name(integ)) +
                                " is not a real-time integrator (its step time is not bounded); use ros2, rk4 or euler");
  if (!(cfg_.rate_hz > 0 && cfg_.rate_hz <= 100000)) throw std::invalid_argument("rate must be in (0, 100000] Hz");
  // Each cycle advances the simulation by one period (real time); the integrator takes as many
  // substeps of at most dt as that needs. Default dt: default_max_step() (ROS2: one 1 ms step per cycle).
  if (cfg_.dt <= 0) cfg_.dt = default_max_step(integ);
  const double period_s = 1.0 / cfg_.rate_hz;
  const int substeps = std::max(1, static_cast<int>(std::ceil(period_s / cfg_.dt - 1e-9)));
  cfg_.dt = period_s / substeps;
  if (cfg_.priority < 1 || cfg_.priority > 99) throw std::invalid_argument("priority must be in 1..99");
  if (!(cfg_.input_timeout > 0)) throw std::invalid_argument("input timeout must be positive");
  if (cfg_.busy_wait_us < 0) throw std::invalid_argument("busy-wait must be >= 0");
  if (cfg_.duration < 0) throw std::invalid_argument("duration must be >= 0");
  if (cfg_.max_packets_per_cycle < 1) cfg_.max_packets_per_cycle = 1;
  period_ns_ = 1e9 / cfg_.rate_hz;
  max_cycles_ = cfg_.duration > 0 ? static_cast<std::int64_t>(std::llround(cfg_.duration * cfg_.rate_hz)) : 0;
  if (cfg_.state_rate_hz < 0) throw std::invalid_argument("state rate must be >= 0");
  state_every_ = cfg_.state_rate_hz > 0 ? std::max(1, static_cast<int>(std::lround(cfg_.rate_hz / cfg_.state_rate_hz))) : 0;

  sim_ = std::make_unique<Simulator>(*def, integ, period_s, substeps);
  n_el_ = sim_->model.num_elements;
  if (!cfg_.q0.empty()) {
    if (static_cast<int>(cfg_.q0.size()) != kNumDofs)
      throw std::invalid_argument("q0 needs " + std::to_string(kNumDofs) + " values");
    sim_->reset(cfg_.q0.data(), nullptr, nullptr);
  }
  sim_->data.excitation.fill(0.0);

  auto build = [](Mapping& m, const GroupDef* g, int n) {
    m.offsets.assign(1, 0);
    for (int k = 0; k < n; ++k) {
      m.elements.insert(m.elements.end(), g[k].elements, g[k].elements + g[k].num_elements);
      m.offsets.push_back(static_cast<int>(m.elements.size()));
    }
  };
  build(muscles_, def->muscles, def->num_muscles);
  build(groups_, def->groups, def->num_groups);
  channels_.offsets.assign(1, 0);
  for (const std::string& name : cfg_.channels) {
    int e = -1;
    for (int i = 0; i < def->num_elements; ++i)
      if (name == def->elements[i].name) e = i;
    if (e >= 0) {
      channels_.elements.push_back(e);
    } else {
      const GroupDef* g = find_group(def->muscles, def->num_muscles, name);
      if (!g) g = find_group(def->groups, def->num_groups, name);
      if (!g) throw std::invalid_argument("unknown channel name '" + name + "' (expected an element, muscle or group name)");
      channels_.elements.insert(channels_.elements.end(), g->elements, g->elements + g->num_elements);
    }
    channels_.offsets.push_back(static_cast<int>(channels_.elements.size()));
  }

  cap_ = static_cast<std::int64_t>(cfg_.record_capacity);
  if (cap_ <= 0) cap_ = max_cycles_ > 0 ? max_cycles_ + 1 : static_cast<std::int64_t>(600 * cfg_.rate_hz);
  rec_tet_.assign(cap_, 0);  // assign() writes every element: the pages are touched now
  rec_cycle_.assign(cap_, 0);
  rec_latency_.assign(cap_, 0);
  rx_buf_.assign(kMaxPacket + 64, 0);
  tx_buf_.assign(kMaxPacket, 0);
  values_.assign(kMaxValues, 0.0);

  if (!cfg_.listen.empty() || !cfg_.state_to.empty()) {
    sock_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (sock_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    if (!cfg_.listen.empty()) {
      sockaddr_in a = parse_endpoint(cfg_.listen);
      if (::bind(sock_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        const std::string msg = std::string("bind ") + cfg_.listen + ": " + std::strerror(errno);
        ::close(sock_);
        throw std::runtime_error(msg);
      }
      socklen_t len = sizeof a;
      ::getsockname(sock_, reinterpret_cast<sockaddr*>(&a), &len);
      bound_port_ = ntohs(a.sin_port);
    }
    if (!cfg_.state_to.empty()) {
      dest_ = parse_endpoint(cfg_.state_to);
      have_dest_ = fixed_dest_ = true;
    }
  }
}

RtLoop::~RtLoop() {
  if (thread_started_) {
    request_stop();
    join();
  }
  if (sock_ >= 0) ::close(sock_);
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

void RtLoop::apply_mapping(const Mapping& m, const double* values) {
  auto& u = sim_->data.excitation;
  for (int i = 0; i < n_el_; ++i) u[i] = 0.0;
  // An element in several groups (or channels) takes the largest of their values.
  for (int k = 0; k < m.size(); ++k)
    for (int j = m.offsets[k]; j < m.offsets[k + 1]; ++j) u[m.elements[j]] = std::max(u[m.elements[j]], values[k]);
}

void RtLoop::apply_packet(const std::uint8_t* buf, long n, const sockaddr_in& from, double now_s) {
  if (n > kMaxPacket) { ++pk_.bad_size; return; }
  Header h;
  switch (decode_header(buf, n, h)) {
    case DecodeError::kBadMagic: ++pk_.bad_magic; return;
    case DecodeError::kBadVersion: ++pk_.bad_version; return;
    case DecodeError::kBadSize: ++pk_.bad_size; return;
    case DecodeError::kOk: break;
  }
  const Mapping* map = nullptr;
  int expected = 0;
  switch (h.type) {
    case kExcitationElements: expected = n_el_; break;
    case kExcitationMuscles: map = &muscles_; expected = map->size(); break;
    case kExcitationGroups: map = &groups_; expected = map->size(); break;
    case kExcitationChannels: map = &channels_; expected = map->size(); break;
    default: ++pk_.bad_type; return;
  }
  if (h.count != expected || expected == 0) { ++pk_.bad_count; return; }
  bool clipped = false;
  for (int k = 0; k < h.count; ++k) {
    double v = get_f64(buf + kHeaderSize + 8 * k);
    if (!std::isfinite(v)) { ++pk_.non_finite; return; }
    if (v < 0.0) { v = 0.0; clipped = true; }
    if (v > 1.0) { v = 1.0; clipped = true; }
    values_[k] = v;
  }
  // Sequence numbers: wrap-around aware. After a silence (timed out) any number is accepted, so a
  // restarted controller is picked up again.
  if (have_seq_ && !timed_out_) {
    const std::int32_t diff = static_cast<std::int32_t>(h.seq - last_seq_);
    if (diff == 0) { ++pk_.stale; return; }
    if (diff < 0) { ++pk_.out_of_order; return; }
  }
  if (clipped) ++pk_.clipped;
  if (map) apply_mapping(*map, values_.data());
  else for (int i = 0; i < n_el_; ++i) sim_->data.excitation[i] = values_[i];
  have_seq_ = true;
  last_seq_ = h.seq;
  last_valid_s_ = now_s;
  timed_out_ = false;
  ++pk_.applied;
  if (!fixed_dest_) {
    dest_ = from;
    have_dest_ = true;
  }
}

void RtLoop::receive_packets(double now_s) {
  if (sock_ >= 0 && !cfg_.listen.empty()) {
    for (int k = 0; k < cfg_.max_packets_per_cycle; ++k) {
      sockaddr_in from{};
      socklen_t len = sizeof from;
      // MSG_TRUNC: the return value is the datagram's real length even if it did not fit.
      const ssize_t n = ::recvfrom(sock_, rx_buf_.data(), rx_buf_.size(), MSG_DONTWAIT | MSG_TRUNC,
                                   reinterpret_cast<sockaddr*>(&from), &len);
      if (n < 0) break;  // EAGAIN: nothing more this cycle (other errors: try again next cycle)
      ++pk_.received;
      apply_packet(rx_buf_.data(), static_cast<long>(n), from, now_s);
    }
  }
  if (!timed_out_ && now_s - last_valid_s_ > cfg_.input_timeout) {
    for (int i = 0; i < n_el_; ++i) sim_->data.excitation[i] = 0.0;  // safety default
    timed_out_ = true;
    ++pk_.timeouts;
  }
}

void RtLoop::send_state() {
  if (sock_ < 0 || !have_dest_) return;
  Data& d = sim_->data;
  if (d.status == Status::kOk) sim_->evaluate_outputs();  // outputs at the current state
  std::uint8_t* b = tx_buf_.data();
  std::uint16_t flags = 0;
  if (cfg_.send_forces) flags |= kFlagForces;
  if (timed_out_) flags |= kFlagTimedOut;
  if (finished_.load(std::memory_order_relaxed) || diverged_) flags |= kFlagStopped;
  if (diverged_) flags |= kFlagError;
  double* v = values_.data();  // reused as the output staging area (the input is applied by now)
  int c = 0;
  v[c++] = d.time;
  for (int j = 0; j < kNumDofs; ++j) v[c++] = d.x[kQ + j];
  for (int j = 0; j < kNumDofs; ++j) v[c++] = d.x[kQd + j];
  for (int j = 0; j < 3; ++j) v[c++] = d.hand_position[j];
  v[c++] = d.gh_stab;
  v[c++] = have_seq_ ? static_cast<double>(last_seq_) : -1.0;
  if (cfg_.send_forces)
    for (int i = 0; i < n_el_; ++i) v[c++] = d.muscle_force[i];
  const int len = encode(b, kState, tx_seq_++, flags, v, c);
  const ssize_t rc = ::sendto(sock_, b, len, MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&dest_), sizeof dest_);
  if (rc == len) ++pk_.state_sent;
  else ++pk_.send_errors;
}

void RtLoop::run_cycles(std::int64_t n) {
  const std::int64_t period = static_cast<std::int64_t>(std::llround(period_ns_));
  const std::int64_t busy = static_cast<std::int64_t>(cfg_.busy_wait_us * 1000.0);
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
    if (max_cycles_ > 0 && cycle >= max_cycles_) { reason = "duration"; break; }
    if (n > 0 && cycle - first >= n) { reason = "cycles"; break; }

    // Sleep to the absolute deadline (optionally to deadline - busy, then spin).
    const std::int64_t wake_at = deadline - busy;
    const timespec ts = to_timespec(wake_at);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
    std::int64_t woke = now_ns();
    if (busy > 0) while (woke < deadline) woke = now_ns();
    const std::int64_t latency = woke - deadline;

    receive_packets(static_cast<double>(woke - t_start) * 1e-9);
    const std::int64_t t0 = now_ns();
    const bool ok = sim_->step();
    const std::int64_t t1 = now_ns();
    if (!ok) {
      diverged_ = true;
      reason = "diverged";
      ++cycle;
      break;
    }
    if (state_every_ > 0 && (cycle + 1) % state_every_ == 0) send_state();
    const std::int64_t t_end = now_ns();

    const std::int64_t idx = cycle % cap_;
    rec_tet_[idx] = clamp_i32(t1 - t0);
    rec_cycle_[idx] = clamp_i32(t_end - woke);
    rec_latency_[idx] = clamp_i32(latency);
    ++cycle;
    cycles_.store(cycle, std::memory_order_relaxed);

    deadline += period;
    if (t_end > deadline) {  // the work ended after the next deadline: skip the periods already gone
      ++overruns_;
      while (deadline < t_end) {
        deadline += period;
        ++missed_;
      }
    }
  }
  cycles_.store(cycle, std::memory_order_relaxed);
  elapsed_s_ += static_cast<double>(now_ns() - t_start) * 1e-9;
  stop_reason_ = reason;
  if (diverged_) error_ = sim_->error_message();
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
  self->send_state();  // last state, flagged stopped (and error if diverged)
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

Percentiles RtLoop::percentiles(const std::int32_t* v, std::int64_t n) {
  Percentiles p;
  p.count = n;
  if (n <= 0) return p;
  std::vector<std::int32_t> s(v, v + n);
  std::sort(s.begin(), s.end());
  auto at = [&](double q) {  // nearest rank
    std::int64_t k = static_cast<std::int64_t>(std::ceil(q * static_cast<double>(n))) - 1;
    k = std::clamp<std::int64_t>(k, 0, n - 1);
    return static_cast<double>(s[k]);
  };
  p.min = s.front();
  p.max = s.back();
  p.median = at(0.5);
  p.p99 = at(0.99);
  p.p999 = at(0.999);
  double sum = 0;
  for (auto x : s) sum += x;
  p.mean = sum / static_cast<double>(n);
  return p;
}

RtStats RtLoop::stats() const {
  RtStats st;
  st.cycles = cycles_.load(std::memory_order_relaxed);
  st.recorded = std::min(st.cycles, cap_);
  st.overruns = overruns_;
  st.missed_deadlines = missed_;
  st.elapsed_s = elapsed_s_;
  st.sim_time = sim_->data.time;
  st.tet = percentiles(rec_tet_.data(), st.recorded);
  st.cycle = percentiles(rec_cycle_.data(), st.recorded);
  st.latency = percentiles(rec_latency_.data(), st.recorded);
  st.packets = pk_;
  st.scheduler = scheduler_;
  st.priority = priority_;
  st.memory_locked = memory_locked_;
  st.cpu = cpu_;
  st.rt_note = rt_note_;
  st.stop_reason = stop_reason_;
  st.error = error_;
  st.rate_hz = cfg_.rate_hz;
  st.dt = cfg_.dt;
  st.integrator = cfg_.integrator;
  return st;
}

namespace {
std::string json_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') { o += '\\'; o += c; }
    else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
    else o += c;
  }
  return o;
}
std::string json_pct(const Percentiles& p) {
  char b[320];
  std::snprintf(b, sizeof b,
                "{\"min\": %.0f, \"median\": %.0f, \"p99\": %.0f, \"p999\": %.0f, \"max\": %.0f, \"mean\": %.1f, \"count\": %lld}",
                p.min, p.median, p.p99, p.p999, p.max, p.mean, static_cast<long long>(p.count));
  return b;
}
}  // namespace

std::string RtLoop::stats_json() const {
  const RtStats s = stats();
  const PacketCounters& k = s.packets;
  char b[1024];
  std::string o = "{\n";
  std::snprintf(b, sizeof b,
                "  \"rate_hz\": %.6g,\n  \"dt\": %.6g,\n  \"integrator\": \"%s\",\n  \"cycles\": %lld,\n"
                "  \"recorded\": %lld,\n  \"overruns\": %lld,\n  \"missed_deadlines\": %lld,\n"
                "  \"elapsed_s\": %.6f,\n  \"sim_time\": %.6f,\n",
                s.rate_hz, s.dt, json_escape(s.integrator).c_str(), static_cast<long long>(s.cycles),
                static_cast<long long>(s.recorded), static_cast<long long>(s.overruns),
                static_cast<long long>(s.missed_deadlines), s.elapsed_s, s.sim_time);
  o += b;
  o += "  \"scheduler\": \"" + s.scheduler + "\",\n";
  o += "  \"priority\": " + std::to_string(s.priority) + ",\n";
  o += std::string("  \"memory_locked\": ") + (s.memory_locked ? "true" : "false") + ",\n";
  o += "  \"cpu\": " + std::to_string(s.cpu) + ",\n";
  o += "  \"rt_note\": \"" + json_escape(s.rt_note) + "\",\n";
  o += "  \"stop_reason\": \"" + json_escape(s.stop_reason) + "\",\n";
  o += "  \"error\": \"" + json_escape(s.error) + "\",\n";
  o += "  \"units\": \"ns\",\n";
  o += "  \"tet_ns\": " + json_pct(s.tet) + ",\n";
  o += "  \"cycle_ns\": " + json_pct(s.cycle) + ",\n";
  o += "  \"latency_ns\": " + json_pct(s.latency) + ",\n";
  std::snprintf(b, sizeof b,
                "  \"packets\": {\"received\": %llu, \"applied\": %llu, \"dropped\": %llu, \"bad_magic\": %llu, "
                "\"bad_version\": %llu, \"bad_size\": %llu, \"bad_type\": %llu, \"bad_count\": %llu, "
                "\"non_finite\": %llu, \"stale\": %llu, \"out_of_order\": %llu, \"clipped\": %llu, "
                "\"timeouts\": %llu, \"state_sent\": %llu, \"send_errors\": %llu}\n",
                (unsigned long long)k.received, (unsigned long long)k.applied, (unsigned long long)k.dropped(),
                (unsigned long long)k.bad_magic, (unsigned long long)k.bad_version, (unsigned long long)k.bad_size,
                (unsigned long long)k.bad_type, (unsigned long long)k.bad_count, (unsigned long long)k.non_finite,
                (unsigned long long)k.stale, (unsigned long long)k.out_of_order, (unsigned long long)k.clipped,
                (unsigned long long)k.timeouts, (unsigned long long)k.state_sent, (unsigned long long)k.send_errors);
  o += b;
  o += "}\n";
  return o;
}

}  // namespace armrt::rt
