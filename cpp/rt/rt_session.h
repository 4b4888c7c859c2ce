// Datagrams in -> the owner's per-element excitation command (checked, clipped to [0, 1], zero when
// the session ends); state values -> signed state packets out to the owner and the subscribers.
// UDP sockets, session ownership, HMAC, sequence numbers and the excitation mappings live here.
//
// Sessions: excitations are taken from one controller at a time, the session's owner. A controller
// asks for the session id (kHello -> kOffer); the first excitation carrying it claims the session
// when none is active; packets from any other source are then dropped unread beyond the address.
// The session ends on kRelease from the owner or after input_timeout s without a valid packet from
// it: the excitation falls to zero, state stops going to the owner, and a new session id is drawn,
// so no packet of the old session is ever applied again.
//
// After a timeout (not a release: that is the owner's deliberate hand-over) the zero is held for
// hold_s() of simulated time, ln(100) deactivation time constants of the model's slowest element
// (activation dynamics da/dt = -a / tdeact at zero excitation, He et al. 1991, the model's tdeact): every
// activation is then below 1 % of its value at the timeout. Nobody may own the arm during the hold; then,
// for resume_grace_s(), only the timed-out owner may; then anyone. The timed-out owner is told at once
// (kSessionEnded), and again when a packet of its ended session arrives. Both intervals are counted in
// cycles (one period of simulated time each), so a loop that falls behind holds longer in wall time,
// never shorter in the model's time.
//
// Replies (offers, session-ended notices) are shared between sources: at most one per source per
// kReplyInterval s and kRepliesPerCycle per cycle, the sources remembered in a fixed table of
// kReplySources (least recently answered evicted), so a hello flood from one source cannot take the
// offers every other source asks for. The notice sent at a timeout is the exception: it always goes (it is
// counted in the source's share), so the owner hears at once why its arm stopped.
//
// Everything that allocates happens in the constructor; receive() and send_state() do not.
#pragma once

#include <netinet/in.h>
#include <sys/socket.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "armrt/model_def.h"
#include "armrt/names.h"
#include "armrt/stimulation.h"
#include "endpoint.h"
#include "hmac.h"
#include "packet.h"
#include "rt_config.h"
#include "rt_stats.h"

