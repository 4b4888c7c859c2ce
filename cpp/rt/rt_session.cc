// Datagrams in -> the owner's excitation command; state values -> state packets out (rt_session.h).
#include "rt_session.h"

#include <arpa/inet.h>
#include <errno.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "armrt/clock.h"
#include "armrt/model.h"
#include "armrt/static_optimization.h"

namespace armrt::rt {

namespace {

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

// The receive buffer both queues ask for: 4 MB, as the kernel counts it 8 MB with its bookkeeping (getsockopt
// reports the doubled value), which holds about 10 000 of the smallest datagrams (24 bytes, each costing
// ~830 bytes of kernel memory) or about 990 of the largest packets (4152 bytes) between two cycles (the
// default, 212 992 bytes, held 256 and 25). Beyond net.core.rmem_max only with CAP_NET_ADMIN (FORCE first);
// the size obtained is in the statistics. Drops beyond it are counted (SO_RXQ_OVFL).
constexpr int kRcvBufBytes = 4 << 20;

int size_queue(int fd) {
  if (::setsockopt(fd, SOL_SOCKET, SO_RCVBUFFORCE, &kRcvBufBytes, sizeof kRcvBufBytes) != 0)
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &kRcvBufBytes, sizeof kRcvBufBytes);
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_RXQ_OVFL, &one, sizeof one);  // each datagram carries the queue's drop count
  int got = 0;
  socklen_t len = sizeof got;
  ::getsockopt(fd, SOL_SOCKET, SO_RCVBUF, &got, &len);
  return got;
}

bool same_source(const sockaddr_in& a, const sockaddr_in& b) {
  return a.sin_addr.s_addr == b.sin_addr.s_addr && a.sin_port == b.sin_port;
}

// The model's muscles or groups as one mapping, in the model's order, at their own level (not
// looked up by name: a group may share a muscle's name).
NamedElements model_mapping(const GroupDef* g, int n, NameLevel level) {
  NamedElements m;
  for (int k = 0; k < n; ++k) {
    m.names.emplace_back(g[k].name);
    m.elements.insert(m.elements.end(), g[k].elements, g[k].elements + g[k].num_elements);
    m.offsets.push_back(static_cast<int>(m.elements.size()));
    m.levels.push_back(level);
  }
  return m;
}

}  // namespace

