#include "rt_loop.h"

#include "armrt/names.h"

#include <arpa/inet.h>
#include <errno.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "armrt/clock.h"

namespace armrt::rt {

namespace {

inline timespec to_timespec(std::int64_t ns) {
  timespec ts;
  ts.tv_sec = static_cast<time_t>(ns / 1000000000LL);
  ts.tv_nsec = static_cast<long>(ns % 1000000000LL);
  return ts;
}


std::uint64_t splitmix64(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint32_t next_session_id(std::uint64_t& s) {
  for (;;) {
    const auto id = static_cast<std::uint32_t>(splitmix64(s) >> 32);
    if (id != 0) return id;
  }
}

bool same_source(const sockaddr_in& a, const sockaddr_in& b) {
  return a.sin_addr.s_addr == b.sin_addr.s_addr && a.sin_port == b.sin_port;
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// A finite number in [lo, hi], else an error naming the option.
void check_range(const char* option, double v, double lo, double hi, const char* unit) {
  if (!std::isfinite(v) || v < lo || v > hi)
    throw std::invalid_argument(std::string(option) + " must be a finite number in [" + fmt(lo) + ", " + fmt(hi) +
                                "] " + unit + ", got " + fmt(v));
}

}  // namespace

RtLoop::RtLoop(const RtConfig& config) : cfg_(config) {
  const ModelDef* def = find_model(cfg_.model);
  if (!def) throw std::invalid_argument("unknown model '" + cfg_.model + "' (compiled-in models: " + model_names() + ")");
  const Integrator integ = parse_integrator(cfg_.integrator);
  if (!is_fixed_cost(integ))
    throw std::invalid_argument(std::string(integrator_name(integ)) +
                                " is not a real-time integrator (its step time is not bounded); use ros2, rk4 or euler");
  // Every numeric option is checked here, so the executable and RealtimeSession refuse the same things.
  check_range("--rate", cfg_.rate_hz, 1.0, 10000.0, "Hz");
  const double period_s = 1.0 / cfg_.rate_hz;
  // Each cycle advances the simulation by one period (real time); the integrator takes as many
  // substeps of at most dt as that needs. Default dt: default_max_step() (ROS2: one 1 ms step per cycle).
  if (cfg_.dt != 0) {
    check_range("--dt", cfg_.dt, 1e-7, 1.0, "s");
    if (cfg_.dt > period_s * (1 + 1e-12))
      throw std::invalid_argument("--dt " + fmt(cfg_.dt) + " s does not fit in one period (1/--rate = " + fmt(period_s) + " s)");
  }
  if (cfg_.dt <= 0) cfg_.dt = default_max_step(integ);
  const int substeps = std::max(1, static_cast<int>(std::ceil(period_s / cfg_.dt - 1e-9)));
  if (substeps > 10000) throw std::invalid_argument("--dt gives " + std::to_string(substeps) + " substeps per period (at most 10000)");
  cfg_.dt = period_s / substeps;
  if (cfg_.priority < 1 || cfg_.priority > 99) throw std::invalid_argument("--priority must be an integer in 1..99");
  if (cfg_.cpu < -1 || cfg_.cpu >= CPU_SETSIZE) throw std::invalid_argument("--cpu must be a CPU number >= 0");
  // The safety timeout is bounded: at least two periods (one late packet is not a silence), at most 10 s.
  check_range("--timeout", cfg_.input_timeout, 2 * period_s, 10.0, "s");
  check_range("--busy-wait", cfg_.busy_wait_us, 0.0, 0.5e6 * period_s, "us (at most half the period)");
  if (cfg_.duration != 0) check_range("--duration", cfg_.duration, period_s, 1e7, "s (0: until stopped; else at least one period)");
  check_range("--max-lag", cfg_.max_lag, 0.0, 1e6, "s");
  if (cfg_.rx_budget_us == 0) cfg_.rx_budget_us = std::min(150.0, 0.25e6 * period_s);
  check_range("--rx-budget", cfg_.rx_budget_us, 1.0, 0.5e6 * period_s, "us (at most half the period)");
  check_range("--state-rate", cfg_.state_rate_hz, 0.0, cfg_.rate_hz, "Hz (at most --rate)");
  period_ns_ = 1e9 / cfg_.rate_hz;
  max_cycles_ = cfg_.duration > 0 ? static_cast<std::int64_t>(std::llround(cfg_.duration * cfg_.rate_hz)) : 0;
  state_every_ = 0;
  if (cfg_.state_rate_hz > 0) {
    // Only rates the loop delivers exactly: one state packet every whole number of cycles.
    const double ratio = cfg_.rate_hz / cfg_.state_rate_hz;
    const long k = std::lround(ratio);
    if (k < 1 || std::fabs(ratio - static_cast<double>(k)) > 1e-9 * ratio) {
      const long lo = std::max(1L, static_cast<long>(std::floor(ratio))), hi = lo + 1;
      throw std::invalid_argument("--state-rate " + fmt(cfg_.state_rate_hz) + " Hz is not --rate / an integer (" +
                                  fmt(cfg_.rate_hz) + " Hz / " + fmt(ratio) + "); the nearest are " +
                                  fmt(cfg_.rate_hz / lo) + " and " + fmt(cfg_.rate_hz / hi) + " Hz");
    }
    state_every_ = static_cast<int>(k);
  }

  sim_ = std::make_unique<Simulator>(*def, integ, period_s, substeps);
  n_el_ = sim_->model.num_elements;
  layout_ = state_layout(sim_->model.num_dofs);
  if (n_el_ > kMaxValues || layout_.fixed_values + 2 * n_el_ > kMaxValues)
    throw std::invalid_argument("model '" + cfg_.model + "' has " + std::to_string(n_el_) +
                                " elements: too many for one packet (state with forces and excitations)");
  if (!cfg_.q0.empty()) {
    if (static_cast<int>(cfg_.q0.size()) != def->num_dofs)
      throw std::invalid_argument("--q0 needs " + std::to_string(def->num_dofs) + " values (model '" + cfg_.model +
                                  "' has " + std::to_string(def->num_dofs) + " DOFs)");
    for (double v : cfg_.q0)
      if (!std::isfinite(v)) throw std::invalid_argument("--q0 values must be finite");
    sim_->reset(cfg_.q0.data(), nullptr, nullptr);
  }
  sim_->data.excitation.fill(0.0);
  // max_activation lives in the model: forward() caps every excitation at it, whatever its source.
  for (const std::string& item : cfg_.max_activation) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("max activation '" + item + "' is not NAME=VALUE");
    const std::string name = item.substr(0, eq);
    char* end = nullptr;
    const double v = std::strtod(item.c_str() + eq + 1, &end);
    if (end == item.c_str() + eq + 1 || *end != '\0' || !(v >= 0.0 && v <= 1.0))
      throw std::invalid_argument("max activation of '" + name + "' must be a number in [0, 1], got '" + item.substr(eq + 1) + "'");
    std::vector<int> ix;
    if (!find_elements(*def, name, ix)) throw std::invalid_argument("--max-activation: " + unknown_names_message(*def, {name}));
    for (int i : ix) sim_->data.settings.max_activation[i] = v;
  }
  if (!cfg_.max_activation.empty()) sim_->apply_settings();

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
    std::vector<int> ix;
    if (!find_elements(*def, name, ix)) throw std::invalid_argument("--channels: " + unknown_names_message(*def, {name}));
    channels_.elements.insert(channels_.elements.end(), ix.begin(), ix.end());
    channels_.offsets.push_back(static_cast<int>(channels_.elements.size()));
  }
  if (static_cast<int>(cfg_.channels.size()) > kMaxValues) throw std::invalid_argument("too many --channels");