namespace armrt::rt {

class Session {
 public:
  // Opens the sockets (listen, state_to), resolves the channel names of cfg against def; throws
  // std::invalid_argument (bad names, endpoints, key) or std::runtime_error (socket, bind). map: the
  // simulator's stimulation map (num_channels 0: none; kStimulation packets are then refused), which must
  // outlive the session.
  Session(const RtConfig& cfg, const ModelDef& def, const StimulationMap& map, std::vector<std::string>& warnings);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Reads what arrived this cycle (the owner's queue first, within the receive budget) and ends a
  // session silent for longer than the input timeout. now_s: loop time.
  void receive(double now_s);
  // True once after the command changed (a packet applied, a session ended); command(): one
  // excitation per element in [0, 1], before the model's max activation; stimulation_command(): 3 values
  // per channel of the map (pulse width s, amplitude A, frequency Hz), within the channels' limits, all
  // zero while no session is active.
  bool take_changed() {
    const bool c = changed_;
    changed_ = false;
    return c;
  }
  const double* command() const { return command_.data(); }
  const double* stimulation_command() const { return stim_command_.data(); }
  // --static-optimization: the owner's last kTarget (q, qdot, qddot: 3 * DOFs), valid while has_target().
  bool has_target() const { return has_target_; }
  const double* target() const { return target_.data(); }
  int num_channels() const { return map_.num_channels; }

  bool wants_state() const { return sock_ >= 0 && (!subscribers_.empty() || have_owner_ || notify_previous_); }
  // Sends one state packet (rows per cfg's --forces / --excitations; last_applied_seq is the
  // session's own) with the loop's status flags (stopped, error, overrun).
  void send_state(const StateValues& values, std::uint16_t loop_flags);

  int bound_port() const { return bound_port_; }
  double hold_s() const { return hold_s_; }                 // zero held after a timeout (simulated s)
  double resume_grace_s() const { return grace_s_; }        // the timed-out owner's turn after the hold (s)
  // The receive buffers obtained (getsockopt SO_RCVBUF: twice the request, the kernel's bookkeeping included);
  // 0: no such queue.
  int rcvbuf_bytes() const { return rcvbuf_bytes_; }
  int owner_rcvbuf_bytes() const { return owner_rcvbuf_bytes_; }
  bool authenticated() const { return key_.enabled(); }
  const PacketCounters& counters() const { return pk_; }

 private:
  void handle_datagram(const std::uint8_t* buf, long n, const sockaddr_in& from, double now_s);
  // The sequence check and claim of an applicable packet (excitation or stimulation); false: not applied.
  bool accept_sequence(const Header& h, const sockaddr_in& from);
  void applied(const Header& h, double now_s);
  bool drain(int fd, int queue, double now_s, std::int64_t budget_end);
  void isolate_owner(const sockaddr_in* owner);
  void end_session(bool released);
  void send_offer(const sockaddr_in& to);
  void send_session_ended(const sockaddr_in& to);
  // May `from` claim the session now (not in the hold; in the grace window only the timed-out owner)?
  bool may_claim(const sockaddr_in& from) const;
  // Is a reply to `to` within its share (per source and per cycle)? Records it if so.
  // within_share = false: the timeout's own notice, sent whatever the source's share (at most one per session
  // end, so no amplification; an owner that said hello just before its timeout lost it), still counted there.
  bool reply_allowed(const sockaddr_in& to, bool within_share = true);
  void send_to(const std::uint8_t* b, int len, const sockaddr_in& to);

  bool listening_ = false;
  double input_timeout_ = 0, rx_budget_us_ = 0;
  std::uint16_t block_flags_ = 0;       // kFlagForces / kFlagExcitation as configured
  int n_dofs_ = 0, n_el_ = 0;

  // Excitation mappings (names.h: the most specific name wins, ties take the largest value).
  NamedElements muscles_, groups_, channels_;
  std::vector<NameLevel> level_scratch_;
  std::vector<double> command_;
  const StimulationMap& map_;
  std::vector<double> stim_command_;    // 3 per channel
  bool changed_ = false;
  int target_count_ = 0;                // 3 * DOFs with --static-optimization, else 0 (kTarget refused)
  std::vector<double> target_, dof_lo_, dof_hi_;
  bool has_target_ = false;

  // UDP.
  static constexpr int kBatch = 32;     // datagrams per recvmmsg
  int sock_ = -1;
  // The owner's own queue: a second socket on the same port (SO_REUSEPORT), connect()ed to the owner
  // while a session lasts, so the kernel delivers the owner's datagrams there and a flood from others
  // fills only sock_'s queue. Between sessions it is connected to sock_'s own address (silent).
  int owner_sock_ = -1;
  sockaddr_in bound_addr_{};
  int bound_port_ = 0;
  std::vector<sockaddr_in> subscribers_;
  std::vector<SourceFilter> allow_;
  HmacKey key_;
  std::vector<std::uint8_t> rx_buf_, tx_buf_;
  std::vector<sockaddr_in> rx_from_;
  std::vector<char> rx_hdr_storage_;    // mmsghdr[kBatch] + iovec[kBatch], preallocated
  // Ancillary data per datagram (the SO_RXQ_OVFL drop count), 8-byte aligned, preallocated.
  static constexpr std::size_t kCtrlWords = (CMSG_SPACE(sizeof(std::uint32_t)) + 7) / 8;
  std::vector<std::uint64_t> rx_ctrl_;
  std::uint32_t queue_drops_[2] = {0, 0};  // the kernel's drop count of the shared and the owner's queue
  int rcvbuf_bytes_ = 0, owner_rcvbuf_bytes_ = 0;  // as getsockopt(SO_RCVBUF) reports them
  std::vector<double> values_;          // decoded packet values / state staging (kMaxValues)
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
  PacketCounters pk_;

  // Hold and grace after a timeout, in cycles (receive() calls: one period of simulated time each).
  std::int64_t cycle_ = 0;
  double hold_s_ = 0, grace_s_ = 0;
  std::int64_t hold_cycles_ = 0, grace_cycles_ = 0;
  std::int64_t hold_end_ = 0, grace_end_ = 0;  // cycle numbers; 0: no hold (never timed out)
  std::uint32_t ended_session_id_ = 0;  // the timed-out session's id (0: none, or ended by release)

  // Fair replies: one per source per reply_interval_cycles_, kRepliesPerCycle per cycle.
  static constexpr int kReplySources = 64;
  static constexpr int kRepliesPerCycle = 4;
  static constexpr double kReplyInterval = 0.01;  // s; UdpClient.join says hello every 50 ms
  struct ReplySlot {
    in_addr_t addr = 0;
    in_port_t port = 0;
    std::int64_t last_cycle = -1;  // -1: free
  };
  std::array<ReplySlot, kReplySources> reply_slots_{};
  std::int64_t reply_interval_cycles_ = 1;
  int replies_this_cycle_ = 0;
};

}  // namespace armrt::rt