Session::Session(const RtConfig& cfg, const ModelDef& def, const StimulationMap& map,
                 std::vector<std::string>& warnings)
    : listening_(!cfg.listen.empty()), input_timeout_(cfg.input_timeout), rx_budget_us_(cfg.rx_budget_us),
      n_dofs_(def.num_dofs), n_el_(def.num_elements), map_(map) {
  if (cfg.send_forces) block_flags_ |= kFlagForces;
  if (cfg.send_excitation) block_flags_ |= kFlagExcitation;
  if (map_.num_channels > 0) block_flags_ |= kFlagStimulation;
  stim_command_.assign(3 * static_cast<std::size_t>(map_.num_channels), 0.0);
  muscles_ = model_mapping(def.muscles, def.num_muscles, NameLevel::kMuscle);
  groups_ = model_mapping(def.groups, def.num_groups, NameLevel::kGroup);
  try {
    channels_ = resolve_names(def, cfg.channels);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--channels: ") + e.what());
  }
  level_scratch_.assign(n_el_, NameLevel::kUnnamed);
  command_.assign(n_el_, 0.0);
  if (cfg.static_optimization) {  // kTarget packets: desired q, qdot, qddot; their joint angles checked as the Python API
    target_count_ = 3 * n_dofs_;
    target_.assign(target_count_, 0.0);
    for (int j = 0; j < n_dofs_; ++j) {
      dof_lo_.push_back(def.dofs[j].range_min - kJointRangeMargin);
      dof_hi_.push_back(def.dofs[j].range_max + kJointRangeMargin);
    }
  }

  // The hold after a timeout: at zero excitation each activation decays as exp(-t / tdeact) (the model's
  // activation dynamics, da/dt = (c1 u + c2)(u - a) with c2 = 1/tdeact, He et al. 1991); ln(100) time
  // constants of the slowest element take every activation below 1 % of its value (das2: deltoid, tdeact
  // 83.5 ms: 0.385 s). Counted in cycles of simulated time.
  double tdeact_max = 0;
  for (int i = 0; i < def.num_elements; ++i) tdeact_max = std::max(tdeact_max, def.elements[i].tdeact);
  const double period_s = 1.0 / cfg.rate_hz;
  hold_cycles_ = static_cast<std::int64_t>(std::ceil(std::log(100.0) * tdeact_max / period_s - 1e-9));
  hold_s_ = static_cast<double>(hold_cycles_) * period_s;
  grace_cycles_ = static_cast<std::int64_t>(std::ceil(cfg.resume_grace / period_s - 1e-9));
  grace_s_ = static_cast<double>(grace_cycles_) * period_s;
  reply_interval_cycles_ = std::max<std::int64_t>(1, std::llround(kReplyInterval / period_s));

  rx_buf_.assign(static_cast<std::size_t>(kBatch) * (kMaxPacket + 64), 0);
  rx_from_.assign(kBatch, sockaddr_in{});
  rx_hdr_storage_.assign(kBatch * (sizeof(mmsghdr) + sizeof(iovec)), 0);
  rx_ctrl_.assign(kBatch * kCtrlWords, 0);
  tx_buf_.assign(kMaxPacket, 0);
  values_.assign(kMaxValues, 0.0);

  if (!cfg.key.empty()) key_ = HmacKey(cfg.key);
  for (const auto& a : cfg.allow) {
    try {
      allow_.push_back(parse_source(a));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--allow: ") + e.what());
    }
  }
  for (const auto& d : cfg.state_to) subscribers_.push_back(parse_endpoint(d, true));
  if (::getrandom(&session_rng_, sizeof session_rng_, 0) != sizeof session_rng_)
    session_rng_ = static_cast<std::uint64_t>(now_ns());
  session_id_ = next_session_id(session_rng_);

  if (!cfg.listen.empty() || !subscribers_.empty()) {
    sock_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (sock_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    if (!cfg.listen.empty()) {
      sockaddr_in a = parse_endpoint(cfg.listen);
      if (a.sin_port != 0) {
        // SO_REUSEPORT below would let a second runner share a fixed port (and half the packets):
        // a plain bind first fails as it always did if anything holds the port.
        const int probe = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        const bool taken = probe >= 0 && ::bind(probe, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0;
        const int err = errno;
        if (probe >= 0) ::close(probe);
        if (taken) {
          ::close(sock_);
          throw std::runtime_error("bind " + cfg.listen + ": " + std::strerror(err));
        }
      }
      const int one = 1;
      ::setsockopt(sock_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);  // the owner's socket joins it
      if (::bind(sock_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        const std::string msg = std::string("bind ") + cfg.listen + ": " + std::strerror(errno);
        ::close(sock_);
        throw std::runtime_error(msg);
      }
      socklen_t len = sizeof a;
      ::getsockname(sock_, reinterpret_cast<sockaddr*>(&a), &len);
      bound_port_ = ntohs(a.sin_port);
      // A receive buffer that holds a period of a flood, so the owner's packets are not dropped by the
      // kernel between two cycles (kRcvBufBytes above).
      rcvbuf_bytes_ = size_queue(sock_);
      bound_addr_ = a;
      if (bound_addr_.sin_addr.s_addr == htonl(INADDR_ANY)) bound_addr_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      owner_sock_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
      // Sized as the shared queue: with the default buffer, junk from the owner's own address (a buggy
      // controller) cost owner packets (3 lost in the audit of issue 29).
      if (owner_sock_ >= 0) owner_rcvbuf_bytes_ = size_queue(owner_sock_);
      if (owner_sock_ < 0 || ::setsockopt(owner_sock_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one) != 0 ||
          ::bind(owner_sock_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
          ::connect(owner_sock_, reinterpret_cast<sockaddr*>(&bound_addr_), sizeof bound_addr_) != 0) {
        // Still correct without it (one queue for everyone), only less robust against floods.
        warnings.push_back(std::string("no separate queue for the session's owner (") + std::strerror(errno) +
                            "): a flood from others can crowd the owner's packets out of the socket buffer");
        if (owner_sock_ >= 0) ::close(owner_sock_);
        owner_sock_ = -1;
        owner_rcvbuf_bytes_ = 0;
      }
      if (!is_loopback(a) && !key_.enabled())
        warnings.push_back("listening on " + to_string(a) +
                            " (not loopback) without a shared key: any host that can reach it can ask for the "
                            "session; use --key-file (and --allow) on a network (docs/realtime.md, threat model)");
    }
  }
}

Session::~Session() {
  if (sock_ >= 0) ::close(sock_);
  if (owner_sock_ >= 0) ::close(owner_sock_);
}

void Session::send_to(const std::uint8_t* b, int len, const sockaddr_in& to) {
  const ssize_t rc = ::sendto(sock_, b, len, MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&to), sizeof to);
  if (rc != len) ++pk_.send_errors;
}

bool Session::may_claim(const sockaddr_in& from) const {
  if (cycle_ < hold_end_) return false;                                          // the hold: nobody
  if (cycle_ < grace_end_) return had_owner_ && same_source(from, previous_owner_);  // the old owner's turn
  return true;
}

bool Session::reply_allowed(const sockaddr_in& to, bool within_share) {
  // A flood from one source used to take the one offer per cycle every cycle (0 of 10 joins from elsewhere
  // succeeded): each source now has its own share, and the cycle's replies are bounded (no amplification).
  ReplySlot* slot = nullptr;
  ReplySlot* oldest = &reply_slots_[0];
  for (auto& r : reply_slots_) {
    if (r.last_cycle >= 0 && r.addr == to.sin_addr.s_addr && r.port == to.sin_port) { slot = &r; break; }
    if (r.last_cycle < oldest->last_cycle) oldest = &r;
  }
  if (within_share &&
      ((slot && cycle_ - slot->last_cycle < reply_interval_cycles_) || replies_this_cycle_ >= kRepliesPerCycle)) {
    ++pk_.replies_limited;
    return false;
  }
  if (!slot) {  // a new source takes a free slot or the least recently answered one
    slot = oldest;
    slot->addr = to.sin_addr.s_addr;
    slot->port = to.sin_port;
  }
  slot->last_cycle = cycle_;
  ++replies_this_cycle_;
  return true;
}

void Session::send_session_ended(const sockaddr_in& to) {
  std::uint8_t* b = tx_buf_.data();
  const std::uint16_t flags = key_.enabled() ? kFlagAuth : 0;
  const double why[3] = {1.0, hold_s_, grace_s_};  // reason 1: timeout
  const int len = encode(b, kSessionEnded, tx_seq_++, flags, why, 3, ended_session_id_);
  if (key_.enabled()) key_.sign(b, len - kTagSize, b + len - kTagSize);
  send_to(b, len, to);
  ++pk_.session_ended;
}

void Session::send_offer(const sockaddr_in& to) {
  if (!may_claim(to)) { ++pk_.held_off; return; }  // no offer while the source could not claim
  if (!reply_allowed(to)) return;
  std::uint8_t* b = tx_buf_.data();
  const std::uint16_t flags = key_.enabled() ? kFlagAuth : 0;
  const int len = encode(b, kOffer, tx_seq_++, flags, nullptr, 0, session_id_);
  if (key_.enabled()) key_.sign(b, len - kTagSize, b + len - kTagSize);
  send_to(b, len, to);
  ++pk_.offers;
}

void Session::end_session(bool released) {
  for (int i = 0; i < n_el_; ++i) command_[i] = 0.0;  // safety default: no excitation, no stimulation
  std::fill(stim_command_.begin(), stim_command_.end(), 0.0);
  has_target_ = false;  // --static-optimization: no target, zero excitation
  changed_ = true;
  if (released) ++pk_.releases;
  else ++pk_.timeouts;
  have_owner_ = false;
  previous_owner_ = owner_;
  had_owner_ = true;
  have_seq_ = false;
  notify_previous_ = true;  // the ex-owner gets one last state packet, flagged timed out, and no more
  isolate_owner(nullptr);
  ended_session_id_ = released ? 0 : session_id_;
  if (!released) {
    // The hold, then the old owner's grace (rt_session.h); it is told now, so it does not send into a void.
    hold_end_ = cycle_ + hold_cycles_;
    grace_end_ = hold_end_ + grace_cycles_;
    if (sock_ >= 0 && reply_allowed(previous_owner_, false)) send_session_ended(previous_owner_);
  }
  session_id_ = next_session_id(session_rng_);  // no packet of the ended session is accepted again
}

void Session::handle_datagram(const std::uint8_t* buf, long n, const sockaddr_in& from, double now_s) {
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
  const NamedElements* map = nullptr;
  int expected = 0;
  switch (h.type) {
    case kHello:
      ++pk_.hellos;
      send_offer(from);  // none in the hold, only to the old owner in its grace, within each source's share
      return;
    case kRelease:
      if (have_owner_ && h.session == session_id_) end_session(true);
      else ++pk_.bad_session;
      return;
    case kExcitationElements: expected = n_el_; break;
    case kExcitationMuscles: map = &muscles_; expected = map->size(); break;
    case kExcitationGroups: map = &groups_; expected = map->size(); break;
    case kExcitationChannels: map = &channels_; expected = map->size(); break;
    case kStimulation: expected = 3 * map_.num_channels; break;  // 0 without a map: refused as bad_count
    case kTarget: expected = target_count_; break;  // 0 without --static-optimization: refused as bad_count
    default: ++pk_.bad_type; return;
  }
  // With --static-optimization the runner computes the excitations: excitation packets are refused.
  if (target_count_ && h.type != kTarget && h.type != kStimulation) { ++pk_.bad_type; return; }
  if (h.count != expected || expected == 0) { ++pk_.bad_count; return; }
  if (h.session != session_id_) {
    // Not (or no longer) this session's: never applied. The sender learns the current id, so a
    // controller that missed the offer or outlived a timeout can start over.
    ++pk_.bad_session;
    if (ended_session_id_ != 0 && h.session == ended_session_id_ && had_owner_ && same_source(from, previous_owner_)) {
      // The timed-out owner still sends in its ended session: it is told again that the session ended (it
      // must join again, UdpClient raises SessionEnded), instead of silently getting a new id.
      if (reply_allowed(from)) send_session_ended(from);
    } else {
      send_offer(from);
    }
    return;
  }
  for (int k = 0; k < h.count; ++k) {
    values_[k] = get_f64(buf + kHeaderSize + 8 * k);
    if (!std::isfinite(values_[k])) { ++pk_.non_finite; return; }  // the whole packet: nothing applied
  }
  if (h.type == kTarget) {
    // StaticOptimizer's own check (checks.joint_range without warning: the engine's state margin): a joint angle
    // beyond its range by more is refused, the previous target kept.
    for (int j = 0; j < n_dofs_; ++j)
      if (values_[j] < dof_lo_[j] || values_[j] > dof_hi_[j]) { ++pk_.bad_target; return; }
    // And its acceleration bound: the solve would run for seconds in the loop (static_optimization.h).
    for (int j = 2 * n_dofs_; j < 3 * n_dofs_; ++j)
      if (std::abs(values_[j]) > kStaticOptimizationMaxJointAcceleration) { ++pk_.bad_target; return; }
    // And its joint-speed bound (the arm's max_joint_speed, the runner's default): faster is a diverged simulation
    // or degrees per second, not a motion to solve for.
    for (int j = n_dofs_; j < 2 * n_dofs_; ++j)
      if (std::abs(values_[j]) > kDefaultMaxJointSpeed) { ++pk_.bad_target; return; }
  }
  if (h.type == kStimulation) {
    // A value Arm.set_stimulation refuses (negative, beyond a channel's pulse width, amplitude, frequency or charge
    // per phase) drops the whole packet, the previous command held (and zero after --timeout if nothing valid
    // follows). Clamping applied a unit slip as the channel's maximum: 15 (mA written for A) became 20 mA.
    for (int c = 0; c < map_.num_channels; ++c)
      if (!stimulation_command_allowed(map_.channels[c], values_[3 * c], values_[3 * c + 1], values_[3 * c + 2])) {
        ++pk_.stimulation_refused;
        return;
      }
  }
  if (!accept_sequence(h, from)) return;
  if (h.type == kTarget) {
    std::copy(values_.begin(), values_.begin() + h.count, target_.begin());
    has_target_ = true;
    ++pk_.targets_applied;
    applied(h, now_s);
    return;
  }
  if (h.type == kStimulation) {
    std::copy(values_.begin(), values_.begin() + h.count, stim_command_.begin());
    ++pk_.stimulation_applied;
    applied(h, now_s);
    return;
  }
  bool clipped = false;
  for (int k = 0; k < h.count; ++k) {
    if (values_[k] < 0.0) { values_[k] = 0.0; clipped = true; }
    if (values_[k] > 1.0) { values_[k] = 1.0; clipped = true; }
  }
  if (clipped) ++pk_.clipped;
  // Overlapping names (a channel mapping of a group and its muscles): the rule of names.h.
  if (map) combine_named_values(*map, values_.data(), n_el_, command_.data(), level_scratch_.data());
  else for (int i = 0; i < n_el_; ++i) command_[i] = values_[i];
  applied(h, now_s);
}

bool Session::accept_sequence(const Header& h, const sockaddr_in& from) {
  // Sequence numbers (wrap-around aware) within the session: one counter for excitation and stimulation.
  if (have_seq_) {
    const std::int32_t diff = static_cast<std::int32_t>(h.seq - last_seq_);
    if (diff == 0) { ++pk_.stale; return false; }
    if (diff < 0) { ++pk_.out_of_order; return false; }
  }
  if (!have_owner_) {  // the first valid packet with the offered id claims the session
    if (!may_claim(from)) { ++pk_.held_off; return false; }  // the hold / the old owner's grace
    have_owner_ = true;
    owner_ = from;
    isolate_owner(&owner_);
    ++pk_.sessions;
    if (!had_owner_ || !same_source(from, previous_owner_)) ++pk_.owner_changes;
  }
  return true;
}

void Session::applied(const Header& h, double now_s) {
  changed_ = true;
  have_seq_ = true;
  last_seq_ = h.seq;
  last_valid_s_ = now_s;
  ++pk_.applied;
}

void Session::isolate_owner(const sockaddr_in* owner) {
  if (owner_sock_ < 0) return;
  // One connect() per session start or end (not per cycle).
  const sockaddr_in& to = owner ? *owner : bound_addr_;
  ::connect(owner_sock_, reinterpret_cast<const sockaddr*>(&to), sizeof to);
}

// Reads fd (queue 0: shared, 1: the owner's) in batches until it is empty or the budget is spent; true if the
// budget ran out.
bool Session::drain(int fd, int queue, double now_s, std::int64_t budget_end) {
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
      msgs[i].msg_hdr.msg_control = rx_ctrl_.data() + i * kCtrlWords;
      msgs[i].msg_hdr.msg_controllen = kCtrlWords * sizeof(std::uint64_t);
      msgs[i].msg_len = 0;
    }
    const int got = ::recvmmsg(fd, msgs, kBatch, MSG_DONTWAIT, nullptr);
    if (got <= 0) return false;  // EAGAIN: empty (other errors: try again next cycle)
    for (int i = 0; i < got; ++i) {
      // SO_RXQ_OVFL: the queue's drop count so far (datagrams the kernel dropped because the queue was full),
      // carried by every datagram read; drops after the last one read show with the next.
      for (cmsghdr* cm = CMSG_FIRSTHDR(&msgs[i].msg_hdr); cm; cm = CMSG_NXTHDR(&msgs[i].msg_hdr, cm))
        if (cm->cmsg_level == SOL_SOCKET && cm->cmsg_type == SO_RXQ_OVFL) {
          std::uint32_t v;
          std::memcpy(&v, CMSG_DATA(cm), sizeof v);
          queue_drops_[queue] = v;
        }
      ++pk_.received;
      long len = static_cast<long>(msgs[i].msg_len);
      if (msgs[i].msg_hdr.msg_flags & MSG_TRUNC) len = kMaxPacket + 1;  // larger than any packet
      handle_datagram(rx_buf_.data() + i * slot, len, rx_from_[i], now_s);
    }
    pk_.kernel_drops = static_cast<std::uint64_t>(queue_drops_[0]) + queue_drops_[1];
    if (got < kBatch) return false;
    if (now_ns() >= budget_end) return true;
  }
}

void Session::receive(double now_s) {
  ++cycle_;
  replies_this_cycle_ = 0;
  if (sock_ >= 0 && listening_) {
    // The owner's queue first (others cannot fill it), then everything else until empty or the
    // budget is spent, so junk from others cannot queue up in front of the owner's packets.
    const std::int64_t budget_end = now_ns() + static_cast<std::int64_t>(rx_budget_us_ * 1e3);
    bool hit = owner_sock_ >= 0 && drain(owner_sock_, 1, now_s, budget_end);
    hit = drain(sock_, 0, now_s, budget_end) || hit;
    if (hit) ++pk_.rx_budget_hits;
  }
  if (have_owner_ && now_s - last_valid_s_ > input_timeout_) end_session(false);
}

void Session::send_state(const StateValues& values, std::uint16_t loop_flags) {
  std::uint16_t flags = loop_flags | block_flags_;
  if (!have_owner_) flags |= kFlagTimedOut;
  if (key_.enabled()) flags |= kFlagAuth;
  StateValues v = values;
  const double last_seq = have_seq_ ? static_cast<double>(last_seq_) : -1.0;
  v.last_applied_seq = &last_seq;
  // values_ is reused as the output staging area (the input is applied by now).
  const int c = put_state_values(v, flags, n_dofs_, n_el_, map_.num_channels, values_.data());
  std::uint8_t* b = tx_buf_.data();
  const int len = encode(b, kStatePacket, tx_seq_++, flags, values_.data(), c, session_id_);
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
}

}  // namespace armrt::rt