  rx_buf_.assign(static_cast<std::size_t>(kBatch) * (kMaxPacket + 64), 0);
  rx_from_.assign(kBatch, sockaddr_in{});
  rx_hdr_storage_.assign(kBatch * (sizeof(mmsghdr) + sizeof(iovec)), 0);
  tx_buf_.assign(kMaxPacket, 0);
  values_.assign(kMaxValues, 0.0);

  if (!cfg_.key.empty()) key_ = HmacKey(cfg_.key);
  for (const auto& a : cfg_.allow) allow_.push_back(parse_source(a));
  for (const auto& d : cfg_.state_to) subscribers_.push_back(parse_endpoint(d, true));
  if (::getrandom(&session_rng_, sizeof session_rng_, 0) != sizeof session_rng_)
    session_rng_ = static_cast<std::uint64_t>(now_ns());
  session_id_ = next_session_id(session_rng_);

  if (!cfg_.listen.empty() || !subscribers_.empty()) {
    sock_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (sock_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    if (!cfg_.listen.empty()) {
      sockaddr_in a = parse_endpoint(cfg_.listen);
      if (a.sin_port != 0) {
        // SO_REUSEPORT below would let a second runner share a fixed port (and half the packets):
        // a plain bind first fails as it always did if anything holds the port.
        const int probe = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        const bool taken = probe >= 0 && ::bind(probe, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0;
        const int err = errno;
        if (probe >= 0) ::close(probe);
        if (taken) {
          ::close(sock_);
          throw std::runtime_error("bind " + cfg_.listen + ": " + std::strerror(err));
        }
      }
      const int one = 1;
      ::setsockopt(sock_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);  // the owner's socket joins it
      if (::bind(sock_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        const std::string msg = std::string("bind ") + cfg_.listen + ": " + std::strerror(errno);
        ::close(sock_);
        throw std::runtime_error(msg);
      }
      socklen_t len = sizeof a;
      ::getsockname(sock_, reinterpret_cast<sockaddr*>(&a), &len);
      bound_port_ = ntohs(a.sin_port);
      // A receive buffer that holds a period of a flood, so the owner's packets are not dropped by the
      // kernel between two cycles (beyond net.core.rmem_max only with CAP_NET_ADMIN: FORCE first).
      const int rcvbuf = 4 << 20;
      if (::setsockopt(sock_, SOL_SOCKET, SO_RCVBUFFORCE, &rcvbuf, sizeof rcvbuf) != 0)
        ::setsockopt(sock_, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
      bound_addr_ = a;
      if (bound_addr_.sin_addr.s_addr == htonl(INADDR_ANY)) bound_addr_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      owner_sock_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
      if (owner_sock_ < 0 || ::setsockopt(owner_sock_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one) != 0 ||
          ::bind(owner_sock_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
          ::connect(owner_sock_, reinterpret_cast<sockaddr*>(&bound_addr_), sizeof bound_addr_) != 0) {
        // Still correct without it (one queue for everyone), only less robust against floods.
        warnings_.push_back(std::string("no separate queue for the session's owner (") + std::strerror(errno) +
                            "): a flood from others can crowd the owner's packets out of the socket buffer");
        if (owner_sock_ >= 0) ::close(owner_sock_);
        owner_sock_ = -1;
      }
      if (!is_loopback(a) && !key_.enabled())
        warnings_.push_back("listening on " + to_string(a) +
                            " (not loopback) without a shared key: any host that can reach it can ask for the "
                            "session; use --key-file (and --allow) on a network (docs/realtime.md, threat model)");
    }
  }
}

RtLoop::~RtLoop() {
  if (thread_started_) {
    request_stop();
    join();
  }
  if (sock_ >= 0) ::close(sock_);
  if (owner_sock_ >= 0) ::close(owner_sock_);
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

void RtLoop::send_to(const std::uint8_t* b, int len, const sockaddr_in& to) {
  const ssize_t rc = ::sendto(sock_, b, len, MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&to), sizeof to);
  if (rc != len) ++pk_.send_errors;
}

void RtLoop::send_offer(const sockaddr_in& to) {
  if (offered_this_cycle_) return;  // at most one per cycle: a flood of hellos gets no flood back
  offered_this_cycle_ = true;
  std::uint8_t* b = tx_buf_.data();
  const std::uint16_t flags = key_.enabled() ? kFlagAuth : 0;
  const int len = encode(b, kOffer, tx_seq_++, flags, nullptr, 0, session_id_);
  if (key_.enabled()) key_.sign(b, len - kTagSize, b + len - kTagSize);
  send_to(b, len, to);
  ++pk_.offers;
}

void RtLoop::end_session(bool released) {
  for (int i = 0; i < n_el_; ++i) sim_->data.excitation[i] = 0.0;  // safety default
  if (released) ++pk_.releases;
  else ++pk_.timeouts;
  have_owner_ = false;
  previous_owner_ = owner_;
  had_owner_ = true;
  have_seq_ = false;
  notify_previous_ = true;  // the ex-owner gets one last state packet, flagged timed out, and no more
  isolate_owner(nullptr);
  session_id_ = next_session_id(session_rng_);  // no packet of the ended session is accepted again
}

void RtLoop::handle_datagram(const std::uint8_t* buf, long n, const sockaddr_in& from, double now_s) {
  // Cheap checks first, on the address only: a flood from elsewhere costs a compare per datagram.
  if (!allow_.empty()) {
    bool ok = false;
    for (const auto& f : allow_) ok = ok || f.matches(from);
    if (!ok) { ++pk_.not_allowed; return; }
  }
  if (have_owner_ && !same_source(from, owner_)) { ++pk_.foreign; return; }
  if (n > kMaxPacket) { ++pk_.bad_size; return; }
  Header h;
  switch (decode_header(buf, n, h)) {
    case DecodeError::kBadMagic: ++pk_.bad_magic; return;
    case DecodeError::kBadVersion: ++pk_.bad_version; return;
    case DecodeError::kBadSize: ++pk_.bad_size; return;
    case DecodeError::kOk: break;
  }
  if (key_.enabled()) {
    if (!(h.flags & kFlagAuth) || !key_.verify(buf, n - kTagSize, buf + n - kTagSize)) { ++pk_.bad_auth; return; }
  }
  const Mapping* map = nullptr;
  int expected = 0;
  switch (h.type) {
    case kHello:
      ++pk_.hellos;
      send_offer(from);
      return;
    case kRelease:
      if (have_owner_ && h.session == session_id_) end_session(true);
      else ++pk_.bad_session;
      return;
    case kExcitationElements: expected = n_el_; break;
    case kExcitationMuscles: map = &muscles_; expected = map->size(); break;
    case kExcitationGroups: map = &groups_; expected = map->size(); break;
    case kExcitationChannels: map = &channels_; expected = map->size(); break;
    default: ++pk_.bad_type; return;
  }
  if (h.count != expected || expected == 0) { ++pk_.bad_count; return; }
  if (h.session != session_id_) {
    // Not (or no longer) this session's: never applied. The sender learns the current id, so a
    // controller that missed the offer or outlived a timeout can start over.
    ++pk_.bad_session;
    send_offer(from);
    return;
  }
  bool clipped = false;
  for (int k = 0; k < h.count; ++k) {
    double v = get_f64(buf + kHeaderSize + 8 * k);
    if (!std::isfinite(v)) { ++pk_.non_finite; return; }
    if (v < 0.0) { v = 0.0; clipped = true; }
    if (v > 1.0) { v = 1.0; clipped = true; }
    values_[k] = v;
  }
  // Sequence numbers (wrap-around aware) within the session.
  if (have_seq_) {
    const std::int32_t diff = static_cast<std::int32_t>(h.seq - last_seq_);
    if (diff == 0) { ++pk_.stale; return; }
    if (diff < 0) { ++pk_.out_of_order; return; }
  }
  if (!have_owner_) {  // the first valid packet with the offered id claims the session
    have_owner_ = true;
    owner_ = from;
    isolate_owner(&owner_);
    ++pk_.sessions;
    if (!had_owner_ || !same_source(from, previous_owner_)) ++pk_.owner_changes;
  }
  if (clipped) ++pk_.clipped;
  if (map) apply_mapping(*map, values_.data());
  else for (int i = 0; i < n_el_; ++i) sim_->data.excitation[i] = values_[i];
  // Held (and streamed with --excitations) as the dynamics use it: capped at max_activation.
  for (int i = 0; i < n_el_; ++i)
    sim_->data.excitation[i] = std::min(sim_->data.excitation[i], sim_->data.muscles.max_activation[i]);
  have_seq_ = true;
  last_seq_ = h.seq;
  last_valid_s_ = now_s;
  ++pk_.applied;
}

void RtLoop::isolate_owner(const sockaddr_in* owner) {
  if (owner_sock_ < 0) return;
  // One connect() per session start or end (not per cycle).
  const sockaddr_in& to = owner ? *owner : bound_addr_;
  ::connect(owner_sock_, reinterpret_cast<const sockaddr*>(&to), sizeof to);
}

// Reads fd in batches until it is empty or the budget is spent; true if the budget ran out.
bool RtLoop::drain(int fd, double now_s, std::int64_t budget_end) {
  auto* msgs = reinterpret_cast<mmsghdr*>(rx_hdr_storage_.data());
  auto* iov = reinterpret_cast<iovec*>(rx_hdr_storage_.data() + kBatch * sizeof(mmsghdr));
  const std::size_t slot = kMaxPacket + 64;
  for (;;) {
    for (int i = 0; i < kBatch; ++i) {
      iov[i].iov_base = rx_buf_.data() + i * slot;
      iov[i].iov_len = slot;
      msgs[i].msg_hdr = msghdr{};
      msgs[i].msg_hdr.msg_name = &rx_from_[i];
      msgs[i].msg_hdr.msg_namelen = sizeof(sockaddr_in);
      msgs[i].msg_hdr.msg_iov = &iov[i];
      msgs[i].msg_hdr.msg_iovlen = 1;
      msgs[i].msg_len = 0;
    }
    const int got = ::recvmmsg(fd, msgs, kBatch, MSG_DONTWAIT, nullptr);
    if (got <= 0) return false;  // EAGAIN: empty (other errors: try again next cycle)
    for (int i = 0; i < got; ++i) {
      ++pk_.received;
      long len = static_cast<long>(msgs[i].msg_len);
      if (msgs[i].msg_hdr.msg_flags & MSG_TRUNC) len = kMaxPacket + 1;  // larger than any packet
      handle_datagram(rx_buf_.data() + i * slot, len, rx_from_[i], now_s);
    }
    if (got < kBatch) return false;
    if (now_ns() >= budget_end) return true;
  }
}

void RtLoop::receive_packets(double now_s) {
  offered_this_cycle_ = false;
  if (sock_ >= 0 && !cfg_.listen.empty()) {
    // The owner's queue first (others cannot fill it), then everything else until empty or the
    // budget is spent, so junk from others cannot queue up in front of the owner's packets.
    const std::int64_t budget_end = now_ns() + static_cast<std::int64_t>(cfg_.rx_budget_us * 1e3);
    bool hit = owner_sock_ >= 0 && drain(owner_sock_, now_s, budget_end);
    hit = drain(sock_, now_s, budget_end) || hit;
    if (hit) ++pk_.rx_budget_hits;
  }
  if (have_owner_ && now_s - last_valid_s_ > cfg_.input_timeout) end_session(false);
}

void RtLoop::send_state() {
  if (sock_ < 0 || (subscribers_.empty() && !have_owner_ && !notify_previous_)) return;
  Data& d = sim_->data;
  if (d.status == Status::kOk) sim_->evaluate_outputs();  // outputs at the current state
  std::uint8_t* b = tx_buf_.data();
  std::uint16_t flags = 0;
  if (cfg_.send_forces) flags |= kFlagForces;
  if (cfg_.send_excitation) flags |= kFlagExcitation;
  if (!have_owner_) flags |= kFlagTimedOut;
  if (finished_.load(std::memory_order_relaxed) || diverged_ || lagged_) flags |= kFlagStopped;
  if (diverged_ || lagged_) flags |= kFlagError;
  if (overrun_since_state_) flags |= kFlagOverrun;
  if (key_.enabled()) flags |= kFlagAuth;
  double* v = values_.data();  // reused as the output staging area (the input is applied by now)
  const StateLayout& st = layout_;
  const Model& m = sim_->model;
  v[st.time] = d.time;
  for (int j = 0; j < m.num_dofs; ++j) v[st.q + j] = d.x[q_offset(m) + j];
  for (int j = 0; j < m.num_dofs; ++j) v[st.qd + j] = d.x[qd_offset(m) + j];
  for (int j = 0; j < 3; ++j) v[st.hand + j] = d.hand_position[j];
  v[st.gh_stab] = d.gh_stab;
  v[st.gh_theta] = d.gh_theta;
  v[st.gh_phi] = d.gh_phi;
  v[st.gh_rim_margin] = d.gh_rim_margin;
  v[st.gh_rim_direction] = d.gh_rim_direction;
  v[st.last_seq] = have_seq_ ? static_cast<double>(last_seq_) : -1.0;
  v[st.lag] = static_cast<double>(missed_) * period_ns_ * 1e-9;
  v[st.overruns] = static_cast<double>(overruns_);
  int c = st.fixed_values;
  if (cfg_.send_forces)
    for (int i = 0; i < n_el_; ++i) v[c++] = d.muscle_force[i];
  if (cfg_.send_excitation)
    for (int i = 0; i < n_el_; ++i) v[c++] = d.excitation[i];
  const int len = encode(b, kState, tx_seq_++, flags, v, c, session_id_);
  if (key_.enabled()) key_.sign(b, len - kTagSize, b + len - kTagSize);
  bool owner_is_subscriber = false;
  for (const auto& to : subscribers_) {
    send_to(b, len, to);
    owner_is_subscriber = owner_is_subscriber || (have_owner_ && same_source(to, owner_));
  }
  if (have_owner_ && !owner_is_subscriber) send_to(b, len, owner_);
  if (notify_previous_) {
    bool subscribed = false;
    for (const auto& to : subscribers_) subscribed = subscribed || same_source(to, previous_owner_);
    if (!subscribed && !(have_owner_ && same_source(owner_, previous_owner_))) send_to(b, len, previous_owner_);
    notify_previous_ = false;
  }
  ++pk_.state_sent;
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
    const bool ok = sim_->step();  // measures its TET (Simulator::step: the one place)
    if (!ok) {
      diverged_ = true;
      reason = "diverged";
      ++cycle;
      break;
    }
    if (state_every_ > 0 && (cycle + 1) % state_every_ == 0) send_state();
    const std::int64_t t_end = now_ns();

    rec_tet_.record(static_cast<std::int64_t>(sim_->data.tet.last_ns));
    rec_cycle_.record(t_end - woke);
    rec_latency_.record(latency);
    ++cycle;
    cycles_.store(cycle, std::memory_order_relaxed);

    deadline += period;
    if (t_end > deadline) {
      // Resynchronisation policy: skip and report. The periods already past are not simulated
      // (catching up would make the next cycles overrun too); the simulated time falls behind the
      // wall-clock schedule by one period per skipped deadline, reported as `lag` in the state
      // packets and statistics, with the overrun flag on the next state packet.
      ++overruns_;
      overrun_since_state_ = true;
      while (deadline < t_end) {
        deadline += period;
        ++missed_;
      }
      if (max_missed >= 0 && missed_ > max_missed) {
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
    error_ = "the simulation fell " + fmt(static_cast<double>(missed_) * period_ns_ * 1e-9) +
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

Percentiles RtLoop::percentiles(const LogHistogram& h) {
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

RtStats RtLoop::stats() const {
  RtStats st;
  st.cycles = cycles_.load(std::memory_order_relaxed);
  st.recorded = rec_tet_.count();
  st.overruns = overruns_;
  st.missed_deadlines = missed_;
  st.lag_s = static_cast<double>(missed_) * period_ns_ * 1e-9;
  st.elapsed_s = elapsed_s_;
  st.sim_time = sim_->data.time;
  st.tet = percentiles(rec_tet_);
  st.cycle = percentiles(rec_cycle_);
  st.latency = percentiles(rec_latency_);
  st.packets = pk_;
  st.scheduler = scheduler_;
  st.priority = priority_;
  st.memory_locked = memory_locked_;
  st.cpu = cpu_;
  st.rt_note = rt_note_;
  st.stop_reason = stop_reason_;
  st.error = error_;
  st.warnings = warnings_;
  st.rate_hz = cfg_.rate_hz;
  st.dt = cfg_.dt;
  st.integrator = cfg_.integrator;
  return st;
}

namespace {
nlohmann::ordered_json json_pct(const Percentiles& p) {
  return {{"min", p.min}, {"median", p.median}, {"p99", p.p99}, {"p999", p.p999},
          {"max", p.max}, {"mean", p.mean}, {"count", p.count}};
}
}  // namespace

std::string RtLoop::stats_json() const {
  const RtStats s = stats();
  const PacketCounters& k = s.packets;
  nlohmann::ordered_json j;
  j["rate_hz"] = s.rate_hz;
  j["dt"] = s.dt;
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
  j["authenticated"] = key_.enabled();
  j["units"] = "ns";
  j["percentile_precision"] = "log-bucket histogram: values within 1/64 of their size";
  j["tet_ns"] = json_pct(s.tet);
  j["cycle_ns"] = json_pct(s.cycle);
  j["latency_ns"] = json_pct(s.latency);
  j["packets"] = {{"received", k.received}, {"applied", k.applied}, {"dropped", k.dropped()},
                  {"foreign", k.foreign}, {"not_allowed", k.not_allowed}, {"bad_magic", k.bad_magic},
                  {"bad_version", k.bad_version}, {"bad_size", k.bad_size}, {"bad_type", k.bad_type},
                  {"bad_count", k.bad_count}, {"bad_auth", k.bad_auth}, {"bad_session", k.bad_session},
                  {"non_finite", k.non_finite}, {"stale", k.stale}, {"out_of_order", k.out_of_order},
                  {"clipped", k.clipped}, {"hellos", k.hellos}, {"offers", k.offers}, {"sessions", k.sessions},
                  {"owner_changes", k.owner_changes}, {"releases", k.releases}, {"timeouts", k.timeouts},
                  {"rx_budget_hits", k.rx_budget_hits}, {"state_sent", k.state_sent},
                  {"send_errors", k.send_errors}};
  return j.dump(2) + "\n";
}

}  // namespace armrt::rt
